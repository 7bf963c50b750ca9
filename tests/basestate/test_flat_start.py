"""A voltage branch's start next to the inflation asymptote (check round 32, D1).

`(I1-3)/2 + I5/2 (1 + 2 (I1-3)) + 0.05 I5^2`, one layer [1, 2], lambda_z 1, P_i = ln 2 - d,
Vbar 0.3. Uncharged, the wall is neo-Hookean and its traction flat next to the asymptote:
T = ln 2 - d0(r_i), d0 ~ 3.75 / r_i^4, so dT/d ln r_i = 4 d. The start's probe read T - P_i
1e-6 from the start (6e-16 at d = 1.6e-10, two eps of the cancelling 1.39) as the start
itself, and main refused every charged state as "the field closes the bore".

The other route (no integral, solve or chart of the package's): with q = c^2, I5 = q / r^2,
Omega_1 = 1/2 + I5 and Omega_5 = (1 + 2 (I1 - 3)) / 2 + 0.1 I5,

    tau_2 - tau_1 = 2 Omega_1 (l2^2 - l1^2) - 2 Omega_5 I5
                  = (l2^2 - l1^2) + I5 (3 - 4 l1^2 - 0.2 I5)      (l3 = 1: the I1 terms cancel),
    E_r = 2 Omega_5 c / r,   r^2 = r_i^2 + R^2 - 1,   dr / r = R dR / r^2,

so T - P_i = (ln 2 - P_i) - int_1^2 R^3 / r^4 dR + int_1^2 I5 (3 - 4 l1^2 - 0.2 I5) R / r^2 dR
and V = int_1^2 E_r R / r dR, each integrand free of cancellation, by scipy's quad; ln 2 -
P_i exact (ln 2's rounding from mpmath). r_i from T = P_i by brentq at each c, c from V = Vbar.
"""

import dataclasses
import math

import mpmath
import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from electrogrowth import Layer, Material, Tube, solve_base_state, threshold
from electrogrowth.basestate import start_probe, thresholds, voltage
from electrogrowth.basestate.start_probe import FIRST_STEP, RESOLVED
from electrogrowth.basestate.thresholds import prepare
from electrogrowth.errors import BaseStateError, ConvergenceError, StartUnresolved

FOLD = Material("foldE", "(I1-3)/2 + I5/2*(1 + 2.0*(I1-3)) + 0.05*I5**2")
LN2_LO = float(mpmath.log(2) - mpmath.mpf(math.log(2)))  # ln 2 - fl(ln 2)
_QUAD = dict(epsabs=0.0, epsrel=2e-14, limit=200)
EPS = float(np.finfo(float).eps)


def _tube(deficit: float, voltage: float = 0.3) -> Tube:
    """The tube at P_i = ln 2 - deficit."""
    return Tube(
        [Layer(2.0, material=FOLD)],
        stretch=1.0,
        inner_pressure=math.log(2) - deficit,
        voltage=voltage,
        length=3.0,
    )


def _unbalanced(r_i: float, c: float, P_i: float) -> float:
    """T - P_i at (r_i, c) by the module docstring's integrals."""
    a, q = r_i * r_i - 1.0, c * c

    def charged(R):
        r2 = R * R + a
        i5 = q / r2
        return i5 * (3.0 - 4.0 * R * R / r2 - 0.2 * i5) * R / r2

    flat = quad(lambda R: R**3 / (R * R + a) ** 2, 1.0, 2.0, **_QUAD)[0]
    return (math.log(2) - P_i) + LN2_LO - flat + quad(charged, 1.0, 2.0, **_QUAD)[0]


def _voltage(r_i: float, c: float) -> float:
    """V = int E_r dr (Rbar_o - 1 = 1: V = Vbar)."""
    a = r_i * r_i - 1.0

    def field(R):
        r2 = R * R + a
        i1 = R * R / r2 + r2 / (R * R) - 2.0  # I1 - 3
        return (1.0 + 2.0 * i1 + 0.2 * c * c / r2) * c * R / r2

    return quad(field, 1.0, 2.0, **_QUAD)[0]


def _by_quadrature(P_i: float, vbar: float) -> tuple[float, float]:
    """(r_i, c) of the state at P_i and Vbar (the module docstring)."""
    r0 = (3.75 / (math.log(2) - P_i)) ** 0.25  # the uncharged r_i, to leading order

    def r_of(c):
        return brentq(lambda x: _unbalanced(x, c, P_i), 0.5 * r0, 2.0 * r0, xtol=1e-15 * r0)

    c = brentq(lambda c: _voltage(r_of(c), c) - vbar, 0.1, 0.5, xtol=1e-16, rtol=1e-15)
    return r_of(c), c


