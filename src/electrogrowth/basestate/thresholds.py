"""Following a loading branch of a layered tube from its start, and where it is lost
(docs/derivation-layered.md; the branches' states at given r_i: :mod:`.branches`).

A branch is walked from its start on a geometric grid (``BRANCH_STEPS``) in r_i, or in
lambda_z where r_i falls back as the load rises (its :func:`chart`), and its threshold
(:class:`Threshold`) is where it is lost: a limit point (first maximum of the
load, located on a Chebyshev interpolant), an asymptote (Richardson extrapolation of the
load as lambda_i -> inf), locking (the energy ends, located by bisection) or none. A load is
solved for on the walked branch by Brent's method in its bracketing cell of the walked coordinate
(:func:`solve_on`). A tube is prepared once (:func:`prepare`, cached): its unloaded state
(V = 0, P_i = P_o), the pressure stage to its P_i at V = 0, and the voltage branch from
there, whose threshold is walked when first asked for. A load beyond the branch's threshold
raises BaseStateError.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ..continuation.events import BRANCH, LOCK, Remembered, bisect, brent, reached, turned
from ..continuation.path import GeometricGrid
from ..errors import (
    NEAR_LOCK,
    OVERFLOW,
    BaseStateError,
    Beyond,
    ConvergenceError,
    Remedy,
    StartUnresolved,
)
from ..model.layers import Tube
from .branches import Branch, clean
from .ellipticity import check_in_plane
from .plies import Ply, Wall, choose_nodes, numeric_energy, start_guess
from .start_probe import FIRST_STEP, probe_step

#: branch scans: r_start 1.08^k up to 1e3 r_start, eight points evaluated at a time
BRANCH_STEPS = GeometricGrid(ratio=1.08, span=1e3, batch=8)


# -- following a branch, its threshold ----------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class Threshold:
    """Where the axisymmetric branch from the unloaded state is lost.

    control: "voltage" (value in Vbar) or "pressure" (value = P_i); kind: "limit point" (first
    maximum of the load along the branch, a snap-through), "asymptote" (the load tends to
    ``value`` as lambda_i -> inf), "locking" (the energy ends at lambda_i, the load unbounded
    before it, value = inf), "none" (the load rises without bound, value = inf) or, for the
    voltage, "closing" (no charge balances the traction on either side of the start, value
    0 there: :func:`opens`, :func:`inward`) or "unresolved" (which side a charge balances
    it on is not resolved: the traction is flat to rounding at the start, start_probe.py;
    value 0, no charged state followed); lambda_i and stretch (lambda_z) at
    the threshold (inf / the last scanned lambda_z for an asymptote).
    """

    control: str
    value: float
    kind: str
    lambda_i: float
    stretch: float
    error: float = 0.0
    # the scanned branch from its start (r_i, lambda_z, analytic load): brackets for solves
    grid: tuple = dataclasses.field(default=(), repr=False, compare=False)
    # the coordinate the grid was walked in, monotone along it: "r_i" or "stretch" (Chart)
    walked: str = dataclasses.field(default="r_i", repr=False, compare=False)


#: the relative step of lambda_z that probes, at a branch's start, which way r_i moves as
#: the load rises (first order: r_i moves by |d ln r_i / d ln lambda_z| times it)
PROBE = 1e-6


@dataclasses.dataclass(frozen=True)
class Chart:
    """A branch's states along one coordinate: ``by`` "r_i" (lambda_z solved at each r_i,
    Branch.at), "stretch" (r_i solved at each lambda_z, Branch.at_stretch) or, under stretch
    control, "charge" (r_i solved at each charge c, Branch.at_charge: the other coordinate
    is r_i), walked in direction ``step`` (+1 rising, -1 falling) as the load rises from
    the start."""

    branch: Branch
    by: str = "r_i"
    step: int = 1

    def at(self, u, guess) -> dict:
        """Points at the walked coordinate's values u, the other one solved from guess."""
        if self.by == "r_i":
            return self.branch.at(u, guess)
        if self.by == "charge":
            return self.branch.at_charge(u, guess)
        return self.branch.at_stretch(u, guess)

    def point(self, u, other) -> dict:
        """The point at the walked coordinate u and the other one, as given."""
        if self.by == "charge":
            lz = np.full(np.shape(np.atleast_1d(other)), self.branch.wall.tube.stretch)
            return self.branch.point(np.atleast_1d(other), lz, np.atleast_1d(u))
        r_i, lz = (u, other) if self.by == "r_i" else (other, u)
        return self.branch.point(np.atleast_1d(r_i), np.atleast_1d(lz))

    def split(self, pt: dict):
        """(walked coordinate, the other one) of points."""
        if self.by == "charge":
            return pt["charge"], pt["r_i"]
        r_i, lz = pt["r_i"], pt["stretch"]
        return (r_i, lz) if self.by == "r_i" else (lz, r_i)

    def physical(self, us, vs, loads) -> tuple:
        """A walked grid as (r_i, lambda_z, load), and the charge after them on the charge
        chart (r_i is not monotone along it: it is read in the charge, :meth:`read`)."""
        if self.by == "charge":
            return vs, np.full_like(vs, self.branch.wall.tube.stretch), loads, us
        return self.state(us, vs) + (loads,)

    def read(self, grid) -> tuple:
        """(walked coordinate, the other one) of a Threshold's grid (:meth:`physical`)."""
        return (grid[3], grid[0]) if self.by == "charge" else self.start(grid[0], grid[1])

    def start(self, x0: float, lz0: float) -> tuple[float, float]:
        """(walked coordinate, the other one) of the start (r_i, lambda_z) = (x0, lz0)."""
        return (x0, lz0) if self.by == "r_i" else (lz0, x0)

    def state(self, u: float, other: float) -> tuple[float, float]:
        """(r_i, lambda_z) of the walked coordinate u and the other one."""
        if self.by == "charge":
            return other, self.branch.wall.tube.stretch
        return (u, other) if self.by == "r_i" else (other, u)


