"""The benchmark scripts run (no timing asserts): the evaluation counter of the peer model,
the tables, and the figure comparison."""

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "benchmarks"))

bench = pytest.importorskip("bench")
compare_figures = pytest.importorskip("compare_figures")


def test_bench_case_at_tiny_size():
    """One point of the suite with a 2 x 2 mode range: counts, ratios and errors."""
    from electrogrowth import Tube
    from electrogrowth.bifurcation.scan import ScanOptions

    r = bench.bench_case(
        "tiny",
        Tube.uniform(1.4, 1.0, voltage=0.4),
        "growth",
        None,
        ScanOptions((0, 1), (1, 2), extend=False),
        1,
        False,
    )
    assert r["kernel_evaluations"]["loose"] > 0 and r["kernel_evaluations"]["fine"] > 0
    assert r["error"] < 1e-12 and r["baseline_error"] < 1e-6
    assert r["peer_seconds"] > 0 and r["baseline_seconds"] > 0
    results = {
        "date": "today",
        "machine": "here",
        "note": "quick",
        "scans": [r],
        "other": {"warm_mode": (0.01, 0.01, 0.01), "fresh": (1.0, 2.0), "max_rss_mb": 100.0},
    }
    text = bench.tables(results)
    assert "| tiny | bifurcation (0, 1)" in text and "warm process" in text


def test_figure_comparison_of_the_committed_figures_with_themselves(capsys):
    assert compare_figures.compare(ROOT / "docs/figures", ROOT / "docs/figures")
    assert "fig9.csv: 60 rows" in capsys.readouterr().out


@pytest.mark.slow  # the peer's collocation march: ~15 s idle, minutes on a loaded machine
def test_layered_march_head_to_head_at_tiny_size(monkeypatch):
    """The layered points' march, ours and the collocation peer's, on two modes: the same
    first mode and value (to the peer's accuracy); the table prints the row."""
    import numpy as np

    layered_bench = pytest.importorskip("layered_bench")
    monkeypatch.setattr(layered_bench, "GRID", np.array([[2.0, 0.0, 1.0], [3.0, 0.0, 1.0]]))
    tube = layered_bench.PRESSURISED
    # the prismatic modes of this grid bifurcate in collapse (P_i below P_o), not on the
    # inflation side the bench's scan takes: ask for that side
    ours = layered_bench.march(tube, "pressure", "compression", "impedance")
    peer = layered_bench.march(tube, "pressure", "compression", "collocation")
    assert (ours.m, ours.n) == (peer.m, peer.n)
    assert peer.value == pytest.approx(ours.value, rel=1e-8)
    row = {
        "name": "tiny",
        "kind": "bifurcation",
        "mode": [ours.m, ours.n],
        "family": ours.family,
        "value": ours.value,
        "scan_seconds": 1.0,
        "scan_cpu_seconds": 1.0,
        "scan_error": 1e-14,
        "march": {
            "modes": 2,
            "mode": [ours.m, ours.n],
            "seconds": 0.1,
            "cpu_seconds": 0.1,
            "peer_seconds": 10.0,
            "peer_cpu_seconds": 10.0,
            "error": 1e-14,
            "peer_error": 1e-11,
        },
    }
    assert "| 100x (100x) |" in layered_bench.layered_table([row])
