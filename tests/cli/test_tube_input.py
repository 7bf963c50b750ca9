"""The command line and the sweep file with a layered tube (issue 12): --tube, --layer,
--component, pressure and force controls; one-line errors for what a tube cannot do."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from electrogrowth import critical_value
from electrogrowth.cli.app import main
from electrogrowth.errors import ConfigError
from electrogrowth.model.tube_file import load_tube
from electrogrowth.sweep.config import SweepConfig
from electrogrowth.sweep.file import parse_config

EXAMPLE = str(Path(__file__).resolve().parents[2] / "examples" / "bilayer.toml")


def test_critical_of_one_growth_component_equals_the_api(capsys):
    argv = ["critical", "--tube", EXAMPLE, "--solve-for", "growth", "--layer", "1"]
    argv += ["--component", "theta", "--mode", "12", "1", "--voltage", "0", "--json"]
    assert main(argv) == 0
    rec = json.loads(capsys.readouterr().out)
    tube = load_tube(EXAMPLE).at("voltage", 0.0)
    want = critical_value(tube, 12, 1, "growth[1].theta")
    assert rec["solve_for"] == "growth[1].theta" and rec["kind"] == "bifurcation"
    assert rec["value"] == pytest.approx(want.value, rel=1e-12)
    assert rec["layers"][0]["growth"][1] == pytest.approx(want.value, rel=1e-12)


@pytest.mark.parametrize(
    ("extra", "needle"),
    [
        (
            ["--solve-for", "growth", "--layer", "3", "--mode", "2", "1"],
            "layer = 3 does not exist",
        ),
        (["--solve-for", "growth", "--mode", "2", "1"], "needs a layer"),
        (["--solve-for", "force", "--mode", "1", "1"], "prescribe an axial force"),
        (["--solve-for", "voltage", "--component", "theta", "--mode", "2", "1"], "growth"),
        (
            ["--solve-for", "growth", "--layer", "1", "--component", "phi", "--mode", "2", "1"],
            "component 'phi' is unknown",
        ),
        (["--solve-for", "voltage", "--side", "extension", "--mode", "2", "1"], "--side"),
    ],
)
def test_what_a_tube_cannot_vary_is_one_line_and_exit_2(capsys, extra, needle):
    assert main(["critical", "--tube", EXAMPLE, *extra]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and needle in err[0], err


def _sweep(tmp_path, body: str) -> SweepConfig:
    (tmp_path / "tube.toml").write_text(Path(EXAMPLE).read_text())
    path = tmp_path / "sweep.toml"
    path.write_text('[tube]\nfile = "tube.toml"\n' + body)
    return parse_config(path.read_text(), source=str(path))


def test_a_sweep_varies_the_keys_of_a_tube_file(tmp_path):
    c = _sweep(
        tmp_path,
        '[solve]\nfor = "growth"\nlayer = 1\ncomponent = "r+theta"\n[fixed]\nvoltage = 0.1\n'
        '[grid]\n"layers[1].thickness" = [0.05, 0.1, 0.2]\n"layers[1].shear_modulus" = [5, 20]\n',
    )
    assert c.solve_for == "growth[1].r+theta" and c.size == 6
    tubes = c.points((slice(0, 3), slice(0, 2)))
    assert [round(t.layers[0].outer_radius - 1.0, 12) for t in tubes[::2]] == [0.05, 0.1, 0.2]
    assert [t.layers[0].shear_modulus for t in tubes[:2]] == [5.0, 20.0]
    assert all(t.voltage == 0.1 for t in tubes)
    # the outer layer keeps its thickness: R_2 - R_1 = 0.9 as in the file
    assert all(t.radii[2] - t.radii[1] == pytest.approx(0.9) for t in tubes)
    assert SweepConfig.from_dict(json.loads(c.to_json())) == c


@pytest.mark.parametrize(
    ("body", "needle"),
    [
        ('[solve]\nfor = "growth"\n[grid]\nvoltage = [0.1]\n', "needs a layer"),
        ('[solve]\nfor = "stretch"\n[grid]\n"layers[3].thickness" = [0.1]\n', "layer 3"),
        ('[solve]\nfor = "voltage"\n[grid]\nwidth = [0.1]\n', "width"),
        ('[solve]\nfor = "voltage"\n[material]\nname = "gent"\n[grid]\nlength = [2]\n', "tube"),
    ],
)
def test_bad_tube_sweeps_are_refused_with_the_key(tmp_path, body, needle):
    with pytest.raises(ConfigError, match=needle):
        _sweep(tmp_path, body)


@pytest.mark.parametrize("layers", [1, 2])
@pytest.mark.parametrize("command", [["state"], ["critical", "--solve-for", "growth"]])
def test_a_voltage_beyond_its_threshold_names_its_file_line(capsys, tmp_path, layers, command):
    """One layer (the uniform solver) or two (the layered one), `state` or `critical`: the
    file's load beyond its threshold is prefixed FILE:LINE: voltage: (docs/derivation-
    layered.md Sec. 11; probe 14e D2: a one-layer file lost it). The same voltage from the
    command line is no line of the file."""
    path = tmp_path / "t.toml"
    inner = "[[layers]]\nouter_radius = 1.5\n" if layers == 2 else ""
    path.write_text(f"length = 3.0\nvoltage = 5\n{inner}[[layers]]\nouter_radius = 2\n")
    layer = ["--layer", "1"] if layers == 2 and command[0] == "critical" else []
    argv = [*command, "--tube", str(path), *layer]
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert err.startswith(f"electrogrowth: error: {path}:2: voltage: Vbar = 5 is at or above")
    assert main([*argv, "--voltage", "5"]) == 2
    assert capsys.readouterr().err.startswith("electrogrowth: error: Vbar = 5 ")
