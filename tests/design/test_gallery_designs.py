"""The design pages of the gallery (examples/gallery/design), each headline number by an
independent route: the stored gut-fold designs by full scans and direct solves at the
stored designs, the switches along the voltage and the axial stretch by a root-find on two
single-mode critical values (not the sequence's own bracketing)."""

from __future__ import annotations

import math
import runpy
from pathlib import Path

import pytest
from scipy.optimize import brentq

from electrogrowth import critical_value, scan_modes
from electrogrowth.figures.design_gallery import (
    CONTROL,
    FOLDS,
    FULL_OPTIONS,
    gut_bilayer,
    read_fold_designs,
)

DESIGN = Path(__file__).resolve().parents[2] / "examples" / "gallery" / "design"
STORED = DESIGN / "gut_folds.json"


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
