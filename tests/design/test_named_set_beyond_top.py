"""A named target set none of whose modes is among a scan's first TOP_MAX (1000) is ranked
by solving its members directly (probe round 7b): 'axisymmetric' on a film 0.008 thick and
100 times as stiff as its substrate, where the 65 x 31 folds and wrinkles of the scan come
before any ring, was 'not_reached' with the advice to widen --m-max / --n-max (widening made
it worse). Its rings are reached, never first: the window's (0, 30) at 1.3660721 at
thickness 0.0083 by a direct solve; past the window (probe 13c), its closest ring is
(0, 117) at 1.1408283 at thickness 0.0081, M = -0.0598."""

import math

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value
from electrogrowth.design import prescribe
from electrogrowth.design.prescribe import set_members
from electrogrowth.design.targets import check_target
from electrogrowth.errors import NoBifurcationFound

FILM = Tube((Layer(1.01, growth=(1, 1.0, 1)), Layer(3.0, shear_modulus=0.01)), length=10.0)
HOOP, THICK = "growth[1].theta", "layers[1].thickness"
OPTIONS = ScanOptions((0, 64), (1, 30))


def test_a_sets_members_are_the_scanned_modes_it_accepts():
    assert set_members(check_target("axisymmetric"), OPTIONS) == tuple(
        (0, n) for n in range(1, 31)
    )
    assert set_members(check_target((3, 1)), OPTIONS) == ()  # a list is solved as listed
    assert set_members(check_target("prismatic"), ScanOptions((0, 2000), (1, 2))) == ()


@pytest.mark.slow
def test_rings_reached_behind_a_thousand_modes_are_not_first():
    d = prescribe(FILM, HOOP, "axisymmetric", (THICK, 0.0081, 0.0083), options=OPTIONS, points=3)
    assert d.status == "not_first"
    assert d.mode[0] == 0 and math.isfinite(d.value) and d.margin < 0
    at = FILM.at(THICK, d.x)
    assert d.value == pytest.approx(critical_value(at, *d.mode, HOOP).value, rel=1e-10)
    rings = [p.value for n in range(1, 31) if (p := _ring(at, n)) is not None]
    assert d.value < min(rings)  # past the window's edge ring (0, 30): the set's, not its
    assert d.mode[1] > 30
    for n in (d.mode[1] - 1, d.mode[1] + 1):  # the set's closest ring: its neighbours later
        assert _ring(at, n).value > d.value


def _ring(tube, n):
    """The critical point of (0, n), or None where it never bifurcates (long rings)."""
    try:
        return critical_value(tube, 0, n, HOOP)
    except NoBifurcationFound:
        return None
