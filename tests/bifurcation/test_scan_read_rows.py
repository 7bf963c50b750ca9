"""The read beyond a scan's ranges: which rows, which samples (beyond.py).

Two blind spots found by check round 35d (an independent solver's brute force over
40-541 modes per point), both failing on the code before:

* Q3, a film [1, 1.00462] (mu 529.19) grown in hoop inside a thin wall to R_o = 1.04692,
  L = 1: scanned as (11, 5) at 1.7169810360, status ok, while the wrinkle (15, 4) comes at
  1.7163264316 (3.8e-4 earlier). The read looked along m only at (m, 0) and (m, 1); the
  film's first modes lie about a circle (m / R)^2 + (n pi / L)^2 ~ k^2, and the row n = 4
  has its least m beyond the scan's m <= 12.
* Q7, an outer film [1.5, 1.503023] (mu 510.95) at L = 0.0243163: the fold (89, 0) comes
  1.8e-9 after the critical ring (0, 1) and before every runner-up, but was missing from
  them: at the last runner-up's value only m = 88, 89 of the fold row are unstable, between
  the read's samples 81 and 101.
"""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from electrogrowth import Layer, Tube, critical_value, scan_modes
from electrogrowth.bifurcation import beyond
from electrogrowth.bifurcation.beyond import (
    DENSE,
    ROWS_MAX,
    fold_windows,
    read_rows,
    window_samples,
)
from electrogrowth.incremental.targets import Family

Q3 = Tube(
    (Layer(1.00462, shear_modulus=529.192723), Layer(1.0469154832357013)),
    length=1.0,
    stretch=1.0,
)
Q7 = Tube(
    (Layer(1.5), Layer(1.503023, shear_modulus=510.954039)),
    length=0.024316287421031473,
    stretch=1.0,
)
#: check round 36a's W1t: a film in a thin wall whose first modes lie on rows n = 2 ... 5,
#: all beyond m <= 12; the scan of m <= 12 puts (11, 1) first
W1T = Tube(
    (Layer(1.005411, shear_modulus=621.894), Layer(1.05273)),
    length=1.30134731463049,
    stretch=1.0,
)
#: its first five modes by the checker's own solver (a first-order compound-matrix
#: integration, two tolerances agreeing to 5e-13; the rectangle m <= 2 m*, n <= 40 of all
#: three families read by sign with an own collocation)
W1T_FIRST = {
    (15, 3): 1.8539003284137825,
    (15, 4): 1.85390032891339,
    (14, 2): 1.8542436237987643,
    (14, 5): 1.854617273975306,
    (16, 4): 1.8546504699831132,
}
WRINKLE, PRISMATIC = Family.WRINKLE.code, Family.PRISMATIC.code


class _Mode:
    """A scan's critical mode, as read_rows sees it."""

    def __init__(self, m, n, family="wrinkle"):
        self.m, self.n, self.family = m, n, family


def _modes(scan):
    c = scan.critical
    return [(c.m, c.n)] + [(r.m, r.n) for r in scan.runners_up]


def test_a_wrinkle_off_the_fold_rows_is_found():
    """Q3: the scan's first mode is (15, 4), the wrinkle the read now sees on the row of the
    critical mode's neighbouring n, at its value solved alone; (14, 4) next, then the
    scanned (11, 5) and (16, 3) (check round 36a's brute force over every mode)."""
    scan = scan_modes(Q3, "growth[1].theta")
    c = scan.critical
    assert (c.m, c.n, c.status) == (15, 4, "ok")
    alone = critical_value(Q3, 15, 4, "growth[1].theta").value
    assert c.value == pytest.approx(alone, rel=1e-12)
    assert c.value == pytest.approx(1.7163264315760, rel=1e-11)
    assert _modes(scan)[1] == (14, 4)
    # then (11, 5) and (16, 3), tied (the tube is at their switch), on a row the search
    # for (15, 4) did not follow: read again at the last runner-up's value
    assert set(_modes(scan)[2:4]) == {(11, 5), (16, 3)}


def test_a_narrow_fold_before_the_runners_up_is_listed():
    """Q7: the ring (0, 1) first, then the folds (89, 0) and (88, 0) (dense read of the fold
    window), then (1, 1); each at its value alone."""
    scan = scan_modes(Q7, "growth[2]")
    assert _modes(scan)[:4] == [(0, 1), (89, 0), (88, 0), (1, 1)]
    fold = scan.runners_up[0]
    alone = critical_value(Q7, 89, 0, "growth[2]").value
    assert fold.value == pytest.approx(alone, rel=1e-12)
    assert 0 < fold.value - scan.critical.value < 1e-8


