"""A torsional mode first bifurcates where the wall's torsional shear moduli vanish
(check round 21; bifurcation/torsion_onset.py, docs/derivation-families.md section 2).

The energy (1.2 (I1 - 3) - 0.2 (I2 - 3)) / 2 + I5 / 2, a Mooney-Rivlin solid with a negative
I2 weight, has A3232 = 2 lambda_z^2 (0.6 - 0.1 / lambda_z) in a uniform wall under stretch
(an independent sympy route in check round 21), zero at lambda_z = 1/6 on the whole wall:
there u_theta = r cos kz is a traction-free solution of zero energy for every k, and the
exact Bessel dispersion relation puts the other roots of (0, 100) at 0.166235, 0.165006,
0.162998, 0.160266, ... The march returned the fifth, 0.16026615877486758 (and for (0, 400)
its 113th root), status ok, certified.
"""

import math

import numpy as np
import pytest

from electrogrowth import Layer, Material, Tube, critical_value, solve_base_state
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.bifurcation.torsion_onset import margin, torsional_onset
from electrogrowth.errors import BaseStateError, NoBifurcationFound
from electrogrowth.incremental.targets import impedance_targets

NEGATIVE_I2 = Material("mrneg", "(1.2*(I1-3) - 0.2*(I2-3))/2 + I5/2")
TUBE = Tube((Layer(1.4, material=NEGATIVE_I2),), length=2.0)


@pytest.mark.parametrize("n", [1, 100, 400])
def test_every_torsional_mode_bifurcates_where_a3232_vanishes(n):
    c = critical_value(TUBE, 0, n, "stretch", side="compression", family="torsional")
    assert c.kind == "bifurcation" and c.status == "ok"
    assert c.value == pytest.approx(1 / 6, rel=1e-12)  # was 0.16026615877 for n = 100
    assert c.error_estimate < 1e-11


def test_the_onset_is_the_zero_of_the_closed_form():
    at = TubeAt(TUBE, "stretch")
    onset = torsional_onset(at, 1.0, 0.05, 1e-12)
    assert onset is not None and onset.exact
    assert onset.value == pytest.approx(1 / 6, rel=1e-13)
    for lz in (0.9, 0.5, 0.2):  # A3232 / A1212 uniform, positive before the onset
        low, gamma, top = margin(at.solved(lz))
        assert low > 0 and gamma > 0 and top > 0


def test_where_the_moduli_vanish_in_part_of_the_wall_the_root_is_not_called_first():
    """Charged, the wall's A3232 vanishes first at one face: the first root lies past that
    point, and the march's root is returned as not located to be the first."""
    charged = Tube((Layer(1.4, material=NEGATIVE_I2),), length=2.0, voltage=0.3)
    c = critical_value(charged, 0, 1, "stretch", side="compression", family="torsional")
    assert c.status == "inaccurate" and "vanishes at stretch = 0.16654" in c.message
    assert c.value < 0.16654  # past it, along the compression


def test_built_in_energies_keep_no_torsional_root():
    with pytest.raises(NoBifurcationFound, match="torsional modes never bifurcate"):
        critical_value(Tube((Layer(1.4),), length=2.0), 0, 100, "stretch", family="torsional")


def test_under_extension_the_lost_state_is_no_internal_error():
    """Past lambda_z = sqrt(6) (gamma_12 = 0) the voltage branch's first maximum had a
    negative Vbar^2: 'math domain error' (ValueError), exit 1; then "not resolved", the
    loss not established. gamma_12 = 2 lambda_r^2 (W_1 + lambda_z^2 W_2) vanishes at
    sqrt(6): past it the energy is not strongly elliptic in the r-theta plane and no state
    is followed (basestate/ellipticity.py), so the march's state ends exactly there."""
    c = critical_value(TUBE, 0, 1, "stretch", side="extension", family="torsional")
    assert c.kind == "threshold" and c.value == pytest.approx(math.sqrt(6.0), rel=1e-12)
    assert "loses strong ellipticity, gamma_12 of layer 1" in c.message  # why it ends
    with pytest.raises(BaseStateError, match="not strongly elliptic") as e:
        solve_base_state(TUBE.at("stretch", 2.45))
    assert "elliptic below lambda_z / g_z = 2.44948974" in str(e.value)


def test_the_verdict_names_a_torsional_mode_so():
    """Its meaning read "next: the wrinkle mode (m, n) = (0, 100)" (check round 21, D3)."""
    c = critical_value(TUBE, 0, 100, "stretch", side="compression", family="torsional")
    meaning = c.verdict.meaning
    assert "the torsional mode (m, n) = (0, 100)" in meaning and "wrinkle mode" not in meaning


#: A3232 = A1313 = lambda_z^2 (3 - 2 / lambda_z) in the uniform wall of this energy under
#: stretch: both vanish at lambda_z = 2/3, and at the float 0.6666666666666667 A1313 is 0
#: exactly. Brent's iterates for (0, 100) reached it.
STEEP_I2 = Material("mrneg3", "(3.0*(I1-3) + (-2.0)*(I2-3))/2 + I5/2")


def test_a_modulus_vanishing_exactly_is_no_internal_error():
    """The Stroh matrix divides by gamma_13 = A1313 - ...; numba's Python error model
    raised ZeroDivisionError there for every mode ('internal error: ZeroDivisionError'
    from critical_value(..., 0, 100, ..., family='torsional')). A state that has lost
    strong ellipticity has no meaningful target; IEEE division lets the root finders go on,
    and the torsional onset below is the answer."""
    tube = Tube((Layer(1.4, material=STEEP_I2),), length=2.0)
    state = solve_base_state(tube.at("stretch", 0.6666666666666667))
    rows = np.array([[0, 100, 2], [0, 100, 0], [3, 2, 0], [4, 0, 1]], float)
    assert np.isfinite(impedance_targets(state, rows)).all()
    c = critical_value(tube, 0, 100, "stretch", side="compression", family="torsional")
    assert c.status == "ok" and c.value == pytest.approx(2 / 3, rel=1e-12)