@pytest.mark.parametrize("deficit", [1e-6, 1e-8, 1e-9, 1.6e-10, 1e-11])
def test_states_next_to_the_asymptote_solve_and_agree_with_quadrature(deficit):
    # main: BranchNotFollowed ("the field closes the bore") from d = 1e-10; r_i 385.65 at
    # 1.6e-10 (the uncharged 391.27), the check's charge 0.2164
    tube = _tube(deficit)
    state = solve_base_state(tube)
    r_i, c = _by_quadrature(tube.inner_pressure, 0.3)
    assert state.charge == pytest.approx(c, rel=1e-10)
    assert _voltage(state.lambda_i, state.charge) == pytest.approx(0.3, rel=1e-14)
    # the state balances the traction to rounding of P_i (a few ulp of ln 2) ...
    assert abs(_unbalanced(state.lambda_i, state.charge, tube.inner_pressure)) <= 8 * EPS
    # ... and r_i follows within that rounding over dT/d ln r_i = 4 d: to 1e-8 where 4 d
    # allows (d >= 1e-8), beyond that no double-precision solve of T = P_i resolves it
    assert state.lambda_i == pytest.approx(r_i, rel=max(1e-8, 8 * EPS / (4 * deficit)))


def test_the_probe_steps_until_its_reading_is_resolved():
    prep = prepare(_tube(1.6e-10, 0.0), 1e-12)
    x0, lz0 = prep.loaded
    branch = prep.branch

    def read(h):
        return branch.unbalanced(x0 * (1.0 + h), lz0)

    h = start_probe.probe_step(read, "the start")
    f, level = read(h)
    assert level == pytest.approx(EPS * (2 * math.log(2)), rel=1e-3)  # T and P_i cancel
    assert abs(f) >= RESOLVED * level > abs(read(h / 10)[0])  # the first resolved step
    # T rises outward at 4 d: the reading has that sign and size (1e-6 read 6e-16)
    assert f == pytest.approx(4 * 1.6e-10 * h, rel=0.05)
    assert h == 1e-3
    walk = thresholds.chart(branch, x0, lz0)
    assert not thresholds.opens(walk, x0, lz0) and thresholds.inward(walk, x0, lz0)


def test_an_ordinary_start_keeps_the_first_step():
    # check round 30 D2's start (P_i 0.3, test_folded_branch.py): resolved 1e-6 from it
    prep = prepare(dataclasses.replace(_tube(0.0, 0.0), inner_pressure=0.3), 1e-12)
    x0, lz0 = prep.loaded
    for side in (1, -1):

        def read(h, side=side):
            return prep.branch.unbalanced(x0 * (1.0 + side * h), lz0)

        assert start_probe.probe_step(read, "the start") == FIRST_STEP
    # the one-layer route (P_i = P_o): the I6 energy that runs inward (test_closing_field)
    i6 = Material("i6", "(I1-3)/2 + 0.2*I4 + 0.4*I5 - 0.1*I6")
    wall = voltage.UniformWall(i6, 2.0, 1.0, 0.45)
    lam0 = math.sqrt(1.0 / 0.45)
    assert voltage._probe(wall, lam0, 1) == voltage._probe(wall, lam0, -1) == FIRST_STEP


def test_an_ideal_dielectric_keeps_the_first_step_where_its_wall_is_flat():
    # its charge c^2 ~ M is finite whatever M reads, so the branch rises as it always read:
    # at lambda_z = sqrt 6 (1 - 1e-13) this wall's in-plane modulus is ~0 and M is flat
    # (no probe step resolves it), and the limit point on the scan's grid is main's
    mrneg = Material("mrneg", "(1.2*(I1-3) - 0.2*(I2-3))/2 + I5/2")
    tube = Tube((Layer(1.4, material=mrneg),), length=2.0)
    thr = threshold(tube.at("stretch", math.sqrt(6.0) * (1 - 1e-13)), "voltage")
    assert thr.kind == "limit point"
    assert thr.value == pytest.approx(2.010101071345758e-07, rel=1e-9)  # main's


def test_a_start_no_step_resolves_is_named_unresolved():
    # d = 1e-13 (r_i 2474): 1e-2 from the start T - P_i is 4e-15, 13 eps of the 1.39
    with pytest.raises(StartUnresolved, match="not resolved") as err:
        solve_base_state(_tube(1e-13))
    assert isinstance(err.value, ConvergenceError) and not isinstance(err.value, BaseStateError)
    assert "closes the bore" not in str(err.value) and "tolerance" in err.value.remedy
    # uncharged, that state solves, its threshold named unresolved (main: "closing")
    state = solve_base_state(_tube(1e-13, 0.0))
    assert (state.threshold_kind, state.voltage_threshold) == ("unresolved", 0.0)
