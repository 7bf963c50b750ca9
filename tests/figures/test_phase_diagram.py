"""The phase diagram of a sweep: mode regions, threshold boundary, PNG and SVG."""

import math

import numpy as np
import pytest

pytest.importorskip("xarray")
pytest.importorskip("zarr")

from electrogrowth.cli import app as cli  # noqa: E402
from electrogrowth.cli import sweep as cli_sweep  # noqa: E402
from electrogrowth.figures.phase_diagram import (  # noqa: E402
    THRESHOLD,
    boundaries,
    cell_edges,
    outcomes,
    phase_diagram,
    regions,
    select_plane,
)
from electrogrowth.sweep.file import parse_config  # noqa: E402
from electrogrowth.sweep.store import open_results, open_store  # noqa: E402
from electrogrowth.sweep.unit import ChunkResult, PointResult  # noqa: E402

TOML = """\
[solve]
for = "growth"
[fixed]
outer_radius = 1.4
[grid]
stretch = [1.0, 1.1, 1.2, 1.3]
voltage = [0.0, 0.2, 0.4]
length = [1.0, 2.0]
[run]
chunk = 6
"""


def fake(stretch, voltage, length):
    """Modes (0, 1) then (2, 1) with the stretch, the threshold at the highest voltage, one
    failure."""
    if voltage == 0.4:
        return PointResult("ok", value=1.5 - stretch / 10, kind="threshold", seconds=0.0)
    if (stretch, voltage) == (1.3, 0.2):
        return PointResult("failed", message="ConvergenceError: no", seconds=0.0)
    m = 0 if stretch < 1.15 else 2
    return PointResult(
        "ok",
        value=1.2 + voltage + length / 10,
        m=m,
        n=1,
        kind="bifurcation",
        error_estimate=1e-11,
        runners_up=((1, 1, 1.9),),
        seconds=0.0,
    )


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    """A store filled with the fake results (no computation), written chunk by chunk."""
    config = parse_config(TOML)
    out = tmp_path_factory.mktemp("plot") / "fake.zarr"
    st = open_store(out, config)
    axes = dict(config.grid)
    for index, block in enumerate(st.blocks):
        pts = [
            fake(axes["stretch"][i], axes["voltage"][j], axes["length"][k])
            for i, j, k in np.ndindex(*(s.stop - s.start for s in block))
            for i, j, k in [(i + block[0].start, j + block[1].start, k + block[2].start)]
        ]
        st.write_chunk(
            ChunkResult(index, tuple((s.start, s.stop) for s in block), tuple(pts)), run=1
        )
    return out


def test_regions_and_threshold_boundary(store):
    ds = open_results(store)
    plane = select_plane(ds, "stretch", "voltage", {"length": 1.9})
    assert plane["critical_value"].dims == ("voltage", "stretch")
    assert float(plane["length"]) == 2.0  # nearest grid value
    labels = outcomes(plane)
    found = {
        r.label: r.cells for r in regions(labels, plane["stretch"].values, plane["voltage"].values)
    }
    assert found == {(0, 1): 4, (2, 1): 3, THRESHOLD: 4, "failed": 1}
    segs, thr = boundaries(labels, cell_edges(plane["stretch"]), cell_edges(plane["voltage"]))
    assert len(thr) == 4 and len(segs) == 4
    assert all(math.isclose(y, 0.3) for seg in thr for _, y in seg)  # between V = 0.2, 0.4


def test_phase_diagram_figure_is_labelled(store):
    fig = phase_diagram(open_results(store), "stretch", "voltage")
    ax = fig.axes[0]
    texts = {t.get_text() for t in ax.texts}
    assert {"m=0, n=1", "m=2, n=1", "threshold", "failed"} <= texts
    assert "axial stretch" in ax.get_xlabel() and "voltage" in ax.get_ylabel()
    assert "critical growth factor" in fig.axes[1].get_ylabel()  # the colour bar
    assert "L/Rᵢ = 1" in ax.get_title()


