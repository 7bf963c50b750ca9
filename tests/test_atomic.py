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
    row = (0.0, value, NO_MODE, Kind.THRESHOLD, "", False, np.nan)
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
