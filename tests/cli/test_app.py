"""The dispatcher (cli/app.py): how the words of the command line reach the options."""

import json

import pytest

from electrogrowth.cli.app import COMMANDS, build_parser, main
from electrogrowth.errors import UsageError

GENT_TEXT = "-10*log(1-(I1-3)/20)+I5/2"  # Gent's energy, J_m = 20, as usually written


def _one_value_options(command: str):
    """Every option of ``command`` that takes exactly one value (its dest), and the words of
    the positionals and options the command requires."""
    sub = build_parser(command)._subparsers._group_actions[0].choices[command]
    required = []
    for a in sub._actions:
        if a.required:
            values = [str(next(iter(a.choices))) if a.choices else "1"] * (a.nargs or 1)
            required += [a.option_strings[0], *values] if a.option_strings else values
    options = {
        a.option_strings[-1]: a.dest for a in sub._actions if a.option_strings and a.nargs is None
    }
    return required, options


@pytest.mark.parametrize("command", COMMANDS)
def test_a_value_starting_with_a_minus_is_the_options_value(command):
    """Check round 29, D1: `--energy "-10*log(1-(I1-3)/20)+I5/2"` (a text with no space
    starting with "-") was refused by argparse as "expected one argument". Every option of
    every command that takes one value now reads such a word as its value: it is parsed
    (an energy, a path, a name) or refused by the option's own check, which names it."""
    positionals, options = _one_value_options(command)
    assert options, command
    for option, dest in options.items():
        value = "-a1/b"
        try:
            args = build_parser(command).parse_args([command, *positionals, option, value])
        except UsageError as exc:
            assert value in str(exc) and "expected one argument" not in str(exc), option
        else:
            read = getattr(args, dest)
            assert str(read[-1] if isinstance(read, list) else read) == value, option


def test_every_command_with_energy_reads_a_text_starting_with_a_minus():
    with_energy = [c for c in COMMANDS if "--energy" in _one_value_options(c)[1]]
    assert {"state", "critical", "curve", "design", "pattern", "postbuckle"} <= set(with_energy)
    for command in with_energy:
        positionals, _ = _one_value_options(command)
        args = build_parser(command).parse_args([command, *positionals, "--energy", GENT_TEXT])
        assert args.energy == GENT_TEXT


def test_an_energy_starting_with_a_minus_equals_the_builtin_gent(capsys):
    """The text route and the built-in energy are the same Gent material (J_m = 20): the
    base state at Vbar = 0.5 agrees to rounding (an independent route: generated code)."""
    tube = ["state", "--outer-radius", "2", "--voltage", "0.5", "--json"]
    assert main([*tube, "--energy", GENT_TEXT]) == 0
    text = json.loads(capsys.readouterr().out)
    assert main([*tube, "--material", "gent", "--jm", "20"]) == 0
    builtin = json.loads(capsys.readouterr().out)
    assert text["lambda_i"] == pytest.approx(builtin["lambda_i"], rel=1e-13)
    assert text["lambda_i"] > 1.01  # a loaded state, not the reference one


@pytest.mark.parametrize(
    "argv",
    [
        ["--energy", "--stretch", "2"],  # a forgotten value is not the next option
        ["--energy", "-h"],
        ["--energy"],
    ],
)
def test_an_option_is_never_taken_as_a_value(capsys, argv):
    assert main(["state", "--outer-radius", "2", *argv]) == 2
    assert "argument --energy: expected one argument" in capsys.readouterr().err


def test_an_abbreviated_option_takes_its_dashed_value_too():
    args = build_parser("state").parse_args(["state", "--outer-radius", "2", "--ener", GENT_TEXT])
    assert args.energy == GENT_TEXT


@pytest.mark.parametrize("exists", [True, False])
@pytest.mark.parametrize(
    "argv",
    [["sweep", "-x.toml"], ["sweep", "--check", "-x.toml"], ["plot", "-x.toml"]],
)
def test_a_file_named_like_an_option_is_refused_naming_it_and_the_remedy(
    capsys, monkeypatch, tmp_path, argv, exists
):
    """Check round 29 ("Left out"): `sweep -x.toml` said "the following arguments are
    required: SWEEP.toml", naming neither the word nor the remedy. The word is refused
    whether or not such a file exists (a mistyped option must not run on a file that
    happens to be there), in one line that names it and says how to give a file."""
    monkeypatch.chdir(tmp_path)
    if exists:
        (tmp_path / "-x.toml").write_text("")
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("electrogrowth: error: -x.toml is not an")
    assert "./-x.toml" in err and "--" in err
    assert ("to give the file -x.toml" in err) == exists


def test_a_file_named_like_an_option_is_read_after_dashes_or_dot_slash(
    capsys, monkeypatch, tmp_path
):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "-x.toml").write_text("[grid]\nouter_radius = [2, 3]\n")  # no [solve]
    for argv in (["sweep", "--check", "--", "-x.toml"], ["sweep", "--check", "./-x.toml"]):
        assert main(argv) == 2
        assert "-x.toml: solve: missing key 'for'" in capsys.readouterr().err  # it was read


def test_an_unknown_option_is_named_without_a_file_hint_where_no_file_is_meant(capsys):
    assert main(["critical", "--bogus"]) == 2
    err = capsys.readouterr().err
    assert (
        err == "electrogrowth: error: --bogus is not an option of critical (see"
        " electrogrowth critical --help)\n"
    )