def test_plot_command_writes_png_and_svg(store, tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(
        cli.COMMANDS, "plot", ("plot", cli_sweep.configure_plot, cli_sweep.run_plot)
    )
    assert (
        cli.main(
            [
                "plot",
                str(store),
                "--x",
                "stretch",
                "--y",
                "voltage",
                "--at",
                "length=2",
                "--out",
                str(tmp_path),
            ]
        )
        == 0
    )
    printed = capsys.readouterr().out.split()
    png, svg = tmp_path / "fake_stretch_voltage.png", tmp_path / "fake_stretch_voltage.svg"
    assert printed == [str(png), str(svg)]
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10_000
    assert svg.read_text()[:200].lstrip().startswith("<?xml") and "<svg" in svg.read_text()


@pytest.mark.parametrize(
    "extra, needle",
    [
        (["--x", "radius"], "--x 'radius' is not a swept parameter"),
        (["--x", "stretch", "--y", "stretch"], "both 'stretch'"),
        (["--at", "voltage=0.2"], "--at voltage: not a further swept parameter"),
        (["--at", "length"], "expected PARAM=VALUE"),
        (["--at", "length=abc"], "the value 'abc' is not a number"),
    ],
)
def test_plot_command_rejects_bad_axes(store, tmp_path, monkeypatch, capsys, extra, needle):
    monkeypatch.setitem(
        cli.COMMANDS, "plot", ("plot", cli_sweep.configure_plot, cli_sweep.run_plot)
    )
    assert cli.main(["plot", str(store), "--out", str(tmp_path)] + extra) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and needle in err
    assert not list(tmp_path.glob("*.png"))


def test_plot_of_a_non_store_is_one_line(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(
        cli.COMMANDS, "plot", ("plot", cli_sweep.configure_plot, cli_sweep.run_plot)
    )
    (tmp_path / "x.zarr").mkdir()
    assert cli.main(["plot", str(tmp_path / "x.zarr")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "is not an electrogrowth sweep store" in err
    # a reader's remedy, said once (it gave the sweep's advice, twice for an existing file)
    assert err.count("(") == 1 and "written by electrogrowth sweep FILE --out STORE" in err
    assert cli.main(["plot", str(tmp_path / "missing.zarr")]) == 2
    assert "written by electrogrowth sweep" in capsys.readouterr().err


def test_a_tube_unstable_from_the_start_is_labelled_so_not_failed():
    """A point whose tube is already unstable at the start of the march (g = 1) is
    recorded as failed with the march's message; its cell says so, in the control's
    symbol. Other failures stay "failed"."""
    import xarray as xr

    unstable = (
        "ParameterError: the tube is already unstable in mode (0, 1) (axisymmetric) at"
        " growth = 1; start from a stable state"
    )
    status = [["ok", "failed"], ["failed", "pending"]]
    message = [["", unstable], ["ConvergenceError: no", ""]]
    dims = ("voltage", "stretch")
    plane = xr.Dataset(
        {
            "status": (dims, np.array(status, dtype=object)),
            "message": (dims, np.array(message, dtype=object)),
            "kind": (dims, np.array([["bifurcation", ""], ["", ""]], dtype=object)),
            "m": (dims, [[0, -1], [-1, -1]]),
            "n": (dims, [[1, -1], [-1, -1]]),
        }
    )
    labels = outcomes(plane)
    assert labels.tolist() == [
        [(0, 1), "already unstable at $g$ = 1"],
        ["failed", "pending"],
    ]


def test_text_of_a_foreign_store_is_drawn_as_text_not_mathtext(store):
    """A store's title and labels are someone else's text: '$...$' in them is drawn as it
    is (matplotlib's mathtext parser ended the plot with an internal error on a malformed
    one)."""
    import io

    ds = open_results(store)
    ds.attrs["title"] = r"tampered $\foo{ title"
    ds["length"].attrs["symbol"] = r"$\bar{"
    fig = phase_diagram(ds, "stretch", "voltage")
    fig.savefig(io.BytesIO(), format="png")  # drawing is where mathtext would fail
    assert r"tampered \$\foo{ title" in fig.axes[0].get_title()


def test_an_axis_over_decades_is_logarithmic(store):
    """Moduli 1e-3 .. 1e-1 on a geometric grid were drawn on a linear axis, the low rows'
    cells (and labels) collapsed together (probe round 7b): such an axis is logarithmic,
    its cells' edges the geometric means of their neighbours."""
    from electrogrowth.figures.phase_diagram import axis_edges, logarithmic

    geometric = np.geomspace(1e-3, 1e-1, 5)
    edges, log = axis_edges(geometric)
    assert log and np.allclose(edges[1:-1], np.sqrt(geometric[1:] * geometric[:-1]), rtol=1e-12)
    assert not logarithmic(np.linspace(1e-3, 1e-1, 5))  # even steps: linear
    assert not logarithmic(np.geomspace(1.0, 10.0, 5))  # one decade: linear
    assert not logarithmic(np.array([-1.0, 0.1, 10.0, 1000.0]))
    ds = open_results(store).assign_coords(voltage=np.geomspace(1e-3, 1e-1, 3))
    ax = phase_diagram(ds, "stretch", "voltage").axes[0]
    assert ax.get_yscale() == "log" and ax.get_xscale() == "linear"
