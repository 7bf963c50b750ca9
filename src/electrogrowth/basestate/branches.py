"""The loading branches of a layered tube: its states parametrised by the inner radius
(docs/derivation-layered.md; one state of the wall, (*) and the integrals: :mod:`.plies`).

For each inner radius r_i (and lambda_z) one of (*) or the voltage fixes the charge c, the other
gives the load: on the *voltage branch* (P_i - P_o fixed) the voltage V(r_i), on the *pressure
branch* (V fixed) the pressure P_i(r_i). Under force control lambda_z(r_i) is solved at each r_i
from the axial balance. A state is reached from the unloaded one (V = 0, P_i = P_o) along the
pressure branch, then the voltage branch; following a branch from its start and its threshold,
where it is lost, are in :mod:`.thresholds`.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..continuation.events import BRANCH, BRANCH_STRETCH, brent
from .plies import Wall, illinois
from .start_probe import rounding

# -- the two branches -------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class Branch:
    """States parametrised by r_i: on the voltage branch (P_i - P_o = dp fixed) (*) fixes c and
    the load is Vbar; on the pressure branch (Vbar = vbar fixed) the voltage fixes c and the load
    is P_i = P_o + T. The outer pressure is the tube's throughout. ``compiled``: the wall's
    integrals by the compiled closed form where it has one (plies.Wall.integrals)."""

    wall: Wall
    load: str  # "voltage" or "pressure"
    dp: float = 0.0
    vbar: float = 0.0
    compiled: bool = False

    def point(self, r_i, lz, charge=None) -> dict:
        """The state at (r_i, lambda_z), its charge solved (:meth:`_charge`) or, for a general
        energy, the given ``charge`` (a branch walked in its charge: :meth:`at_charge`)."""
        # an energy's own finite range (a Fung exponential, a Gent lock) ends in inf or
        # NaN, which marks the point as no state: not a numpy warning to the user
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            return self._point(r_i, lz, charge)

    def _point(self, r_i, lz, charge=None) -> dict:
        wall, tube = self.wall, self.wall.tube
        r_i, lz = np.broadcast_arrays(np.asarray(r_i, float), np.asarray(lz, float))
        thick = tube.outer_radius - 1.0
        if wall.ideal and charge is None:
            M, scale, _, Nm = wall.integrals(r_i, lz, 0.0, self.compiled)
            Q, Lam = wall.electric(r_i, lz)
            if self.load == "voltage":
                q = (M - self.dp) / Q  # signed c^2: analytic through the branch's start
                c = np.sign(q) * np.sqrt(abs(q))
                dp = np.full_like(M, self.dp)
            else:
                c = np.full_like(M, self.vbar * thick) / Lam
                q, dp = c * c, M - c * c * Q
            V, N = c * Lam, Nm - math.pi * q * Lam
        else:
            c = self._charge(r_i, lz) if charge is None else np.broadcast_to(charge, r_i.shape)
            T, scale, V, N = wall.integrals(r_i, lz, c, self.compiled)
            dp = T if self.load == "pressure" else np.where(np.isfinite(T), self.dp, np.nan)
        P_o = tube.outer_pressure
        P_i = P_o + dp
        r_o2 = r_i * r_i + 2.0 * wall.faces_G[-1] / lz
        ends = math.pi * (P_i * r_i * r_i - P_o * r_o2)  # pressure load on closed ends
        N = N + ends
        applied = N - ends if tube.closed_ends else N
        residual = applied - tube.axial_force if tube.control == "force" else applied * 0.0
        return dict(
            r_i=r_i,
            stretch=lz,
            charge=c,
            voltage=V / thick,
            dp=dp,
            P_i=P_i,
            axial_force=N,
            end_force=applied,
            residual=residual,
            r_o=np.sqrt(r_o2),
        )

    def _charge(self, r_i, lz):
        """c for a general energy: (*) = dp in q = c^2, or V(c) = Vbar (R_N - 1) on the
        pressure branch. On the voltage branch a field lowers T where the uncharged T
        exceeds dp (outward of the uncharged state); inward of it (T < dp) a field that
        raises T balances it (a coupling that stiffens with I1, check round 28 D1: the
        branch runs inward), NaN where none does, and where the field lowers T there too, except
        at the uncharged state to rounding (q = 0: :meth:`_uncharged`); outward, NaN at once
        where T rises linearly with the charge (:meth:`_lowered`)."""
        wall, thick = self.wall, self.wall.tube.outer_radius - 1.0
        Q, Lam = wall.electric(r_i, lz)
        if self.load == "voltage":
            M, start = self._uncharged(r_i, lz)
            f0 = M - self.dp
            q = np.zeros_like(M)  # q = 0 at the start, whichever way the field moves T
            up = np.flatnonzero((f0 > 0) & ~start)
            if up.size:
                q[up] = self._lowered(r_i[up], lz[up], f0[up], 2.0 * f0[up] / Q[up])
            down = np.flatnonzero((f0 < 0) & ~start)
            if down.size:
                f = self._traction(r_i[down], lz[down])
                rises = f(-2.0 * f0[down] / Q[down])[0] > f0[down]  # the field raises T
                if (at := down[rises]).size:
                    q[at] = self._balance(r_i[at], lz[at], f0[at], -2.0 * f0[at] / Q[at])
                # where it lowers T no charge balances it: past the coupling's limit (r_i
                # 9.03 there) a load of 0 read as the branch turning back
                q[down[~rises]] = np.nan
            with np.errstate(invalid="ignore"):
                return np.where(np.isfinite(M), np.sqrt(q), np.nan)
        M = wall.integrals(r_i, lz, 0.0, self.compiled)[0]
        target = self.vbar * thick
        if target == 0:
            return np.where(np.isfinite(M), 0.0, np.nan)

        def g(c):
            return wall.integrals(r_i, lz, c, self.compiled)[2] - target, target

        hi = 1.5 * target / Lam
        ghi = g(hi)[0]
        for _ in range(100):
            more = ghi < 0
            if not more.any():
                break
            hi = np.where(more, 2.0 * hi, hi)
            ghi = g(hi)[0]
        return illinois(g, np.zeros_like(hi), hi, np.full_like(hi, -target), ghi)

    def _uncharged(self, r_i, lz):
        """(T at q = 0, whether each point is the uncharged state to rounding): T = dp to the
        charge solve's own zero (illinois's, 1e-15 of the stress scale), or T - dp changing
        sign within the resolution of r_i to which the branch's start is solved (Brent,
        BRANCH: |r_i - root| <= xtol + rtol r_i). Next to a Gent layer's lock T moves by
        1e-14 .. 2e-13 per ulp of r_i (dT/d ln r_i 84 .. 1759, test_nan_charge's bilayer
        grown g_theta 4.34 .. 5.5), and the solved start's T - dp, -2e-15 .. -9e-15 of the
        scale, read as inward of the start where the field lowers T: NaN, the walk's first
        load, and no state beside the start solved. Both sides in the same call of the
        integrals (a call costs about as much for 3 points as for 1)."""
        w = BRANCH.xtol + BRANCH.rtol  # relative (BRANCH.scale)
        sides = np.concatenate((r_i, r_i * (1.0 - w), r_i * (1.0 + w)))
        T, scale, _, _ = self.wall.integrals(sides, np.tile(lz, 3), 0.0, self.compiled)
        M, below, above = np.split(T, 3)
        f0 = M - self.dp
        rounding = abs(f0) <= 1e-15 * scale[: M.size]
        return M, rounding | ((below - self.dp) * (above - self.dp) <= 0.0)

    def _traction(self, r_i, lz):
        """f(q) = (T - dp, noise scale) at the points, q = c^2 (NaN where no charge
        balances the traction: no state there)."""

        def f(q):
            with np.errstate(invalid="ignore"):
                T, s, _, _ = self.wall.integrals(r_i, lz, np.sqrt(q), self.compiled)
            return T - self.dp, s

        return f

    def _lowered(self, r_i, lz, f0, hi):
        """q where a field lowers T (f0 = T - dp > 0 at q = 0) to dp (:meth:`_balance`), NaN
        at once where T rises linearly in q through hi and 2 hi (to the rounding of its
        scale): the field closes the bore and doubling q 100 times cannot bracket (an
        energy linear in I5, I6, such as check round 28's coupi4 / i45 trilayer, pulled to
        F = 247: ~100 integrals a point, 12 s a threshold whose charts probe such points)."""
        f = self._traction(r_i, lz)
        f1, scale = f(hi)
        f2 = f(2.0 * hi)[0]
        closes = (f1 > f0) & (f2 > f1) & (abs(f2 - 2.0 * f1 + f0) <= 1e-13 * scale)
        q = np.full_like(f0, np.nan)
        if (k := np.flatnonzero(~closes)).size:
            q[k] = self._balance(r_i[k], lz[k], f0[k], hi[k])
        return q

    def _balance(self, r_i, lz, f0, hi):
        """q where T(q) = dp, from q = 0 (f = f0) towards hi, doubled until f changes sign
        (at most 100 times); NaN where it does not (no charge balances the traction)."""
        f = self._traction(r_i, lz)
        fhi = f(hi)[0]
        for _ in range(100):
            more = np.sign(fhi) == np.sign(f0)
            if not more.any():
                break
            hi = np.where(more, 2.0 * hi, hi)
            fhi = f(hi)[0]
        q = illinois(f, np.zeros_like(hi), hi, f0, fhi)
        return np.where(np.sign(fhi) == np.sign(f0), np.nan, q)

    def value(self, pt) -> np.ndarray:
        """The load in analytic form: sign(Vbar) Vbar^2 (Vbar ~ sqrt near the start) or P_i."""
        return np.sign(pt["voltage"]) * pt["voltage"] ** 2 if self.load == "voltage" else pt["P_i"]

    def at(self, r_i, lz_guess) -> dict:
        """Points at the r_i (1-d, in order); under force control lambda_z is solved at each
        from the guess (a number: continuation from it; or an array, one guess per r_i)."""
        r_i = np.atleast_1d(np.asarray(r_i, float))
        tube = self.wall.tube
        if tube.control == "stretch":
            return self.point(r_i, np.full_like(r_i, tube.stretch))
        lz = _each(r_i, lz_guess, self._stretch)
        return self.point(r_i, np.where(np.isfinite(lz), lz, 1.0)) | _nan_where(~np.isfinite(lz))

    def at_stretch(self, lz, r_guess) -> dict:
        """Points at the lambda_z (1-d, in order, force control), r_i solved at each from the
        guess as :meth:`at` solves lambda_z: the chart of a branch whose r_i turns where its
        lambda_z keeps moving (a charged force-free tube under suction, probe 12b D7)."""
        lz = np.atleast_1d(np.asarray(lz, float))
        r_i = _each(lz, r_guess, self._inner_radius)
        return self.point(np.where(np.isfinite(r_i), r_i, 1.0), lz) | _nan_where(~np.isfinite(r_i))

    def at_charge(self, c, r_guess) -> dict:
        """Points at the charges c (1-d, in order; stretch control), r_i solved at each from
        the guess (continued as in :meth:`at`) where (*) holds, T(r_i, c) = P_i - P_o: the
        chart of a voltage branch whose r_i turns while its charge rises (a field that
        raises T at small charge and lowers it at large, check round 30 D2)."""
        c = np.atleast_1d(np.asarray(c, float))
        lz = self.wall.tube.stretch
        r_i = _each(c, r_guess, lambda cj, x: _balance(lambda r: self._off(r, lz, cj), x))
        ok = np.isfinite(r_i)
        return self.point(np.where(ok, r_i, 1.0), lz, c) | _nan_where(~ok)

    def _off(self, x: float, lz: float, c: float) -> float:
        """T - (P_i - P_o) of (*) at r_i = x, lambda_z and the charge c."""
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            T = self.wall.integrals(np.array([x]), np.array([lz]), np.array([c]), self.compiled)[0]
        return float(T[0]) - self.dp

    def leaves(self, r_i: float, lz: float) -> bool:
        """Does a small charge move T towards dp at (r_i, lambda_z): the sign of dT/dq at
        q = 0 against that of T - dp, read at the ideal dielectric's balancing charge
        2 |T - dp| / Q (the charge of a branch leaving the uncharged state is of that
        order, and vanishes with T - dp)? Always for an ideal dielectric (T = M - q Q, the
        charge found where T > dp)."""
        if self.wall.ideal:
            return True
        r_i, lz = np.array([r_i]), np.array([lz])
        f = self._traction(r_i, lz)
        f0 = f(np.zeros(1))[0][0]
        Q = self.wall.electric(r_i, lz)[0]
        return bool((f(2.0 * abs(f0) / Q)[0][0] - f0) * f0 < 0)

    def unbalanced(self, r_i: float, lz: float) -> tuple[float, float]:
        """(T - dp at q = 0, its rounding level: start_probe.rounding) at one point: what the
        probe of the voltage branch's start reads (thresholds.opens, thresholds.inward)."""
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            T, scale, _, _ = self.wall.integrals(
                np.array([r_i]), np.array([lz]), 0.0, self.compiled
            )
        return float(T[0]) - self.dp, float(rounding(scale[0], self.dp))

    def _residual(self, x: float, lz: float) -> float:
        return float(self.point(np.array([x]), np.array([lz]))["residual"][0])

    def _stretch(self, x: float, guess: float) -> float:
        """lambda_z balancing the axial force at r_i = x (:func:`_balance` from the guess)."""
        return _balance(lambda lz: self._residual(x, lz), guess)

    def _inner_radius(self, lz: float, guess: float) -> float:
        """r_i balancing the axial force at lambda_z = lz (:func:`_balance` from the guess)."""
        return _balance(lambda x: self._residual(x, lz), guess)


