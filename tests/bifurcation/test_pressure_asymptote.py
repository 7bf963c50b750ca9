"""Roots next to a pressure asymptote: a wall inflated to a film is marched on toward it.

Found by the lead (fix24b's doubt): a neo-Hookean tube (Rbar_o = 1.4, L = 1) inflated under
Vbar = 0.01 was reported kind "threshold" at its asymptote P_inf = ln 1.4 - Vbar^2 / 3,
error estimate 0.0, status ok: its inner face wrinkles at lambda_i = 120, 3.4e-9 below it.
Both marches stopped where lambda_i had grown 50-fold (the "film" cap) and reported the
asymptote; every root past lambda_i = 50 was missed (Vbar < 0.0235 for the face, and mode
(0, 20) even with no voltage).

The independent route is closed form (plane strain, lambda_z = 1, R_i = 1, mu = eps = 1,
compliant electrodes on both faces, V = Vbar (Rbar_o - 1)). The state at a = lambda_i:
b^2 = a^2 + Rbar_o^2 - 1, the field E = V / (r ln(b / a)),

    P(a) = ln(a Rbar_o / b) + Rbar_o^2 / (2 b^2) - 1 / (2 a^2)
           - V^2 (1/a^2 - 1/b^2) / (2 ln^2(b/a)).

The inner face's half-space, waves along z (psi = pi/2), stretches 1 along them and 1/a
normal to the face: the incremental field is harmonic and the electrode holds the potential
on the face, so the field adds -eps E^2 k u_2 to the normal traction, and the follower
pressure drops out. With beta = 1 / (1/a) = a and G = eps E^2 a^2 = V^2 / ln^2(b / a) the
secular equation is (beta^3 + beta^2 + 3 beta - 1) - G (beta + 1) = 0 (Biot's cubic at
G = 0); the outer face's root lies later (lambda_i 120.02 against 120.008 at Vbar = 0.01).
"""

import math

import pytest
from scipy.optimize import brentq

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.continuation.path import ControlPath, Stepper, StepPolicy
from electrogrowth.model.layers import Tube

RO = 1.4
C = RO * RO - 1.0


def _log_ratio(a: float) -> float:
    """ln(b / a) without cancellation at large a."""
    return 0.5 * math.log1p(C / (a * a))


def pressure(a: float, vbar: float) -> float:
    """The inner pressure of the state with lambda_i = a (closed form, module docstring)."""
    v, b2 = vbar * (RO - 1.0), a * a + C
    mech = math.log(RO) - _log_ratio(a) + RO * RO / (2.0 * b2) - 1.0 / (2.0 * a * a)
    return mech - v * v * (1.0 / (a * a) - 1.0 / b2) / (2.0 * _log_ratio(a) ** 2)


def inner_face(a: float, vbar: float) -> float:
    """The inner face's secular function along z: > 0 stable."""
    v = vbar * (RO - 1.0)
    return a**3 + a**2 + 3.0 * a - 1.0 - (v / _log_ratio(a)) ** 2 * (a + 1.0)


def tube(vbar: float) -> Tube:
    return Tube.uniform(outer_radius=RO, length=1.0, voltage=vbar)


@pytest.mark.parametrize("vbar", [0.023, 0.01])
def test_the_inner_face_wrinkles_next_to_the_pressure_asymptote(vbar):
    """Was kind "threshold" at P_inf (0.33629590328787956, 0.3364389032878796)."""
    a = brentq(inner_face, 0.5 / vbar, 3.0 / vbar, args=(vbar,), xtol=1e-13, rtol=1e-15)
    expected = pressure(a, vbar)
    res = short_wave_limit(tube(vbar), "pressure")
    assert res.kind == "surface" and res.face == "inner"
    assert res.psi == pytest.approx(math.pi / 2, abs=1e-9)
    assert res.value == pytest.approx(expected, abs=2e-15)  # 2e-16, 4e-16 measured
    assert res.value < math.log(RO) - vbar * vbar / 3.0  # below its asymptote
    assert solve_base_state(res.params).lambda_i == pytest.approx(a, rel=1e-4)  # 52, 120
    assert 0 < res.error_estimate < 1e-11


def test_without_voltage_the_threshold_is_the_asymptote_to_rtol():
    """No field, no wrinkle of a face: the threshold ln 1.4 (NH-5), examined up to rtol short
    of it; its error estimate what rtol achieves (was 0.0), the message says why."""
    res = short_wave_limit(tube(0.0), "pressure")
    assert res.kind == "threshold"
    assert res.value == pytest.approx(math.log(RO), abs=1e-15)
    assert res.error_estimate == pytest.approx(5e-12 * res.value, rel=1e-12)
    assert "asymptote" in res.message and "no face wrinkles up to" in res.message


def test_a_mode_bifurcates_past_the_film_before_the_asymptote():
    """Mode (0, 20) of the tube inflated without voltage was kind "threshold" at ln 1.4 by
    both methods: it bifurcates at lambda_i = 84.8, 1.4e-8 below. The impedance and
    collocation values (independent discretisations) agree."""
    imp = critical_value(tube(0.0), 0, 20, "pressure")
    col = critical_value(tube(0.0), 0, 20, "pressure", method="collocation")
    assert imp.kind == col.kind == "bifurcation"
    assert imp.value == pytest.approx(col.value, abs=1e-14)
    assert 1e-8 < math.log(RO) - imp.value < 2e-8
    assert solve_base_state(imp.params).lambda_i > 50.0  # past the old cap


def test_the_approach_to_an_asymptote_doubles_the_monitor_each_step():
    """A state x -> 1 with lambda_i = (1 - x)^(-1/4): past the film every proposal doubles
    lambda_i (once the order 4 is read), no jump is flagged, and the path ends 1e-12 short
    of the asymptote."""
    step = Stepper(ControlPath(0.0, 1.0, 1.0), StepPolicy(smallest=1e-6), 1.0)
    monitor = lambda x: (1.0 - x) ** -0.25  # noqa: E731
    x = 1.0 - 60.0**-4  # lambda_i = 60: a film
    step.accept(1.0 - 50.0**-4, 50.0)
    step.accept(x, monitor(x))
    assert step.film(monitor(x))
    step.approach(1.0, 1e-12)
    assert not step.film(monitor(x))
    lams = []
    while not step.at_end():
        x = step.propose()
        assert not step.jumped(monitor(x))
        step.accept(x, monitor(x))
        lams.append(monitor(x))
    assert step.x == 1.0 - 1e-12
    # (1 - x) rounds to 1e-16 / 1e-11 near the end: lambda_i to ~1e-5
    assert lams[1:-1] == pytest.approx([2.0 * lam for lam in lams[:-2]], rel=1e-5)
    assert len(lams) <= 6  # 60 -> 1000 in doublings
