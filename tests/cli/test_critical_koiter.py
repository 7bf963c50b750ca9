"""`critical --koiter`: the amplitude equation's verdict in the JSON record and the text,
equal to the library's expansion, and a one-line reason where it is not covered."""

import json
from pathlib import Path

import pytest

from electrogrowth.bifurcation.koiter import axisymmetric_expansion, tube_expansion
from electrogrowth.cli.app import main
from electrogrowth.model.layers import Layer, Tube

MUCOSA = [
    "--tube",
    str(Path(__file__).parents[2] / "examples" / "mucosa.toml"),
    "--solve-for",
    "growth",
    "--layer",
    "1",
]
MUCOSA += ["--component", "theta", "--mode", "12", "0", "--koiter"]


def test_json_has_the_branch_and_the_coefficient(capsys):
    assert main(["critical", *MUCOSA, "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    tube = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0)
    c2 = tube_expansion(tube, 12, "growth[1].theta", nodes=32).coefficient  # the door's finest
    assert rec["branch"] == "supercritical"
    assert abs(rec["koiter"] - c2) < 1e-9 * abs(c2)
    assert "grow gradually" in rec["meaning"]


def test_a_case_not_covered_says_why_in_one_line(capsys):
    """A dielectric that is not ideal under a voltage (wrinkles (m, n) are covered now)."""
    args = ["critical", "--solve-for", "growth", "--outer-radius", "1.4", "--voltage", "0.4"]
    args += ["--energy", "(I1 - 3)/2 + I5/2 + (I1 - 3)*I5/50"]
    assert main([*args, "--mode", "1", "1", "--koiter", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["branch"] is None and rec["koiter"] is None
    assert "ideal dielectric" in rec["branch_note"] and "\n" not in rec["branch_note"]


AXIAL_FILM = """
stretch = 1.0
length = 1.0

[[layers]]
outer_radius = 1.1
shear_modulus = 1.0

[[layers]]
outer_radius = 2.0
shear_modulus = 0.2
"""


def test_axisymmetric_mode_has_its_branch(tmp_path, capsys):
    """Mode (0, 3) of a film growing axially: the record carries the library's expansion
    of the axisymmetric family (bifurcation/koiter_tube.py), supercritical."""
    path = tmp_path / "film.toml"
    path.write_text(AXIAL_FILM)
    args = ["critical", "--tube", str(path), "--solve-for", "growth", "--layer", "1"]
    args += ["--component", "z", "--mode", "0", "3", "--koiter", "--json"]
    assert main(args) == 0
    rec = json.loads(capsys.readouterr().out)
    tube = Tube((Layer(1.1, shear_modulus=1.0), Layer(2.0, shear_modulus=0.2)), stretch=1.0)
    c2 = axisymmetric_expansion(tube, 3, "growth[1].z").coefficient
    assert rec["branch"] == "supercritical" and (rec["m"], rec["n"]) == (0, 3)
    assert abs(rec["koiter"] - c2) < 1e-9 * abs(c2)


@pytest.mark.slow
def test_mooney_rivlin_and_gent_have_their_branch(capsys):
    """--material mooney-rivlin / gent: the record carries the library's expansion of the
    critical mode (0, 1) of the paper's tube (any strain energy, docs/derivation-koiter.md
    "Any strain energy"), supercritical."""
    from electrogrowth.model.materials import gent, mooney_rivlin

    base = ["critical", "--solve-for", "growth", "--outer-radius", "1.4", "--stretch", "1.1"]
    for flags, material in (
        (["--material", "mooney-rivlin", "--alpha", "0.7"], mooney_rivlin(0.7)),
        (["--material", "gent", "--jm", "5"], gent(5.0)),
    ):
        assert main([*base, *flags, "--koiter", "--json"]) == 0
        rec = json.loads(capsys.readouterr().out)
        assert (rec["m"], rec["n"]) == (0, 1) and rec["branch"] == "supercritical"
        tube = Tube.uniform(1.4, stretch=1.1, material=material)
        c2 = axisymmetric_expansion(tube, 1, "growth").coefficient
        assert abs(rec["koiter"] - c2) < 1e-9 * abs(c2)


CHARGED_FILM = """
stretch = 1.0
length = 1.0

[[layers]]
outer_radius = 1.1
shear_modulus = 1.0
growth = [1, 1.5, 1]
permittivity = 2.0

[[layers]]
outer_radius = 2.0
shear_modulus = 0.2
permittivity = 0.5
"""


@pytest.mark.slow  # ~10 s: make test-slow runs it
def test_voltage_control_has_its_branch(tmp_path, capsys):
    """`--solve-for voltage --koiter`: the critical voltage's branch (the voltage the
    control, bifurcation/koiter_controls.py) is the library's expansion, supercritical."""
    path = tmp_path / "film.toml"
    path.write_text(CHARGED_FILM)
    args = ["critical", "--tube", str(path), "--solve-for", "voltage"]
    assert main([*args, "--mode", "12", "0", "--koiter", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    layers = (
        Layer(1.1, shear_modulus=1.0, growth=(1, 1.5, 1), permittivity=2.0),
        Layer(2.0, shear_modulus=0.2, permittivity=0.5),
    )
    c2 = tube_expansion(Tube(layers, stretch=1.0), 12, "voltage").coefficient
    assert rec["branch"] == "supercritical" and abs(rec["koiter"] - c2) < 1e-9 * abs(c2)


def test_without_koiter_a_wrinkle_says_how_to_learn_its_branch(capsys):
    """Every wrinkle's record speaks of its branch: without --koiter, how to get it."""
    args = ["critical", "--solve-for", "growth", "--outer-radius", "1.4", "--voltage", "0.4"]
    assert main([*args, "--mode", "0", "1", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["branch"] is None and "--koiter" in rec["branch_note"]
    assert main([*args, "--mode", "0", "1"]) == 0
    assert "amplitude equation not computed: not asked: add --koiter" in capsys.readouterr().out


@pytest.mark.parametrize("command", ["critical", "design"])
def test_the_help_says_what_koiter_costs_as_measured(command, capsys):
    """Check round 29, D8: the help said "one to five seconds" while critical's own note
    said ~10 s layered, and the README's mucosa took ~10 s more with --koiter. Both helps
    and the note now quote one measured text (cli/options.KOITER_COST)."""
    from electrogrowth.cli.options import KOITER_COST

    assert main([command, "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "one to five seconds" not in text and KOITER_COST in text
    assert "~12 s on a layered tube" in KOITER_COST
