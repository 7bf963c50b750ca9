"""The Koiter coefficient of a tube's wrinkle (m, n), m, n >= 1 (docs/derivation-koiter.md,
"The tube's general family (m, n)"): the three-dimensional forms of
incremental/wall_forms.py (any strain energy), the mode on the harmonic (1, 1) of
(m Theta, K Z), the correction on (0, 0), (2, 0), (0, 2) and (2, 2), and

    c_2 = (2 A[psi, psi] - 4 E4(phi)) / A'[phi, phi],   eps = max |u_r| / R_i,

through the same expansion as the prismatic and axisymmetric families (koiter_tube.py)."""

from __future__ import annotations

import math

from ..incremental.polar_forms import rings
from ..incremental.wall_dielectric_forms import WallDielectricForms
from ..incremental.wall_forms import WallForms
from ..model.layers import Tube
from .koiter_tube import TubeExpansion, axial_wavenumber, expand, onset_value

#: the mode: U_r, U_th, U_z and q on the harmonic (1, 1) of (m Theta, K Z)
MODE = ((0, 1, 1), (1, 1, 1), (2, 1, 1), (3, 1, 1))

#: the correction: the products of two first harmonics, (0 or 2, 0 or 2), each with the
#: fields that are not sin(0) (no U_th at j = 0, no U_z at l = 0: reflection symmetries)
SECOND = (
    (0, 0, 0),
    (3, 0, 0),
    (0, 2, 0),
    (1, 2, 0),
    (3, 2, 0),
    (0, 0, 2),
    (2, 0, 2),
    (3, 0, 2),
    (0, 2, 2),
    (1, 2, 2),
    (2, 2, 2),
    (3, 2, 2),
)


#: the potential's harmonics under a voltage: the mode's and the correction's
POTENTIAL = ((4, 1, 1),), ((4, 0, 0), (4, 2, 0), (4, 0, 2), (4, 2, 2))


def wall_forms(
    tube: Tube, mode: tuple[int, int], harmonics, nodes: int, *, charged=False, **kw
) -> WallForms:
    """The forms of ``harmonics`` for the wrinkle ``mode`` = (m, n): K = n pi / L, the rings
    cut for a decay rate hypot(m, K) (as the prismatic and axisymmetric families at n = 0
    and m = 0); with the potential's energy when ``charged``."""
    m, n = mode
    K = axial_wavenumber(tube, n) if n else 0.0
    cut = rings(tube, max(math.hypot(m, K), 1.0), nodes)
    kind = WallDielectricForms if charged else WallForms
    return kind.build(cut, m, K, harmonics, **kw)


def wrinkle_expansion(
    tube: Tube, mode: tuple[int, int], control: str, *, nodes: int = 24, side: str | None = None
) -> TubeExpansion:
    """The Koiter coefficient of the wrinkle ``mode`` = (m, n) of an unpressurised tube at
    fixed axial stretch, in a control that moves its base state (a growth, the stretch,
    the voltage); under a voltage (or in the voltage control) with the potential, the
    layers ideal dielectrics."""
    charged = tube.voltage != 0 or control == "voltage"
    extra = POTENTIAL if charged else ((), ())
    first = wall_forms(tube, mode, MODE + extra[0], nodes, charged=charged)
    second = wall_forms(tube, mode, SECOND + extra[1], nodes, charged=charged)
    start = onset_value(tube, mode, control, side)
    return expand(tube, control, first, second, start, f"{control} of mode {mode}")
