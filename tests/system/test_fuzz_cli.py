"""A fuzz target for the command line: every command, every option, malformed tube and sweep
files. Each command line must exit 0 with finite output, or exit 2 with exactly one line
``electrogrowth: error: ...`` on stderr: never a traceback, an internal error (exit 1), a NaN
or an inf in the output. The lines are drawn on a fixed seed, so a failure reproduces; the
``slow`` variant draws many more.
"""

import random
import re
from pathlib import Path

import pytest

from electrogrowth.cli import app as cli
from electrogrowth.cli import sweep as cli_sweep

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SEED = 20261202

#: Values that are wrong for most options: not numbers, not finite, out of range, huge.
BAD = [
    "", " ", "nan", "-nan", "inf", "-inf", "Infinity", "1e400", "-1e400", "1e-400", "-1",
    "-0", "0", "1e20", "-1e20", "1" * 400, "-" + "9" * 400, "abc", "1,5", "0x10", "1e", "--",
    "2.5.1", "\u00bd", "١", "1_000", "+-1", "None", "true",
]  # fmt: skip
#: Legal values of the numeric options, extreme ones included.
NUMBERS = {
    "--outer-radius": ["1.4", "1.02", "5", "2", "1.0001", "99", "100.5", "1"],
    "--growth": ["1", "1.2", "0.8", "0.01", "1e-3", "50", "150"],
    "--stretch": ["1", "1.1", "0.9", "0.5", "2", "0.02", "60"],
    "--voltage": ["0", "0.2", "0.4", "1.5", "100"],
    "--length": ["1", "0.5", "3", "0.01", "1000", "2000"],
    "--jm": ["97.2", "10", "2", "0.5", "1e6"],
    "--alpha": ["0.5", "1", "0.1", "1.5"],
    "--m-max": ["0", "3", "12", "64", "2000", "2001", "1000001"],
    "--n-max": ["1", "3", "30", "2000", "2001", "1000001"],
    "--top": ["1", "3", "0", "-1", "1001", "1000000000000"],
    "--rtol": ["1e-8", "1e-12", "1e-3", "1e-16", "0"],
    "--inner-pressure": ["0", "0.05", "-0.1", "10"],
    "--outer-pressure": ["0", "0.05", "5"],
    "--axial-force": ["0", "0.5", "-3"],
    "--points": ["2", "5", "1", "0", "100000000", "10001", "1000000000000"],
    "--amplitude": ["0", "0.1", "-1", "1e9"],
    "--from": ["0", "0.1", "1"],
    "--to": ["0.2", "0.4", "1.2"],
    "--workers": ["1", "0", "-2", "1000000"],
}
CHOICES = {
    "--solve-for": ["growth", "stretch", "voltage", "pressure"],
    "--side": ["compression", "extension", "both"],
    "--material": ["neo-hookean", "gent", "mooney-rivlin", "rubber"],
    "--method": ["impedance", "collocation", "fem"],
    "--family": ["wrinkle", "prismatic", "torsional", "spiral"],
    "--along": ["voltage", "stretch", "growth", "length"],
}
#: Cheap valid command lines (seconds at most), the fuzz's starting points.
SEEDS = [
    "state --outer-radius 1.4",
    "state --outer-radius 2 --growth 1.2 --voltage 0.3 --material gent --jm 10",
    "state --outer-radius 1.5 --stretch 1.2 --voltage 0.2 --material mooney-rivlin --alpha 0.3",
    "state --tube {tube}",
    "state --tube {tube} --voltage 0.2 --json",
    "critical --solve-for voltage --outer-radius 1.4 --mode 1 1 --rtol 1e-8",
    "critical --solve-for growth --outer-radius 1.4 --voltage 0.4 --mode 0 1 --rtol 1e-8",
    "critical --solve-for stretch --outer-radius 1.6 --mode 2 1 --rtol 1e-8 --json",
    "critical --solve-for stretch --side extension --outer-radius 1.6 --mode 0 1 --rtol 1e-8",
    "sweep {sweep} --check --out {tmp}/s.zarr",
    "plot {tmp}/missing.zarr --out {tmp}",
    "figure 99 --out {tmp}",
    "curve --solve-for growth --along voltage --from 0 --to 0.4 --outer-radius 1.4 --out {tmp}/c",
    "pattern --solve-for growth --outer-radius 1.4 --mode 2 1 --out {tmp}/p",
    "reproduce --quick --out {tmp}/r",
    "demo --out {tmp}/d",
    "curve --tube {tube} --solve-for growth --layer 1 --along layers[1].thickness --from -0.05"
    " --to 0.2 --out {tmp}/c",
    "curve --tube {tube} --solve-for growth --layer 2 --along layers[2].outer_radius --from 0.5"
    " --to 3 --out {tmp}/c",
    "curve --tube {tube} --solve-for growth --layer 1 --along stretch[2] --from 1 --to 2"
    " --out {tmp}/c",
    "reproduce --quick --out {tube}",
    "reproduce --quick --out {tube}/sub",
]
#: Commands that compute for minutes when valid: each line of theirs ends refused.
REFUSED_LAST = {
    "curve": ["--points", "1"],
    "pattern": ["--points", "1"],
    "reproduce": ["--figures", "99"],
    "demo": ["--bogus"],
}