def _each(fixed: np.ndarray, guess, solve) -> np.ndarray:
    """solve(fixed[j], start) at each fixed value in order, the other coordinate from the
    guess (a number: continued from the last finite solution; an array: one per value);
    NaN from the first value where none is found."""
    guesses = np.broadcast_to(np.asarray(guess, float), fixed.shape)
    out, follow = np.full_like(fixed, np.nan), np.ndim(guess) == 0
    for j, x in enumerate(fixed):
        start = (
            (out[j - 1] if j and np.isfinite(out[j - 1]) else guesses[j]) if follow else guesses[j]
        )
        out[j] = solve(x, start)
        if not np.isfinite(out[j]):
            break
    return out


def _balance(h, guess: float) -> float:
    """The root of the axial force's residual h in one coordinate: bracketed from the guess
    (or, where h is not finite there, the nearest finite value: :func:`_finite_near`)
    outward in both directions (steps growing 1.5-fold), then brentq; NaN if no bracket."""
    h0 = h(guess)
    if h0 == 0:
        return guess
    if not np.isfinite(h0):
        found = _finite_near(h, guess)
        if found is None:
            return math.nan
        guess, h0 = found
    ends = {1: (guess, h0), -1: (guess, h0)}
    step = 0.02
    for _ in range(40):
        for sense in (1, -1):
            if ends[sense] is None:
                continue
            last, hl = ends[sense]
            nxt = last * math.exp(sense * step)
            if not 1e-3 * guess < nxt < 1e3 * guess:
                ends[sense] = None
                continue
            hn = h(nxt)
            if not np.isfinite(hn):  # past the states at this r_i (a Gent layer's lock)
                ends[sense] = None
                bracket = _short_of_edge(h, last, hl, nxt)
                if bracket is not None:
                    return brent(h, *sorted(bracket), BRANCH_STRETCH, named=False)
            elif np.sign(hn) != np.sign(hl):
                return brent(h, *sorted((last, nxt)), BRANCH_STRETCH, named=False)
            else:
                ends[sense] = (nxt, hn)
        if ends[1] is None and ends[-1] is None:
            break
        step *= 1.5
    return math.nan


