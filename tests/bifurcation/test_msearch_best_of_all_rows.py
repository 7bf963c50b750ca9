"""The m search's best is the earliest mode it found on any row, and never a rigid motion.

Found by probing (round 8b, 2026-12-06):

* D2: bifurcation/msearch.py `_search` returned as `best` the refinement's best on the
  samples' best row, (16, 1) at 2.48025, while its `found` list (after `_neighbourhood`
  marched every row) started with (17, 0) at 2.46173; scan._searched compared the scan's
  critical (14, 1) at 2.46765 with that `best` alone and kept (14, 1), status OK, with
  (17, 0) among its own runners-up.
* D11: with m range (0, 1) the search started at the scanned edge m = 1 on the prismatic
  row too and marched (1, 0), a rigid translation of the cross-section: the march read the
  unloaded tube as "already unstable in mode (1, 0)" and the scan blamed the user ("start
  from a stable state")."""

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, scan_modes
from electrogrowth.bifurcation import msearch
from electrogrowth.bifurcation.march import ModeValue
from electrogrowth.incremental.targets import Family

THETA = "growth[1].theta"
PRISMATIC, WRINKLE = Family.PRISMATIC.code, Family.WRINKLE.code


def _row_values(m, n):
    """A sharp prismatic minimum at m = 17 that the geometric samples (8, 10, 12, 16, 20, ...)
    miss, and a shallow wrinkle row n = 1 whose minimum at 16 wins among the samples."""
    return 1.9 + 0.2 * abs(m - 17) if n == 0 else 2.0 + 1e-3 * (m - 16) ** 2


def test_the_best_is_the_earliest_found_on_any_row(monkeypatch):
    def first(params, solve_for, side, rows, rtol, ks, only=None, *, axis="m", top=3):
        modes = [(k, n, code) for k in ks for n, code in (only or rows)]
        ordered = sorted(modes, key=lambda mode: _row_values(*mode[:2]))[:top]
        fam = {PRISMATIC: "prismatic", WRINKLE: "wrinkle"}
        return [ModeValue(m, n, _row_values(m, n), fam[code]) for m, n, code in ordered]

    monkeypatch.setattr(msearch, "_first", first)
    rows = [(0, PRISMATIC), (1, WRINKLE)]
    found = msearch.search_m(None, THETA, None, rows, 8, 40, 1e-10, top=3)
    assert (found.best.m, found.best.n) == (17, 0)  # was (16, 1), behind its own found[0]
    assert found.best == found.found[0]


def _bilayer(p):
    return Tube(
        [Layer(1.1, shear_modulus=10.0), Layer(2.0)], length=1.0, stretch=1.0, inner_pressure=p
    )


def test_the_scan_critical_mode_comes_before_its_runners_up():
    """Bilayer (mu 10 | 1) under inner pressure 0.1545, m range (8, 16): the scan reported
    (14, 1) at 2.4676498389 with (17, 0) at 2.4617339052 among its runners-up."""
    s = scan_modes(_bilayer(0.1545), THETA, options=ScanOptions((8, 16), (1, 1)))
    v17 = critical_value(_bilayer(0.1545), 17, 0, THETA, rtol=1e-12).value  # 2.4617339052
    assert (s.critical.m, s.critical.n) == (17, 0)
    assert s.critical.value == pytest.approx(v17, rel=1e-9, abs=0)
    assert all(s.critical.value <= r.value for r in s.runners_up)


def test_the_search_never_marches_the_rigid_translation(monkeypatch):
    """From the edge m = 1 the prismatic row starts at m = 2 ((1, 0) is a rigid
    translation, (0, 0) the base state's own limit point); the wrinkles start at the edge."""
    marched = []

    def first_bifurcations(params, solve_for, side, modes, *args, **kwargs):
        marched.extend(tuple(int(x) for x in mode) for mode in modes)
        raise msearch.NoBifurcationFound("none")

    monkeypatch.setattr(msearch, "first_bifurcations", first_bifurcations)
    monkeypatch.setattr(msearch, "_stable", lambda modes, targets: None)
    rows = [(0, PRISMATIC), (1, WRINKLE)]
    with pytest.raises(msearch.NoBifurcationFound):
        msearch.search_m(None, "stretch", "compression", rows, 1, 40, 1e-10)
    assert (1, 0, PRISMATIC) not in marched and (2, 0, PRISMATIC) in marched
    assert (1, 1, WRINKLE) in marched


def test_a_scan_with_m_range_0_1_is_not_refused_for_the_rigid_translation():
    """A film-lined tube, stable at lambda_z = 1: the scan with m range (0, 1) raised
    "the tube is already unstable in mode (1, 0) (prismatic) at stretch = 1"; with m range
    (0, 2) (or extend=False) it gives (0, 14) at 0.9415611881."""
    t = Tube(
        [Layer(1.0297005688638941, shear_modulus=43.95917035609731), Layer(2.0555259436628885)],
        length=3.0,
        stretch=1.0,
    )
    s = scan_modes(t, "stretch", side="compression", options=ScanOptions((0, 1), (14, 15)))
    assert (s.critical.m, s.critical.n) == (0, 14)
    assert s.critical.value == pytest.approx(0.9415611881, abs=1e-9)
