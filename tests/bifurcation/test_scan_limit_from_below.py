"""A soft lining (shear modulus 1e-2 on a substrate of 1, [1, 1.01] in [1, 3]) reaches its
free face's short-wave limit from below: its folds (m, 0) with m ~ 800-1030 and its rings
(0, n) with n ~ 300-340 come 2.5e-4 to 3.2e-3 before the exact limit (collocation agrees
with them to 1e-12), while the flat film never comes before Biot's limit (the tube's
O(1/k) corrections do). The scan returned the limit (kind "surface", status ok) with the
folds unchecked, by three paths of bifurcation/scan.py (probe 13b):

* D1: no scanned mode bifurcates (m <= 12, n <= 2): the ``except NoBifurcationFound``
  branch of scan_modes returned the limit with no look beyond the ranges; without the
  surface it raised "no mode bifurcates", which is false;
* D2: the limit came before the scanned modes: ``_widened_scan.limit_stands`` read the
  modes beyond along m only, and the rings along n came first;
* D3: the scanned best came after the limit on no edge: ``_with_short_waves`` returned the
  limit, ``_beyond_value`` having skipped the check since the face was past its limit.

Now every path goes through scan._folds_before_limit (both axes read at the limit).
"""

import numpy as np
import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, scan_modes
from electrogrowth.bifurcation.beyond import unstable_past_cap
from electrogrowth.bifurcation.options import M_CAP, N_CAP, mode_caps
from electrogrowth.cli.app import main
from electrogrowth.incremental.modes import MODE_MAX

SOFT = Layer(1.01, shear_modulus=1e-2)
SHORT = ScanOptions(m_range=(0, 12), n_range=(1, 2))


def _is_first(scan, m, n, solve_for, side=None):
    """The scan's critical mode is the finite mode (m, n), solved alone, and the limit it
    computed comes after it."""
    c = scan.critical
    want = critical_value(scan.critical.params, m, n, solve_for, side=side).value
    assert c.kind == "bifurcation" and (c.m, c.n) == (m, n) and c.status == "ok"
    assert c.value == pytest.approx(want, rel=1e-10)
    sense = -1.0 if side == "compression" else 1.0
    assert scan.short_wave_limit is not None and (scan.short_wave_limit - c.value) * sense > 0


def test_no_scanned_mode_folds_beyond_before_the_limit():
    """D1: was surface 1.8245777636, no runners-up; (1028, 0) comes at 1.8239095766."""
    tube = Tube([SOFT, Layer(3.0)], stretch=1.0)
    _is_first(scan_modes(tube, "growth[1].theta", options=SHORT), 1028, 0, "growth[1].theta")


def test_no_scanned_mode_without_the_surface_finds_the_folds():
    """D1, options.surface False: raised NoBifurcationFound "between 1 and 6"."""
    tube = Tube([SOFT, Layer(3.0)], stretch=1.0)
    options = ScanOptions(m_range=(0, 12), n_range=(1, 2), surface=False)
    scan = scan_modes(tube, "growth[1].theta", options=options)
    c = scan.critical
    assert (c.kind, c.m, c.n) == ("bifurcation", 1028, 0) and scan.short_wave_limit is None
    assert not scan.surface_instability


def test_limit_before_the_scanned_modes_rings_beyond_come_first():
    """D2: was surface 1.8317856539 (m checked only); (0, 340) comes at 1.8313272644."""
    tube = Tube([SOFT, Layer(3.0)], stretch=1.0, length=1.0)
    _is_first(scan_modes(tube, "growth[1].z"), 0, 340, "growth[1].z")


def test_face_past_its_limit_at_the_scanned_best_folds_come_first():
    """D3: was surface P_i = -0.3888920984 (runners-up (2, 0), (3, 0)); (811, 0) comes at
    -0.38764313 (the probe's (810, 0) at -0.38764315 is its neighbour)."""
    grown = Layer(1.01, shear_modulus=1e-2, growth=(1, 1.5, 1))
    tube = Tube([grown, Layer(3.0)], stretch=1.0)
    scan = scan_modes(tube, "pressure", side="compression")
    _is_first(scan, 811, 0, "pressure", side="compression")


def test_limit_not_ok_when_a_turned_mode_beyond_is_not_found(monkeypatch):
    """The rule's guard: a mode beyond the ranges is past its root at the limit but the
    search beyond finds none (faked here: _searched as if the march met no root). The limit
    cannot then be the first instability for sure: it is returned INACCURATE, saying why,
    not "ok" (D1's tube had it ok, with (1028, 0) 3.7e-4 earlier)."""
    import electrogrowth.bifurcation.scan as scan

    monkeypatch.setattr(scan, "_searched", lambda *args, **kwargs: (args[3], False))
    tube = Tube([SOFT, Layer(3.0)], stretch=1.0)
    c = scan_modes(tube, "growth[1].theta", options=SHORT).critical
    assert c.kind == "surface" and c.value == pytest.approx(1.8245777636, rel=1e-9)
    assert c.status == "inaccurate" and "past its root" in c.message


