"""The design pages of the gallery (examples/gallery/design), each headline number by an
independent route: the stored gut-fold designs by full scans and direct solves at the
stored designs, the stored map's triple points by full scans wider than the map's window
and by a root-finder on two single-mode conditions, the switches along the voltage and the
axial stretch by a root-find on two single-mode critical values (not the sequence's own
bracketing)."""

from __future__ import annotations

import itertools
import math
import runpy
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq, root

from electrogrowth import ScanOptions, critical_value, scan_modes
from electrogrowth.figures.design_gallery import (
    CONTROL,
    FOLDS,
    FULL_OPTIONS,
    gut_bilayer,
    read_fold_designs,
)

DESIGN = Path(__file__).resolve().parents[2] / "examples" / "gallery" / "design"
STORED = DESIGN / "gut_folds.json"
#: wider than the map's window in m and n, with short waves and the short-wave limit
WIDE = ScanOptions((0, 24), (1, 4), top=8)


@pytest.fixture(scope="module")
def stored():
    res, _ = read_fold_designs(STORED)
    return res


def _at(design):
    return gut_bilayer().at(design.keys[0], design.x).at(design.keys[1], design.y)


def _prismatic(b) -> bool:
    """A boundary between two fold numbers (m, 0) | (m - 1, 0), edge to edge."""
    return b.ends == ("edge", "edge") and b.left[1] == b.right[1] == 0


def test_stored_fold_boundaries_by_fresh_solves(stored):
    """Each boundary between two fold numbers is certified, and at its middle point both
    modes' critical growths, solved afresh, equal the stored common value."""
    bounds = [b for b in stored.map.boundaries if _prismatic(b)]
    assert {b.left[0] for b in bounds} >= {16, 13, 12}  # the regions of 16 and 12 folds
    for b in bounds:
        assert b.certified
        k = len(b.x) // 2
        at = gut_bilayer().at(stored.map.keys[0], b.x[k]).at(stored.map.keys[1], b.y[k])
        for mode in (b.left, b.right):
            assert critical_value(at, *mode, CONTROL).value == pytest.approx(b.value[k], abs=1e-8)


def test_fold_boundaries_follow_the_film_scaling(stored):
    """Fewer folds as the mucosa thickens or stiffens, along lines of constant m close to
    the flat-film scaling h (mu_1/mu_2)^(1/3) = const (slope -1/3; here -0.32 to -0.37, the
    thicker layers further off)."""
    for b in (b for b in stored.map.boundaries if _prismatic(b)):
        k, mmap = len(b.x) // 2, stored.map
        dx, dy = 1e-4 * (mmap.box[0][1] - mmap.box[0][0]), 1e-4 * (mmap.box[1][1] - mmap.box[1][0])
        thin, thick = mmap.pattern_at(b.x[k] - dx, b.y[k]), mmap.pattern_at(b.x[k] + dx, b.y[k])
        soft, stiff = mmap.pattern_at(b.x[k], b.y[k] - dy), mmap.pattern_at(b.x[k], b.y[k] + dy)
        assert thin[0] == soft[0] == thick[0] + 1 == stiff[0] + 1
        h0, h1 = b.x[0] - 1.0, b.x[-1] - 1.0
        slope = math.log(h1 / h0) / math.log(b.y[-1] / b.y[0])
        assert abs(slope + 1 / 3) < 0.15 / 3, (b.left, slope)


@pytest.mark.parametrize("m", FOLDS)
def test_stored_design_by_a_full_scan_there(stored, m):
    """At each stored design a full scan (the map's modes) finds the target first, with
    the stored critical value, and the runner-up gives the stored margin; for a target never
    first, fresh solves give the stored gap to the mode that beats it, and nothing in the
    scan comes earlier."""
    d = stored.designs[m]
    scan = scan_modes(_at(d), CONTROL, options=FULL_OPTIONS)
    first = (scan.critical.m, scan.critical.n)
    v = critical_value(_at(d), *d.mode, CONTROL).value
    assert v == pytest.approx(d.value, abs=1e-8)
    if d.status == "found":
        assert first[0] == m
        assert scan.critical.value == pytest.approx(d.value, abs=1e-8)
        w = critical_value(_at(d), *d.next_mode, CONTROL).value
        assert (w - v) / abs(v) == pytest.approx(d.margin, abs=1e-8)
    else:  # the closest design: the mode that beats it, by the stored gap
        assert d.status == "not_first" and d.margin < 0 and first[0] != m
        w = critical_value(_at(d), *d.next_mode, CONTROL).value
        assert w == pytest.approx(d.next_value, abs=1e-8)
        assert (w - v) / abs(v) == pytest.approx(d.margin, abs=1e-8)
        # the scan's first mode comes no earlier (the closest design of 8 folds sits where
        # two modes beat it equally, (10, 0) and (6, 1): the scan may name either)
        assert scan.critical.value == pytest.approx(w, abs=1e-8)


