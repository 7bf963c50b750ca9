"""The march's base states by continuation (along.TubeAt.state, basestate/warm.py).

Independent routes: the cold solve (every state walked from the unloaded tube), and the
paper's tube in closed form (basestate/uniform.py), which a tube of identical layers must
reproduce wherever the wall is split.
"""

from __future__ import annotations

import pickle

import pytest

from electrogrowth.basestate import layered
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.model.layers import Layer, Tube
from tests.tubes import FORCE_BILAYER as FORCE
from tests.tubes import MUCOSA

UNIFORM = Tube.uniform(1.4, 1.0, growth=1.1)
SPLIT = Tube((Layer(1.2, growth=1.1), Layer(1.4, growth=1.1)), length=1.0)


@pytest.mark.parametrize(
    "control, mode, side",
    [("voltage", (0, 1), None), ("stretch", (2, 3), "compression"), ("voltage", (3, 2), None)],
)
def test_two_identical_layers_are_the_one_layer_tube(control, mode, side):
    one = critical_value(UNIFORM, *mode, control, side=side)
    two = critical_value(SPLIT, *mode, control, side=side)
    assert two.value == pytest.approx(one.value, rel=1e-10, abs=0)


@pytest.mark.parametrize(
    "control, mode",
    [("voltage", (0, 1)), ("growth[1].theta", (4, 1)), ("pressure", (0, 2))],
)
def test_continued_march_equals_the_cold_march(monkeypatch, control, mode):
    warm = critical_value(MUCOSA, *mode, control)
    monkeypatch.setattr(layered, "continued", lambda *args: None)  # every state walked
    cold = critical_value(MUCOSA, *mode, control)
    assert warm.value == pytest.approx(cold.value, rel=1e-12, abs=0)


def test_neighbours_are_not_shipped():
    at = TubeAt(MUCOSA, "voltage")
    at.state(0.3), at.state(0.31)
    assert len(at.neighbours.states) == 2
    copy = pickle.loads(pickle.dumps(at))
    assert copy == at and copy.neighbours.states == []


def test_a_march_to_a_limit_point_continues_its_states(monkeypatch):
    """Next to the limit point the state nearest in Vbar may be the limit point itself,
    whose Jacobian is singular: Newton's start is then the line through it and the nearest
    state at another Vbar (the same state solved twice is one neighbour, not a line), and a
    state solved before at the same Vbar is reused. Only the limit point itself is walked
    (it was 5 states of 45), and the value is the cold march's (every state walked)."""
    walked = []
    continued = layered.continued

    def counting(tube, near, rtol, guess=None, nodes=None):
        out = continued(tube, near, rtol, guess, nodes)
        walked.extend([tube.voltage] if out is None else [])
        return out

    monkeypatch.setattr(layered, "continued", counting)
    warm = critical_value(FORCE, 0, 1, "voltage")
    assert len(walked) <= 1
    monkeypatch.setattr(layered, "continued", lambda *args: None)  # every state walked
    cold = critical_value(FORCE, 0, 1, "voltage")
    assert warm.value == pytest.approx(cold.value, rel=1e-12, abs=0)


def test_neighbours_line_through_two_distinct_points():
    """The same state kept twice (two rtols' neighbours, or a revisit) leaves the guess to
    the next distinct control value; one distinct value gives no line."""
    at = TubeAt(MUCOSA, "voltage")
    s1, s2 = at.state(0.30), at.state(0.32)
    at.neighbours.keep(0.32, 1e-12, s2)
    near, guess = at.neighbours.nearest(0.33, 1e-12)
    assert near is s2
    t = (0.33 - 0.32) / (0.32 - 0.30)
    assert guess == pytest.approx((s2.r_i + t * (s2.r_i - s1.r_i), s2.stretch), rel=1e-15)
    lone = TubeAt(MUCOSA, "voltage")
    lone.neighbours.keep(0.3, 1e-12, s1)
    lone.neighbours.keep(0.3, 1e-12, s1)
    assert lone.neighbours.nearest(0.31, 1e-12) == (s1, None)
    assert at.state(0.32) is s2  # solved here before: the same state, no Newton step


def test_one_preparation_however_nodes_is_passed():
    from electrogrowth.basestate.thresholds import prepare

    key = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), length=3.0)
    assert prepare(key, 1e-12) is prepare(key, 1e-12, None)