def chart(branch: Branch, x0: float, lz0: float, sense: int = 1) -> Chart:
    """How to walk the branch from its start (x0, lz0) so that the load moves in ``sense``:
    in r_i moving with it (every branch under stretch control; under force control where r_i
    rises with a rising load: the walk as it always was), else in the coordinate that moves
    faster, from the two states at lambda_z = lz0 (1 +- PROBE). A charged force-free film
    tube under suction (P_i < -9.69, probe 12b D7) lets r_i fall as the voltage rises, to a
    minimum where it turns (a fold of the r_i chart: no lambda_z beyond it) while lambda_z
    rises throughout: walked in rising r_i, the branch's first states were skipped."""
    ri_chart = Chart(branch, "r_i", sense)
    if branch.wall.tube.control != "force":
        return ri_chart
    lz = lz0 * (1.0 + PROBE * np.array([1.0, -1.0]))
    pt = clean(branch.at_stretch(lz, np.array([x0, x0])))  # each from the start's r_i
    up = sense * branch.value(pt)
    if not (np.all(np.isfinite(up)) and up[0] != up[1]):
        return ri_chart  # lambda_z does not move through the start: r_i does
    j = int(np.argmax(up))  # the side where the load moves in sense
    dr = math.log(pt["r_i"][j] / x0)
    if sense * dr >= 0:
        return ri_chart
    if abs(dr) > abs(math.log(lz[j] / lz0)):
        return Chart(branch, "r_i", -sense)
    return Chart(branch, "stretch", 1 if j == 0 else -1)


def _walk(chart: Chart, x0: float, lz0: float, *, sense: int = 1, target=None):
    """Follow the branch from (r_i, lambda_z) = (x0, lz0) on the chart's coordinate u0 1.08^(step
    k) up to a factor 1e3; returns the chart walked, arrays (u, the other coordinate, analytic
    load) from the start and why it stopped: "target" (sense (load - target) >= 0), "peak"
    (the load turned back), "lock" (an energy ended: last entry NaN) or "end". A chart that
    folds is exchanged once for the other one (:func:`_past_fold`), the grid read in it."""
    u0, v0 = chart.start(x0, lz0)
    # the start (x0, lz0) is a solved state: solved again for lambda_z, a charged tube's
    # voltage branch under suction found none (two lambda_z close by), and the grid began
    # with a NaN load (probe 12b, D7)
    first = clean(chart.point(u0, v0))
    us, vs, loads = [u0], [v0], [float(chart.branch.value(first)[0])]
    stop = _leg(chart, us, vs, loads, sense, target)
    if stop in ("nan", "jump") and (other := _past_fold(chart, us, vs, loads)) is not None:
        before = chart, us, vs, loads
        chart, us, vs, loads = other
        stop = _leg(chart, us, vs, loads, sense, target)
        turned_back = np.any(before[0].step * np.diff(vs) < 0)
        if stop in ("end", "nan") and chart.by == "charge" and not turned_back:
            # r_i never turned: the charge grows without bound as r_i nears where the r_i
            # walk found no state, a lock of the coupling (check round 30, case A: Vbar
            # unbounded as r_i falls to 1.26122), read from that walk as before
            (chart, us, vs, loads), stop = before, "nan"
    if stop == "jump":  # no other chart to walk: the point stands
        stop = _leg(chart, us, vs, loads, sense, target, jumps=False)
    if stop == "nan":
        if not _energy_ends(chart, us[-1], vs[-2]):
            name = "lambda_z" if chart.by == "r_i" else "r_i"
            fixed = "lambda_i" if chart.by == "r_i" else "lambda_z"
            raise ConvergenceError(
                f"no {name} balances the axial force at {fixed} = {us[-1]:.12g}"
            )
        stop = "lock"
    return chart, np.array(us), np.array(vs), np.array(loads), stop


