"""A voltage branch that runs inward from the uncharged state (check round 28 D1).

A bilayer whose coupling `(I1-3)/2 + I5/2 (1 + 0.1 (I1-3))` stiffens with I1, at fixed
lambda_z and P_o: T(q) is linear in q = c^2 with a slope that changes sign at r_i ~ 9.0334.
Past P_i ~ 4.4482 the uncharged state lies outward of that limit, where the field raises T:
no charge balances the traction outward, and the charged states lie inward, the voltage
rising without bound towards the limit. On main they were refused ("the field closes the
bore", kind "closing"). The reference numbers are the check's own quadrature
(probe/k28/pk0d.py, 160- and 320-point Gauss rules, brentq on T(q) = dp).
"""

import dataclasses

import numpy as np
import pytest

from electrogrowth import Layer, Material, Tube, solve_base_state
from electrogrowth.basestate.thresholds import prepare
from electrogrowth.basestate.tube import voltage_threshold

COUP = Material("coup", "(I1-3)/2 + I5/2*(1 + 0.1*(I1-3))")
COUPI4 = Material("coupi4", "(I1-3)/2 + 0.45*I5 + 0.05*I4*(1 + 0.1*(I1-3))")
VBAR = 0.1083518738228662

#: the check's uncharged r_i at P_i 4.45, its inward states r0 (0.999 - 0.003 k), Vbar
R0 = 9.259299375131839
INWARD = {0: 0.18467, 1: 0.39552, 3: 0.74419, 6: 1.67488, 7: 2.70359}
#: the check's last r_i with a charge (k = 7) and first without (k = 8)
LAST, NONE = R0 * (0.999 - 0.021), R0 * (0.999 - 0.024)


def _stiffening_bilayer(inner_pressure: float) -> Tube:
    inner = Layer(1.8084397861935206, COUP, shear_modulus=2.6200505657523743)
    outer = Layer(2.2693066463787863, COUPI4, shear_modulus=7.860779293048664)
    growth = (1.150437756076137, 1.1313952076652471, 1.1219382139347056)
    return Tube(
        (
            dataclasses.replace(inner, permittivity=0.9122528046112701),
            dataclasses.replace(outer, permittivity=0.652746813978254, growth=growth),
        ),
        length=4.1481538834933875,
        stretch=0.8109099045777046,
        inner_pressure=inner_pressure,
        outer_pressure=0.04364916679215165,
    )


def test_the_charge_balances_the_traction_inward_of_the_uncharged_state():
    # on main: Vbar 0 at each (q = 0 where the uncharged T < dp)
    prep = prepare(_stiffening_bilayer(4.45), 1e-12)
    assert prep.loaded[0] == pytest.approx(R0, rel=1e-12)
    r_i = R0 * (0.999 - 0.003 * np.array(list(INWARD)))
    vbar = prep.branch.at(r_i, prep.loaded[1])["voltage"]
    assert vbar == pytest.approx(list(INWARD.values()), abs=5e-6)  # the check's 5 digits
    # past the coupling's limit no charge balances it: no state (on main, Vbar 0)
    assert np.isnan(prep.branch.at([NONE], prep.loaded[1])["voltage"][0])


@pytest.mark.parametrize("inner_pressure", [4.45, 4.46])
def test_the_inward_branch_ends_at_the_couplings_limit(inner_pressure):
    # on main: (0, "closing") at the uncharged state
    value, kind, lam = voltage_threshold(_stiffening_bilayer(inner_pressure))
    assert (value, kind) == (np.inf, "locking")
    assert NONE < lam < LAST


def test_a_charged_state_on_the_inward_branch_is_solved():
    # on main: BranchNotFollowed "the field closes the bore"; the check: r_i in
    # (9.25004, r0) at P_i 4.45 (Vbar 0.18467 at the first), 11.31 at 4.46
    state = solve_base_state(_stiffening_bilayer(4.45).at("voltage", VBAR))
    assert R0 * 0.999 < state.lambda_i < R0
    assert state.threshold_kind == "locking"
    state = solve_base_state(_stiffening_bilayer(4.46).at("voltage", VBAR))
    assert state.lambda_i == pytest.approx(11.31, abs=5e-3)


def test_below_the_crossing_the_branch_still_opens_outward():
    # P_i 4.448: uncharged r_i 9.0111 inside the limit; the check's Vbar 0.189 at 9.01202
    value, kind, lam = voltage_threshold(_stiffening_bilayer(4.448))
    assert kind == "locking" and lam == pytest.approx(9.0334, abs=1e-4)
