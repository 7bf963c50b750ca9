"""The stability of the post-buckled branch: the pattern of the lowest eigenvector of the
tangent at fixed control (the mode's own family, or a subharmonic that a sector of k half
wavelengths holds: period doubling at k = 2), and where the lowest eigenvalue changes sign
along the branch (a secondary bifurcation, or a limit point of the control).

A sector of k half wavelengths (k pi / m; the meridian's window k L / n) with mirror
planes at both ends holds the patterns cos(j m Theta / k), j = 0, 1, 2, ... Extended by
its mirror images it is one period 2 k pi / m of a periodic field, u_R even and u_Theta odd
about each end. The patterns of period d wavelengths of the mode (d divides k) are the
fields unchanged by a turn of 2 d pi / m: the average of the k / d turns projects on them.
A branch point's tangent commutes with the turns and mirrors that keep its state (the
mode's own period), so its eigenvectors lie (up to rounding) in one family each; the
smallest d whose projection keeps most of the eigenvector names it: d = 1 the mode's
family ("symmetric"), d = 2 "period-doubling".
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.optimize as so

from ..errors import ConvergenceError
from .harmonics import ELEMENT_SCALE, element_scale_fraction, face_harmonic, is_element_scale
from .onset import lowest_eigenvalue

#: the names of the eigenvector's pattern by its period in wavelengths of the mode
PATTERNS = {1: "symmetric", 2: "period-doubling", 3: "period-tripling"}
#: the amplitude tolerance (units R_i) of a sign change located by Brent's method
XTOL = 1e-7


def pattern_name(period: int) -> str:
    return PATTERNS.get(period, f"period-{period}")


def _periodic_extension(model, z: np.ndarray) -> np.ndarray:
    """The vertex values of (u_R, u_Y) of ``z`` over the sector and its mirror image, one
    period of 2 N vertex intervals along Y: shape (2, radial vertices, 2 N)."""
    R, Y = model.mesh.p
    n_y = model.size.hoop + 1
    order = np.lexsort((Y, R))  # rows of constant R, each along Y
    out = []
    for comp, parity in ((0, 1.0), (1, -1.0)):  # u_R even, u_Y odd about the ends
        f = z[model.basis.nodal_dofs[comp]][order].reshape(-1, n_y)
        out.append(np.concatenate([f, parity * f[:, -2:0:-1]], axis=1))
    return np.array(out)


def outside_fraction(model, z: np.ndarray, period: int) -> float:
    """|z - P z| / |z| on the vertices, P the projection on the patterns of ``period``
    wavelengths of the mode (``period`` divides the model's ``periods``)."""
    k = model.periods
    f = _periodic_extension(model, z)
    turns = k // period
    shift = f.shape[-1] // turns  # a turn of 2 period pi / m, in vertex intervals
    projected = sum(np.roll(f, j * shift, axis=-1) for j in range(turns)) / turns
    norm = np.linalg.norm(f)
    return float(np.linalg.norm(f - projected) / norm) if norm > 0 else 0.0


def classify(model, z: np.ndarray) -> tuple[float, int]:
    """(the fraction of ``z`` outside the mode's family, the period of its pattern in
    wavelengths of the mode: the smallest divisor d of ``periods`` whose patterns hold
    most of it, 1 = the mode's family)."""
    k = model.periods
    subharmonic = outside_fraction(model, z, 1)
    for d in range(1, k + 1):
        if k % d == 0 and (d == k or outside_fraction(model, z, d) < 0.5):
            return subharmonic, d
    return subharmonic, k  # not reached: d = k holds everything


@dataclasses.dataclass(frozen=True)
class Secondary:
    """Where the lowest eigenvalue at fixed control changes sign on the branch: the control
    and amplitude there, the pattern of the eigenvector ("symmetric": a limit point of the
    control or a symmetric bifurcation; "period-doubling", ...: a bifurcation to that
    subharmonic), its fraction outside the mode's family, and whether Brent's method
    located it (else it is interpolated linearly between the two branch points)."""

    control: float
    amplitude: float
    kind: str
    subharmonic: float
    located: bool
    #: the eigenvector there is of the elements' size (is_element_scale): not the tube's
    element_scale: bool = False

    def as_dict(self) -> dict:
        return dataclasses.asdict(self)


def secondaries(branch, points) -> tuple[Secondary, ...]:
    """The sign changes of the lowest eigenvalue between consecutive ``points`` (branch
    points of the AmplitudeBranch ``branch``, eigenvalues computed), each located by
    Brent's method on the amplitude (every evaluation a branch point solved from the
    interpolated guess and its lowest eigenvalue). A point whose negative lowest eigenvalue
    is of the elements' size (``unresolved``) has no known sign: no change is sought on
    either side of it. A located zero whose eigenvector is of the elements' size is
    returned with ``element_scale`` set (the caller reports it as unresolved, not as a
    secondary)."""
    found = []
    for p, q in zip(points, points[1:]):
        known = not (p.unresolved or q.unresolved)
        if known and np.isfinite(p.eigenvalue) and np.isfinite(q.eigenvalue):
            if (p.eigenvalue < 0) != (q.eigenvalue < 0):
                found.append(_locate(branch, p, q))
    return tuple(found)


def _locate(branch, p, q) -> Secondary:
    model = branch.section
    states = {}

    def eigenvalue(a: float) -> float:
        t = (a - p.amplitude) / (q.amplitude - p.amplitude)
        x, c, _ = branch.solve(p.x + t * (q.x - p.x), p.control + t * (q.control - p.control), a)
        lam, z = lowest_eigenvalue(model, x, vector=True)
        states[a] = (c, z)
        return lam

    try:
        a = so.brentq(eigenvalue, p.amplitude, q.amplitude, xtol=XTOL)
        if a not in states:  # Brent returns a point it evaluated; this is a safeguard
            eigenvalue(a)
        c, z = states[a]
        located = True
    except ConvergenceError:  # a bordered Newton step failed near the singular point
        t = p.eigenvalue / (p.eigenvalue - q.eigenvalue)
        a = p.amplitude + t * (q.amplitude - p.amplitude)
        c = p.control + t * (q.control - p.control)
        _, z = lowest_eigenvalue(model, q.x, vector=True)
        located = False
    subharmonic, period = classify(model, z)
    kind = pattern_name(period)
    return Secondary(float(c), float(a), kind, subharmonic, located, is_element_scale(model, z))


__all__ = [
    "PATTERNS",
    "Secondary",
    "ELEMENT_SCALE",
    "classify",
    "element_scale_fraction",
    "face_harmonic",
    "is_element_scale",
    "outside_fraction",
    "pattern_name",
    "secondaries",
]
