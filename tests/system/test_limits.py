"""Resource limits: a huge grid, point count, mode count or worker count is refused up front
(one line naming the limit, exit 2), before any allocation, never a MemoryError or a run of
days."""

import pytest

from electrogrowth.bifurcation.curves import critical_curve
from electrogrowth.bifurcation.scan import ScanOptions
from electrogrowth.cli import app as cli
from electrogrowth.errors import ConfigError, ParameterError
from electrogrowth.model.layers import Tube
from electrogrowth.sweep.file import parse_config

SWEEP = """\
[solve]
for = "growth"
[modes]
top = {top}
[fixed]
outer_radius = 1.4
[grid]
voltage = {{start = 0.0, stop = 0.3, num = {num}}}
{more}
"""
CURVE = "curve --solve-for growth --along voltage --from 0 --to 0.4 --outer-radius 1.4"
PATTERN = "pattern --solve-for growth --outer-radius 1.4 --mode 2 1"


@pytest.mark.parametrize(
    "num, top, more, message",
    [
        (10**12, 5, "", "grid.voltage.num: num = 1000000000000 is out of range; need 1 <= num"
         " <= 1000000"),
        (10**6, 5, "length = {start = 1.0, stop = 2.0, num = 11}", "grid: 1.1e+07 grid points,"
         " more than the limit 1e+07"),
        (1, 10**12, "", "modes.top: top = 1000000000000 is invalid; need an integer from 1 to"
         " 1000"),
        (10**6, 500, "", "modes.top: top = 500 modes at each of 1,000,000 points is"
         " 500,000,000 mode records; the store holds at most 1e+08"),
    ],
)  # fmt: skip
def test_a_huge_sweep_is_refused_naming_the_limit(num, top, more, message):
    with pytest.raises(ConfigError) as err:
        parse_config(SWEEP.format(num=num, top=top, more=more))
    assert message in str(err.value)


def test_the_largest_sweep_is_accepted():
    config = parse_config(SWEEP.format(num=1000, top=10, more="length = [1.0, 2.0]"))
    assert config.size == 2000


@pytest.mark.parametrize(
    "argv, message",
    [
        (f"{CURVE} --points 100000000000", "--points = 100000000000 is out of range; need 2 to"
         " 10000"),
        (f"{CURVE} --points 1", "--points = 1 is out of range; need 2 to 10000"),
        (f"{PATTERN} --points 1000000000", "--points = 1000000000 is out of range; need 2 to"
         " 10000 radii"),
        ("critical --solve-for growth --outer-radius 1.4 --top 1000000", "argument --top:"
         " '1000000' is not a whole number from 1 to 1000"),
        ("critical --solve-for growth --outer-radius 1.4 --m-max 1000001", "argument --m-max:"
         " '1000001' is not a whole number from 0 to 1000000"),
        ("critical --solve-for growth --outer-radius 1.4 --n-max 99999999999999999999999",
         "argument --n-max: '99999999999999999...' is not a whole number from 1 to 1000000"),
        ("reproduce --gallery --workers 1000000", "--workers 1000000 is out of range; need 1"
         " to"),
    ],
)  # fmt: skip
def test_a_huge_count_on_the_command_line_is_refused(argv, message, capsys):
    assert cli.main(argv.split()) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err


def test_a_huge_sweep_worker_count_is_refused(tmp_path, capsys):
    (tmp_path / "s.toml").write_text(SWEEP.format(num=2, top=5, more=""))
    assert cli.main(["sweep", str(tmp_path / "s.toml"), "--workers", "1000000"]) == 2
    err = capsys.readouterr().err
    assert "--workers 1000000 is out of range; need 1 to" in err and "per usable core" in err


def test_library_limits():
    with pytest.raises(ParameterError, match="need an integer from 1 to 1000"):
        ScanOptions(top=1001)
    with pytest.raises(
        ParameterError, match="non-empty sequence of at most 10000 numbers, got 10001"
    ):
        critical_curve(Tube.uniform(1.4), "growth", "voltage", [0.1] * 10001)
