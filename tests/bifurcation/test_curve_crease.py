"""The crease along a critical curve: the paper's ungrown, uncharged tubes, L = 1, in
axial compression cross from wrinkle first (Rbar_o = 1.6) to crease first (1.8, 2.0)
(docs/derivation-crease.md section 6). The crease is the closed form lambda_z =
2.4^(-2/3) of the homogeneous tube; the wrinkle is checked against the exact
Bessel-function root (test_verdict.py); the flag agrees with the verdict of a scan at
each point."""

import csv
import json
import math

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.crease import CREASE_RATIO
from electrogrowth.bifurcation.curve_crease import CreaseAlong
from electrogrowth.bifurcation.curves import _curve, critical_curve
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes
from electrogrowth.cli.curve import crease_line
from tests.bifurcation.test_verdict import bessel_wrinkle

OPTIONS = ScanOptions((0, 2), (1, 2), extend=False)
RADII = [1.6, 1.8, 2.0]


@pytest.fixture(scope="module")
def curve():
    return critical_curve(
        Tube.uniform(), "stretch", "outer_radius", RADII, side="compression", options=OPTIONS
    )


def test_the_curve_crosses_from_wrinkle_first_to_crease_first(curve):
    crease = CREASE_RATIO ** (-2 / 3)  # lambda_r / lambda_z = lambda_z^(-3/2) = 2.4
    assert np.allclose(curve.crease.value, crease, rtol=1e-12, atol=0)
    for x, v in zip(curve.x, curve.value):  # the wrinkle by an independent route
        assert v == pytest.approx(bessel_wrinkle(x), rel=1e-9)
    assert curve.crease.first.tolist() == [False, True, True]
    assert curve.crease.trigger == ("axial",) * 3
    expected = (2 / 3) * crease * 0.03 / 2.4  # the criterion's accuracy, section 4
    assert np.allclose(curve.crease.error, expected, rtol=1e-3)


def test_the_flag_is_the_verdict_of_a_scan(curve):
    for x, first in zip(curve.x, curve.crease.first):
        res = scan_modes(
            Tube.uniform(x, length=1.0), "stretch", side="compression", options=OPTIONS
        )
        assert (str(res.verdict.kind) == "crease") == first


def test_csv_json_and_xarray_carry_the_crease(curve, tmp_path):
    with open(curve.to_csv(tmp_path / "c.csv"), newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["crease_first"] for r in rows] == ["0", "1", "1"]
    assert float(rows[1]["crease_value"]) == curve.crease.value[1]
    rec = json.loads(json.dumps(curve.as_dict()))
    assert rec["crease_first"] == [False, True, True]
    assert rec["crease_face"] == list(curve.crease.face) and rec["crease_value"][0] > 0
    pytest.importorskip("xarray")
    ds = curve.to_xarray()
    assert ds["crease_first"].values.tolist() == [0, 1, 1]
    assert ds["crease_value"].dims == ("point",)


def test_the_text_says_where_it_creases_first(curve):
    line = crease_line(curve)
    assert "crease first at 2 of 3 points, outer_radius 1.8 .. 2" in line
    assert "stretch = 0.5579 before the wrinkle" in line


def test_nowhere_first_and_not_computed():
    """A thin tube wrinkles first at every point; an interrupted curve's grid points have
    no crease (NaN, never first)."""
    thin = critical_curve(
        Tube.uniform(), "stretch", "outer_radius", [1.4, 1.5], side="compression", options=OPTIONS
    )
    assert not thin.crease.first.any()
    assert crease_line(thin).startswith("  crease: no point creases before it wrinkles; a face")
    row = (1.5, 0.6, (0, 1), "bifurcation", "", False, math.nan, "", "")
    partial = _curve("outer_radius", "stretch", "compression", Tube.uniform(), [row], [])
    empty = CreaseAlong.empty(1)
    assert math.isnan(partial.crease.value[0]) and not partial.crease.first[0]
    assert partial.crease.face == empty.face


def test_a_field_crease_at_the_start_leaves_the_mechanical_crease_in_the_columns():
    """Probe 8b D1: `curve --solve-for growth --along voltage` of Tube.uniform(1.8) reported
    crease_value 1.8008 (outer, axial) at Vbar 0.70, then 1.0 (inner, field) at 0.73 and
    0.76, where the field criterion is met at g = 1: the outer face's crease was hidden.
    Every row now carries the mechanical crease (lambda_r / lambda_z = 2.4, Brent on the
    base state), before the wrinkle (~1.896)."""
    from scipy.optimize import brentq

    from electrogrowth.bifurcation.curve_crease import crease_along
    from tests.bifurcation.test_crease import _outer_axial_ratio

    tube, xs = Tube.uniform(1.8, length=1.0), [0.70, 0.73, 0.76]
    c = crease_along(tube, "growth", "voltage", None, xs, [1.89] * 3)
    exact = [
        brentq(lambda g, t=tube.at("voltage", x): _outer_axial_ratio(t, g) - 2.4, 1.5, 1.89)
        for x in xs
    ]
    assert c.value == pytest.approx(exact, abs=1e-8)
    assert c.face == ("outer",) * 3 and c.trigger == ("axial",) * 3 and c.first.all()
