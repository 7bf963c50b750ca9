"""A layered state continued from its neighbour (basestate/warm.py) is the walk's state.

The independent route is the cold solve: the walk from the unloaded tube along the loading
branches and Brent's method (basestate/thresholds.py). Along a march of each control, every
continued state must be the cold state to 1e-12, and the continuation must really be taken
(not its fallback); past a threshold it must refuse, so the cold solve raises.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from electrogrowth.basestate import layered, warm
from electrogrowth.basestate.layered import solve_layered_state
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.errors import BaseStateError
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.materials import gent, mooney_rivlin
from tests.tubes import FORCE_BILAYER as FORCE
from tests.tubes import MUCOSA

STACK = Tube(
    (
        Layer(1.05, shear_modulus=20.0, growth=(1.0, 1.15, 1.0)),
        Layer(1.3, shear_modulus=2.0, material=mooney_rivlin(0.3)),
        Layer(1.8, shear_modulus=0.5, growth=1.05, material=gent(30.0)),
    ),
    length=2.0,
    voltage=0.2,
)

#: a charged force-free film-lined tube under suction: its voltage branch is walked in
#: lambda_z, r_i first falling as Vbar rises (thresholds.chart; tests/basestate/
#: test_charged_suction.py); was walked from the unloaded tube at each step
SUCTION = Tube(
    (Layer(1.003, shear_modulus=300.0, growth=(1, 1.02, 1.01)), Layer(2.2)),
    length=4.0,
    axial_force=0.0,
    inner_pressure=-10.0,
    voltage=0.1,
)

#: (tube, control, the control's values along a march)
MARCHES = [
    (MUCOSA, "voltage", np.linspace(0.3, 0.6, 13)),
    (MUCOSA, "growth[1].theta", np.linspace(1.2, 1.6, 13)),
    (MUCOSA, "pressure", np.linspace(0.05, -0.1, 13)),
    (MUCOSA, "stretch", np.linspace(1.0, 0.7, 13)),
    (FORCE, "voltage", np.linspace(0.2, 0.45, 11)),
    (FORCE, "force", np.linspace(0.0, -1.5, 11)),
    (STACK, "growth[1].theta", np.linspace(1.15, 1.4, 11)),
    (STACK, "voltage", np.linspace(0.2, 0.5, 11)),
    (SUCTION, "pressure", np.linspace(-9.8, -11.0, 11)),
    (SUCTION, "voltage", np.linspace(0.02, 1.2, 13)),  # r_i falls, turns (~0.4), rises
]


def _close(a, b, tol=1e-12):
    for key in ("r_i", "stretch", "charge", "r_o", "axial_force"):
        x, y = getattr(a, key), getattr(b, key)
        assert abs(x - y) <= tol * max(1.0, abs(y)), (key, x, y)


@pytest.mark.parametrize(
    "tube, control, values", MARCHES, ids=[f"{i}-{m[1]}" for i, m in enumerate(MARCHES)]
)
def test_continued_states_are_the_walks_states(tube, control, values):
    prev = solve_layered_state(tube.at(control, values[0]))
    for v in values[1:]:
        t = tube.at(control, v)
        assert warm.continued(t, prev, 1e-12) is not None, v  # the continuation is taken
        state = solve_layered_state(t, near=prev)
        cold = solve_layered_state(t)
        _close(state, cold)
        assert state.quadrature_error <= 1e-12
        # the profiles the tables are built from agree too
        R = np.linspace(1.0, t.radii[-1], 9)
        assert np.allclose(state.sigma_rr(R), cold.sigma_rr(R), rtol=0, atol=1e-12)
        prev = state
    # a continued state's thresholds are the tube's (walked on demand)
    assert state.voltage_threshold == pytest.approx(cold.voltage_threshold, rel=1e-12)


def test_past_the_voltage_threshold_the_continuation_refuses():
    """Two identical layers of the paper's tube at g = 1.1 lose the state at the voltage
    asymptote of its branch: a neighbour just below it continues no state above it."""
    tube = Tube((Layer(1.2, growth=1.1), Layer(1.4, growth=1.1)), length=1.0)
    thr = solve_layered_state(tube).voltage_threshold
    near = solve_layered_state(tube.at("voltage", 0.995 * thr))
    beyond = tube.at("voltage", 1.005 * thr)
    assert warm.continued(beyond, near, 1e-12) is None
    with pytest.raises(BaseStateError):
        solve_layered_state(beyond, near=near)


@pytest.mark.parametrize(
    "tube",
    [Tube((Layer(1.3, growth=1.0), Layer(2.5)), length=1.0, axial_force=0.0), SUCTION],
    ids=["free", "suction"],
)
def test_a_limit_point_is_not_continued_onto_the_falling_side(tube):
    """Under force control the voltage branch of a free tube has a limit point (a maximum
    of Vbar): from the rising side just below it, a Vbar above it is refused, and a state
    continued onto the falling side (from a neighbour there) is never returned. Also where
    the branch's r_i first falls with Vbar (the direction of rising load compared with the
    neighbour's, not the sign of d Vbar / d r_i)."""
    thr = solve_layered_state(tube).voltage_threshold
    assert solve_layered_state(tube).threshold_kind == "limit point"
    near = solve_layered_state(tube.at("voltage", 0.999 * thr))
    assert warm.continued(tube.at("voltage", 1.001 * thr), near, 1e-12) is None
    # a state below the threshold continued from one nearer the threshold: the root on the
    # rising side, the walk's
    t = tube.at("voltage", 0.99 * thr)
    _close(solve_layered_state(t, near=near), solve_layered_state(t))


