"""A crease before the wrinkle in a design: the paper's ungrown tubes, L = 1, in axial
compression, target (0, 1) along Rbar_o. Their faces crease at the closed form lambda_z =
2.4^(-2/3) (docs/derivation-crease.md), before the wrinkle (0, 1) from Rbar_o = 1.6808 on:
a range there has no design whose pattern is the wrinkle, and the result says so
(status crease_first, M < 0 the gap to the crease) where the margin of the modes alone
would report a design found with M > 0."""

import json
import math

import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.crease import CREASE_RATIO
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions
from electrogrowth.cli.app import main
from electrogrowth.cli.design import summary
from electrogrowth.design.onset import CREASE_FIRST, observable
from electrogrowth.design.prescribe import FOUND, prescribe

OPTIONS = ScanOptions((0, 2), (1, 2))
CREASE = CREASE_RATIO ** (-2 / 3)


def _design(lo, hi, **kw):
    return prescribe(
        Tube.uniform(lo, length=1.0),
        "stretch",
        (0, 1),
        ("outer_radius", lo, hi),
        side="compression",
        options=OPTIONS,
        points=3,
        **kw,
    )


@pytest.fixture(scope="module")
def creased():
    return _design(1.75, 2.0)


@pytest.fixture(scope="module")
def mixed():
    return _design(1.6, 2.0, koiter=True)


def test_crease_first_everywhere_is_not_a_design_found(creased):
    d = creased
    assert d.status == CREASE_FIRST and d.limited_by == "crease"
    v = critical_value(Tube.uniform(d.x, length=1.0), 0, 1, "stretch", side="compression").value
    assert d.value == pytest.approx(v, rel=1e-10)
    assert d.crease_value == pytest.approx(CREASE, rel=1e-12)
    assert d.margin == pytest.approx(-(CREASE - v) / v, rel=1e-9) and d.margin < 0
    # the nearest design: the smallest gap to the crease is at the thin end (the wrinkle's
    # lambda_z falls as the wall thickens)
    assert d.x == pytest.approx(1.75, abs=1e-6)
    assert d.verdict["kind"] == "crease" and d.verdict["crease"]["face"] in ("inner", "outer")
    assert "may not be observed" in observable(d.verdict)
    assert all(r["crease_first"] == "all" for r in d.as_dict()["region"])
    # the crease's sensitivities, by implicit differentiation of its onset condition: the
    # crease is at lambda_z = g 2.4^(-2/3), whatever the radius or the length
    cs = d.crease_sensitivity
    assert cs["growth"] == pytest.approx(CREASE, rel=1e-9)
    assert abs(cs["outer_radius"]) < 1e-9 and abs(cs["length"]) < 1e-9
    # M = 1 - v_C / v: isotropic growth scales both values by g, so dM/dg = 0; along the
    # radius only the wrinkle moves, dM/dR = v_C / v^2 dv/dR
    dm = d.margin_sensitivity
    assert abs(dm["growth"]) < 1e-8
    assert dm["outer_radius"] == pytest.approx(CREASE / v**2 * d.sensitivity["outer_radius"])


def test_a_mixed_range_keeps_the_wrinkle_first_design(mixed):
    d = mixed
    assert d.status == FOUND and d.margin > 0 and d.verdict["kind"] == "bifurcation"
    assert d.value > CREASE  # reached before the crease (lambda_z falls)
    assert d.crease_margin == pytest.approx((d.value - CREASE) / d.value, rel=1e-9)
    assert d.crease_margin >= d.margin and d.limited_by == "mode"
    # the stretch control has its amplitude equation now: the only warning is its branch's
    assert d.verdict["branch"] in ("supercritical", "subcritical")
    assert ("subcritical" in observable(d.verdict)) == (d.verdict["branch"] == "subcritical")
    assert "crease" not in observable(d.verdict)
    (region,) = d.as_dict()["region"]
    assert region["crease_first"] == "part" and region["crease_first_points"] == [2, 3]
    # --koiter: the stretch control's amplitude equation of the axisymmetric mode is there
    assert d.verdict["branch_note"] == "" and d.verdict["koiter"] is not None


def test_cli_json_best_has_the_verdict(capsys):
    args = ["design", "--solve-for", "stretch", "--side", "compression", "--target", "0", "1"]
    args += ["--vary", "outer_radius", "1.9", "2.0", "--points", "2", "--m-max", "2"]
    args += ["--n-max", "2", "--length", "1", "--json"]
    assert main(args) == 0
    out = json.loads(capsys.readouterr().out)
    best = out["best"]
    assert out["status"] == "crease_first" and best["limited_by"] == "crease"
    assert best["crease_value"] == pytest.approx(CREASE, rel=1e-12)
    v = best["verdict"]
    assert v["kind"] == "crease" and v["crease"]["trigger"] == "axial"
    assert {"value", "face", "meaning", "wrinkle", "branch", "koiter", "branch_note"} <= set(v)
    assert v["branch"] is None and v["branch_note"] == "not asked (--koiter)"
    assert out["region"][0]["crease_first"] == "all"


