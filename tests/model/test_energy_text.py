"""A user's energy as text: --energy on the command line, [material] energy in a sweep file."""

import json

import pytest

from electrogrowth import ConfigError, MaterialError, Tube, solve_base_state
from electrogrowth.cli.app import main
from electrogrowth.model.energy_grammar import _OPERATORS as OPERATORS
from electrogrowth.model.energy_grammar import CONSTANTS, FUNCTIONS, SYMBOLS, parse_energy
from electrogrowth.model.energy_text import energy_material
from electrogrowth.model.materials import mooney_rivlin
from electrogrowth.sweep.file import parse_config

MR = "0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2"


def test_energy_equals_the_builtin():
    text = energy_material(MR)
    builtin = mooney_rivlin(0.8)
    a = solve_base_state(Tube.uniform(1.4, growth=1.1, voltage=0.3, material=text))
    b = solve_base_state(Tube.uniform(1.4, growth=1.1, voltage=0.3, material=builtin))
    assert a.lambda_i == pytest.approx(b.lambda_i, rel=1e-10)


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("(I1 - 3)/2 + I5/2 +", "position 20: the end where a number"),
        ("(I1 - 3/2 + I5/2", "unbalanced parentheses"),
        ("(I1 - 3)/2 + I3/2", "unknown name 'I3'"),
        ("__import__('os').getcwd()", "unknown name '__import__'"),
        ("(I1 - 3)/2; I5", "character ';'"),
        ("log(I1 - 3) + I5/2", "not finite"),
        ("", "empty"),
    ],
)
def test_malformed_energy_is_one_line(text, match):
    with pytest.raises(MaterialError, match=match) as err:
        energy_material(text)
    assert "\n" not in str(err.value)


def test_cli_energy_equals_material(capsys):
    base = ["state", "--outer-radius", "1.4", "--growth", "1.1", "--voltage", "0.3", "--json"]
    assert main([*base, "--energy", MR]) == 0
    text = json.loads(capsys.readouterr().out)
    assert main([*base, "--material", "mooney-rivlin", "--alpha", "0.8"]) == 0
    builtin = json.loads(capsys.readouterr().out)
    assert text["material"] == MR
    assert text["lambda_i"] == pytest.approx(builtin["lambda_i"], rel=1e-10)


def test_cli_energy_with_other_units_is_refused(capsys):
    """Shear modulus 2 (1/2 + 0.1) = 1.2 in the reference state: every result would be in
    the wrong units, so it is one error line saying which (issue 14)."""
    argv = ["state", "--outer-radius", "1.4", "--energy", "(I1 - 3)/2 + 0.1*(I2 - 3) + I5/2"]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "shear modulus" in err[0] and "1.2" in err[0], err


@pytest.mark.parametrize(
    ("extra", "match"),
    [
        (["--energy", "(I1 - 3)/2 + I5/2 +"], "position 20: the end where a number"),
        (["--energy", "(I1-3)/2 + I5/2", "--material", "gent"], "not allowed with"),
        (["--energy", "(I1-3)/2 + I5/2", "--jm", "20"], "--jm = 20 is a parameter"),
    ],
)
def test_cli_bad_energy_exit_2(capsys, extra, match):
    assert main(["state", "--outer-radius", "1.4", *extra]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and match in err


SWEEP = """
[solve]
for = "growth"
[material]
energy = "{energy}"
[fixed]
outer_radius = 1.4
[grid]
voltage = [0.0, 0.2]
"""


def test_sweep_file_energy():
    config = parse_config(SWEEP.format(energy=MR), source="s.toml")
    assert config.build_material().name == MR
    again = type(config).from_dict(json.loads(config.to_json()))
    assert again.build_material().energy == config.build_material().energy


def test_sweep_file_bad_energy_names_file_line_key():
    with pytest.raises(ConfigError, match=r"s.toml:5: material.energy: .*unknown name .x."):
        parse_config(SWEEP.format(energy="(I1 - 3)/2 + x"), source="s.toml")


def test_the_energy_help_lists_every_word_the_grammar_accepts(capsys):
    """Probe 14e D6: --energy's help listed log, exp, sqrt of the grammar's seven functions
    and neither ^ nor pi, E. Every function, constant, operator and invariant the parser
    knows (its own tables) is in the help, and each function parses."""
    assert main(["state", "--help"]) == 0
    text = capsys.readouterr().out
    help_ = " ".join(text[text.index("  --energy OMEGA") : text.index("  --jm JM")].split())
    words = help_.split("(paper eq. 8)")[1].replace(",", " ").replace(";", " ").split()
    for word in (*FUNCTIONS, *CONSTANTS, *SYMBOLS, *OPERATORS):
        assert word in words, word
    for name in FUNCTIONS:
        parse_energy(f"(I1 - 3)/2 + 0*{name}(I1 - 2) + I5/2")
    parse_energy("(I1 - 3)^1/2 + pi*E*0 + I5/2")
