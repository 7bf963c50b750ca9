"""Physics that holds for every tube, run over the ``tubes`` fixture (uniform, two-layer,
graded, pressurised, force-controlled): the one door returns a state of the one protocol,
in equilibrium with its loads."""

from __future__ import annotations

import math

import numpy as np
import pytest

from electrogrowth import critical_value, solve_base_state, threshold
from electrogrowth._types import State
from electrogrowth.incremental.impedance import integrate_one
from electrogrowth.incremental.impedance_reference import shooting_target
from electrogrowth.incremental.radial_table import build_table
from electrogrowth.incremental.targets import mode_pairs

#: every member of the State protocol (_types.State)
MEMBERS = [name for name in dir(State) if not name.startswith("_") and name not in ("register",)]


def test_every_state_has_the_whole_protocol(tubes):
    state = solve_base_state(tubes)
    missing = [name for name in MEMBERS if not hasattr(state, name)]
    assert not missing and state.tube == tubes
    assert state.radii[0] == state.r_i and state.radii[-1] == state.r_o
    assert len(state.radii) == len(tubes.layers) + 1 and np.all(np.diff(state.radii) > 0)
    assert state.hoop_stretches[0] == pytest.approx(state.lambda_i, rel=1e-14)
    assert state.current_length == pytest.approx(state.stretch * tubes.length, rel=1e-15)


def test_faces_carry_their_pressures_and_the_wall_is_in_equilibrium(tubes):
    """sigma_rr = -P on each face, and d sigma_rr / dr = (sigma_tt - sigma_rr) / r inside
    every layer (a fourth-order difference in R, dr/dR from the radius)."""
    state = solve_base_state(tubes)
    P_i, P_o = state.face_pressures
    R_o = tubes.outer_radius
    assert state.sigma_rr(1.0) == pytest.approx(-P_i, abs=1e-10)
    assert state.sigma_rr(R_o, side="inner") == pytest.approx(-P_o, abs=1e-10)
    h = 1e-4
    for a, b in zip(tubes.radii, tubes.radii[1:]):
        R = np.linspace(a + 5 * h, b - 5 * h, 7)
        s = lambda x: state.sigma_rr(x)  # noqa: E731
        dsdR = (-s(R + 2 * h) + 8 * s(R + h) - 8 * s(R - h) + s(R - 2 * h)) / (12 * h)
        r = state.radius(R)
        drdR = (
            -state.radius(R + 2 * h)
            + 8 * state.radius(R + h)
            - 8 * state.radius(R - h)
            + state.radius(R - 2 * h)
        ) / (12 * h)
        srr, stt, _ = state.stresses(R)
        scale = max(1.0, float(np.abs(stt).max()))
        np.testing.assert_allclose(dsdR / drdR, (stt - srr) / r, atol=1e-7 * scale)


def test_the_voltage_threshold_has_one_shape(tubes):
    t = threshold(tubes, "voltage")
    assert t.control == "voltage" and t.kind in ("asymptote", "limit point", "locking", "none")
    assert t.value > tubes.voltage or not math.isfinite(t.value)


@pytest.mark.parametrize(("m", "n"), [(3, 1), (0, 2), (5, 0)])
def test_the_kernel_target_equals_orthonormalised_shooting(tubes, m, n):
    """The compiled kernel reads every tube's state through the same table, and equals the
    slow twin that shoots the Stroh system with QR (no impedance, no charts)."""
    state = solve_base_state(tubes)
    k = n * math.pi / state.current_length
    keep = int(mode_pairs(np.array([[m, n]], float))[0])
    f = integrate_one(float(m), k, keep, build_table(state), 1e-13, 20000)[0]
    assert f == pytest.approx(shooting_target(state, m, k, pairs=keep), rel=1e-8)


#: a control of each tube of the fixture that bifurcates before its threshold
CONTROL = {
    "uniform": "growth",
    "two-layer": "growth[1].theta",
    "graded": "voltage",
    "pressurised": "growth",
    "force-controlled": "force",
}


@pytest.mark.parametrize("mode", [(3, 1), pytest.param((0, 2), marks=pytest.mark.slow)])
def test_both_methods_give_one_critical_value(tubes, request, mode):
    """The compiled impedance march and the independent multi-domain collocation agree on
    one mode's critical value for every kind of tube (to the collocation's accuracy)."""
    control = CONTROL[request.node.callspec.params["tubes"]]
    a = critical_value(tubes, *mode, control)
    b = critical_value(tubes, *mode, control, method="collocation")
    assert a.kind == "bifurcation" and b.value == pytest.approx(a.value, rel=1e-8)
