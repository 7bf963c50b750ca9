"""The sweep file: every mistake is rejected before any work, naming the line and the
reason, with exit status 2 and nothing written."""

import pytest

from electrogrowth.cli import app as cli
from electrogrowth.cli import sweep as cli_sweep
from electrogrowth.errors import ConfigError
from electrogrowth.sweep.config import SweepConfig, differences
from electrogrowth.sweep.file import line_of, parse_config

GOOD = """\
[solve]
for = "voltage"
rtol = 1e-10

[modes]
m = [0, 3]
n = [1, 3]
extend = false

[material]
name = "gent"
jm = 97.2

[fixed]
length = 1.0

[grid]
stretch = {start = 1.0, stop = 1.4, num = 3}
outer_radius = [1.6, 1.4]
"""


def edit(line: int, new: str) -> str:
    """GOOD with line ``line`` (1-based) replaced by ``new``."""
    lines = GOOD.splitlines()
    lines[line - 1] = new
    return "\n".join(lines) + "\n"


@pytest.fixture
def sweep(monkeypatch, tmp_path, capsys):
    """Run `electrogrowth sweep FILE --out STORE` on a text; return (status, stderr, store)."""
    monkeypatch.setitem(
        cli.COMMANDS, "sweep", ("sweep", cli_sweep.configure_sweep, cli_sweep.run_sweep)
    )

    def run(text):
        path, out = tmp_path / "bad.toml", tmp_path / "bad.zarr"
        path.write_text(text)
        status = cli.main(["sweep", str(path), "--out", str(out), "--quiet"])
        return status, capsys.readouterr().err, out

    return run


def test_good_file_is_normalised():
    c = parse_config(GOOD)
    assert c.dims == ("stretch", "outer_radius") and c.shape == (3, 2)
    assert c.grid[1] == ("outer_radius", (1.4, 1.6))  # sorted
    assert dict(c.fixed) == {"length": 1.0, "growth": 1.0}  # solved-for voltage left out
    assert c.material == ("gent", (("jm", 97.2),)) and c.chunk == 1
    assert c.spec.options.m_range == (0, 3) and c.spec.rtol == 1e-10
    assert not c.spec.options.extend
    assert SweepConfig.from_dict(c.to_dict()) == c
    other = parse_config(GOOD.replace("num = 3", "num = 4").replace("97.2", "50"))
    assert differences(c, other) == ["material.jm", "grid.stretch"]


@pytest.mark.parametrize(
    "text, line, needle",
    [
        (edit(8, "extnd = false"), 8, "modes.extnd: unknown key; [modes] takes m, n, extend"),
        (GOOD + "\n[output]\npath = 'x'\n", 21, "output: unknown key"),
        (edit(3, 'rtol = "1e-10"'), 3, "solve.rtol: expected a number, got a string"),
        (edit(3, "rtol = 1.0"), 3, "rtol = 1.0 is out of range"),
        (edit(2, "for = "), 2, "invalid TOML"),
        (edit(2, 'for = "heat"'), 2, "'heat' is unknown"),
        (edit(2, 'for = "growth"\nside = "extension"'), 3, "side applies only"),
        (edit(6, "m = [3, 0]"), 6, "modes.m: m range [3, 0] is invalid"),
        (edit(7, "n = [1.5, 3]"), 7, "modes.n: expected an inclusive range"),
        (edit(11, 'name = "rubber"'), 11, "unknown material 'rubber'"),
        (edit(12, "alpha = 0.5"), 12, "material.alpha: unknown key; material 'gent' takes jm"),
        (edit(12, "jm = -1"), 12, "Gent parameter jm = -1.0 is invalid"),
        (edit(15, "length = 0"), 15, "fixed.length: length L = 0.0 is out of range"),
        (edit(15, "voltage = 0.1"), 15, "fixed.voltage: voltage is what is solved for"),
        (edit(15, "stretch = 1.0"), 15, "fixed.stretch: stretch is also swept"),
        (edit(18, "stretch = []"), 18, "grid.stretch: empty grid"),
        (edit(18, "stretch = {start = 1.0, stop = 1.4, num = 0}"), 18, "num = 0 gives an empty"),
        (edit(18, "stretch = {start = 1.0, stop = 1.4}"), 18, "num is missing"),
        (edit(18, "stretch = [1.0, 1.0]"), 18, "the value 1.0 appears twice"),
        (edit(18, 'stretch = [1.0, "1.2"]'), 18, "value 2 is a string"),
        (edit(19, "outer_radius = [0.5, 1.6]"), 19, "outer radius Rbar_o = 0.5 is out of range"),
        (edit(19, "voltage = [0.1, 0.2]"), 19, "grid.voltage: voltage is what is solved for"),
        (edit(19, "radius = [1.4]"), 19, "grid.radius: unknown key; [grid] takes outer_radius"),
        (edit(19, "# no outer radius"), 14, "missing outer_radius"),
        (edit(17, "[grids]"), 17, "grids: unknown key"),
    ],
)
def test_bad_file_names_line_and_reason_and_writes_nothing(sweep, text, line, needle):
    status, err, out = sweep(text)
    assert status == 2 and err.count("\n") == 1 and "Traceback" not in err
    assert f"bad.toml:{line}: " in err, err
    assert needle in err, err
    assert not out.exists() and not list(out.parent.glob(".bad.zarr*"))


def test_empty_grid_table_is_rejected():
    text = GOOD.split("[grid]")[0].replace("length = 1.0", "outer_radius = 1.4") + "[grid]\n"
    with pytest.raises(ConfigError, match=r"^<sweep>:17: grid: nothing to sweep"):
        parse_config(text)


def test_unreadable_file_is_one_line(sweep, tmp_path, capsys):
    status = cli.main(["sweep", str(tmp_path / "missing.toml")])
    err = capsys.readouterr().err
    assert status == 2 and "missing.toml: cannot read the sweep file" in err


@pytest.mark.parametrize(
    "key, line",
    [
        (("fixed", "length"), 1),
        (("grid", "stretch", "num"), 4),
        (("modes",), 6),
        (("modes", "top"), 6),
        (("modes", "m"), 7),
        (("absent",), None),
    ],
)
def test_line_of_follows_tables_and_inline_tables(key, line):
    text = (
        "fixed.length = 0\n# comment\n[grid]\nstretch = {start = 1, stop = 2, num = 0}\n"
        '\n[ modes ]\n"m" = [0, 1]\n'
    )
    assert line_of(text, key) == line
