"""The growth-voltage map (design/growth_voltage.py) of the electro-active gut-like bilayer
(R = 1 .. 1.1 stiff, mu_1/mu_2 = 10, growing in the hoop direction, under a voltage): the
regions' modes against single-mode solves of their neighbours, the onset curve continuous
at the switch, the figure's axes; the switch voltages against Brent's method on two
single-mode critical values (slow), for this map and the gallery page's."""

from __future__ import annotations

import runpy
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from electrogrowth import ScanOptions, critical_value
from electrogrowth.design.growth_voltage import growth_voltage_map
from electrogrowth.errors import ParameterError
from electrogrowth.figures.design import plot_growth_voltage
from electrogrowth.figures.design_gallery import gut_bilayer

HOOP = "growth[1].theta"
TUBE = gut_bilayer(0.1, 10.0)
TWO = ScanOptions((11, 12), (1, 1), top=2, extend=False, surface=False)
PAGE = Path(__file__).resolve().parents[2] / "examples/gallery/design/plot_17_growth_voltage.py"


@pytest.fixture(scope="module")
def gv():
    return growth_voltage_map(TUBE, HOOP, (0.15, 0.25), options=TWO, points=2, fill=1)


def _g(mode, v):
    return critical_value(TUBE.at("voltage", v), *mode, HOOP).value


def test_two_regions_one_switch(gv):
    (s,) = gv.switches
    assert [r.mode for r in gv.regions] == [(11, 0), (12, 0)]
    assert (s.mode_before, s.mode_after) == ((11, 0), (12, 0)) and 0.15 < s.x < 0.25
    low, high = gv.regions
    assert low.hi == high.lo == s.x and (low.lo, high.hi) == (0.15, 0.25)
    # the onset curve is continuous at the switch: both modes' value there
    assert low.growth[-1] == pytest.approx(s.value, abs=1e-8)
    assert high.growth[0] == pytest.approx(s.value, abs=1e-8)
    assert gv.region_at(0.16).mode == (11, 0) and gv.region_at(0.24).mode == (12, 0)
    assert gv.region_at(0.3) is None


def test_each_region_has_its_mode_first(gv):
    """At each filled voltage the region's mode is below the other one (single-mode solves,
    not the scans the regions came from)."""
    for r, other in zip(gv.regions, [(12, 0), (11, 0)], strict=True):
        (v,) = [x for x in r.voltage if r.lo < x < r.hi]  # fill = 1: the one inside
        g = dict(zip(r.voltage, r.growth, strict=True))[v]
        assert g == pytest.approx(_g(r.mode, v), abs=1e-10)
        assert g < _g(other, v)


def test_growth_voltage_figure(gv):
    ax = plot_growth_voltage(gv)
    assert r"\bar V" in ax.get_xlabel() and r"g_\theta" in ax.get_ylabel()
    texts = [t.get_text() for t in ax.texts]
    assert "(11, 0)" in texts and "(12, 0)" in texts
    assert any(t.startswith(r"$\bar V$ = ") for t in texts)
    assert ax.get_xlim() == (0.15, 0.25)


@pytest.mark.parametrize(
    "kw, words",
    [
        ({"growth": "stretch"}, "growth = 'stretch' is not a growth control"),
        ({"voltage": (0.3, 0.1)}, "vary range 0.3 to 0.1 of voltage is invalid"),
        ({"voltage": 0.2}, "voltage = 0.2 is invalid"),
        ({"fill": -1}, "fill = -1 is out of range"),
    ],
)
def test_bad_input(kw, words):
    args = {"growth": HOOP, "voltage": (0.0, 0.4), **kw}
    with pytest.raises(ParameterError, match=words):
        growth_voltage_map(TUBE, args.pop("growth"), args.pop("voltage"), **args)


def _brent_switch(before, after, lo, hi) -> float:
    return brentq(lambda v: _g(before, v) - _g(after, v), lo, hi, xtol=1e-12)


def _check_switches(gv):
    xs = [s.x for s in gv.switches]
    for s in gv.switches:
        assert s.kind == "switch"
        gap = min([abs(s.x - x) for x in xs if x != s.x] + [gv.hi - gv.lo])
        span = min(0.02 * (gv.hi - gv.lo), 0.5 * gap)
        lo, hi = max(gv.lo, s.x - span), min(gv.hi, s.x + span)
        assert _brent_switch(s.mode_before, s.mode_after, lo, hi) == pytest.approx(s.x, abs=1e-8)
        assert _g(s.mode_after, s.x) == pytest.approx(s.value, abs=1e-8)


@pytest.mark.slow
def test_switch_voltage_by_a_root_find(gv):
    _check_switches(gv)


@pytest.mark.slow
def test_gallery_switch_voltages_by_a_root_find():
    gv = runpy.run_path(str(PAGE), run_name="__main__")["gv"]
    assert len(gv.switches) >= 2
    _check_switches(gv)


def test_branch_labels_set_apart():
    """Three branches within 1e-3 of each other on a range of 0.06 (the slivers of the
    stretch page): their labels do not overlap each other nor cover the switch dots."""
    from types import SimpleNamespace

    import matplotlib as mpl
    from matplotlib.figure import Figure

    from electrogrowth.figures.design import _text_box, label_branches

    x = np.array([0.94, 0.9588, 0.9588, 0.9596, 0.9596, 0.9597, 0.9597, 0.98, 1.0])
    v = np.array([1.52, 1.675, 1.675, 1.681, 1.681, 1.682, 1.682, 1.712, 1.712])
    modes = [(0, 2), (0, 2), (1, 2), (1, 2), (8, 1), (8, 1), (9, 1), (9, 1), (9, 1)]
    curve = SimpleNamespace(
        x=x, value=v, surface=np.zeros(len(x), bool),
        switches=[SimpleNamespace(x=x[i], value=v[i]) for i in (1, 3, 5)], ends=[],
        branches=lambda: [(m, np.array([i for i, k in enumerate(modes) if k == m]))
                          for m in dict.fromkeys(modes)],
    )  # fmt: skip
    with mpl.rc_context({"figure.dpi": 100}):
        ax = Figure(figsize=(4.4, 3.3), layout="constrained").subplots()
    ax.plot(x, v, "k-")
    anns = label_branches(ax, curve)
    assert [a.get_text() for a in anns] == ["(0, 2)", "(1, 2)", "(8, 1)", "(9, 1)"]
    renderer = ax.figure.canvas.get_renderer()
    boxes = [_text_box(a, renderer) for a in anns]
    assert not any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1 :])
    dots = [ax.transData.transform((s.x, s.value)) for s in curve.switches]
    assert not any(b.contains(*d) for b in boxes for d in dots)
