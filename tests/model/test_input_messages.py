"""A refused input is named as the user gave it: a thickness as the thickness (not the radius
it moves), a layer by the number the tube file and the keys use (layers[K], K = 1 innermost),
a growth component as g_theta (growth[K] is layer K's growth), a curve's --along as itself
(not as solve_for), and the remedy of "no mode bifurcates" in the terms of what was asked
(no --m-max for one --mode, no --side for growth)."""

import math
import re
import types
import warnings
from pathlib import Path

import pytest

from electrogrowth.bifurcation import scan
from electrogrowth.bifurcation.critical import no_bifurcation_remedy
from electrogrowth.cli import app as cli
from electrogrowth.errors import ConfigError, NoBifurcationFound, ParameterError
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.tube_file import load_tube, parse_tube
from electrogrowth.outcomes import Kind
from electrogrowth.sweep.file import load_config

BILAYER = Path(__file__).resolve().parents[2] / "examples" / "bilayer.toml"
TUBE = Tube((Layer(1.1), Layer(2.0)))


@pytest.mark.parametrize(
    "key, value, named, valid",
    [
        ("layers[1].thickness", -0.05, "layers[1].thickness = -0.05", "> 0"),
        ("layers[2].thickness", 0.0, "layers[2].thickness = 0.0", "> 0"),
        # below the spacing of floating-point radii at R = 1.1 (probe round 6b: the error
        # named layers[2].outer_radius = 1.1, which the user never gave)
        ("layers[2].thickness", 1e-17, "layers[2].thickness = 1e-17", ">= 2e-16"),
        ("layers[1].outer_radius", 2.25, "layers[1].outer_radius = 2.25", "1 < R < 2"),
        ("layers[2].outer_radius", 0.5, "layers[2].outer_radius = 0.5", "> 1.1"),
        ("layers[2].shear_modulus", -1.0, "layers[2].shear_modulus = -1.0", "1e-08 to 1e+08"),
    ],
)
def test_a_key_of_a_layered_tube_is_refused_in_its_own_terms(key, value, named, valid):
    with pytest.raises(ParameterError) as err:
        TUBE.at(key, value)
    text = str(err.value)
    assert text.startswith(named) and f"valid range: {valid}" in text


def test_a_layer_is_named_as_in_the_file():
    text = BILAYER.read_text().replace("outer_radius = 2.0", "outer_radius = 1.05")
    with pytest.raises(ConfigError) as err:
        parse_tube(text, source="t.toml")
    assert err.value.key == ("layers", "2", "outer_radius")
    assert "layers[2].outer_radius = 1.05 is out of range" in str(err.value)
    with pytest.raises(ParameterError, match=r"^layers\[2\].outer_radius = 1.5 "):
        Tube((Layer(1.5), Layer(1.5)))


def test_a_growth_component_is_named_by_its_component():
    with pytest.raises(ParameterError, match=r"^growth g_theta = 0.0 is out of range"):
        Layer(1.5, growth=(1.0, 0.0, 1.0))
    text = BILAYER.read_text().replace("growth = [1.0, 1.2, 1.0]", "growth = [1.0, 1.2, -1]")
    with pytest.raises(ConfigError) as err:
        parse_tube(text, source="t.toml")
    assert err.value.key == ("layers", "1", "growth") and "growth g_z = -1" in str(err.value)


@pytest.mark.parametrize(
    "along, named",
    [
        ("bogus", "control 'bogus' is unknown"),
        ("stretch[2]", "control 'stretch[2]': a layer or growth component applies to growth"),
    ],
)
def test_a_curve_along_a_bad_name_blames_that_name(along, named, capsys):
    argv = f"curve --tube {BILAYER} --solve-for growth --layer 1 --along {along}"
    assert cli.main([*argv.split(), "--from", "0", "--to", "1", "--points", "3"]) == 2
    err = capsys.readouterr().err
    assert named in err and "solve_for" not in err
    assert "or a key of the tube: length" in err  # what --along may also be


