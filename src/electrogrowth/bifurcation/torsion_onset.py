"""Where a torsional mode (0, n), u_theta = U(r) cos kz, can first bifurcate: where the
wall's torsional shear moduli first vanish (docs/derivation-families.md, section 2).

The torsional problem is the Euler-Lagrange system of

    F[U] = int gamma_12 r^3 (d(U/r)/dr)^2 dr + k^2 int A3232 r U^2 dr,

so no torsional mode bifurcates while gamma_12 = A1212 - Gamma_122^2 / K22 > 0 and
A3232 > 0 throughout the wall. Past the first point x_e of the path where either vanishes
somewhere, the problem is no longer elliptic there and a mode's roots come densely: for a
wall whose A3232 vanishes everywhere at once, roots at x_e and then ~ j^2 / k^2 beyond it,
windows of instability 4e-4 wide for n = 100 that a march's samples step over (check round
21: an energy text with a negative I2 weight, A3232 = 0 at lambda_z = 1/6; (0, 100) gave
its fifth root, (0, 400) its 113th, status ok).

At x_e itself F vanishes for some U != 0 only where A3232 vanishes on the whole wall and
gamma_12 > 0 (then U = r, for every k: the exact root); else the first root lies past x_e,
nearer to it the shorter the wave.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..basestate.ellipticity import SHEAR_NAMES, wall_shear
from ..continuation.events import THRESHOLD, brent
from ..errors import ElectrogrowthError
from .along import TubeAt

#: samples of the moduli through each layer (both faces included)
PER_LAYER = 17
#: samples of the path between its start and the march's end
STEPS = 64
#: A3232 vanishes on the whole wall where its largest value is below this, relative to its
#: layer's shear modulus (rounding of the moduli ~1e-15, of the located x_e ~1e-13)
UNIFORM = 1e-9

_GAMMA_12, _A3232 = SHEAR_NAMES.index("gamma_12"), SHEAR_NAMES.index("A3232")


@dataclasses.dataclass(frozen=True)
class Onset:
    """The first point ``value`` of the path where the torsional moduli vanish, and whether
    it is an exact root of every torsional mode (``exact``: A3232 vanishes on the whole wall
    and gamma_12 > 0 there)."""

    value: float
    exact: bool


def torsional_onset(at: TubeAt, start: float, end: float, rtol: float) -> Onset | None:
    """The first zero of :func:`margin` along the path from ``start`` to ``end`` (``STEPS``
    samples, then Brent's method), or None where the moduli stay positive up to ``end``
    or a state on the way does not solve (then no such point is claimed)."""

    def low(x: float) -> float:
        return margin(at.solved(float(x), rtol))[0]

    xs = np.linspace(start, end, STEPS + 1)
    try:
        if not low(xs[0]) > 0:  # at the start: the mode is unstable there, the march says so
            return None
        hi = next((j for j in range(1, len(xs)) if not low(xs[j]) > 0), None)
        if hi is None:
            return None
        value = brent(low, float(xs[hi - 1]), float(xs[hi]), THRESHOLD)
        _, gamma, top = margin(at.solved(value, rtol))
    except ElectrogrowthError:
        return None
    return Onset(value, exact=top <= UNIFORM and gamma > UNIFORM)


def margin(state) -> tuple[float, float, float]:
    """(min over the wall of min(gamma_12, A3232), min over the wall of gamma_12, max over
    the wall of |A3232|), each over its layer's small-strain shear modulus (not the loaded
    moduli, which vanish with them: gamma_12 = A1212 where there is no field)."""
    shear = wall_shear(state, PER_LAYER)
    g, a = shear[:, _GAMMA_12], shear[:, _A3232]
    return float(min(g.min(), a.min())), float(g.min()), float(np.max(np.abs(a)))
