"""Physical units at the edge (model/units.py, cli/units.py): hand conversions, the CLI
design (a number keeps its non-dimensional meaning), one-line errors with exit status 2."""

import json
import math
from pathlib import Path

import pytest

from electrogrowth import ParameterError, Tube, solve_base_state, tube_from_quantities
from electrogrowth.basestate.tube import neo_hookean_asymptote
from electrogrowth.cli.app import main
from electrogrowth.model.units import EPSILON_0, Scales

pytest.importorskip("pint")

# R_i = 2 mm, R_o = 2.8 mm, mu = 100 kPa, eps = 4.7 eps_0: by hand,
# sqrt(mu / eps) = sqrt(1e5 / (4.7 * 8.8541878128e-12)) = 4.90203e7 V/m, and the voltage
# scale (R_o - R_i) sqrt(mu / eps) = 0.8e-3 m * 4.90203e7 V/m = 39216.3 V.
EPS = 4.7 * 8.8541878128e-12
SCALE = 0.8e-3 * math.sqrt(1e5 / EPS)
PHYSICAL = ["--inner-radius", "2mm", "--shear-modulus", "100kPa", "--permittivity", "4.7"]


def test_hand_conversion():
    assert SCALE == pytest.approx(39216.3, rel=1e-6)
    tube, scales = tube_from_quantities(
        "2 mm", "0.28 cm", shear_modulus="0.1 MPa", permittivity=4.7, length="1 cm", voltage="3 kV"
    )
    assert tube.outer_radius == pytest.approx(1.4, rel=1e-15)
    assert tube.length == pytest.approx(5.0, rel=1e-15)
    assert tube.voltage == pytest.approx(3000.0 / SCALE, rel=1e-12)
    assert scales.permittivity == pytest.approx(EPS, rel=1e-15)
    assert scales.voltage(tube.voltage).to("V").magnitude == pytest.approx(3000.0, rel=1e-12)
    assert scales.stress(0.25).to("Pa").magnitude == pytest.approx(25e3)
    assert scales.length(1.4).to("mm").magnitude == pytest.approx(2.8)


def test_permittivity_as_quantity_equals_relative():
    a = tube_from_quantities("2 mm", "2.8 mm", shear_modulus="100 kPa", permittivity=4.7)[1]
    b = tube_from_quantities(
        "2 mm", "2.8 mm", shear_modulus="100 kPa", permittivity=f"{4.7 * EPSILON_0} F/m"
    )[1]
    assert a.voltage_scale == pytest.approx(b.voltage_scale, rel=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"inner_radius": "2 kg"}, "not a length"),
        ({"inner_radius": "2"}, "has no unit"),
        ({"inner_radius": "-2 mm"}, "out of range"),
        ({"outer_radius": "1 mm"}, "need R_o > R_i"),
        ({"permittivity": -1.0}, "eps_r"),
        ({"voltage": "3 kV", "shear_modulus": None}, "needs the shear modulus"),
    ],
)
def test_bad_quantities_name_the_value(kwargs, match):
    args = {"inner_radius": "2 mm", "outer_radius": "2.8 mm", "shear_modulus": "100 kPa"}
    args.update(permittivity=4.7)
    args.update(kwargs)
    with pytest.raises(ParameterError, match=match):
        tube_from_quantities(args.pop("inner_radius"), args.pop("outer_radius"), **args)


def test_scales_pickle_without_pint_objects():
    import pickle

    s = Scales(2e-3, 2.8e-3, 1e5, EPS)
    assert pickle.loads(pickle.dumps(s)) == s