def _leg(chart: Chart, us: list, vs: list, loads: list, sense: int, target, jumps=True) -> str:
    """Walk on from the last of (us, vs, loads), appending to them, until the target, a peak,
    the end of the grid, a state not found ("nan", appended) or, with ``jumps`` under force
    control, a step where the other coordinate moved more than the walked one ("jump",
    appended): the chart is at or past a fold, and the other coordinate's solve can land on
    the branch's far side (check round 28, res_61 #12 at F = 248.2: lambda_z 11.02 to 8.75
    for r_i 1.786 to 1.653, then 10.20; a peak 5.4076 read across the two sides, where
    the branch's is 5.4551)."""
    branch = chart.branch
    jumps = jumps and branch.wall.tube.control == "force"
    for u in BRANCH_STEPS.batches(us[-1], chart.step):
        pt = clean(chart.at(u, vs[-1]))
        for uj, vj, lj in zip(u, chart.split(pt)[1], branch.value(pt)):
            us.append(float(uj)), vs.append(float(vj)), loads.append(float(lj))
            if not np.isfinite(lj):
                return "nan"
            if jumps and abs(math.log(vs[-1] / vs[-2])) > abs(math.log(us[-1] / us[-2])):
                return "jump"
            if target is not None and reached(lj, target, sense):
                return "target"
            if turned(loads[-2], lj, sense):
                return "peak"
    return "end"


def _past_fold(chart: Chart, us: list, vs: list, loads: list):
    """The other chart, walked the way its coordinate has moved, and the walk so far in it
    (us, vs, loads without its last step), where the walk found no state at its last step
    (us[-1]) but that coordinate has moved monotonically from the start and the branch has
    a state one step further in it: the walked coordinate folds (turns back) while the other keeps
    moving. Under force control a branch running inward under a charge that lowers lambda_z
    turns in r_i (check round 28, res_61 #12: r_i falls from 1.899 to 1.515 and rises again
    as lambda_z falls from 11.03, the voltage rising to a limit point at lambda_z 7.5);
    walked in r_i it ended at the fold, read as a lock. Under stretch control the other
    coordinate is the charge (a general energy's voltage branch: its r_i is a function of
    c where T falls with r_i nowhere): a field that raises T at small charge and lowers it
    at large turns the branch in r_i as the charge rises (check round 30 D2: inward from
    r0 = 1.28158 to 0.99826 r0 at c 0.575, then outward through r0 at Vbar 0.544). None
    where the other coordinate has turned too, or no state lies one step on in it."""
    branch = chart.branch
    force = branch.wall.tube.control == "force"
    if force and len(vs) >= 3:
        other_us, other_vs, loads = vs[:-1], us[:-1], loads[:-1]
        by = "stretch" if chart.by == "r_i" else "r_i"
    elif not force and branch.load == "voltage" and _no_charge(chart, us[-1]):
        other_us, other_vs, loads = _charges(chart, us)
        by = "charge"
    else:
        return None
    if len(other_us) < 2:
        return None
    d = np.diff(other_us)
    if not (np.all(d > 0) or np.all(d < 0)):
        return None
    other = Chart(branch, by, 1 if d[0] > 0 else -1)
    u = other_us[-1] * BRANCH_STEPS.ratio**other.step
    ahead = branch.value(clean(other.at([u], other_vs[-1])))[0]
    return (other, list(other_us), list(other_vs), list(loads)) if np.isfinite(ahead) else None


def _no_charge(chart: Chart, r_i: float) -> bool:
    """Is the r_i walk's missing state at r_i one where no charge balances the traction,
    the energy finite there uncharged (a general energy: an ideal one's charge is unique,
    and a Gent layer past its lock ends the branch, test_nan_charge.py)?"""
    branch = chart.branch
    if branch.wall.ideal:
        return False
    uncharged = Branch(branch.wall, "pressure", vbar=0.0).point([r_i], [branch.wall.tube.stretch])
    return bool(np.isfinite(uncharged["P_i"][0]))


def _charges(chart: Chart, us: list) -> tuple[list, list, list]:
    """(c, r_i, load) of an r_i walk under stretch control up to its last finite state, with a
    state found short of the step past it (the step's log shortened 2^-k, k < 50) where
    the walk has no charged one: a fold 0.17 % inward of the start (check round 30 D2)
    lies inside the first 8 % step."""
    us = list(us[:-1])
    if len(us) == 1:
        for k in range(1, 50):
            pt = clean(chart.at([us[0] * BRANCH_STEPS.ratio ** (chart.step * 0.5**k)], 1.0))
            if np.isfinite(chart.branch.value(pt)[0]):
                us.append(float(pt["r_i"][0]))
                break
    pt = clean(chart.point(np.array(us), np.full(len(us), chart.branch.wall.tube.stretch)))
    return list(pt["charge"]), us, list(chart.branch.value(pt))