def test_another_tube_is_not_a_neighbour():
    near = solve_layered_state(MUCOSA)
    other = Tube((Layer(1.1, growth=1.1), Layer(1.5), Layer(2.0)), voltage=0.3)
    assert warm.continued(other, near, 1e-12) is None
    _close(solve_layered_state(other, near=near), solve_layered_state(other))


@pytest.mark.parametrize("tube", [MUCOSA, FORCE, dataclasses.replace(FORCE, closed_ends=False)])
def test_ideal_load_rate_is_the_finite_difference_direction(tube):
    """warm._ideal_load_rate (d(P_i - P_o, N_applied) / d Vbar up to a positive factor) has
    the direction of a central difference of the pressure branch in Vbar."""
    state = solve_layered_state(tube)
    wall, x, lz, v = state._wall, state.r_i, state.stretch, tube.voltage
    rate = warm._ideal_load_rate(wall, tube, x, lz)
    h = 1e-5 * v
    pts = [warm.Branch(wall, "pressure", vbar=v + s * h).point([x], [lz]) for s in (1, -1)]
    fd = np.array([(p["dp"][0], p["end_force"][0]) for p in pts])
    fd = (fd[0] - fd[1]) / (2 * h)
    assert np.dot(rate, fd) > 0
    cos = np.dot(rate, fd) / (np.linalg.norm(rate) * np.linalg.norm(fd))
    assert cos == pytest.approx(1.0, abs=1e-9)


#: check round 35b's P17: a stiff Mooney-Rivlin film grown inside a Gent tube (jm = 0.6)
#: under pressure and a compressive axial force; as the Gent layer nears its lock the Gauss
#: rule its states need grows from 16 nodes (g = 1.31) to 128 (g = 1.46)
LOCKING = Tube(
    (
        Layer(1.05, shear_modulus=20.0, material=mooney_rivlin(0.7)),
        Layer(1.8, material=gent(0.6)),
    ),
    length=3.0,
    axial_force=-0.3,
    inner_pressure=0.02,
    closed_ends=True,
)
#: the growth values its march (critical_value of (12, 2) for growth[1]) solves
LOCKING_MARCH = (1.0, 1.004, 1.012, 1.028, 1.06, 1.11, 1.16, 1.21, 1.26, 1.31, 1.36, 1.41, 1.46)


def _march_to_lock(monkeypatch, until: float):
    """The states of LOCKING's march up to ``until`` as a march solves them (each continued
    from its neighbours), and the number of walks from the unloaded tube after the first."""
    at = TubeAt(LOCKING, "growth[1]")
    states = {LOCKING_MARCH[0]: at.solved(LOCKING_MARCH[0])}  # walked: no neighbour yet
    walks = []
    real = layered._prepare

    def counted(*args):
        walks.append(args)
        return real(*args)

    monkeypatch.setattr(layered, "_prepare", counted)
    states.update({g: at.solved(g) for g in LOCKING_MARCH[1:] if g <= until})
    return at, states, len(walks)


def test_a_march_next_to_a_lock_refines_its_rule_without_walking(monkeypatch):
    """Where the neighbour's Gauss rule does not resolve the next state, the continuation
    is made again with a finer rule instead of walking the loading branches from the
    unloaded tube (5-20 s a state against ~50 ms; before: a walk at 1.36, 1.41 and 1.46).
    The state is the walk's (its own rule, 24 nodes, agrees with 32 to 7e-14)."""
    at, states, walks = _march_to_lock(monkeypatch, 1.46)
    assert walks == 0
    assert [states[g]._wall.nodes for g in (1.31, 1.36, 1.46)] == [16, 32, 128]
    cold = solve_layered_state(at(1.36))
    _close(states[1.36], cold, 1e-10)
    R = np.linspace(1.0, 1.8, 9)
    assert np.allclose(states[1.36].sigma_rr(R), cold.sigma_rr(R), rtol=0, atol=1e-10)
    assert states[1.36].quadrature_error <= 1e-12


@pytest.mark.slow
@pytest.mark.parametrize("g", [1.41, 1.46])
def test_the_refined_continuation_is_the_walks_state_next_to_the_lock(monkeypatch, g):
    """Closer to the lock (the Gent layer 1.1e-3 from it at 1.46), by the cold walk (~10 s
    each): 48 and 128 nodes against the continuation's 64 and 128."""
    at, states, _ = _march_to_lock(monkeypatch, g)
    cold = solve_layered_state(at(g))
    _close(states[g], cold, 1e-10)
    R = np.linspace(1.0, 1.8, 9)
    assert np.allclose(states[g].sigma_rr(R), cold.sigma_rr(R), rtol=0, atol=1e-10)