def test_the_remedy_of_no_bifurcation_fits_the_question():
    one_mode = no_bifurcation_remedy("growth[1].r", mode=(1, 1))
    assert "leave out --mode" in one_mode and "--m-max" not in one_mode
    assert "--side" not in one_mode + no_bifurcation_remedy("growth")
    assert "--side" in no_bifurcation_remedy("stretch")
    assert "--m-max" in no_bifurcation_remedy("voltage")


def test_a_scan_finding_nothing_gives_the_scan_remedy(monkeypatch):
    def nothing(*args):
        exc = NoBifurcationFound("no mode bifurcates for growth between 1 and 6")
        exc.remedy = "the remedy of one mode"
        raise exc

    monkeypatch.setattr(scan, "_widened_scan", nothing)
    # no face limit either: else the folds beyond the (faked) scan are read at it, and a
    # uniform tube's are found there (probe 13b, D1: scan._no_scanned_mode)
    no_limit = types.SimpleNamespace(kind=Kind.THRESHOLD)
    monkeypatch.setattr(scan, "short_wave_limit", lambda *args, **kwargs: no_limit)
    options = scan.ScanOptions(surface=False)
    with pytest.raises(NoBifurcationFound) as err:
        scan.scan_modes(Tube.uniform(1.4), "growth", options=options)
    assert err.value.remedy == "raise --m-max / --n-max, or solve for another control parameter"


def test_one_mode_without_a_root_is_not_told_to_raise_the_mode_ranges(capsys):
    argv = "critical --solve-for growth --outer-radius 1.4 --mode 0 1 --family torsional"
    assert cli.main(argv.split()) == 2
    err = capsys.readouterr().err
    assert "leave out --mode" in err and "--m-max" not in err and "--side" not in err


def test_a_layer_growth_outside_the_box_is_named_not_the_pressure(tmp_path, capsys):
    text = BILAYER.read_text().replace("growth = 1.0\n", "growth = 1e-9\n")
    (tmp_path / "t.toml").write_text(text)
    assert cli.main(["state", "--tube", str(tmp_path / "t.toml")]) == 2
    err = capsys.readouterr().err
    assert (
        err.count("\n") == 1 and "layers.2.growth: growth = 1e-09 is outside the supported" in err
    )
    assert "inner_pressure" not in err


def test_floating_point_warnings_stay_off_stderr(monkeypatch, capsys):
    import numpy as np

    def run(args):
        np.divide(np.ones(2), np.zeros(2))  # a solver probing past a threshold
        return 0

    monkeypatch.setitem(cli.COMMANDS, "state", ("state", lambda parser: None, run))
    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        assert cli.main(["state"]) == 0
    assert shown == [] and capsys.readouterr().err == ""


@pytest.mark.parametrize("field", ["shear_modulus", "permittivity"])
@pytest.mark.parametrize("value", [1e-300, 1e-20, 1e-9, 1.1e8, 1e300])
def test_a_layer_s_modulus_outside_the_supported_range_is_refused_in_one_line(field, value):
    # probe 7b D5: a substrate 1e-300 as stiff ended in a ZeroDivisionError ("internal
    # error"), 1e-20 and 1e-100 in spurious roots, a film 1e300 in numpy warnings
    want = f"{field} = {value:.6g} is outside the supported range 1e-08 to 1e+08: "
    with pytest.raises(ParameterError, match="^" + re.escape(want)):
        Layer(3.0, **{field: value})
    with pytest.raises(ParameterError, match="^" + re.escape(f"layers[2].{want}")):
        TUBE.at(f"layers[2].{field}", value)


@pytest.mark.parametrize("field", ["shear_modulus", "permittivity"])
@pytest.mark.parametrize("value", [-0.0, 0.0, -1.0, math.nan, math.inf])
def test_a_layer_s_modulus_not_positive_names_the_supported_range(field, value):
    # probe 9b: permittivity = -0.0 was refused with "valid range: 0 < value < inf", not
    # the supported range the positive values outside it are refused with
    want = f"{field} = {value!r} is out of range; valid range: 1e-08 to 1e+08 (of the reference)"
    with pytest.raises(ParameterError, match="^" + re.escape(want) + "$"):
        Layer(3.0, **{field: value})