def opens(walk: Chart, x0: float, lz0: float) -> bool:
    """Does a charge balance the traction just past the voltage branch's start (x0, lz0)?
    The layered analogue of the one-layer tube's test (voltage._rises): there the wall's
    residual T - (P_i - P_o) of (*) is 0 at q = c^2 = 0 and rises with r_i, so a charged
    state past the start needs T to fall with q. Where the energy's field raises it
    (dT/dq > 0: an I6 term with a negative weight, `(I1-3)/2 + 0.2*I4 + 0.4*I5 - 0.1*I6`
    at lambda_z <= 0.49) no charge balances it (the load is NaN, read one probe step past
    the start, as for one layer): the field closes the bore, the branch may run inward
    (:func:`inward`). The step is the first of 1e-6, 1e-5, ... whose residual at q = 0 is
    resolved (start_probe.probe_step): next to an inflation asymptote T is flat, and 1e-6
    from the start it read ~6e-16 of a cancelling 1.39, noise taken for the start itself
    (check round 32). T is a
    sum over the layers, so identical layers read exactly what one layer does. A point
    that is not finite because the energy ends there (a Gent layer at its lock) is no
    closing field: the walk reads it.

    The probe keeps the start's other coordinate (lambda_z moves by O(the step) along
    the branch): under force control a field that closes the bore outward of the start
    leaves no charge there at any lambda_z, and balancing the axial force found no residual
    to balance; read as "no lambda_z", the walk then bisected its first cell for a lock,
    every step a failed balance (check round 28, res_61 #12: F = 247, lambda_z = 11, 65 s
    a threshold), where the branch runs inward (fix23f's probe)."""
    u0, v0 = walk.start(x0, lz0)

    def read(h: float) -> tuple[float, float]:
        return walk.branch.unbalanced(*walk.state(u0 * (1.0 + walk.step * h), v0))

    h = _step(walk, read, x0, lz0)
    pt = walk.point(u0 * (1.0 + walk.step * h), v0)
    if np.isfinite(walk.branch.value(pt)[0]):
        # the branch leaving the start has a charge that vanishes there, so a small charge
        # moves T towards P_i - P_o; a charge found where it moves T away is a root detached
        # from the start (an I5^2 term, check round 30 D2: c 0.847, Vbar 0.544 at r0 (1 +
        # 1e-5), where the branch runs inward; walked from it, every Vbar below was refused)
        return walk.branch.leaves(float(pt["r_i"][0]), float(pt["stretch"][0]))
    r_i, lz = pt["r_i"], pt["stretch"]
    uncharged = Branch(walk.branch.wall, "pressure", vbar=0.0).point(r_i, lz)
    return not np.isfinite(uncharged["P_i"][0])  # the energy ends there: a lock


def inward(walk: Chart, x0: float, lz0: float) -> Chart | None:
    """The chart walked the other way where the field closes the bore past the start: a
    field that raises T inward of the uncharged state balances the traction there, and
    the voltage rises as r_i falls (a coupling that stiffens with I1, check round 28 D1:
    Vbar 0.185 at r_i 9.25 from the uncharged 9.2593, to the coupling's limit at 9.03);
    None where no charge balances on that side either (the field closes the bore)."""
    back = dataclasses.replace(walk, step=-walk.step)
    u0, v0 = back.start(x0, lz0)
    probed: dict[float, dict] = {}  # the points read, by step

    def read(h: float) -> tuple[float, float]:
        probed[h] = pt = clean(back.at([u0 * (1.0 + back.step * h)], v0))
        return walk.branch.unbalanced(float(pt["r_i"][0]), float(pt["stretch"][0]))

    if (h := _step(walk, read, x0, lz0)) not in probed:
        read(h)
    load = walk.branch.value(probed[h])[0]
    return back if np.isfinite(load) and load > 0 else None


def _step(walk: Chart, read, x0: float, lz0: float) -> float:
    """The probe's step from the start (x0, lz0) (start_probe.probe_step); FIRST_STEP for
    ideal dielectrics, whose answer does not hang on the reading: T = M - q Q, so a charge
    balances wherever T > P_i - P_o and the branch opens (Branch.leaves), as it always
    read (a neo-Hookean tube next to its inflation asymptote under a voltage: fix24d)."""
    if walk.branch.wall.ideal:
        return FIRST_STEP
    return probe_step(read, f"its uncharged start r_i = {x0:.12g} (lambda_z = {lz0:.12g})")


