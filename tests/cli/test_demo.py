"""``electrogrowth demo`` and ``electrogrowth reproduce`` write what they promise."""

import json

import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.cli.app import main


def test_demo_writes_results_and_the_critical_growth(tmp_path, capsys):
    assert main(["demo", "--out", str(tmp_path), "--quick"]) == 0
    out = capsys.readouterr().out
    for name in (
        "state.json",
        "stress_profile.csv",
        "stress_profile.png",
        "critical.json",
        "gcr_curve.csv",
        "gcr_curve.png",
        "pattern.png",
    ):
        assert (tmp_path / name).stat().st_size > 100, name
    crit = json.loads((tmp_path / "critical.json").read_text())
    want = critical_value(Tube.uniform(1.4, 1.0, voltage=0.4), crit["m"], crit["n"], "growth")
    assert crit["value"] == pytest.approx(want.value, rel=1e-12)
    assert f"g_cr = {want.value:.10f}" in out


def test_reproduce_writes_index_with_captions_and_patterns(tmp_path, capsys):
    assert main(["reproduce", "--quick", "--out", str(tmp_path), "--figures", "4", "10"]) == 0
    index = (tmp_path / "index.md").read_text()
    assert "## Figure 4" in index and "## Figure 10" in index
    assert "in the case Rbar_o = 2.0" in index  # the paper's caption
    assert "![P1](fig10-P1.png)" in index and (tmp_path / "fig10-P1.png").exists()


def test_reproduce_rejects_unknown_figure(tmp_path, capsys):
    assert main(["reproduce", "--out", str(tmp_path), "--figures", "3"]) == 2
    assert "figure 3" in capsys.readouterr().err