#: how far (in log) a finite value is looked for about a guess where h is not: a lock 1 %
#: away is met; a NaN farther away ends the chart, not a root on another branch
REACH = math.log(1.1)


def _finite_near(h, guess: float):
    """(x, h(x)) at a finite value of h near the guess, where h(guess) is not, or None: steps
    growing 1.5-fold from 0.1 % outward, both directions alternately, within 10 % (REACH). A
    walk continues lambda_z from its last r_i, and a step of r_i towards a Gent layer's
    lock leaves that lambda_z past it while the balancing one is finite (a Gent core, jm 5,
    grown 1.95: 1 % above); from there the bracketing goes on as from a finite guess."""
    step = 1e-3
    while step < REACH:
        for sense in (1, -1):
            x = guess * math.exp(sense * step)
            hx = h(x)
            if np.isfinite(hx):
                return x, hx
        step *= 1.5
    return None


def _short_of_edge(h, last: float, h_last: float, edge: float):
    """A bracket of a root of h between ``last`` (h finite) and ``edge`` (not), or None: the
    gap halved (geometrically) towards the edge of the finite values. A root next to a
    lock lies in a window narrower than the bracketing's steps (a guess within 1e-13 of
    the root, its h of the wrong sign by rounding, stepped 2 % into the lock on one side
    and away from the root on the other: no lambda_z, and a state reported lost)."""
    for _ in range(60):
        mid = math.sqrt(last * edge)
        if abs(mid - last) <= 1e-15 * last:
            return None
        hm = h(mid)
        if not np.isfinite(hm):
            edge = mid
        elif np.sign(hm) != np.sign(h_last):
            return last, mid
        else:
            last, h_last = mid, hm
    return None


def _nan_where(mask) -> dict:
    return {} if not mask.any() else {"_nan": mask}


def clean(pt: dict) -> dict:
    """Apply a point's NaN mask (points where no lambda_z balances the axial force)."""
    mask = pt.pop("_nan", None)
    if mask is not None:
        for key, v in pt.items():
            pt[key] = np.where(mask, np.nan, v)
    return pt