def test_the_ends_of_the_modulus_range_are_accepted_and_their_ratio_is_bounded():
    Tube((Layer(1.1, shear_modulus=1e8, permittivity=1e-8), Layer(2.0)))
    Tube((Layer(1.1, shear_modulus=1e-8, permittivity=1e8), Layer(2.0)))
    # a film 1e8 on a substrate 1e-8 is, to the wall's equations, a substrate 1e-16 as stiff
    with pytest.raises(
        ParameterError,
        match=r"^layers\[1\]\.shear_modulus / layers\[2\]\.shear_modulus = 1e\+16 is"
        r" outside the supported range 1 to 1e\+08: ",
    ):
        Tube((Layer(1.1, shear_modulus=1e8), Layer(2.0, shear_modulus=1e-8)))


def test_a_denormal_substrate_modulus_is_refused_not_an_internal_error(tmp_path, capsys):
    # probe 7b D5: accepted; critical_value raised ZeroDivisionError (CLI: internal error,
    # exit 1)
    text = BILAYER.read_text().replace(
        "outer_radius = 2.0", "outer_radius = 2.0\nshear_modulus = 1e-300"
    )
    (tmp_path / "t.toml").write_text(text)
    args = [
        "critical",
        "--tube",
        str(tmp_path / "t.toml"),
        "--solve-for",
        "growth",
        "--layer",
        "1",
    ]
    assert cli.main([*args, "--component", "theta", "--mode", "33", "0"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "shear_modulus = 1e-300 is outside the supported" in err


@pytest.mark.parametrize("value", ['"3 kV"', '"2.8mm"', '"100 kPa"'])
def test_a_quantity_in_a_tube_file_says_where_units_go(value):
    """Probe 11b (doubt): `voltage = "3 kV"` in a tube file was "expected a number, got a
    string", with no word that files are non-dimensional and units go on the command line."""
    with pytest.raises(ConfigError, match="give physical units on the command line"):
        parse_tube(f"voltage = {value}\n[[layers]]\nouter_radius = 1.4\n")
    with pytest.raises(ConfigError) as plain:
        parse_tube('[[layers]]\nouter_radius = "abc"\n')
    assert "units" not in str(plain.value)


def test_a_file_with_a_byte_order_mark_reads_as_without(tmp_path, capsys):
    """Probe 14e D3: Windows editors' "UTF-8 with BOM" (EF BB BF first) was "invalid TOML:
    Invalid statement". The tube and sweep files read the same with it; a load beyond its
    threshold still names line 1 of the file."""
    bom = b"\xef\xbb\xbf"
    tube = b"length = 3.0\r\n[[layers]]\r\nouter_radius = 2.0\r\n"
    sweep = b'[solve]\nfor = "voltage"\n[grid]\nouter_radius = [1.4, 1.6]\n'
    for name, text, load in (("t", tube, load_tube), ("s", sweep, load_config)):
        plain, marked = tmp_path / f"{name}.toml", tmp_path / f"{name}_bom.toml"
        plain.write_bytes(text)
        marked.write_bytes(bom + text)
        assert load(marked) == load(plain)
    marked = tmp_path / "v_bom.toml"
    marked.write_bytes(bom + b"voltage = 5\n[[layers]]\nouter_radius = 2\n")
    assert cli.main(["state", "--tube", str(marked)]) == 2
    assert capsys.readouterr().err.startswith(f"electrogrowth: error: {marked}:1: voltage: ")


@pytest.mark.parametrize(
    "material, key, named",
    [
        (
            "",
            "jm = 97.2",
            'jm is a parameter of material = "gent", and this layer\'s material'
            ' is neo-hookean (the default): set material = "gent" or drop jm',
        ),
        (
            'material = "gent"\n',
            "alpha = 0.3",
            "alpha is a parameter of material ="
            ' "mooney-rivlin", and this layer\'s material is gent',
        ),
        ('material = "gent"\n', "frobnicate = 1", "unknown key; a layer takes outer_radius"),
    ],
)
def test_a_material_parameter_on_another_material_names_its_material(material, key, named):
    """Probe 14e D7: jm on a layer of the default material was an "unknown key" whose list
    left jm out; a parameter of another built-in material names that material."""
    with pytest.raises(ConfigError) as refused:
        parse_tube(f"[[layers]]\nouter_radius = 2\n{material}{key}\n")
    assert named in str(refused.value)


@pytest.mark.parametrize(
    "text, line, key, named",
    [
        # check round 29 D4: 1.0999999 after 1.1 read "= 1.1 ... valid range: > 1.1"
        (
            "length = 3\n[[layers]]\nouter_radius = 1.1\nshear_modulus = 10\n"
            "[[layers]]\nouter_radius = 1.0999999\n",
            6,
            "layers.2.outer_radius",
            "outer_radius = 1.0999999 is out of range; valid range: > 1.1,",
        ),
        # check round 29 D5: the paper's tube (one layer) lost its line and key
        (
            "[[layers]]\nouter_radius = 1e300\n",
            2,
            "layers.1.outer_radius",
            "Rbar_o = 1e+300 is outside the supported range 1 to 100",
        ),
        (
            "[[layers]]\nouter_radius = 100.00000000000001\n",
            2,
            "layers.1.outer_radius",
            "Rbar_o = 100.00000000000001 is outside",
        ),
        ("length = 1e5\n[[layers]]\nouter_radius = 1.5\n", 1, "length", "L = 1e+05 is outside"),
        (
            "[[layers]]\nouter_radius = 1.5\n[[layers]]\nouter_radius = 300\n",
            4,
            "layers.2.outer_radius",
            "outer_radius = 300 is outside the supported range 1 to 100",
        ),
        (
            "length = 2\n[[layers]]\nouter_radius = 1.5\n[[layers]]\nouter_radius = 2\n"
            "shear_modulus = 1.00000001e8\n[[layers]]\nouter_radius = 3\nshear_modulus = 1\n",
            6,
            "layers.2.shear_modulus",
            "shear_modulus = 100000001 is outside the supported range 1e-08 to 1e+08",
        ),
        # D5: a growth of 0 and one of 0.001 name one range, the supported one
        (
            "[[layers]]\nouter_radius = 1.5\ngrowth = 0\n",
            3,
            "layers.1.growth",
            "growth = 0.0 is out of range; valid range: 0.01 to 100",
        ),
        (
            "[[layers]]\nouter_radius = 1.5\ngrowth = 0.001\n",
            3,
            "layers.1.growth",
            "growth = 0.001 is outside the supported range 0.01 to 100",
        ),
    ],
)
def test_a_refused_tube_file_value_is_quoted_as_given_at_its_line(text, line, key, named):
    with pytest.raises(ConfigError) as err:
        parse_tube(text, source="t.toml")
    msg = str(err.value)
    assert msg.startswith(f"t.toml:{line}: {key}: ") and named in msg, msg


@pytest.mark.parametrize(
    "name, text, argv, example",
    [
        ("tube.json", '{"layers": [{"outer_radius": 2}]}', ["state", "--tube"], "bilayer"),
        ("tube.toml", '{"layers": [{"outer_radius": 2}]}', ["state", "--tube"], "bilayer"),
        ("sweep.json", '{"solve": {"for": "growth"}}', ["sweep", "--check"], "sweep"),
    ],
)
def test_a_json_file_is_told_the_file_is_toml(tmp_path, capsys, name, text, argv, example):
    """Check round 29 (cosmetic): a JSON tube file got "invalid TOML: Invalid statement",
    with no word that tube files are TOML. One line naming the file, exit 2."""
    path = tmp_path / name
    path.write_text(text)
    assert cli.main([*argv, str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"electrogrowth: error: {path}:1: invalid TOML")
    assert f"this is JSON, and a {'sweep' if example == 'sweep' else 'tube'} file is TOML" in err
    assert f"examples/{example}.toml" in err


def test_a_toml_syntax_error_is_not_called_json(capsys, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text("length = \n")
    assert cli.main(["state", "--tube", str(path)]) == 2
    assert "JSON" not in capsys.readouterr().err
