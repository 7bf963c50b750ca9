"""The ranges of ``design --vary`` and ``curve --from/--to`` take values with units where the
tube has physical scales (--vary outer_pressure -3kPa -1kPa, --from 1kV): converted with the
same scales as the fixed options, so the same tube in units mu gives the same result.
Before, they were refused ("'1kV' is not a number").

A voltage given in volts (--voltage 3kV) is converted to Vbar = V / (R_o - R_i)
sqrt(eps / mu) once, at the given R_o, and held as Vbar. Along a variable that moves the outer
radius that Vbar is another voltage at every point: the 3 kV asked was 4.5 kV at the
design (R_o from 2.8 to 3.2 mm), and neither design's output said so. Refused now, in one
line naming the voltage and the Vbar it stood for."""

import json
from pathlib import Path

import pytest

from electrogrowth.cli.app import main
from electrogrowth.cli.units import key_value, moves_outer_radius
from electrogrowth.model.units import EPSILON_0, Scales

ROOT = Path(__file__).resolve().parents[2]
MUCOSA = str(ROOT / "examples" / "mucosa.toml")
UNITS = ["--shear-modulus", "100kPa", "--inner-radius", "2mm"]
CHARGE = [*UNITS, "--permittivity", "4.7", "--outer-radius", "2.8mm"]


def test_each_kind_of_key_in_its_units():
    """A length in R_i, a pressure or a layer's modulus in mu, a force in mu R_i^2, a
    voltage in Vbar (at the given R_o); a plain number as it is."""
    s = Scales(2e-3, 2.8e-3, 1e5, 4.7 * EPSILON_0)
    assert key_value("--vary", "outer_radius", "3.2mm", s) == pytest.approx(1.6, rel=1e-15)
    assert key_value("--vary", "layers[1].thickness", "20um", s) == pytest.approx(0.01)
    assert key_value("--vary", "outer_pressure", "-3kPa", s) == pytest.approx(-0.03)
    assert key_value("--vary", "layers[2].shear_modulus", "1MPa", s) == pytest.approx(10.0)
    assert key_value("--vary", "force", "-0.1N", s) == pytest.approx(-0.25)
    assert key_value("--from", "voltage", "3kV", s) == pytest.approx(s.to_vbar(3e3), rel=1e-15)
    assert key_value("--from", "growth", "1.25", s) == 1.25


def test_a_curve_from_kv_is_the_curve_in_vbar(tmp_path, capsys):
    argv = ["curve", "--solve-for", "growth", "--along", "voltage", "--points", "2"]
    argv += ["--m-max", "3", "--n-max", "3", "--json", "--out", str(tmp_path)]
    assert main([*argv, *CHARGE, "--from", "1kV", "--to", "3kV"]) == 0
    got = json.loads(capsys.readouterr().out)
    scale = 0.8e-3 * (1e5 / (4.7 * EPSILON_0)) ** 0.5  # (R_o - R_i) sqrt(mu / eps)
    assert got["x"] == pytest.approx([1e3 / scale, 3e3 / scale], rel=1e-9)


@pytest.mark.parametrize(
    "argv",
    [
        ["design", "--vary", "outer_radius", "1.3", "1.6", "--voltage", "3kV"],
        ["design", "--vary", "outer_radius", "2.6mm", "3.2mm", "--vary", "voltage", "1kV", "3kV"],
        ["curve", "--along", "outer_radius", "--from", "1.3", "--to", "1.6", "--voltage", "3kV"],
    ],
)
def test_a_voltage_in_volts_beside_a_moving_wall_is_refused(argv, capsys, tmp_path):
    more = ["--target-set", "axisymmetric"] if argv[0] == "design" else ["--out", str(tmp_path)]
    assert main([*argv, *more, *CHARGE, "--solve-for", "growth"]) == 2
    err = capsys.readouterr().err
    assert "is a voltage, but outer_radius changes the wall R_o - R_i" in err, err
    assert len(err.strip().splitlines()) == 1


def test_a_unit_on_a_pure_number_or_without_scales_is_refused(capsys, tmp_path):
    argv = ["curve", "--solve-for", "growth", "--out", str(tmp_path), "--to", "3"]
    assert main([*argv, "--along", "stretch", "--from", "1mm", *UNITS]) == 2
    assert "stretch is a pure number; give it without a unit" in capsys.readouterr().err
    assert main([*argv, "--along", "length", "--from", "1mm"]) == 2
    assert "is a length; give --inner-radius too" in capsys.readouterr().err


def test_which_keys_move_the_outer_radius():
    assert moves_outer_radius("outer_radius", 1)
    assert moves_outer_radius("layers[1].thickness", 2)  # the outer layer moves out with it
    assert moves_outer_radius("layers[2].outer_radius", 2)
    assert not moves_outer_radius("layers[1].outer_radius", 2)  # an interface: R_o stays
    assert not moves_outer_radius("length", 1) and not moves_outer_radius("voltage", 1)