SOFT_TOML = """[[layers]]
outer_radius = 1.01
shear_modulus = 1e-2
[[layers]]
outer_radius = 3.0
shear_modulus = 1.0
"""


@pytest.mark.slow  # 20 s of collocation over 6003 modes
def test_cli_certify_no_longer_passes_the_limit(tmp_path, capsys):
    """D1 by the CLI: `--certify` said "no finite mode was reached before the end of the
    march, none to certify" and the limit 1.82457776364, exit 0. It now certifies the
    fold (1028, 0) at 1.82390957658."""
    path = tmp_path / "soft.toml"
    path.write_text(SOFT_TOML)
    argv = ["critical", "--tube", str(path), "--solve-for", "growth", "--layer", "1"]
    assert main(argv + ["--component", "theta", "--n-max", "2", "--certify"]) == 0
    out = capsys.readouterr().out
    assert "(m, n) = (1028, 0)" in out and "1.82390957658" in out
    assert "certified by collocation: 1.8239095" in out


#: check round 34: a lining 1e-3 thick and 1e4 times softer than its tube, grown in its hoop
#: direction; and a three-layer tube with such a lining, grown isotropically
THIN = Tube((Layer(1.001, shear_modulus=1e-4), Layer(2.0)), length=3.0, stretch=1.0)
STACK = Tube(
    (Layer(1.00104, shear_modulus=1e-4), Layer(1.34004), Layer(2.48, shear_modulus=10.0)),
    length=3.59,
    stretch=1.0,
)


@pytest.fixture
def caps_of_2000(monkeypatch):
    """Every tube's caps at 2000, as they were before each tube had its own
    (options.mode_caps): these linings then stand for one thinner than its own caps."""
    import electrogrowth.bifurcation.beyond as beyond
    import electrogrowth.bifurcation.scan as scan

    monkeypatch.setattr(scan, "mode_caps", lambda tube: (M_CAP, N_CAP))
    monkeypatch.setattr(beyond, "mode_caps", lambda tube: (M_CAP, N_CAP))


#: (tube, control, the fold, the independent solver's sample on its row (check round 34))
FOLDS = [
    (THIN, "growth[1].theta", (12836, 0), (13000, 1.8376895409025)),
    (STACK, "growth[1]", (6107, 0), (6000, 1.4986160054)),
]


def test_the_caps_are_chosen_by_the_thinnest_layer():
    """m = FOLD_KH R / h and n = FOLD_KH L / (pi h) of the thinnest layer, never below 2000
    nor above MODE_MAX; a uniform tube and thick layers keep 2000."""
    assert mode_caps(THIN) == (64064, 61115) and mode_caps(STACK) == (61602, 70322)
    assert mode_caps(Tube.uniform(1.01, 100.0)) == (M_CAP, N_CAP)
    assert mode_caps(Tube([Layer(1.1, shear_modulus=5.0), Layer(1.5)], length=2.0)) == (2000, 2000)
    assert mode_caps(Tube([Layer(1 + 1e-7), Layer(2.0)])) == (MODE_MAX, MODE_MAX)


def test_a_fold_past_2000_is_solved_alone():
    """The single mode (13000, 0) of the lining 1e-3 thick (refused past m = 2000 before):
    the independent solver's value to 1e-11 (own base state, multi-domain collocation)."""
    c = critical_value(THIN, 13000, 0, "growth[1].theta")
    assert c.status == "ok" and c.value == pytest.approx(1.8376895409025, rel=1e-11)


@pytest.mark.parametrize(("tube", "solve_for", "fold", "sample"), FOLDS)
def test_the_fold_is_the_least_of_its_neighbours(tube, solve_for, fold, sample):
    """The fold numbers by brute force: the single modes m - 3 ... m + 3 at rtol 1e-13 lie
    on a parabola (its vertex within half a step of m) whose least integer is the fold; the
    neighbours differ by ~2e-12 (12836) and 1.5e-11 (6107), above the roots' errors."""
    m0, n = fold
    ms = np.arange(m0 - 3, m0 + 4)
    vs = np.array([critical_value(tube, int(m), n, solve_for, rtol=1e-13).value for m in ms])
    assert ms[np.argmin(vs)] == m0
    a, b, _ = np.polyfit(ms - m0, vs - vs[3], 2)
    assert a > 0 and abs(b / (2 * a)) < 0.5


