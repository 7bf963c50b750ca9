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
from scipy.optimize import minimize_scalar, root

from electrogrowth import Layer, Material, Tube, solve_base_state
from electrogrowth.basestate import thresholds
from electrogrowth.basestate.thresholds import prepare
from electrogrowth.basestate.tube import voltage_threshold
from tests.tubes import COUPI4, PULLED_TRILAYER

COUP = Material("coup", "(I1-3)/2 + I5/2*(1 + 0.1*(I1-3))")

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


#: check round 28 (res_61 #12)'s pulled trilayer at F 247.25 (lambda_z 11.03)
PULLED = 247.25


def _pulled_trilayer(force: float = PULLED) -> Tube:
    return dataclasses.replace(PULLED_TRILAYER, axial_force=force, voltage=0.0)


def _limit_point_by_root(wall, dp: float, thick: float, force: float) -> tuple[float, float]:
    """(Vbar, lambda_z) at the top of the force-controlled branch by another route: at each
    q = c^2, (r_i, lambda_z) from T = dp and N = F by scipy's hybr on the wall's integrals,
    Vbar^2(q) maximised by bounded Brent (not the package's charts, walk or interpolant)."""

    def state(q):
        def res(y):
            T, _, _, N = wall.integrals(y[:1], y[1:], np.sqrt([q]))
            return [T[0] - dp, N[0] / force - 1.0]

        return root(res, [1.80, 7.50], method="hybr", options={"xtol": 1e-14}).x

    def vbar2(q):
        r, lz = state(q)
        return (wall.integrals([r], [lz], np.sqrt([q]))[2][0] / thick) ** 2

    top = minimize_scalar(lambda q: -vbar2(q), bounds=(2.5, 4.5), method="bounded")
    return float(np.sqrt(-top.fun)), float(state(top.x)[1])


@pytest.mark.parametrize("force", [PULLED, 248.2])
def test_a_force_controlled_inward_branch_is_followed_past_its_fold_in_r_i(force):
    # on main: "locking" at the start (value inf, the first cell bisected, ~2700 branch
    # points, 77 s); with the start's probe alone (fix23f): "locking" at lambda_i 1.518,
    # where r_i turns back (the walk in r_i found no state past it, read as a lock).
    # The branch: r_i falls from 1.899 to 1.515 and rises again while lambda_z falls from
    # 11.03 throughout, the voltage rising to a limit point at lambda_z 7.45. At F = 248.2
    # the walk in r_i stepped to the far side (lambda_z 11.02 to 8.75 for r_i 1.79 to 1.65)
    # and read a peak 5.4076 across the two sides, where the branch's is 5.4551
    tube = _pulled_trilayer(force)
    prep = prepare(tube, 1e-12)
    x0, lz0 = prep.loaded
    thr = thresholds.threshold(prep.branch, x0, lz0, "voltage")
    assert thr.kind == "limit point" and thr.walked == "stretch"
    r_i, lz, _ = thr.grid
    k = int(np.argmin(r_i))  # r_i falls, then rises again: past its fold
    assert np.all(np.diff(lz) < 0) and np.all(np.diff(r_i[: k + 1]) < 0)
    assert 0 < k < len(r_i) - 1 and np.all(np.diff(r_i[k:]) > 0) and thr.lambda_i < x0
    vbar, stretch = _limit_point_by_root(
        prep.wall, tube.inner_pressure, tube.outer_radius - 1, force
    )
    assert thr.value == pytest.approx(vbar, rel=1e-10)
    assert thr.stretch == pytest.approx(stretch, rel=1e-6)  # the top is flat: its place less so


def test_a_field_that_closes_the_bore_outward_is_read_without_doubling_the_charge(monkeypatch):
    # outward of the uncharged state (T > dp at q = 0) the field raises T, linearly in q =
    # c^2: no charge balances it. On main q was doubled 100 times before NaN, ~100 integrals
    # a point, which made a threshold of this tube 12 s (its charts probe such points)
    tube = _pulled_trilayer()
    prep = prepare(tube, 1e-12)
    x0, lz0 = prep.loaded
    r, s = np.array([x0 * 1.01]), np.array([lz0])
    # by the wall's integrals alone: T above dp, rising, linear in q (0, 1, 2, 4 x 1e-2)
    T = np.array([prep.wall.integrals(r, s, np.sqrt(q))[0][0] for q in (0.0, 0.01, 0.02, 0.04)])
    assert tube.inner_pressure < T[0] and np.all(np.diff(T) > 0)
    assert T[3] - T[0] == pytest.approx(4.0 * (T[1] - T[0]), rel=1e-9)
    calls = []
    integrals = type(prep.wall).integrals
    monkeypatch.setattr(type(prep.wall), "integrals", lambda *a: calls.append(1) or integrals(*a))
    assert np.isnan(prep.branch.point(r, s)["voltage"][0])
    assert len(calls) <= 4  # q = 0, two trial charges, and the state's integrals