def test_text_says_it(creased, mixed):
    text = "\n".join(summary(creased))
    assert "creases first everywhere; nearest design" in text and "to the crease" in text
    assert "verdict at the design: the inner face creases" in text
    assert "the target pattern may not be observed" in text
    assert "(a face creases first at 3 of its 3 points)" in text
    text = "\n".join(summary(mixed))
    assert "best design" in text and "creases first" not in text.split("best design")[1][:80]
    assert "branch not computed" not in text


def test_map_crease_first_everywhere():
    """Two variables, the same tubes: every raster point of the target's region creases
    first; the nearest design's margin is the gap to the closed-form crease, and the
    verdict there is the crease."""
    from electrogrowth.design.mode_map import mode_map
    from electrogrowth.design.prescribe_map import prescribe_map

    near = ScanOptions((0, 1), (1, 1), extend=False)
    vary = (("outer_radius", 1.75, 2.0), ("length", 0.95, 1.05))
    tube = Tube.uniform()
    mm = mode_map(tube, "stretch", vary, side="compression", points=2, options=near, certify=2)
    d = prescribe_map(tube, (0, 1), mm, options=near)
    assert d.status == CREASE_FIRST and d.limited_by == "crease"
    assert d.region_crease["crease_first"] == "all"
    at = tube.at("outer_radius", d.x).at("length", d.y)
    v = critical_value(at, 0, 1, "stretch", side="compression").value
    assert d.crease_value == pytest.approx(CREASE, rel=1e-12)
    assert d.margin == pytest.approx(-(CREASE - v) / v, rel=1e-8)
    best = d.as_dict()["best"]
    assert best["verdict"]["kind"] == "crease" and best["limited_by"] == "crease"


def test_region_creases_counts_points_not_rows():
    """A located switch is two rows of one x: an interval holding one grid point and two
    switches said [0, 5] (probe round 7b); it is 3 points, the switch ends counted once."""
    from types import SimpleNamespace

    import numpy as np

    from electrogrowth.design.onset import region_creases

    x = np.array([0.0, 0.5, 0.5, 1.0, 1.5, 1.5, 2.0])
    first = np.array([False, False, True, False, True, True, False])
    curve = SimpleNamespace(x=x, crease=SimpleNamespace(first=first))
    iv = SimpleNamespace(lo=0.5, hi=1.5)
    assert region_creases([iv], curve) == [{"crease_first": "part", "crease_first_points": [2, 3]}]


def test_a_field_crease_does_not_steer_the_design_to_a_masked_crease():
    """Probe 8b D1: along Vbar 0.70 .. 0.76 the growth target (0, 1) of Tube.uniform(1.8)
    was "found" at Vbar = 0.76 with crease_value NaN: from Vbar ~ 0.73 on the field
    criterion is met at g = 1, and that advisory crease was all crease_onset computed, so
    the margin saw no crease there. The outer face creases at g ~ 1.80 (Brent on the base
    state's lambda_r / lambda_z = 2.4), before the wrinkle everywhere: crease_first."""
    from scipy.optimize import brentq

    from electrogrowth.design.onset import crease_value
    from tests.bifurcation.test_crease import _outer_axial_ratio

    tube = Tube.uniform(1.8, length=1.0)
    at = tube.at("voltage", 0.76)
    exact = brentq(lambda g: _outer_axial_ratio(at, g) - CREASE_RATIO, 1.5, 1.89, xtol=1e-13)
    assert crease_value(at, "growth", None, 1.0) == pytest.approx(exact, rel=1e-10)
    options = ScanOptions((0, 3), (1, 3))
    d = prescribe(tube, "growth", (0, 1), ("voltage", 0.70, 0.76), points=3, options=options)
    assert d.status == CREASE_FIRST, (d.status, d.x, d.value, d.crease_value)
    g_crease = brentq(lambda g: _outer_axial_ratio(tube.at("voltage", d.x), g) - 2.4, 1.5, 1.89)
    assert d.crease_value == pytest.approx(g_crease, abs=1e-8) and g_crease < d.value


def test_the_crease_rival_looks_only_as_far_as_asked(monkeypatch):
    """CreaseRival (a design's crease, cached per design): before ``until`` only, a march
    not repeated for an ``until`` it has passed, and a crease once found kept for any."""
    from electrogrowth.design import onset

    marches = []
    value = onset.crease_value
    monkeypatch.setattr(onset, "crease_value", lambda *a: marches.append(a[-1]) or value(*a))
    rival = onset.CreaseRival(
        lambda x: Tube.uniform(2.0, length=x), "stretch", "compression", -1.0
    )
    assert rival.value(1.0, until=0.7) == -math.inf
    assert rival.value(1.0, until=0.8) == -math.inf and marches == [0.7]  # looked past 0.8
    assert rival.value(1.0, until=0.5) == pytest.approx(CREASE, rel=1e-10)
    assert rival.value(1.0) == rival.value(1.0, until=0.9) and marches == [0.7, 0.5]