@pytest.mark.slow  # ~10 s each, and 20 s of it on a loaded machine
@pytest.mark.parametrize(("tube", "solve_for", "fold", "sample"), FOLDS)
def test_a_lining_1e3_thick_is_scanned_to_its_fold(tube, solve_for, fold, sample):
    """D4 (check round 34): the scan returned the inner face's limit, status ok (then
    INACCURATE), while an independent solver puts folds beyond m = 2000 first, (13000, 0)
    5.6e-5 and (6000, 0) 9.7e-5 before the limit. With the tube's own caps (64064, 61603)
    the search finds the least of their rows, (12836, 0) and (6107, 0), status ok, below the
    independent samples (which match the single modes, test above) and the limit."""
    scan = scan_modes(tube, solve_for)
    c = scan.critical
    assert (c.kind, c.m, c.n, c.status) == ("bifurcation", *fold, "ok")
    alone = critical_value(tube, *fold, solve_for).value
    assert c.value == pytest.approx(alone, rel=1e-12)
    m, value = sample
    assert critical_value(tube, m, 0, solve_for).value == pytest.approx(value, rel=1e-10)
    assert value - 3e-7 < c.value < value and c.value < scan.short_wave_limit
    assert scan.caps == mode_caps(tube)


@pytest.mark.parametrize(
    ("tube", "solve_for", "limit"),
    [(THIN, "growth[1].theta", 1.8377451822596504), (STACK, "growth[1]", 1.4987126069243817)],
)
def test_a_lining_too_thin_for_its_caps_is_not_ok_at_its_limit(
    tube, solve_for, limit, caps_of_2000
):
    """The read past the caps, the safety net beyond them: with the caps faked at 2000 for
    every tube (as before the caps were the tube's), the scan's limit is INACCURATE, naming
    a mode past the caps that is past its root there (check round 34's D4 as it was)."""
    c = scan_modes(tube, solve_for).critical
    assert c.kind == "surface" and c.value == pytest.approx(limit, rel=1e-10)
    assert c.status == "inaccurate" and "beyond the largest m = 2000" in c.message


@pytest.mark.parametrize(
    ("tube", "solve_for", "before", "past"),
    [(THIN, "growth[1].theta", 1.8376, 1.8377), (STACK, "growth[1]", 1.4986, 1.49862)],
)
def test_the_ladder_past_the_caps_turns_where_the_independent_folds_are(
    tube, solve_for, before, past, caps_of_2000
):
    """The samples beyond the caps of 2000 (m and n to 64 times them) at a value just
    before the independent solver's earliest fold (1.8376895409, 1.4986160054) are all
    stable, and one is past its root just after it: the sign change is the folds', not the
    ladder's noise."""
    assert unstable_past_cap(tube, solve_for, before, True) is None
    m, n = unstable_past_cap(tube, solve_for, past, True)
    assert m > 2000 or n > 2000


def test_a_layered_finite_mode_is_read_past_the_caps_and_a_uniform_one_is_not(monkeypatch):
    """The routing of the check past the caps (its physics: the two tests above): a layered
    tube's finite critical mode is read there (a fold beyond the caps before it makes it
    INACCURATE, an upper bound), a uniform tube's is not (no layer thin against the caps;
    its scans would pay for the read). The read is faked here to report a turned mode."""
    import electrogrowth.bifurcation.scan as scan

    calls = []

    def turned(params, solve_for, value, prismatic):
        calls.append(value)
        return (4000, 0)

    monkeypatch.setattr(scan, "unstable_past_cap", turned)
    bilayer = Tube([Layer(1.1, shear_modulus=5.0), Layer(1.5)], stretch=1.0, length=2.0)
    c = scan_modes(bilayer, "growth[1].theta", options=SHORT).critical
    assert c.kind == "bifurcation" and calls == [c.value]
    assert c.status == "inaccurate" and "mode (4000, 0), beyond the largest m" in c.message
    calls.clear()
    c = scan_modes(Tube.uniform(1.4, 1.0), "growth", options=SHORT).critical
    assert c.kind == "bifurcation" and c.status == "ok" and calls == []


def test_certify_reads_past_2000_on_the_searched_rows_only():
    """A scan's ranges now reach its tube's caps (m to 64064 here), searched along a few
    rows: certify's choice reads every mode up to 2000 as before, and past it those rows at
    the search's samples and every m within 64 of the critical mode, not the 1.9 million
    modes of the rectangle (an hour of reads)."""
    from electrogrowth.bifurcation.certify import choice_modes
    from electrogrowth.bifurcation.scan_grid import every_mode_ranges, scan_grid
    from electrogrowth.bifurcation.scan_record import ScanResult

    crit = critical_value(THIN, 12836, 0, "growth[1].theta", rtol=1e-8)
    scan = ScanResult(crit, (), (0, 64064), (1, 30))
    assert every_mode_ranges(scan.m_range, scan.n_range) == ((0, 2000), (1, 30))
    modes = choice_modes(scan, crit, (True, True))
    rows = {tuple(map(int, r)) for r in modes}
    assert {tuple(map(int, r)) for r in scan_grid((0, 2000), (1, 30), False, (True, True))} <= rows
    assert all((m, 0, 1) in rows for m in range(12836 - 64, 12836 + 65))  # prismatic row
    assert (64064, 0, 1) in rows and (64064, 1, 0) in rows and (5000, 7, 0) not in rows
    assert len(modes) < 63000