def _mutate_toml(text: str, rng: random.Random) -> str:
    """A malformed (or merely unusual) TOML file made from a valid one."""
    lines = text.splitlines()
    keyed = [i for i, line in enumerate(lines) if "=" in line and not line.startswith("#")]
    op = rng.randrange(9)
    i = rng.choice(keyed)
    key = lines[i].split("=")[0]
    if op == 0:
        del lines[i]
    elif op == 1:
        lines[i] = f"{key}= {rng.choice(BAD)!r}"
    elif op == 2:
        huge = ["1000000000000", "{start = 1.0, stop = 2.0, num = 1000000000000}"]
        lines[i] = (
            f"{key}= {rng.choice(['nan', 'inf', '-inf', '1e400', '-5', '0', '[]', '{}'] + huge)}"
        )
    elif op == 3:
        lines.insert(i, lines[i])  # a duplicate key
    elif op == 4:
        lines.insert(i, "unknown_key = 1")
    elif op == 5:
        lines[i] = lines[i].replace("=", "", 1)  # a syntax error
    elif op == 6:
        lines = lines[: rng.randrange(len(lines))]  # truncated
    elif op == 7:
        lines[i] = f'{key}= "{rng.choice(["(I1 - 3)", "(I1 - 3) + I5/2", "I9", "import os"])}"'
    else:
        lines[i] = lines[i] + " " + rng.choice(["]", "[", "= 2", '"'])
    return "\n".join(lines) + "\n"


def _command_line(rng: random.Random, tmp: Path, case: int) -> list[str]:
    tube = tmp / f"tube{case}.toml"
    sweep = tmp / f"sweep{case}.toml"
    tube.write_text(
        _mutate_toml((EXAMPLES / "bilayer.toml").read_text(), rng)
        if rng.random() < 0.5
        else (EXAMPLES / "bilayer.toml").read_text()
    )
    sweep.write_text(
        _mutate_toml((EXAMPLES / "sweep.toml").read_text(), rng)
        if rng.random() < 0.7
        else (EXAMPLES / "sweep.toml").read_text()
    )
    argv = rng.choice(SEEDS).format(tube=tube, sweep=sweep, tmp=tmp).split()
    for _ in range(rng.choice([0, 1, 1, 2, 3])):
        op = rng.randrange(6)
        flags = [i for i, a in enumerate(argv) if a.startswith("--") and i + 1 < len(argv)]
        if op == 0 and flags:  # a bad value for an option that has one
            i = rng.choice(flags)
            if not argv[i + 1].startswith("--"):
                argv[i + 1] = rng.choice(BAD)
        elif op == 1:  # another option, with a legal or extreme value
            flag = rng.choice(sorted(NUMBERS))
            argv += [flag, rng.choice(NUMBERS[flag] + [rng.choice(BAD)])]
        elif op == 2:
            flag = rng.choice(sorted(CHOICES))
            argv += [flag, rng.choice(CHOICES[flag])]
        elif op == 3 and flags:  # an option without its value
            del argv[rng.choice(flags) + 1]
        elif op == 4:
            argv += [rng.choice(["--mode", "--mode", "--certify", "--json", "--quiet", "--x"])]
            if argv[-1] == "--mode":
                argv += [rng.choice(["0", "1", "3", "2", "-1", "1e20", "1" * 50]) for _ in "mn"]
        else:
            argv.insert(rng.randrange(1, len(argv) + 1), rng.choice(BAD + ["--bogus"]))
    if argv[0] == "critical" and "--mode" not in argv:  # keep every line seconds at most
        argv += ["--mode", "1", "1"]
    return argv + REFUSED_LAST.get(argv[0], [])


