"""Mode maps over two design variables (src/electrogrowth/design/mode_map.py): the traced
boundaries against bisection of full scans and against the exact Bessel-function buckling
condition of the stretched neo-Hookean tube (tests/design/wilkes.py, derived in
docs/design.md), the triple point's three equalities, the certificates, the records; and the
contour tracer on a curve known in closed form."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from electrogrowth import ScanOptions, Tube, critical_value
from electrogrowth.bifurcation.scan import scan_modes
from electrogrowth.continuation.contour import CLOSED, EDGE, trace_contour
from electrogrowth.design.map_boundaries import _in_order
from electrogrowth.design.mode_map import mode_map
from electrogrowth.errors import ParameterError, UsageError

from .wilkes import critical_stretch

TUBE = Tube.uniform()  # uncharged, ungrown: a homogeneous state under axial compression
NEAR = ScanOptions((0, 1), (1, 1), extend=False)
VARY = (("outer_radius", 1.2, 1.3), ("length", 0.95, 1.05))


@pytest.fixture(scope="module")
def small_map():
    return mode_map(TUBE, "stretch", VARY, side="compression", points=2, options=NEAR, certify=2)


def test_contour_follows_a_circle_and_a_sine_to_the_edge():
    def circle(u):
        return (u[0] - 0.5) ** 2 + (u[1] - 0.4) ** 2 - 0.09

    tr = trace_contour(circle, (0.8, 0.4), (0.0, 1.0))
    pts = np.array(tr.points)
    assert tr.end == CLOSED and len(pts) > 20
    assert np.abs(np.hypot(pts[:, 0] - 0.5, pts[:, 1] - 0.4) - 0.3).max() < 1e-13

    def wave(u):
        return u[1] - 0.3 - 0.2 * math.sin(6 * u[0])

    tr = trace_contour(wave, (0.5, 0.3 + 0.2 * math.sin(3)), (1.0, 0.0))
    pts = np.array(tr.points)
    assert tr.end == EDGE and pts[-1, 0] == 1.0
    assert abs(pts[-1, 1] - (0.3 + 0.2 * math.sin(6))) < 1e-13
    assert max(abs(wave(p)) for p in pts) < 1e-13


def _bessel_switch(y: float, a=(1, 1), b=(0, 1), lo=1.2, hi=1.3) -> float:
    """The outer radius at length y where modes a and b buckle at the same stretch, from
    the Bessel-function determinant alone."""

    def gap(r):
        return critical_stretch(*a, r, y) - critical_stretch(*b, r, y)

    return brentq(gap, lo, hi, xtol=1e-14, rtol=1e-15)


def test_map_has_one_boundary_certified(small_map):
    (b,) = small_map.boundaries
    assert {b.left, b.right} == {(1, 1), (0, 1)} and b.ends == ("edge", "edge")
    assert b.certified and len(b.certificates) == 2
    assert all(c.gap < 1e-8 for c in b.certificates)
    for x, y, v in zip(b.x, b.y, b.value, strict=True):  # every point: both modes critical
        at = TUBE.at("outer_radius", x).at("length", y)
        for mode in ((1, 1), (0, 1)):
            assert abs(critical_value(at, *mode, "stretch", side="compression").value - v) < 1e-8


def test_traced_boundary_equals_the_bessel_switch(small_map):
    """The exact route: at the ends on the box's edges and at an inner point, the outer
    radius where the two Bessel determinants give the same stretch, to 1e-8."""
    (b,) = small_map.boundaries
    k = len(b.x) // 2
    for i in (0, k, len(b.x) - 1):
        assert abs(b.x[i] - _bessel_switch(b.y[i])) < 1e-8, (b.x[i], b.y[i])
    assert b.y[0] in (0.95, 1.05) and b.y[-1] in (0.95, 1.05)


def test_traced_boundary_equals_bisection_of_full_scans(small_map):
    (b,) = small_map.boundaries
    k = len(b.x) // 2
    y = b.y[k]

    def first(x):
        at = TUBE.at("outer_radius", x).at("length", y)
        c = scan_modes(at, "stretch", side="compression", options=NEAR).critical
        return c.m, c.n

    lo, hi = 1.2, 1.3
    assert first(lo) == (1, 1) and first(hi) == (0, 1)
    while hi - lo > 2e-9:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if first(mid) == (1, 1) else (lo, mid)
    assert abs(b.x[k] - 0.5 * (lo + hi)) < 1e-8


def test_pattern_at_follows_the_traced_boundary(small_map):
    (b,) = small_map.boundaries
    k = len(b.x) // 2
    for dx, mode in ((-1e-6, (1, 1)), (1e-6, (0, 1))):
        assert small_map.pattern_at(b.x[k] + dx, b.y[k]) == mode
    raster = small_map.raster(np.linspace(1.2, 1.3, 5), np.linspace(0.95, 1.05, 3))
    assert raster.shape == (5, 3) and raster[0, 0] == (1, 1) and raster[-1, -1] == (0, 1)


def test_map_records(small_map):
    rec = json.loads(json.dumps(small_map.as_dict()))
    assert rec["vary"] == [list(VARY[0]), list(VARY[1])]
    (bd,) = rec["boundaries"]
    assert sorted(bd["patterns"]) == [[0, 1], [1, 1]] and bd["certified"]
    pytest.importorskip("xarray")
    ds = small_map.to_xarray()
    assert ds["boundary_x"].size == len(small_map.boundaries[0].x)
    assert ds["m"].shape == (2, 2)


@pytest.mark.parametrize(
    "vary, words",
    [
        ((("outer_radius", 1.2, 1.3),), "give two \\(key, lo, hi\\)"),
        ((("length", 1, 2), ("length", 1, 3)), "both 'length'"),
        ((("outer_radius", 1.3, 1.2), ("length", 1, 2)), "need finite numbers lo < hi"),
    ],
)
def test_bad_vary(vary, words):
    with pytest.raises(ParameterError, match=words):
        mode_map(TUBE, "stretch", vary, options=NEAR)


@pytest.mark.slow
def test_triple_point_three_modes_equal():
    """Where (1, 2), (0, 2) and (1, 1) meet: the three critical values agree to 1e-8 by
    full solves and by the Bessel determinants; the three boundaries end there."""
    opts = ScanOptions((0, 1), (1, 2), extend=False)
    mm = mode_map(
        TUBE, "stretch", (("outer_radius", 1.34, 1.40), ("length", 2.3, 2.7)),
        side="compression", points=2, options=opts, certify=1,
    )  # fmt: skip
    (tp,) = mm.triple_points
    assert set(tp.patterns) == {(1, 2), (0, 2), (1, 1)} and tp.gap < 1e-8
    at = TUBE.at("outer_radius", tp.x).at("length", tp.y)
    vals = [critical_value(at, *m, "stretch", side="compression").value for m in tp.patterns]
    exact = [critical_stretch(*m, tp.x, tp.y) for m in tp.patterns]
    assert max(vals) - min(vals) < 1e-8 and max(exact) - min(exact) < 1e-8
    ends = [b for b in mm.boundaries if "triple" in b.ends]
    assert len(ends) == 3 and all(b.certified for b in mm.boundaries)


def test_design_in_the_map_widest_margin(small_map):
    from electrogrowth.design.prescribe_map import prescribe_map

    d = prescribe_map(TUBE, (1, 1), small_map, options=NEAR)
    assert d.status == "found" and d.mode == (1, 1) and d.next_mode == (0, 1)
    assert d.region == small_map.boundaries

    def margin(x, y):  # M = s (v_next - v) / |v|, s = -1 in compression, by direct solves
        at = TUBE.at("outer_radius", x).at("length", y)
        v, w = (critical_value(at, *m, "stretch", side="compression").value
                for m in ((1, 1), (0, 1)))  # fmt: skip
        return -(w - v) / abs(v)

    assert d.margin > 0 and abs(d.margin - margin(d.x, d.y)) < 1e-10
    for x, y in ((1.2, 0.95), (1.2, 1.0), (1.21, 1.05), (1.22, 1.02)):
        assert margin(x, y) <= d.margin + 1e-9, (x, y)
    # the distance to the region's boundary along the outer radius, from the Bessel switch
    assert abs(d.to_boundary["outer_radius"] - (_bessel_switch(d.y) - d.x)) < 1e-8
    v, w = d.value, d.next_value
    expect = -(v * d.next_sensitivity["growth"] - w * d.sensitivity["growth"]) / v**2
    assert d.margin_sensitivity["growth"] == pytest.approx(expect, rel=1e-12, abs=1e-14)


def test_design_in_the_map_never_first(small_map):
    from electrogrowth.design.prescribe_map import prescribe_map

    d = prescribe_map(TUBE, (0, 2), small_map, options=NEAR)
    assert d.status == "not_first" and d.margin < 0 and d.mode == (0, 2)
    at = TUBE.at("outer_radius", d.x).at("length", d.y)
    scan = scan_modes(at, "stretch", side="compression", options=NEAR).critical
    assert d.next_mode == (scan.m, scan.n)
    v = critical_value(at, 0, 2, "stretch", side="compression").value
    assert d.margin == pytest.approx(-(scan.value - v) / abs(v), abs=1e-8)


@pytest.mark.slow
def test_cli_design_two_variables(capsys, tmp_path):
    from electrogrowth.cli.app import main

    args = ["design", "--solve-for", "stretch", "--side", "compression", "--target", "0", "1"]
    args += ["--vary", "outer_radius", "1.2", "1.3", "--vary", "length", "0.95", "1.05"]
    args += ["--points", "2", "--m-max", "1", "--n-max", "1", "--json", "--out", str(tmp_path)]
    assert main(args) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["target"] == "(0, 1)" and out["status"] == "found"
    assert out["best"]["mode"] == [0, 1] and out["best"]["margin"] > 0
    assert out["vary"] == ["outer_radius", "length"]
    assert any(sorted(b["patterns"]) == [[0, 1], [1, 1]] for b in out["region"])
    assert all(b["certified"] for b in out["switches"])
    assert {"outer_radius", "length"} <= set(out["sensitivity"]["value"])
    kinds = sorted(p.rsplit(".", 1)[1] for p in out["files"])
    assert kinds[:2] == ["csv", "nc"] or kinds[:2] == ["csv", "png"]
    from matplotlib.image import imread

    (png,) = [p for p in out["files"] if p.endswith(".png")]
    height, width = imread(png).shape[:2]
    assert width > 2 * height  # the map and, beside it, the design's tube in 3D


def test_cli_design_map_csv_holds_plain_numbers(capsys, tmp_path):
    """probe 9b D4: cli/design.py `_write_map` wrote f"{x!r}" of NumPy 2 scalars, rows like
    `0,np.float64(1.23423654523418),np.float64(0.95),...` that read back as text."""
    import csv

    from electrogrowth.cli.app import main

    args = ["design", "--solve-for", "stretch", "--side", "compression", "--target", "0", "1"]
    args += ["--vary", "outer_radius", "1.2", "1.3", "--vary", "length", "0.95", "1.05"]
    args += ["--points", "2", "--m-max", "1", "--n-max", "1", "--quiet", "--out", str(tmp_path)]
    assert main(args) == 0
    (path,) = tmp_path.glob("*.csv")
    rows = list(csv.DictReader(path.open()))
    assert rows
    for row in rows:
        for key in ("outer_radius", "length", "critical_stretch"):
            float(row[key])  # a number, "np.float64(...)" is refused


def test_map_axes_carry_units_and_symbols(small_map):
    """probe 9b D4: the map's axes x, y had only long_name and boundary_x, boundary_y no
    attributes at all, where a sweep's store gives every axis long_name, symbol, units."""
    pytest.importorskip("xarray")
    ds = small_map.to_xarray()
    for name, key in (("x", "outer_radius"), ("y", "length"), ("boundary_x", "outer_radius"),
                      ("boundary_y", "length"), ("triple_y", "length")):  # fmt: skip
        attrs = ds[name].attrs
        assert {"long_name", "symbol", "units"} <= set(attrs), (name, attrs)
        assert attrs["long_name"] == {"outer_radius": "outer radius", "length": "length"}[key]
    assert ds["y"].attrs["symbol"] == "L/Rᵢ"