def test_rows_turned_after_a_search_are_read_and_searched():
    """W1t: the first read (around the scanned (11, 1)) turns the row n = 2, whose search
    gives (14, 2); read again, the row n = 3 gives (15, 3); read at the last runner-up's,
    the rows n = 4 and 5 give (15, 4), (14, 5), (16, 4). Before, the scan put (11, 1)
    first, 1.2e-3 late, and missed all five."""
    scan = scan_modes(W1T, "growth[1].theta")
    assert scan.critical.status == "ok"
    got = {(v.m, v.n): v.value for v in (scan.critical, *scan.runners_up)}
    assert set(got) == set(W1T_FIRST)
    assert _modes(scan)[:3] == [(15, 3), (15, 4), (14, 2)]  # gaps 2.7e-10, 1.9e-4
    for mode, value in W1T_FIRST.items():
        assert got[mode] == pytest.approx(value, rel=1e-11)


def test_the_rows_read_reach_the_first_modes_neighbours():
    """Along m: the fold rows, then every n up to the largest n of the first modes + 1;
    along n: m_lo, m_lo + 1, then every m up to their largest m + 1; where those are many,
    the rows next to each mode and ROWS_MAX - 3 samples between."""
    rows = read_rows([_Mode(11, 5)], (0, 12), (1, 30), True, "m")
    assert rows == [(1, WRINKLE), (0, PRISMATIC)] + [(n, WRINKLE) for n in range(2, 7)]
    # W1t: its runner-up (11, 6) takes the rows to n = 7, (14, 5) among them
    more = read_rows([_Mode(15, 3), _Mode(11, 6)], (0, 12), (1, 30), True, "m")
    assert more == rows + [(7, WRINKLE)]
    assert read_rows([_Mode(7, 0, "prismatic")], (0, 12), (1, 30), True, "m") == rows[:2]
    assert read_rows((), (0, 12), (2, 30), False, "m") == [(2, WRINKLE)]
    along_n = read_rows([_Mode(11, 5)], (0, 12), (1, 30), True, "n")
    assert along_n[:2] == [(0, WRINKLE), (1, WRINKLE)]
    assert {(10, WRINKLE), (11, WRINKLE), (12, WRINKLE)} <= set(along_n)
    assert len(along_n) - 2 <= ROWS_MAX
    many = read_rows([_Mode(3, 40), _Mode(4, 20)], (0, 12), (1, 50), True, "m")
    near = {(n, WRINKLE) for n in (19, 20, 21, 39, 40, 41)}
    assert near <= set(many) and len(many) - 2 <= ROWS_MAX - 3 + len(near)


def test_fold_windows_hold_the_films_folds():
    """The window of Q7's film (ratio 511 over its substrate, h = 3.0e-3 at R = 1.5) holds
    its fold m = 89, and the flat film's k h (3 mu_s / mu_f)^(1/3) R / h = 89.5; a uniform
    tube, or identical layers, have none."""
    (lo, hi), *more = fold_windows(Q7, "m")
    assert not more and lo < 89 < hi and hi / lo == pytest.approx(6.25, rel=0.05)
    assert fold_windows(Tube.uniform(outer_radius=1.5), "m") == []
    split = Tube((Layer(1.2), Layer(1.5)), length=1.0)
    assert fold_windows(split, "m") == fold_windows(split, "n") == []


@given(
    lo=st.integers(1, 10**5),
    ratio=st.floats(1.0, 10.0),
    edge=st.integers(0, 10**5),
)
def test_window_samples_are_dense(lo, ratio, edge):
    """Inside a window, beyond the edge, neighbouring samples are at most DENSE apart (or
    next integers), and the window's ends are sampled."""
    hi = int(lo * ratio)
    got = window_samples([(lo, hi)], edge, 10**6)
    first = max(lo, edge + 1)
    if first > hi:
        assert got == []
        return
    assert got[0] == first and got[-1] == hi
    gaps = np.diff(got)
    assert np.all((gaps == 1) | (np.array(got[1:]) / np.array(got[:-1]) <= DENSE + 1e-9))


def test_unloaded_signs_remembered_mode_by_mode(monkeypatch):
    """The unloaded signs of a read are those of its modes computed together, whatever was
    asked before (each mode remembered alone)."""
    modes = np.array([(m, n, WRINKLE) for m in (13, 40, 90) for n in (1, 4)], float)
    monkeypatch.setattr(beyond, "_SIGNS", {})
    beyond._stable(modes[::2])
    mixed = beyond._stable(modes)
    monkeypatch.setattr(beyond, "_SIGNS", {})
    assert np.array_equal(mixed, beyond._stable(modes))
    assert set(np.unique(mixed)) <= {-1.0, 1.0}