def _energy_ends(chart: Chart, u: float, v: float) -> bool:
    """Whether a state that is not finite at the walked coordinate u is past an energy's end
    (a lock): any energy with its own domain (Gent, an exponential) ends; polynomials only
    where they overflow a double, i.e. the state at u and the last other coordinate, v, is
    not finite either (else no state balances the axial force)."""
    if any(numeric_energy(p.layer.material) is not None for p in chart.branch.wall.plies):
        return True
    return not np.isfinite(chart.branch.value(clean(chart.point(u, v)))[0])


def _guess(us, vs):
    """The other coordinate's guesses at new values of the walked one, u, by interpolation
    of a scanned branch (u, v) (log-linear; linear in a charge, whose grid starts at 0)."""
    good = np.isfinite(vs)
    order = np.argsort(us[good])
    u, v = us[good][order], vs[good][order]
    axis = np.log if u[0] > 0 else np.asarray
    return lambda x: np.interp(axis(x), axis(u), v)


def threshold(
    branch: Branch, x0: float, lz0: float, control: str, *, sign: int = 1, target=None
) -> Threshold:
    """Scan the branch from its start (x0, lz0) as the load rises (sign = 1) or falls (-1),
    on its :func:`chart`; classify and locate where it is lost. With a target (analytic load)
    the scan stops once it is crossed: kind "" (not lost before it), value nan, the grid
    brackets the target."""
    walk = chart(branch, x0, lz0, sign)
    if control == "voltage" and sign > 0:
        try:
            leaving = walk if opens(walk, x0, lz0) else inward(walk, x0, lz0)
            kind = "closing"
        except StartUnresolved:  # which side is not resolved: no charged state followed
            leaving, kind = None, "unresolved"
        if leaving is None:
            start = (np.array([x0]), np.array([lz0]), np.zeros(1))
            return Threshold(control, 0.0, kind, x0, lz0, 0.0, start, "r_i")
        walk = leaving
    walk, us, vs, loads, stop = _walk(walk, x0, lz0, sense=sign, target=target)
    guess = _guess(us, vs)
    out = lambda v: math.sqrt(v) if control == "voltage" else v  # noqa: E731

    def lost(kind, value, u, v, error=0.0, grid=None):
        x, lz = walk.state(u, v)
        grid = (us, vs, loads) if grid is None else grid
        return Threshold(control, value, kind, x, lz, error, walk.physical(*grid), walk.by)

    if stop == "target":
        return lost("", math.nan, math.nan, math.nan)
    if stop == "peak":
        j = len(us) - 2  # the extreme load scanned
        a, b = sorted((us[max(j - 1, 0)], us[j + 1]))

        def f(u):
            return sign * branch.value(clean(walk.at(u, guess(u))))

        with np.errstate(invalid="ignore"):
            poly = cheb.Chebyshev.interpolate(f, 24, domain=[a, b])
        # a gap between the scan's samples (no charge balances the traction: an energy whose
        # field closes the bore) leaves NaN coefficients, on which eigvals raises
        finite = np.isfinite(poly.coef).all()
        crit = finite and [
            x.real for x in poly.deriv().roots() if abs(x.imag) < 1e-9 and a <= x.real <= b
        ]
        if not crit:
            raise ConvergenceError(
                f"limit point of the {control} not located in [{a:.6g}, {b:.6g}]"
                + ("" if finite else ": the branch has no state somewhere in it")
            )
        top = max(crit, key=poly)
        pt = clean(walk.at([top], guess(top)))
        value = float(branch.value(pt)[0])
        other = float(walk.split(pt)[1][0])
        keep = walk.step * (top - us) > 0
        grid = (
            np.append(us[keep], top),
            np.append(vs[keep], other),
            np.append(loads[keep], value),
        )
        return lost(
            "limit point",
            out(value),
            float(top),
            other,
            abs(sign * float(poly(top)) - value),
            grid,
        )
    if stop == "lock":

        def finite(u):
            return bool(np.isfinite(branch.value(clean(walk.at([u], guess(u))))[0]))

        a, _ = bisect(finite, us[-2], us[-1], LOCK, near_bad=True)  # the energy's domain ends
        grid = (us[:-1], vs[:-1], loads[:-1])
        return lost("locking", sign * math.inf, float(a), float(guess(a)), grid=grid)
    # the limits below are of r_i -> inf or 0: of a walk in r_i, or in the charge with r_i
    # moving the load's way at its end (past the fold of check round 30 D2)
    charged = walk.by == "charge" and sign * (vs[-1] - vs[-2]) > 0
    if not charged and (walk.by != "r_i" or walk.step != sign):
        name = {"r_i": "lambda_i", "stretch": "lambda_z", "charge": "c"}[walk.by]
        raise ConvergenceError(
            f"the {control} branch walked in {name} from {us[0]:.12g} to {us[-1]:.12g} met"
            " no threshold (the load's limit at the end of that walk is not computed)"
        )
    grid = walk.physical(us, vs, loads)
    lz_end = float(grid[1][-1])
    if sign < 0:
        return Threshold(control, -math.inf, "none", 0.0, lz_end, 0.0, grid, walk.by)
    # Richardson: load = L_inf + a x^p + ..., x = lambda_i^-2, the order p measured
    far = x0 * 100.0 * 2.0 ** np.arange(5)
    pt = clean(branch.at(far, guess(far[0]) if walk.by == "r_i" else lz_end))
    t = np.array([out(v) if np.isfinite(v) else np.nan for v in branch.value(pt)])
    d = np.diff(t)
    if not (np.all(np.isfinite(t)) and np.all(d > 0) and d[-2] > d[-1]):
        return Threshold(control, math.inf, "none", math.inf, lz_end, 0.0, grid, walk.by)
    p = math.log(d[-2] / d[-1], 4.0)
    p = round(p) if abs(p - round(p)) < 0.05 else p
    for j in range(3):
        prev, t = t[-1], t[1:] + (t[1:] - t[:-1]) / (4.0 ** (p + j) - 1.0)
    return Threshold(
        control,
        float(t[-1]),
        "asymptote",
        math.inf,
        float(pt["stretch"][-1]),
        abs(float(t[-1]) - prev),
        grid,
        walk.by,
    )


