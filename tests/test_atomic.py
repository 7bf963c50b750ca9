"""Output files: --out naming an existing file is one clear error (was FileExistsError), two
commands writing the same CSV leave a whole file, and an interrupted write leaves the
previous file as it was."""

import os
import threading
from pathlib import Path

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.atomic import replaced
from electrogrowth.bifurcation.curves import _curve
from electrogrowth.cli import app as cli
from electrogrowth.outcomes import NO_MODE, Kind


@pytest.mark.parametrize("under", ["", "/sub"])
def test_out_naming_a_file_is_one_clear_error(tmp_path, capsys, under):
    tube = tmp_path / "tube.toml"
    tube.write_text("length = 1.0\n")
    assert cli.main(["reproduce", "--quick", "--out", f"{tube}{under}"]) == 2
    err = capsys.readouterr().err
    assert err == (
        f"electrogrowth: error: {tube} is an existing file, not a directory: give --out a"
        " directory (new or existing), not a file\n"
    )
    assert tube.read_text() == "length = 1.0\n"


@pytest.mark.parametrize("under", ["", "/sub"])
def test_out_naming_a_dangling_link_says_so(tmp_path, capsys, under):
    """Probe 8b: a dangling symbolic link was called "an existing file" (it is neither a
    file nor a directory)."""
    link = tmp_path / "dangling"
    link.symlink_to(tmp_path / "nowhere" / "x")
    assert cli.main(["reproduce", "--quick", "--out", f"{link}{under}"]) == 2
    err = capsys.readouterr().err
    assert err == (
        f"electrogrowth: error: {link} is a dangling symbolic link (to {tmp_path}/nowhere/x,"
        " which does not exist), not a directory: give --out a directory (new or existing)\n"
    )
    assert not (tmp_path / "nowhere").exists()


def test_out_naming_a_fifo_says_so(tmp_path, capsys):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    assert cli.main(["reproduce", "--quick", "--out", str(fifo)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{fifo} is a named pipe (FIFO), not a directory" in err


def _a_curve(rows: int, value: float):
    row = (0.0, value, NO_MODE, Kind.THRESHOLD, "", False, np.nan, "", None)
    rows = [(float(i), *row[1:]) for i in range(rows)]
    return _curve("voltage", "growth", None, Tube.uniform(1.4), rows, [])


def test_two_writers_of_one_csv_leave_a_whole_file(tmp_path):
    path = tmp_path / "out" / "curve.csv"
    curves = [_a_curve(2000, 1.5), _a_curve(3000, 2.5)]
    whole = []
    for i, curve in enumerate(curves):
        whole.append(curve.to_csv(tmp_path / f"ref{i}.csv").read_text())

    def write(curve):
        for _ in range(20):
            curve.to_csv(path)

    threads = [threading.Thread(target=write, args=(c,)) for c in curves]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert path.read_text() in whole
    assert [p.name for p in path.parent.iterdir()] == ["curve.csv"]  # no temporary left


def test_an_interrupted_write_keeps_the_previous_file(tmp_path):
    path = tmp_path / "curve.csv"
    path.write_text("the finished curve\n")
    with pytest.raises(KeyboardInterrupt), replaced(path) as fh:
        fh.write("half a ")
        raise KeyboardInterrupt
    assert path.read_text() == "the finished curve\n"
    assert [p.name for p in tmp_path.iterdir()] == ["curve.csv"]


def test_a_figure_stopped_while_saving_keeps_its_previous_files(tmp_path):
    """FigureResult.save writes the PNG and the CSV whole or not at all: a drawing that fails
    (or is interrupted) leaves the previous fig<N>.png as it was and no temporary file."""
    import numpy as np
    from matplotlib.figure import Figure

    from electrogrowth.figures.style import FigureResult

    fig = Figure()
    fig.add_subplot().plot([0, 1], [0, 1])
    result = FigureResult(99, ("x", "y"), np.array([[0.0, 1.0], [1.0, 2.0]]), fig, {})
    png, csv = result.save(tmp_path)
    before = png.read_bytes()
    assert csv.read_text() == "x,y\n0,1\n1,2\n"

    def broken(target, **kwargs):  # half a file written, then Ctrl-C
        if hasattr(target, "write"):
            target.write(b"half a png")
        else:
            Path(target).write_bytes(b"half a png")
        raise KeyboardInterrupt

    fig.savefig = broken
    with pytest.raises(KeyboardInterrupt):
        result.save(tmp_path)
    assert png.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig99.csv", "fig99.png"]


def test_every_command_output_is_written_whole(tmp_path):
    """curve, design, pattern, postbuckle, sweep plots, demo and the viewers wrote their PNGs,
    VTK and netCDF files in place: a Ctrl-C while saving left half a file where the last
    complete one was (docs/reliability.md, Left out). They go through atomic.py now: a
    figure or a name-taking writer (meshio, netCDF) that fails leaves the previous file."""
    from matplotlib.figure import Figure

    from electrogrowth.atomic import replaced_name, write_figure, write_text

    fig = Figure()
    fig.add_subplot().plot([0, 1], [0, 1])
    png = write_figure(fig, tmp_path / "a.png")
    svg = write_figure(fig, tmp_path / "a.svg")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and b"<svg" in svg.read_bytes()
    before = png.read_bytes()

    def broken(target, **kwargs):
        target.write(b"half a png")
        raise KeyboardInterrupt

    fig.savefig = broken
    with pytest.raises(KeyboardInterrupt):
        write_figure(fig, png)
    assert png.read_bytes() == before
    with pytest.raises(KeyboardInterrupt), replaced_name(tmp_path / "b.vtu") as name:
        assert name.endswith(".vtu")  # writers choose their format by the suffix
        Path(name).write_text("half a mesh")
        raise KeyboardInterrupt
    assert write_text(tmp_path / "c.json", "{}").read_text() == "{}"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png", "a.svg", "c.json"]


def test_no_command_writes_in_place():
    """The writers of the package's outputs (savefig, meshio.write, to_netcdf, write_text)
    are called only through atomic.py: a new one in place would come back unnoticed."""
    import re

    src = Path(__file__).resolve().parents[1] / "src" / "electrogrowth"
    # (a call broken after its parenthesis is not read: its argument is on the next line)
    in_place = re.compile(r"\.savefig\((?!fh\b|$)|meshio\.write\((?!name\b|$)|"
                          r"\.to_netcdf\((?!name\b|$)|\.write_text\(")  # fmt: skip
    found = [
        f"{p.relative_to(src)}:{n}"
        for p in src.rglob("*.py")
        if p.name != "atomic.py"
        for n, line in enumerate(p.read_text().splitlines(), 1)
        if in_place.search(line) and not line.lstrip().startswith(("#", '"', "Off-screen"))
    ]
    assert not found, found


@pytest.mark.parametrize("command", ["reproduce --quick", "demo --quick"])
def test_an_empty_out_is_refused(command, capsys):
    """Probe 11b (doubt): `--out ''` wrote into the current directory without a word."""
    assert cli.main([*command.split(), "--out", ""]) == 2
    err = capsys.readouterr().err
    assert "argument --out: '' is an empty path" in err and err.count("\n") == 1