def _check(argv, code, out, err) -> None:
    where = f"electrogrowth {' '.join(argv)!r}"
    assert "Traceback" not in out + err, where
    if code == 3:  # a critical value not certified to --rtol: printed, and one warning
        lines = err.strip().splitlines()
        assert len(lines) == 1 and "not certified" in lines[0], (where, err)
    if code in (0, 3):
        for arg in argv:  # a path the user named (e.g. --out -nan) is echoed as given
            if not arg[-1:].isdigit():
                out = out.replace(arg, "")
        words = set(re.findall(r"[A-Za-z]+", out.lower()))
        assert not words & {"nan"}, f"{where}: NaN in the output"
        finite = [line for line in out.splitlines() if re.search(r"\binf\b", line.lower())]
        assert all("threshold" in line for line in finite), f"{where}: inf in {finite}"
    else:
        assert code == 2, f"{where}: exit {code}: {err}"
        lines = err.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("electrogrowth: error: "), (where, err)
        assert not re.search(r"\bnan\b", lines[0].lower()) or "nan" in " ".join(argv), where


def run_fuzz(count: int, tmp: Path, capsys, monkeypatch) -> dict:
    monkeypatch.setitem(
        cli.COMMANDS, "sweep", ("sweep", cli_sweep.configure_sweep, cli_sweep.run_sweep)
    )
    monkeypatch.setitem(
        cli.COMMANDS, "plot", ("plot", cli_sweep.configure_plot, cli_sweep.run_plot)
    )
    rng = random.Random(SEED)
    tally = {0: 0, 2: 0, 3: 0}
    for case in range(count):
        argv = _command_line(rng, tmp, case)
        code = cli.main(argv)
        out, err = capsys.readouterr()
        _check(argv, code, out, err)
        tally[code] += 1
    return tally


def test_cli_fuzz(tmp_path, capsys, monkeypatch):
    tally = run_fuzz(60, tmp_path, capsys, monkeypatch)
    assert tally[0] >= 5 and tally[2] >= 20  # both outcomes are exercised


@pytest.mark.slow
def test_cli_fuzz_long(tmp_path, capsys, monkeypatch):
    tally = run_fuzz(600, tmp_path, capsys, monkeypatch)
    assert tally[0] >= 50 and tally[2] >= 200


#: Lines a fuzz found BAD (traceback, internal error, several stderr lines, a MemoryError or
#: a run of hours), each now exit 2 with one line: {bilayer} is examples/bilayer.toml,
#: {tiny} the same with layer 2's growth 1e-9, {sweep} a sweep of num = 10^12.
REGRESSIONS = [
    # a denormal growth of a layer: RuntimeWarnings and an internal error at the plot
    "curve --tube {bilayer} --solve-for pressure --along growth[2] --from 0.9999999 --to 5e-324"
    " --points 2 --m-max 1 --n-max 2 --out {tmp}/c",
    # "no unloaded state" blamed on inner_pressure, after four RuntimeWarnings
    "state --tube {tiny}",
    # "outer_radius = 0.95 is out of range" for a thickness
    "curve --tube {bilayer} --solve-for growth --layer 1 --along layers[1].thickness"
    " --from -0.05 --to 0.2 --points 3 --out {tmp}/c",
    # FileExistsError from mkdir
    "reproduce --quick --out {bilayer}",
    # MemoryError (745 GiB, 7.28 TiB)
    "curve --solve-for growth --along voltage --from 0 --to 0.4 --outer-radius 1.4"
    " --points 100000000000 --out {tmp}/c",
    "sweep {sweep} --check --out {tmp}/s.zarr",
    # ran for minutes
    "pattern --solve-for growth --outer-radius 1.4 --mode 2 1 --points 1000000000 --out {tmp}/p",
]


@pytest.mark.parametrize("line", REGRESSIONS)
def test_cli_fuzz_regressions(line, tmp_path, capsys):
    bilayer = EXAMPLES / "bilayer.toml"
    tiny = tmp_path / "tiny.toml"
    tiny.write_text(bilayer.read_text().replace("growth = 1.0\n", "growth = 1e-9\n"))
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(
        (EXAMPLES / "sweep.toml").read_text().replace("num = 11", "num = 1000000000000")
    )
    argv = line.format(bilayer=bilayer, tiny=tiny, sweep=sweep, tmp=tmp_path).split()
    code = cli.main(argv)
    out, err = capsys.readouterr()
    _check(argv, code, out, err)
    assert code == 2