def solve_on(branch: Branch, walked: Threshold, target: float, what: str, sign: int = 1):
    """r_i, lambda_z on the scanned branch where the analytic load reaches target (brentq in
    the bracketing cell of the walked coordinate; beyond the scan, a geometric tail towards
    the asymptote or lock). ``walked``: the walk's Threshold, kind "" where the walk reached
    the target before any threshold.

    ``sign``: the direction the load moves from the branch's start (+1 for the voltage, the
    sign of P_i - P_o for the pressure), given by the caller: read off the grid's first load
    it was rounding for a target next to the start (Vbar^2 = 1e-18 below the unloaded
    state's computed 3.8e-16 marched the wrong way and found no state, probe 9b D2)."""
    walk = Chart(branch, walked.walked)
    thr = walked if walked.kind else None
    r_i, lz, loads = walked.grid[:3]
    xs, lzs = walk.read(walked.grid)  # the walked coordinate, the other one
    k = np.flatnonzero(sign * (loads - target) >= 0)
    if k.size and k[0] == 0:
        # the start's load is exactly the control's start value, so the target lies between
        # it and its computed value: within the rounding of the load, the start is the state
        return float(r_i[0]), float(lz[0])
    if not k.size and thr is not None:
        far = math.inf if walk.by == "charge" else walk.start(thr.lambda_i, thr.stretch)[0]
        tail = (
            xs[-1] * 4.0 ** (sign * np.arange(1, 21))
            if not 0 < far < math.inf
            else far - (far - xs[-1]) * 4.0 ** -np.arange(1, 21)
        )
        pt = clean(walk.at(tail, lzs[-1]))
        xs, lzs = np.append(xs[-1], tail), np.append(lzs[-1], walk.split(pt)[1])
        loads = np.append(loads[-1], branch.value(pt))
        k = np.flatnonzero(sign * (loads - target) >= 0)
    if not k.size:
        if thr is not None and thr.kind == "locking":  # the state exists: not a loss
            err = ConvergenceError(
                f"{what} lies too close to the locking stretch lambda_i = {thr.lambda_i:.12g} of"
                " this tube to be resolved (the load is unbounded only at the lock itself)"
            )
            err.remedy = NEAR_LOCK  # neither a looser rtol nor collocation resolves it
            raise err
        raise BaseStateError(f"{what} is within rounding of the threshold of its branch")
    a, b = xs[k[0] - 1], xs[k[0]]
    guess = _guess(xs[k[0] - 1 : k[0] + 1], lzs[k[0] - 1 : k[0] + 1])

    def load(x):
        return float(branch.value(clean(walk.at([x], guess(x))))[0]) - target

    f = Remembered(load)  # Brent evaluates the checked ends again
    # the scan's own load at a: solved again there, the branch's start can land on the other
    # lambda_z (two balance the force at a charged tube's start under suction), or on none
    f.seen[a] = loads[k[0] - 1] - target
    if f(a) * f(b) > 0:  # the scan's sign change was its rounding: next to the threshold
        near = "" if thr is None else f" {thr.value:.12g}"
        raise BaseStateError(
            f"{what} = {target:.12g} is within the accuracy of the threshold{near} of its"
            " branch (the load does not reach it in the scan's cell)"
        )
    name = {"r_i": "lambda_i", "stretch": "lambda_z", "charge": "c"}[walk.by]
    lo, hi = sorted((a, b))
    try:  # tolerances relative to the cell's lower end, or to its upper one at c = 0
        x = brent(f, lo, hi, BRANCH, ref=lo or hi, named=False)
    except ValueError as exc:  # a load NaN inside the cell: no state found there
        err = ConvergenceError(
            f"{what} is not resolved: the branch's load is not finite inside its scan's cell"
            f" {name} in [{min(a, b):.12g}, {max(a, b):.12g}] ({exc})"
        )
        err.remedy = Remedy("")  # no tolerance finds a state there: not "loosen --rtol"
        raise err from None
    return walk.state(x, float(walk.split(clean(walk.at([x], guess(x))))[1][0]))


