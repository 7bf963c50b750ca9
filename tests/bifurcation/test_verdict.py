"""One verdict per result (bifurcation/verdict.py): what comes first of a wrinkle, a crease
and the threshold, and the runner-up of each kind.

The geometry check of docs/derivation-crease.md: the paper's ungrown, uncharged tubes
(L = 1) compressed axially wrinkle first at Rbar_o = 1.6 and crease first at 1.8 and 2.0;
the crease value is the closed form 2.4^(-2/3) of the homogeneous state, the wrinkle the
scan's (checked by the independent collocation in the slow test).
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import iv, kv

from electrogrowth import Layer, Tube
from electrogrowth.bifurcation.crease import CREASE_RATIO
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.options import ScanOptions
from electrogrowth.bifurcation.scan import scan_modes
from electrogrowth.bifurcation.verdict import Rival, judge
from electrogrowth.outcomes import Kind

SMALL = ScanOptions(m_range=(0, 3), n_range=(1, 3), extend=False)
CREASE = CREASE_RATIO ** (-2 / 3)  # lambda_z where lambda_r / lambda_z = 2.4, homogeneous


def bessel_axisymmetric(lz, outer_radius, length=1.0, n=1):
    """det of the face conditions of the axisymmetric mode (0, n) of a homogeneous
    neo-Hookean tube (g = 1, Vbar = 0) at axial stretch lz: zero at its bifurcation.

    docs/derivation-crease.md section 7: lambda_r = lambda_theta = l = lz^(-1/2), radii
    r = l R; U = A I1(kr) + B K1(kr) + C I1(eta k r) + D K1(eta k r), eta = lz / l, with
    P / mu = k (l^2 - lz^2) (A I0 - B K0) and W = -(U' + U/r) / k; the faces need
    2 l^2 U' - P / mu = 0 and W' - k U = 0.
    """
    lam = lz**-0.5
    eta, k, c = lz / lam, n * math.pi / (lz * length), lam**2 - lz**2
    d_i1 = lambda s: iv(0, s) - iv(1, s) / s  # noqa: E731
    d_k1 = lambda s: -kv(0, s) - kv(1, s) / s  # noqa: E731
    rows = []
    for r in (lam, lam * outer_radius):
        x, y = k * r, eta * k * r
        du = [k * d_i1(x), k * d_k1(x), eta * k * d_i1(y), eta * k * d_k1(y)]
        p = [k * c * iv(0, x), -k * c * kv(0, x), 0.0, 0.0]
        rows.append([2 * lam**2 * a - b for a, b in zip(du, p)])
        rows.append(
            [
                -2 * k * iv(1, x),
                -2 * k * kv(1, x),
                -k * (1 + eta**2) * iv(1, y),
                -k * (1 + eta**2) * kv(1, y),
            ]
        )
    return np.linalg.det(np.array(rows))


def bessel_wrinkle(outer_radius) -> float:
    """The first root of :func:`bessel_axisymmetric` below lambda_z = 1."""
    xs = np.linspace(0.99, 0.3, 346)
    ds = [bessel_axisymmetric(x, outer_radius) for x in xs]
    i = next(i for i in range(len(xs) - 1) if ds[i] * ds[i + 1] < 0)
    return brentq(bessel_axisymmetric, xs[i + 1], xs[i], args=(outer_radius,), xtol=1e-15)


def _scan(outer_radius, options=SMALL):
    return scan_modes(
        Tube.uniform(outer_radius, length=1.0), "stretch", side="compression", options=options
    )


@pytest.mark.parametrize(
    ("outer_radius", "first"), [(1.6, "bifurcation"), (1.8, "crease"), (2.0, "crease")]
)
def test_the_papers_ungrown_tubes_wrinkle_or_crease_first(outer_radius, first):
    res = _scan(outer_radius)
    v = res.verdict
    assert v.kind == first
    assert v.crease.value == pytest.approx(CREASE, rel=1e-12)
    assert (v.crease.face, v.crease.trigger) in {("inner", "axial"), ("outer", "axial")}
    assert v.wrinkle.value == res.critical.value and (v.wrinkle.m, v.wrinkle.n) == (0, 1)
    assert v.wrinkle.value == pytest.approx(bessel_wrinkle(outer_radius), rel=1e-10)
    # the verdict is no closer than the criterion's accuracy
    assert abs(v.wrinkle.value - v.crease.value) > 2 * v.crease.error_estimate
    assert v.threshold is None and v.branch is None and v.koiter is None
    other = v.crease if first == "bifurcation" else v.wrinkle
    assert v.runners_up == (other,)
    assert ("creases" in v.meaning) == (first == "crease")


def test_a_single_mode_has_its_verdict():
    c = critical_value(Tube.uniform(1.8, length=1.0), 0, 1, "stretch", side="compression")
    assert c.kind == "bifurcation"  # the linear result's kind is unchanged
    assert c.verdict.kind == "crease" and c.verdict.value == pytest.approx(CREASE, rel=1e-12)
    assert c.verdict.wrinkle.value == c.value


def test_the_voltage_threshold_is_a_runner_up():
    c = critical_value(Tube.uniform(1.4, length=1.0), 0, 1, "voltage")
    t = c.verdict.threshold
    assert t is not None and t.kind == "threshold" and t.detail == "voltage asymptote"
    # the neo-Hookean asymptote (basestate.tube.neo_hookean_asymptote, closed form)
    g, ro = 1.0, 1.4
    asym = g**2 / (ro - 1) * math.sqrt((ro**2 - 1) * math.log(ro) / 2)
    assert t.value == pytest.approx(asym, rel=1e-10)
    assert c.verdict.kind == "bifurcation" and c.verdict.crease.trigger == "field"


def test_judge_orders_along_the_march():
    w = Rival(Kind.BIFURCATION, 1.2, m=2, n=1)
    c = Rival(Kind.CREASE, 1.3, 0.01, face="outer", trigger="prismatic")
    t = Rival(Kind.THRESHOLD, 1.25, detail="voltage limit point")
    up = judge(None, wrinkle=w, crease=c, threshold=t, name="g")
    assert up.kind == "bifurcation" and [r.kind for r in up.runners_up] == ["threshold", "crease"]
    down = judge("compression", wrinkle=w, crease=c, threshold=t)
    assert down.kind == "crease" and down.face == "outer"
    assert [r.kind for r in down.runners_up] == ["threshold", "bifurcation"]
    tie = judge(None, wrinkle=w, crease=Rival(Kind.CREASE, 1.2, 0.01, face="inner"))
    assert tie.kind == "bifurcation"  # a tie goes to the linear result
    none = judge(None)
    assert none.kind == "none" and math.isnan(none.value)


def test_a_crease_within_its_accuracy_of_the_wrinkle_is_too_close_to_call():
    w = Rival(Kind.BIFURCATION, 1.205, m=2, n=1)
    c = Rival(Kind.CREASE, 1.2, 0.01, face="inner", trigger="axial")
    v = judge(None, wrinkle=w, crease=c)
    assert v.kind == "crease" and "too close to call" in v.meaning
    assert "too close" not in judge(None, wrinkle=Rival(Kind.BIFURCATION, 1.5), crease=c).meaning


def test_the_json_record_gives_the_verdict_at_the_top():
    rec = _scan(1.8).as_dict()
    assert rec["kind"] == rec["verdict"] == "crease" and rec["face"] in ("inner", "outer")
    assert rec["value"] == pytest.approx(CREASE, rel=1e-12) == rec["stretch"]
    assert rec["m"] is None and rec["n"] is None and rec["method"] == "crease criterion"
    assert rec["wrinkle"]["kind"] == "bifurcation" and (
        rec["wrinkle"]["m"],
        rec["wrinkle"]["n"],
    ) == (0, 1)
    assert rec["crease"]["trigger"] == "axial" and rec["threshold"] is None
    assert rec["branch"] is None and rec["koiter"] is None and rec["meaning"]
    first = _scan(1.6).as_dict()
    assert first["kind"] == "bifurcation" and (first["m"], first["n"]) == (0, 1)
    assert first["crease"]["value"] == pytest.approx(CREASE, rel=1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("outer_radius", [1.6, 1.8, 2.0])
def test_the_wrinkles_of_the_geometry_check_by_collocation(outer_radius):
    """The wrinkle values of the table in docs/derivation-crease.md by the independent
    discretisation, and their side of the crease value."""
    tube = Tube.uniform(outer_radius, length=1.0)
    col = critical_value(tube, 0, 1, "stretch", side="compression", method="collocation")
    imp = _scan(outer_radius).critical
    assert col.value == pytest.approx(imp.value, rel=1e-8)
    assert (col.value > CREASE) == (outer_radius == 1.6)


def test_a_failed_crease_march_leaves_the_linear_result_standing(monkeypatch):
    from electrogrowth.bifurcation import verdict as verdict_module
    from electrogrowth.errors import ConvergenceError

    def fails(*args, **kwargs):
        raise ConvergenceError("the bracketed root solve failed on [0.5, 0.6]")

    monkeypatch.setattr(verdict_module, "crease_onset", fails)
    c = critical_value(Tube.uniform(1.8, length=1.0), 0, 1, "stretch", side="compression")
    v = c.verdict
    assert v.kind == "bifurcation" and v.value == c.value and v.crease is None
    assert v.criterion.startswith("crease criterion not evaluated: the bracketed root")
    assert v.meaning.endswith("(crease not evaluated)")


def test_a_crease_by_the_field_criterion_informs_but_never_comes_first():
    """The field criterion is a bonded, unstretched film's (derivation-crease.md): for the
    thick stretched tube under voltage it is reached at Vbar = 0.406, before the wrinkle at
    0.4999; the wrinkle stays first and the meaning notes the field."""
    w = Rival(Kind.BIFURCATION, 0.4999, m=30, n=0, family="prismatic")
    c = Rival(Kind.CREASE, 0.406, 0.003, face="inner", trigger="field")
    v = judge(None, wrinkle=w, crease=c, name="Vbar")
    assert v.kind == "bifurcation" and v.value == 0.4999 and v.crease is c
    assert "note: the inner face's field" in v.meaning and "next" not in v.meaning
    alone = judge(None, crease=c, name="Vbar")
    assert alone.kind == "none" and alone.crease is c and "0.406" in alone.meaning
    axial = Rival(Kind.CREASE, 0.406, 0.003, face="inner", trigger="axial")
    assert judge(None, wrinkle=w, crease=axial).kind == "crease"  # a mechanical one does


def test_the_mechanical_crease_ranks_beside_a_field_crease_met_at_the_start():
    """Probe 8b D1: Tube.uniform(1.8, L = 1, Vbar = 0.75) under growth was judged to wrinkle
    smoothly in (0, 1) at g = 1.8957 (the field criterion, met at g = 1, was the only crease
    computed and is advisory); its outer face creases at g = 1.80202 before that (Brent on
    the base state's lambda_r / lambda_z = 2.4). The crease now comes first; the field's is
    a note (``field_crease``), and the verdict no longer flips between Vbar 0.70 and 0.75."""
    from tests.bifurcation.test_crease import _outer_axial_ratio

    for voltage in (0.70, 0.75):
        tube = Tube.uniform(1.8, length=1.0, voltage=voltage)
        exact = brentq(lambda g, t=tube: _outer_axial_ratio(t, g) - CREASE_RATIO, 1.5, 1.89)
        v = critical_value(tube, 0, 1, "growth").verdict
        assert v.wrinkle.value > exact + 0.05
        assert (v.kind, v.face, v.crease.trigger) == ("crease", "outer", "axial")
        assert v.value == pytest.approx(exact, abs=1e-8), v.meaning
    assert v.field_crease.trigger == "field" and v.field_crease.value == 1.0
    assert "note: the inner face's field reaches" in v.meaning
    assert v.as_dict()["field_crease"]["trigger"] == "field"


def test_the_meaning_does_not_round_the_onset_to_the_start():
    """Probe 12b, D2: the meaning printed every value with 4 digits whatever its estimate: a
    film's onset g_cr = 1.00027786548 (estimate 5e-12) read "at growth[1] = 1", the unloaded
    tube's growth, where the march starts. Now the digits its estimate supports."""
    film = Tube([Layer(1.0026, shear_modulus=8000.0), Layer(2.7)], length=170.0)
    c = critical_value(film, 1, 1, "growth[1]")
    assert c.value == pytest.approx(1.00027786548, abs=1e-10) and c.error_estimate < 1e-10
    assert "(1, 1) wrinkles smoothly at growth[1] = 1.00027786548 (" in c.verdict.meaning


def test_the_meaning_tells_the_first_event_from_the_next_and_the_start():
    """Probe 12b, D2: a surface result and the next mode 6.5e-5 apart both read 0.7961; a
    value whose estimate supports 4 digits (1.0003 +- 1e-3) read "1", the start; a value
    without an estimate keeps 4 digits unless they print it as the start."""
    surface = Rival(Kind.SURFACE, 0.79606346300, 7e-11, face="outer")
    ring = Rival(Kind.BIFURCATION, 0.79612846, 1e-5, m=0, n=120, family="wrinkle")
    v = judge(None, surface=surface, wrinkle=ring, name="Vbar", start=0.0)
    assert "outer face at Vbar = 0.796063463;" in v.meaning  # its estimate's digits
    assert "(0, 120) at Vbar = 0.79613" in v.meaning  # 4 digits would be 0.7961 too
    loose = Rival(Kind.BIFURCATION, 1.00027786548, 1e-3, m=1, n=1, family="wrinkle")
    assert "= 1.0003" in judge(None, wrinkle=loose, name="g", start=1.0).meaning
    lost = Rival(Kind.THRESHOLD, 1.01966699017, None, detail="voltage threshold")
    assert "Vbar = 1.02 before" in judge(None, threshold=lost, name="Vbar", start=0.0).meaning
    near = Rival(Kind.THRESHOLD, 1.0000002, None, detail="no axisymmetric state")
    assert "g = 1.0000002 before" in judge(None, threshold=near, name="g", start=1.0).meaning


def test_one_mode_asked_for_is_not_said_to_be_the_tubes_first():
    """Probe round 12a (doubt 3): `critical --mode 12 0` on the mucosa example said "the tube
    wrinkles smoothly in mode (12, 0)" while (11, 0) comes first; only a scan can say which
    mode is the tube's first, and its verdict still does."""
    from electrogrowth import Tube, critical_value, scan_modes
    from electrogrowth.bifurcation.options import ScanOptions

    tube = Tube.uniform(1.4, 1.0, voltage=0.4)
    one = critical_value(tube, 1, 1, "growth").verdict.meaning
    assert one.startswith("mode (m, n) = (1, 1) wrinkles smoothly at g = ")
    assert "the mode asked for: a scan says whether another mode comes first" in one
    scan = scan_modes(tube, "growth", options=ScanOptions((0, 2), (1, 2)))
    assert scan.verdict.meaning.startswith("the tube wrinkles smoothly in mode (m, n) = (0, 1)")


def test_a_crease_or_threshold_before_the_one_mode_asked_for_is_not_before_any_wrinkle():
    """Probe 13c, D1: `critical --mode 0 1` of Tube.uniform(1.5, length 8) in compression
    said "the inner face creases ... at lambda_z = 0.558 before any smooth wrinkle" while
    (1, 1) wrinkles at 0.901: with one mode asked for, no other wrinkle was looked at. A scan's
    verdict keeps the claim, which its own scan supports."""
    from electrogrowth.bifurcation.verdict import ONE_MODE

    ring = Rival(Kind.BIFURCATION, 0.4214, 1e-12, m=0, n=1, detail=ONE_MODE)
    crease = Rival(Kind.CREASE, 0.5579, 0.01, face="inner", trigger="axial")
    one = judge("compression", wrinkle=ring, crease=crease, name="lambda_z")
    assert "before any smooth wrinkle" not in one.meaning
    assert "before the mode asked for wrinkles (a scan says whether" in one.meaning
    lost = Rival(Kind.THRESHOLD, 0.3, None, detail="voltage threshold")
    ring_up = Rival(Kind.BIFURCATION, 0.5, 1e-12, m=0, n=1, detail=ONE_MODE)
    thr = judge(None, wrinkle=ring_up, threshold=lost, name="Vbar").meaning
    assert "before any crease or the mode asked for (a scan says" in thr
    scanned = Rival(Kind.BIFURCATION, 0.4214, 1e-12, m=0, n=1)
    crease_first = judge("compression", wrinkle=scanned, crease=crease, name="lambda_z")
    assert "before any smooth wrinkle" in crease_first.meaning