def _values(mmap, x, y, modes):
    at = gut_bilayer().at(mmap.keys[0], x).at(mmap.keys[1], y)
    return [critical_value(at, *mode, CONTROL).value for mode in modes]


@pytest.mark.slow
def test_stored_map_certified_and_its_triple_points_by_a_wide_scan(stored):
    """Every boundary certified; at each triple point the three modes' critical growths,
    solved afresh, agree to 1e-8, a full scan wider than the map's window finds nothing
    earlier, and a boundary of each two of the three ends there."""
    mmap = stored.map
    assert mmap.triple_points and all(b.certified for b in mmap.boundaries)
    for tp in mmap.triple_points:
        v = _values(mmap, tp.x, tp.y, tp.patterns)
        assert max(v) - min(v) < 1e-8 and v[0] == pytest.approx(tp.value, abs=1e-8)
        at = gut_bilayer().at(mmap.keys[0], tp.x).at(mmap.keys[1], tp.y)
        scan = scan_modes(at, CONTROL, options=WIDE)
        assert scan.critical.value >= min(v) - 1e-8, (tp.patterns, scan.critical)
        for a, b in itertools.combinations(tp.patterns, 2):
            assert any(
                {bd.left, bd.right} == {a, b}
                and min(math.hypot(bd.x[k] - tp.x, bd.y[k] - tp.y) for k in (0, -1)) < 1e-9
                for bd in mmap.boundaries
            ), (tp.patterns, a, b)


@pytest.mark.slow
def test_stored_triple_points_by_newton_on_two_conditions(stored):
    """Each triple point again, from a start 1e-3 of the box away, by scipy's root finder
    on v_A - v_B = v_A - v_C = 0 (single-mode critical values only): the same point to
    1e-8 of the box."""
    mmap = stored.map
    (x0, x1), (y0, y1) = mmap.box
    for tp in mmap.triple_points:

        def conditions(w, tp=tp):
            v = _values(mmap, x0 + w[0] * (x1 - x0), y0 + w[1] * (y1 - y0), tp.patterns)
            return [v[0] - v[1], v[0] - v[2]]

        at = np.array([(tp.x - x0) / (x1 - x0), (tp.y - y0) / (y1 - y0)])
        sol = root(conditions, at + [1e-3, -1e-3], method="hybr", options={"xtol": 1e-13})
        assert sol.success and np.abs(sol.x - at).max() < 1e-8, (tp.patterns, sol.x - at)


def _switch(tube, key, a, b, lo, hi):
    """The root of v_a(x) - v_b(x) on [lo, hi] by Brent's method on two critical_value
    calls per point (hoop growth of layer 1)."""

    def d(x):
        at = tube.at(key, x)
        return critical_value(at, *a, CONTROL).value - critical_value(at, *b, CONTROL).value

    return brentq(d, lo, hi, xtol=1e-12)


@pytest.mark.slow
@pytest.mark.parametrize(
    "script, key",
    [("plot_15_voltage_folds.py", "voltage"), ("plot_16_stretch_rings_folds.py", "stretch")],
)
def test_sequence_switches_by_a_root_find(script, key):
    seq = runpy.run_path(str(DESIGN / script), run_name="__main__")["seq"]
    switches = [s for s in seq.switches if s.kind == "switch"]
    assert switches
    xs = [s.x for s in switches]
    for s in switches:  # a bracket holding this switch only
        gap = min([abs(s.x - x) for x in xs if x != s.x] + [seq.hi - seq.lo])
        span = min(0.02 * (seq.hi - seq.lo), 0.5 * gap)
        lo, hi = max(seq.lo, s.x - span), min(seq.hi, s.x + span)
        x = _switch(gut_bilayer(), key, s.mode_before, s.mode_after, lo, hi)
        assert x == pytest.approx(s.x, abs=1e-8)
        if key == "stretch" and s.mode_after[1] == 0:
            # hoop growth of neo-Hookean layers: a prismatic fold's critical growth does
            # not depend on lambda_z (the plane-strain problem rescales), so the switch
            # into (m, 0) happens at its value at lambda_z = 1
            flat = critical_value(gut_bilayer(), *s.mode_after, CONTROL).value
            assert s.value == pytest.approx(flat, abs=1e-9)
