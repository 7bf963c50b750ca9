"""A scan whose march steps over many roots at once (a film's rings, a film's folds at a
tie) must still report the first modes (found by probing, round 6b, 2026-12-05).

continuation/events.py `_pack` selected the first ``need`` candidates by the loose (rtol
1e-5) signs and called the others LATER, and bifurcation/march.py `_advance` ended every
LATER mode; loose signs cannot order roots closer than their error (a film's modes 1e-8
apart). Now the LATER candidates whose loose value at the need-th root found is small are
asked again with the fine target there, and those past zero are finished
(events._later_before)."""

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, scan_modes

CTRL = "growth[1].z"


def rings_tube():
    # film [1, 1.005], 300 times as stiff as its substrate to R = 2, L = 10, axial growth
    return Tube(
        [Layer(1.005, shear_modulus=1.0, growth=(1, 1, 1.0)), Layer(2.0, shear_modulus=1 / 300)],
        length=10.0,
        stretch=1.0,
    )


def test_single_mode_values():
    t = rings_tube()
    assert critical_value(t, 0, 142, CTRL).value == pytest.approx(1.0151618028419804, rel=1e-10)
    assert critical_value(t, 1, 137, CTRL).value == pytest.approx(1.0151850310547879, rel=1e-10)


@pytest.mark.parametrize("top", [1, 2])
def test_scan_with_small_top_finds_the_rings(top):
    s = scan_modes(rings_tube(), CTRL, options=ScanOptions(top=top))
    # was: (1, 137) at 1.0151850310547879, status ok (2.3e-5 later than the rings)
    assert (s.critical.m, s.critical.n) == (0, 142)


def test_grid_scan_top1():
    opts = ScanOptions(m_range=(0, 12), n_range=(1, 240), extend=False, surface=False, top=1)
    s = scan_modes(rings_tube(), CTRL, options=opts)
    # was: (8, 135) at 1.0156123520, status ok
    assert (s.critical.m, s.critical.n) == (0, 142)


def test_runners_up_are_the_next_modes():
    opts = ScanOptions(m_range=(0, 12), n_range=(1, 240), extend=False, surface=False, top=5)
    s = scan_modes(rings_tube(), CTRL, options=opts)
    # was: (0,141), (0,143), (2,132) 1.0152642, (7,136) 1.0155027; (0,140) 1.0151636508
    # and (0,144) 1.0151662549 (single-mode solves) come before both of the last two
    assert [(r.m, r.n) for r in s.runners_up] == [(0, 141), (0, 143), (0, 140), (0, 144)]


def test_default_scan_runners_up_L14():
    """Default ScanOptions (top = 5), the same film at L = 14: rings (0, 198)."""
    t = Tube(
        [Layer(1.005, shear_modulus=1.0, growth=(1, 1, 1.0)), Layer(2.0, shear_modulus=1 / 300)],
        length=14.0,
        stretch=1.0,
    )
    s = scan_modes(t, CTRL)
    assert (s.critical.m, s.critical.n) == (0, 198)
    # was: (0,199), (0,197), (4,185) 1.0153401, (9,189) 1.0157242; single-mode solves give
    # (0,200) 1.0151629506 and (0,196) 1.0151636508 before them
    assert [(r.m, r.n) for r in s.runners_up] == [(0, 199), (0, 197), (0, 200), (0, 196)]


def test_default_scan_runners_up_outer_skin_rings():
    """An outer skin [1.995, 2] 300 times as stiff as its substrate, axial growth, L = 10,
    Vbar = 0.03, default ScanOptions: the critical rings (0, 136) are right, but the
    runners-up skip (0, 137) and (0, 138)."""
    t = Tube(
        [Layer(1.995, shear_modulus=1 / 300), Layer(2.0, shear_modulus=1.0, growth=(1, 1, 1.0))],
        length=10.0,
        stretch=1.0,
        voltage=0.03,
    )
    s = scan_modes(t, "growth[2].z")
    assert (s.critical.m, s.critical.n) == (0, 136)
    # single-mode solves (rtol 1e-12): (0,137) 1.0267322732, (0,135) 1.0267331412,
    # (0,138) 1.0267338557, (0,134) 1.0267356331; was (0,135), (0,134), (0,133), (1,133)
    assert [(r.m, r.n) for r in s.runners_up] == [(0, 137), (0, 135), (0, 138), (0, 134)]


def test_default_scan_of_a_stiff_film_misses_the_prismatic_row():
    """Film [1, 1.001] (mu 0.96211174) on a substrate to 4 (mu 1e-4), hoop growth, L = 1:
    the design `prescribe(..., (70, 0), ('layers[1].shear_modulus', 0.9, 1.1))` chose this
    tube. Default scan: (70, 1) at 1.0252541172, status ok; single-mode (70, 0) is
    1.0252281869 (2.5e-5 earlier), (69, 0) and (71, 0) 1.0252334281. The m search
    (msearch._first, top = 3) packs its 32 candidates by loose signs and kills the prismatic
    row as LATER; with the LATER candidates re-checked by fine signs at the need-th root the
    scan returns (70, 0)."""
    t = Tube(
        [
            Layer(1.001, shear_modulus=0.9621117397985697, growth=(1, 1.0, 1)),
            Layer(4.0, shear_modulus=1e-4),
        ],
        length=1.0,
        stretch=1.0,
    )
    c = critical_value(t, 70, 0, "growth[1].theta")
    assert c.value == pytest.approx(1.0252281869261022, rel=1e-10)
    s = scan_modes(t, "growth[1].theta")
    assert (s.critical.m, s.critical.n) == (70, 0)  # was (70, 1)