def _state(capsys, argv):
    assert main(["state", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_cli_quantities_equal_the_nondimensional_input(capsys):
    vbar = 3000.0 / SCALE
    phys = _state(
        capsys, [*PHYSICAL, "--outer-radius", "2.8mm", "--voltage", "3kV", "--growth", "1.1"]
    )
    plain = _state(capsys, ["--outer-radius", "1.4", "--voltage", repr(vbar), "--growth", "1.1"])
    assert phys["voltage"] == pytest.approx(vbar, rel=1e-12)
    assert phys["lambda_i"] == pytest.approx(plain["lambda_i"], rel=1e-12)
    assert "physical" not in plain
    # results back in physical units: the voltage in kV, radii in mm, stresses in kPa
    assert phys["physical"]["voltage"] == [pytest.approx(3.0, rel=1e-12), "kV"]
    assert phys["physical"]["r_i"][0] == pytest.approx(2.0 * phys["r_i"], rel=1e-12)
    assert phys["physical"]["sigma_zz_min"] == [
        pytest.approx(100.0 * phys["sigma_zz_min"], rel=1e-12),
        "kPa",
    ]
    state = solve_base_state(Tube.uniform(1.4, growth=1.1, voltage=vbar))
    thr = state.voltage_threshold * SCALE / 1e3
    assert phys["physical"]["voltage_threshold"][0] == pytest.approx(thr, rel=1e-9)


def test_cli_mixed_number_and_quantity(capsys):
    """A number keeps its non-dimensional meaning next to the unit options."""
    rec = _state(capsys, [*PHYSICAL, "--outer-radius", "1.4", "--voltage", "0.2"])
    assert rec["outer_radius"] == 1.4 and rec["voltage"] == 0.2
    assert rec["physical"]["voltage"][0] == pytest.approx(0.2 * SCALE / 1e3, rel=1e-12)


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["--outer-radius", "2.8mm"], "--outer-radius 2.8mm is a length; give --inner-radius"),
        (
            ["--outer-radius", "1.4", "--voltage", "3kV", "--inner-radius", "2mm"],
            "needs --shear-modulus, --permittivity",
        ),
        (["--outer-radius", "1.4", "--inner-radius", "2kg"], "'2kg' is not a length"),
        (["--outer-radius", "1.4", *PHYSICAL, "--voltage", "3mm"], "is not a voltage"),
        (["--outer-radius", "1.4", "--inner-radius", "2mm", "--permittivity", "0"], "eps_r"),
    ],
)
def test_cli_bad_units_one_line_exit_2(capsys, argv, match):
    assert main(["state", *argv]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and match in err


def test_cli_axial_force_in_newtons(capsys):
    """The force scale is mu R_i^2 = 1e5 Pa * (2e-3 m)^2 = 0.4 N."""
    rec = _state(capsys, [*PHYSICAL, "--outer-radius", "2.8mm", "--voltage", "3kV"])
    assert rec["axial_force"] != 0
    assert rec["physical"]["axial_force"] == [
        pytest.approx(0.4 * rec["axial_force"], rel=1e-11),
        "N",
    ]
    text = main(["state", *PHYSICAL, "--outer-radius", "2.8mm", "--voltage", "3kV"])
    assert text == 0 and "axial_force = " in capsys.readouterr().out.replace("\n    ", " ")


def test_cli_converted_input_comes_back_without_rounding_noise(capsys):
    """3 kV -> Vbar -> kV is 3.0000000000000004 in floating point: reported as 3."""
    assert 3000.0 / SCALE * SCALE / 1e3 != 3.0  # the noise the report must not show
    rec = _state(capsys, [*PHYSICAL, "--outer-radius", "2.8mm", "--voltage", "3kV"])
    assert rec["physical"]["voltage"] == [3.0, "kV"] and rec["physical"]["outer_radius"] == [
        2.8,
        "mm",
    ]
    assert main(["state", *PHYSICAL, "--outer-radius", "2.8mm", "--voltage", "3kV"]) == 0
    out = capsys.readouterr().out
    assert "voltage = 3 kV" in out and "00000" not in out.split("in physical units")[1]


@pytest.mark.parametrize(
    ("length", "reported"),
    [([], None), (["--length", "5"], 10.0), (["--length", "1"], 2.0), (["--length", "1cm"], 10.0)],
)
def test_cli_reports_a_length_only_if_one_was_given(capsys, length, reported):
    rec = _state(capsys, [*PHYSICAL, "--outer-radius", "2.8mm", *length])
    assert rec["physical"].get("length") == (None if reported is None else [reported, "mm"])
    assert rec["physical"]["outer_radius"] == [2.8, "mm"]  # the radii were given


def test_scales_force_and_given_length():
    s = Scales(2e-3, 2.8e-3, 1e5, EPS)
    assert s.force(2.5).to("N").magnitude == pytest.approx(1.0, rel=1e-15)
    assert s.given_length == 0.0  # none given
    _, scales = tube_from_quantities("2 mm", "2.8 mm", shear_modulus="100 kPa", length="1 cm")
    assert scales.given_length == pytest.approx(0.01, rel=1e-15)


def test_physical_line_breaks_between_entries_only():
    from electrogrowth.cli.report import physical_line

    physical = {f"quantity_{k}": [12345.6789 * k, "kPa"] for k in range(1, 9)}
    lines = physical_line(physical)
    assert len(lines) > 1 and all(len(line) <= 95 for line in lines)
    entries = ", ".join(line.strip() for line in lines).removeprefix("in physical units: ")
    # each "name = value unit" whole on one line, the entries in order
    assert entries.replace(",,", ",").split(", ") == [
        f"quantity_{k} = {12345.6789 * k:.6g} kPa" for k in range(1, 9)
    ]


# Probe 8b D7: with a layered --tube, resolve_units took R_o only from --outer-radius, which a
# layered tube must not set: `--voltage 3kV` was refused ("needs --outer-radius as well"), and
# no voltage was printed in kV (the scales had R_o = NaN); `state` printed no physical units.
# R_o is now the file's outermost radius (2 R_i for examples/bilayer.toml).
BILAYER = str(Path(__file__).resolve().parents[2] / "examples" / "bilayer.toml")
BILAYER_SCALE = (4e-3 - 2e-3) * math.sqrt(1e5 / EPS)  # R_o - R_i = 2 mm


def test_cli_layered_tube_takes_a_voltage_in_kV(capsys):
    rec = _state(capsys, ["--tube", BILAYER, *PHYSICAL, "--voltage", "3kV"])
    assert rec["voltage"] == pytest.approx(3000.0 / BILAYER_SCALE, rel=1e-14)  # 0.03059
    assert rec["physical"]["voltage"] == [3.0, "kV"]
    assert rec["physical"]["outer_radius"] == [4.0, "mm"]


def test_cli_layered_state_prints_physical_units(capsys):
    assert main(["state", "--tube", BILAYER, *PHYSICAL]) == 0
    out = capsys.readouterr().out.replace("\n    ", " ")
    vbar = 0.3  # the file's voltage
    assert f"voltage = {vbar * BILAYER_SCALE / 1e3:.6g} kV" in out
    assert "outer_radius = 4 mm" in out and "inner_pressure = 5 kPa" in out  # P_i 0.05 mu


def test_cli_layered_critical_voltage_in_kV(capsys, tmp_path):
    tube = tmp_path / "voltR.toml"
    tube.write_text(
        "length = 1.5\nstretch = 1.0\n[[layers]]\nouter_radius = 1.2\nshear_modulus = 2.0\n"
        "[[layers]]\nouter_radius = 1.5\n"
    )
    argv = ["critical", "--tube", str(tube), *PHYSICAL, "--solve-for", "voltage"]
    assert main([*argv, "--m-max", "3", "--n-max", "3", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    kv = rec["value"] * (3e-3 - 2e-3) * math.sqrt(1e5 / EPS) / 1e3  # R_o = 1.5 R_i = 3 mm
    assert rec["physical"]["voltage"] == [pytest.approx(kv, rel=1e-10), "kV"]


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["--inner-radius", "-2mm"], "--inner-radius = '-2mm' is out of range; need 0 <"),
        (["--inner-radius", "2mm", "--length", "-5 mm"], "--length = '-5 mm' is out of range"),
        ([*PHYSICAL, "--voltage", "-3kV"], "--voltage = '-3kV' is out of range; need 0 <="),
    ],
)
def test_cli_negative_quantity_is_named_with_its_range(capsys, argv, match):
    """Probe 8b: `--inner-radius -2mm` gave argparse's "expected one argument" (a word
    starting with "-" and no plain number was read as an option), not the value's range."""
    assert main(["state", "--outer-radius", "1.4", *argv]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and match in err


def test_cli_loads_in_physical_units_equal_the_nondimensional_input(capsys):
    """Probe 9b: `--inner-pressure 5kPa` was refused though pressures are printed in kPa.
    With --shear-modulus 100 kPa a pressure of 5 kPa is P / mu = 0.05 (the outer one may be
    negative); with --inner-radius 2 mm a force of -0.1 N is N / (mu R_i^2) = -0.25."""
    units = ["--shear-modulus", "100kPa", "--inner-radius", "2mm", "--outer-radius", "1.4"]
    phys = _state(capsys, [*units, "--inner-pressure", "5kPa", "--outer-pressure", "-2kPa"])
    plain = _state(capsys, ["--outer-radius", "1.4", "--inner-pressure", "0.05",
                            "--outer-pressure", "-0.02"])  # fmt: skip
    assert (phys["inner_pressure"], phys["outer_pressure"]) == (0.05, -0.02)
    assert phys["lambda_i"] == pytest.approx(plain["lambda_i"], rel=1e-14)
    phys = _state(capsys, [*units, "--axial-force", "-0.1N"])
    plain = _state(capsys, ["--outer-radius", "1.4", "--axial-force", "-0.25"])
    assert phys["axial_force"] == pytest.approx(-0.25, rel=1e-14)
    assert phys["lambda_i"] == pytest.approx(plain["lambda_i"], rel=1e-14)


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["--inner-pressure", "5kPa"], "5kPa is a pressure; give --shear-modulus"),
        (["--shear-modulus", "1kPa", "--axial-force", "0.1N"], "give --inner-radius too"),
        (["--shear-modulus", "1kPa", "--outer-pressure", "3mm"], "is not a pressure"),
        # probe 10b: an overflowing load was told "need 0 < --inner-pressure < inf"
        (["--shear-modulus", "1kPa", "--inner-pressure", "-1e400kPa"], "not a finite pressure"),
        (
            ["--shear-modulus", "1kPa", "--inner-radius", "1mm", "--axial-force", "1e400N"],
            "'1e400N' is not a finite force",
        ),
    ],
)
def test_cli_a_load_without_its_scale_is_one_line(capsys, argv, match):
    assert main(["state", "--outer-radius", "1.4", *argv]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and match in err


@pytest.mark.parametrize(
    ("argv", "want"),
    [
        # the paper's tube (Rbar_o 1.4): its asymptote in closed form (NH-5), times the
        # wall's scale (R_o - R_i) sqrt(mu / eps) worked by hand
        (
            ["--outer-radius", "2.8mm", "--voltage", "100kV"],
            lambda: (
                "V",
                100,
                neo_hookean_asymptote(Tube.uniform(1.4)) * 0.8e-3 * math.sqrt(1e5 / EPS) / 1e3,
                "kV",
            ),
        ),
        # an inflated neo-Hookean tube's asymptote P_i = ln(Rbar_o) mu (g = lambda_z = 1)
        (
            ["--outer-radius", "2", "--inner-pressure", "80kPa"],
            lambda: ("P_i", 80, math.log(2) * 100, "kPa"),
        ),
    ],
)
def test_cli_a_load_beyond_its_threshold_is_refused_in_the_units_given(capsys, argv, want):
    """Check round 29, D6: `--voltage 100kV` beyond the threshold was refused in Vbar only;
    the refusal now quotes the load and its threshold in the user's units too."""
    assert main(["state", *PHYSICAL, *argv]) == 2
    err = capsys.readouterr().err
    name, value, threshold, unit = want()
    assert err.count("\n") == 1
    assert f"; in {unit}: {name} = {value:.6g} {unit}, its threshold {name} =" in err
    assert f" = {threshold:.6g} {unit} (" in err