# -- preparation: the unloaded start, the pressure stage, the voltage branch -------------------


def _start(wall: Wall, P_i: float | None = None) -> tuple[float, float]:
    """The unloaded state (V = 0, P_i = P_o), or the state at V = 0 and the inner pressure
    ``P_i``: the root of P_i(r_i) - P_i, bracketed outward from the guess, under force
    control with lambda_z balancing the axial force at each r_i, continued from the last
    r_i where it did (from the guess itself, a soft Gent layer's lock can lie between: no
    lambda_z found, and a state that exists reported lost)."""
    branch = Branch(wall, "pressure", vbar=0.0)
    xg, lg = start_guess(wall)
    start, last_lz, seen = xg, [lg], {}
    target = wall.tube.outer_pressure if P_i is None else P_i
    which = (
        "unloaded state (V = 0, P_i = P_o)" if P_i is None else f"state at V = 0, P_i = {P_i:g}"
    )

    def f(x):
        # remembered: continued lambda_z moves the rounding of a value at the same r_i, and
        # Brent must see the signs that bracketed it (a root at the guess, f = -1e-16)
        if x not in seen:
            pt = clean(branch.at([x], last_lz[0]))
            lz = float(pt["stretch"][0])
            if math.isfinite(lz):
                last_lz[0] = lz
            seen[x] = float(pt["P_i"][0] - target), lz
        return seen[x]

    f0, _ = f(xg)
    for j in range(1, 41):  # a guess past a Gent layer's lock: the nearest finite state
        if np.isfinite(f0):
            break
        xg = start * 1.1 ** (j // 2 + 1) if j % 2 else start / 1.1 ** (j // 2)
        f0, _ = f(xg)
    if not np.isfinite(f0):  # the window of finite states narrower than those steps
        xg = _least_stretched(wall, start, lg, 1.1**20)
        f0, _ = f(xg)
    edge = LockedSearch(f"no {which} found before a layer's lock", wall.nodes)
    if not np.isfinite(f0):
        _not_found(wall, start, lg, which, edge)
    if f0 == 0:
        return xg, f(xg)[1]
    step, last, f_last = 1.1, xg, f0
    for _ in range(200):
        nxt = last / step if f_last > 0 else last * step
        fn, _ = f(nxt)
        if not np.isfinite(fn):
            # past the edge of the states (a Gent layer's lock): the root may lie between
            # the last state and that edge, in a window narrower than the step
            if step - 1.0 < 1e-12:
                raise edge
            step = math.sqrt(step)
            continue
        if np.sign(fn) != np.sign(f_last):
            try:
                x = brent(lambda x: f(x)[0], *sorted((last, nxt)), BRANCH, named=False)
            except ValueError:  # a state inside the bracket past a layer's lock
                raise edge from None
            return x, f(x)[1]
        last, f_last = nxt, fn
    if wall.overflow(start, lg) is None:  # the search read a wall that opens: did it?
        for k, layer in enumerate(wall.tube.layers, 1):
            if not layer.graded:
                where = f"layer {k} of this tube (lambda_z = {lg:g}, g_z = {layer.growth[2]:g})"
                check_in_plane(layer.material, lg / layer.growth[2], where)
    lost = BaseStateError(f"no {which} found for this tube")
    lost.remedy = NO_UNLOADED
    _not_found(wall, start, lg, which, lost)


def _least_stretched(wall: Wall, x: float, lz: float, span: float) -> float:
    """The r_i in [x / span, x span] of the least-stretched state at lambda_z (the smallest
    largest I1 of the layers that can lock): next to a Gent layer's lock, e.g. lambda_z within
    1e-4 of its point lock lambda_z^2 + 2 / lambda_z = 3 + jm, the finite states form a
    window around it a few per cent wide or less, which the guess's 1.1 steps jump over."""
    from scipy.optimize import minimize_scalar  # 0.5 s of imports: only next to a lock

    res = minimize_scalar(
        lambda r: wall.peak_invariant(r, lz),
        bounds=(x / span, x * span),
        method="bounded",
        options={"xatol": 1e-12 * x},
    )
    return float(res.x)


#: what to do where no unloaded state is found (the tube's own growth and stretch: no load
#: of the user's, such as a voltage, is the cause, since the search is made at V = 0)
NO_UNLOADED = Remedy(
    "move the growth or stretch back towards 1 (no unloaded state was found at them)"
)


#: what to do where the inner pressure is beyond its threshold (BaseStateError's own remedy
#: names the voltage, which may not even be applied; probe 14e D1)
PRESSURE_BEYOND = Remedy(
    "bring the inner pressure back towards the outer one, inside the threshold named here,"
    " or move the growth or stretch back towards 1"
)


class LockedSearch(BaseStateError):
    """The unloaded-state search met the edge of the finite states (a layer's lock) before
    the root, at ``nodes`` Gauss nodes. Next to a Gent layer's lock a coarse rule misplaces
    the root (its T errs by tenths there) past that edge while the state exists: the caller
    tries a finer rule before calling the state lost."""

    remedy = Remedy(
        "the tube's unloaded state, if any, lies next to a Gent layer's lock: grow or"
        " stretch it less, or give the layer a larger jm"
    )

    def __init__(self, message: str, nodes: int):
        super().__init__(message)
        self.nodes = nodes


def _not_found(wall: Wall, x: float, lz: float, which: str, otherwise: BaseStateError):
    """Raise: no start state found from the guess (r_i, lambda_z) = (x, lz). Where the
    stresses at the guess overflow a double, the search met the end of double precision, not
    of the states (an exponential energy's exist at every stretch): ConvergenceError naming
    it. Otherwise ``otherwise`` (past a lock, or none found)."""
    if (at := wall.overflow(x, lz)) is not None:
        err = ConvergenceError(
            f"no {which} found for this tube: its stresses overflow a double (I1 = {at:.6g} at"
            " the homogeneous-growth guess), beyond which no state is computed"
        )
        err.remedy = OVERFLOW  # neither a looser rtol nor collocation reaches it
        raise err
    raise otherwise


@dataclasses.dataclass(frozen=True)
class _Prepared:
    wall: Wall
    start: tuple[float, float]  # unloaded (V = 0, P_i = P_o)
    loaded: tuple[float, float]  # the tube's pressures at V = 0

    @property
    def branch(self) -> Branch:
        """The voltage branch at the tube's pressures."""
        tube = self.wall.tube
        return Branch(self.wall, "voltage", dp=tube.inner_pressure - tube.outer_pressure)

    @functools.cached_property
    def voltage(self) -> Threshold:
        """The threshold of the voltage branch from ``loaded`` (walked once, when asked)."""
        return threshold(self.branch, *self.loaded, "voltage")

    def voltage_to(self, vbar: float) -> Threshold:
        """The voltage branch walked only as far as Vbar (kind "": reached first, the grid
        brackets it), or the threshold met before it; the whole walk when it is known."""
        if "voltage" in self.__dict__:
            return self.voltage
        return threshold(self.branch, *self.loaded, "voltage", target=vbar * vbar)


def prepare(tube: Tube, rtol: float, nodes: int | None = None) -> _Prepared:
    """Everything but the voltage (tube.voltage is 0 here): cached per tube, rtol and nodes
    (one cache key however ``nodes`` is passed: a state at the voltage threshold then reads
    the threshold the march's path walked instead of walking it again). The voltage
    branch's threshold is walked when first asked for (``_Prepared.voltage``)."""
    return _prepared(tube, rtol, nodes)


@functools.lru_cache(maxsize=256)
def _prepared(tube: Tube, rtol: float, nodes: int | None) -> _Prepared:
    """:func:`prepare`, cached."""
    plies = Ply.stack(tube)
    wall = Wall.build(tube, nodes or choose_nodes(tube, rtol, plies), plies)
    dp = tube.inner_pressure - tube.outer_pressure
    try:
        x0, lz0 = _start(wall)
    except BaseStateError:
        if dp == 0:
            raise
        # a Gent core locked when unloaded that its inner pressure holds open: the loaded
        # state found directly (no pressure branch walked to it, so no threshold on it)
        loaded = _start(wall, tube.inner_pressure)
        return _Prepared(wall, loaded, loaded)
    loaded = (x0, lz0)
    if dp != 0:
        branch = Branch(wall, "pressure", vbar=0.0)
        target, sign = tube.inner_pressure, (1 if dp > 0 else -1)
        thr = threshold(branch, x0, lz0, "pressure", sign=sign, target=target)
        if thr.kind and not sign * (thr.value - target) > 0:
            err = BaseStateError(
                f"inner pressure P_i = {target:.12g} is at or beyond the pressure threshold"
                f" P_i = {thr.value:.12g} ({thr.kind}) of this tube; no axisymmetric state",
                beyond=Beyond("inner_pressure", target, thr.value, tube.outer_radius),
            )
            err.remedy = PRESSURE_BEYOND  # the load is the pressure, not a voltage
            raise err
        loaded = solve_on(branch, thr, target, "P_i", sign)
    return _Prepared(wall, (x0, lz0), loaded)
