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

UNIFORM = Tube.uniform(1.4, 1.0, growth=1.1)
SPLIT = Tube((Layer(1.2, growth=1.1), Layer(1.4, growth=1.1)), length=1.0)
MUCOSA = Tube(
    (Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)),
    length=3.0,
    voltage=0.3,
    inner_pressure=0.05,
)


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
