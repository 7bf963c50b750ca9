"""The control registry (model/controls.py KINDS): every list, side check, label and march
path of a control is read from its one entry."""

from __future__ import annotations

import dataclasses

import pytest

from electrogrowth import Layer, Tube
from electrogrowth.basestate import tube as door
from electrogrowth.bifurcation.march import control_path
from electrogrowth.errors import ParameterError
from electrogrowth.figures.labels import axis_label
from electrogrowth.model import controls
from electrogrowth.model.controls import KINDS, SIDED, TUBE_CONTROLS, check_side, parse_control

BILAYER = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), voltage=0.1)


def test_the_lists_are_read_off_the_registry():
    assert TUBE_CONTROLS == tuple(KINDS) == ("growth", "stretch", "voltage", "pressure", "force")
    assert SIDED == ("stretch", "pressure", "force")
    fields = {f.name for f in dataclasses.fields(Tube)}
    for name, kind in KINDS.items():
        assert kind.name == name and (kind.field in fields or name == "growth")
        assert axis_label(name).startswith(kind.words)


@pytest.mark.parametrize("name", ["stretch", "voltage", "pressure"])
def test_a_control_sets_and_reads_its_own_field(name):
    tube = BILAYER.at(name, 0.07 if name != "stretch" else 1.2)
    assert getattr(tube, KINDS[name].field) == tube.value_of(name)


def test_default_sides_and_refusals():
    assert check_side("stretch", None) == "compression"
    assert check_side("pressure", None) == "extension"
    assert check_side("growth[2].theta", None) is None
    assert check_side("force", "extension") == "extension"
    with pytest.raises(ParameterError, match="sideways"):
        check_side("stretch", "sideways")


@pytest.mark.parametrize("control", ["growth", "growth[2].theta", "voltage"])
def test_a_side_of_a_control_that_only_increases_is_refused(control):
    # as the command line refuses --side; it was ignored, and the increase returned for a
    # "compression" (probe 7a, D4)
    with pytest.raises(ParameterError) as err:
        check_side(control, "compression")
    message = str(err.value)
    assert "\n" not in message and "'compression'" in message and control in message
    assert "stretch, pressure or force" in message


def test_the_march_path_is_the_kinds_path_on_the_door():
    t = Tube.uniform(1.4, growth=1.2, voltage=0.2)
    assert control_path(t, "stretch", "compression") == (1.2, 0.06, 1.2)  # lambda_z = g, free
    assert control_path(t, "stretch", "extension") == (1.2, 9.6, 1.2)
    start, end, scale = control_path(t, "voltage", None)
    assert start == 0.0 and end == pytest.approx(scale) and scale == door.threshold(t).value
    forced = Tube(BILAYER.layers, axial_force=0.0)
    assert control_path(forced, "force", "compression") == KINDS["force"].path(forced, False, door)


def test_a_new_kind_is_one_entry(monkeypatch):
    """A control kind registered once is known to the parser and refused nowhere else."""
    kind = dataclasses.replace(KINDS["pressure"], name="outer_pressure", field="outer_pressure")
    monkeypatch.setitem(controls.KINDS, "outer_pressure", kind)
    assert str(parse_control("outer_pressure")) == "outer_pressure"
    with pytest.raises(ParameterError, match="choose one of .*outer_pressure"):
        parse_control("temperature")