def test_cli_design_two_variables_bad_input(capsys):
    from electrogrowth.cli.app import main

    args = ["design", "--solve-for", "stretch", "--target", "0", "1"]
    assert main([*args, "--vary", "length", "1", "2", "--vary", "length", "1", "3"]) == 2
    more = ["--vary", "outer_radius", "1.2", "1.3", "--vary", "length", "1", "2"]
    assert main([*args, *more, "--vary", "voltage", "0", "1"]) == 2
    assert main([*args, *more, "--points", "500"]) == 2
    assert main([*args, *more, "--workers", "0"]) == 2
    assert main([*args, "--vary", "length", "1", "2", "--workers", "2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 5 and all(e.startswith("electrogrowth: error:") for e in err)
    assert "given twice" in err[0] and "once or twice" in err[1] and "at most 101" in err[2]
    assert "--workers 0 is out of range" in err[3] and "give --vary twice" in err[4]


MUCOSA = Path(__file__).resolve().parents[2] / "examples" / "mucosa.toml"


@pytest.mark.parametrize(
    "x, y",
    [
        ("outer_radius", "layers[2].outer_radius"),  # Tube.at's alias
        ("layers[2].thickness", "outer_radius"),  # the outermost thickness sets R_2
        ("growth[1]", "growth[1].theta"),  # every component, and one of them
    ],
)
def test_one_number_under_two_names_is_refused_as_a_map(x, y, capsys):
    """Probe 10b D3: on the two-layer mucosa ``outer_radius`` is ``layers[2].outer_radius``
    (Tube.at), yet the map compared the key strings: it ran 95 s and reported the best
    design at outer_radius = 2.175 and layers[2].outer_radius = 2.085 at once (x had no
    effect). The names as Tube.at resolves them are compared now, in Python and the CLI."""
    from electrogrowth.cli.app import main
    from electrogrowth.model.tube_file import load_tube

    tube = load_tube(MUCOSA)
    vary = ((x, *sorted((tube.value_of(x), 1.01 * tube.value_of(x)))),)
    vary += ((y, *sorted((tube.value_of(y), 1.02 * tube.value_of(y)))),)
    with pytest.raises(ParameterError, match="both set"):
        mode_map(tube, "pressure", vary, options=NEAR)
    argv = ["design", "--tube", str(MUCOSA), "--solve-for", "pressure", "--target", "2", "0"]
    for key, lo, hi in vary:
        argv += ["--vary", key, repr(lo), repr(hi)]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--vary {x} and --vary {y} both set" in err[0], err


def test_two_layer_radii_of_one_tube_are_two_variables():
    """Not refused: an inner layer's thickness and outer radius (the thickness also moves
    the layers outside it), two growth components, the two pressures."""
    from electrogrowth.design.sequence import shared_variable
    from electrogrowth.model.tube_file import load_tube

    tube = load_tube(MUCOSA)
    for x, y in (
        ("layers[1].thickness", "layers[1].outer_radius"),
        ("growth[1].r", "growth[1].theta"),
        ("pressure", "outer_pressure"),
    ):
        assert shared_variable(tube, x, y) is None


@pytest.mark.slow
def test_boundary_to_the_short_wave_limit():
    """A thick tube under voltage: where the finite mode (0, 1) gives way to the exact
    short-wave limit, the traced boundary's two values agree by full solves and scans."""
    mm = mode_map(
        TUBE, "voltage", (("outer_radius", 1.6, 2.6), ("growth", 1.0, 1.1)),
        options=ScanOptions((0, 2), (1, 2), extend=False), points=2, certify=2,
    )  # fmt: skip
    (b,) = mm.boundaries
    assert {b.left, b.right} == {(0, 1), "surface"} and b.ends == ("edge", "edge")
    assert b.certified and all(c.gap < 1e-8 for c in b.certificates)
    k = len(b.x) // 2
    assert mm.pattern_at(b.x[k] - 1e-6, b.y[k]) == (0, 1)
    assert mm.pattern_at(b.x[k] + 1e-6, b.y[k]) == "surface"


@pytest.mark.parametrize(
    "keyword, words",
    [
        ({"points": 1}, "points = \\(1, 1\\) is invalid"),
        ({"max_step": 0.9}, "max_step = 0.9 is out of range"),
        ({"certify": -1}, "certify = -1 is invalid"),
    ],
)
def test_bad_options(keyword, words):
    with pytest.raises(ParameterError, match=words):
        mode_map(TUBE, "stretch", VARY, options=NEAR, **keyword)


def _same_map(a, b):
    """Two maps equal to the last bit but for the time they took (NaN gaps compare by
    their JSON text)."""
    da, db = a.as_dict(), b.as_dict()
    da.pop("seconds"), db.pop("seconds")
    assert json.dumps(da, sort_keys=True) == json.dumps(db, sort_keys=True)
    np.testing.assert_array_equal(a.values, b.values)


@pytest.mark.slow  # ~10 s: make test-slow runs it
def test_a_pool_draws_the_same_map():
    """Two worker processes scan the grid, trace the two boundaries (seeds of different
    pattern pairs: one batch) and certify them: the same map, to the last bit (every task is
    a pure function of its inputs), the solves counted once."""
    args = (TUBE, "stretch", (("outer_radius", 1.2, 1.3), ("length", 0.95, 1.05)))
    kw = {"side": "compression", "points": 2, "certify": 1, "options": ScanOptions((0, 1), (1, 1))}
    serial, pooled = mode_map(*args, **kw), mode_map(*args, **kw, workers=2)
    assert len(serial.boundaries) == 2
    _same_map(serial, pooled)


@pytest.mark.slow
def test_a_pool_draws_the_same_triple_point():
    """The map of test_triple_point_three_modes_equal on two workers: the boundaries from
    the grid's edges, then the one leaving the triple point, all the same to the last bit."""
    args = (TUBE, "stretch", (("outer_radius", 1.34, 1.40), ("length", 2.3, 2.7)))
    kw = {"side": "compression", "points": 2, "certify": 1,
          "options": ScanOptions((0, 1), (1, 2), extend=False)}  # fmt: skip
    serial, pooled = mode_map(*args, **kw), mode_map(*args, **kw, workers=2)
    assert len(serial.triple_points) == 1 and len(serial.boundaries) == 3
    _same_map(serial, pooled)


@pytest.mark.parametrize("width", [1, 2, 3, 5])
def test_seeds_kept_in_order_whatever_ran_ahead(width):
    """The merge of design/map_boundaries.py on a model: seed k, once kept, covers seed
    k + 3 of the same pair (k % 2); tasks run in batches of ``width`` and come back in
    reverse. The kept seeds are those of the serial order for every width; the tasks run
    ahead and found covered are the only extra work."""
    seeds = list(range(12))
    kept: list[int] = []
    calls: list[int] = []

    def run(fn, tasks):
        calls.extend(seed for _, seed in tasks)
        return reversed([(k, fn(task)) for k, task in enumerate(tasks)])

    def skip(seed):
        return any(seed == k + 3 for k in kept)

    order = _in_order(lambda task: task[1] * 10, None, seeds, lambda s: s % 2, skip, run, width)
    for seed, piece in order:
        assert piece == seed * 10
        kept.append(seed)
    assert kept == [0, 1, 2, 6, 7, 8]
    assert set(kept) <= set(calls) and len(calls) == len(set(calls))
    assert width > 1 or calls == kept


@pytest.mark.parametrize("workers", [0, -1, 2.0, True, 10_000])
def test_bad_workers(workers):
    with pytest.raises(UsageError, match="workers"):
        mode_map(TUBE, "stretch", VARY, options=NEAR, workers=workers)


def test_a_region_met_only_where_a_boundary_leaves_the_box():
    """probe14f D1: on the edge Rbar_o = 1.1 of this box (charged tube, Vbar = 0.3), (3, 2)
    comes first for L between two switches, in a region no grid node lands in that narrows
    into the box. The (3, 1) | (2, 1) curve leaves the box inside it; the scan there must
    find (3, 2), and its region be traced with ends where single-mode critical values cross
    (Brent on critical_value along L, independent of the tracer)."""
    tube = Tube.uniform(1.3, 1.0, voltage=0.3)
    vary = (("outer_radius", 1.1, 1.13), ("length", 2.0, 3.0))
    options = ScanOptions((2, 3), (1, 2))
    mm = mode_map(tube, "stretch", vary, side="compression", points=2, options=options)

    def switch(a, b, lo, hi):
        def gap(y):
            at = tube.at("outer_radius", 1.1).at("length", y)
            va = critical_value(at, *a, "stretch", side="compression").value
            return va - critical_value(at, *b, "stretch", side="compression").value

        return brentq(gap, lo, hi, xtol=1e-13, rtol=1e-15)

    ends = {}
    for b in mm.boundaries:
        assert b.certified
        if (3, 2) in (b.left, b.right) and b.ends[1] == "edge":
            ends[frozenset((b.left, b.right))] = b.y[-1]
            assert b.x[-1] == 1.1
    lower = switch((3, 1), (3, 2), 2.1, 2.4)
    upper = switch((3, 2), (2, 1), 2.5, 2.9)
    assert abs(ends[frozenset(((3, 1), (3, 2)))] - lower) < 1e-9
    assert abs(ends[frozenset(((3, 2), (2, 1)))] - upper) < 1e-9
    assert [mm.pattern_at(1.1, y) for y in (2.2, 2.45, 2.65, 2.75)] == [
        (3, 1), (3, 2), (3, 2), (2, 1)
    ]  # fmt: skip
    labels = {frozenset(t.patterns) for t in mm.triple_points}
    assert frozenset(((3, 1), (2, 1), (3, 2))) in labels


def test_an_uncertified_boundary_names_what_came_first():
    """The design's text says which pattern a failed certificate's scan found first, where
    and how far ahead (probe14f D1's map said only "NOT certified")."""
    from electrogrowth.cli.design import _uncertified
    from electrogrowth.design.map_record import Boundary, Certificate

    cert = Certificate(1.1, 2.460798, 1e-15, (3, 2), -0.00268, False)
    b = Boundary((3, 1), (2, 1), (1.1,), (2.460798,), (0.95,), ("edge", "edge"), (cert,))
    text = _uncertified(b)
    assert "(3, 2) comes first at (1.1, 2.460798), 0.00268 ahead" in text
    assert "raise --points" in text
