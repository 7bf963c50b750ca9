"""A named target set whose modes a scan examines but never ranks among its six earliest:
the closest design, as for the same modes listed (found by probing: "not_reached", x = NaN).
The design now ranks a set's modes further (a scan with TOP_MAX runners-up) at an x where
none of them is among the six; the earliest competitors decide the margin."""

from __future__ import annotations

import math

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, prescribe

#: a stiff film (50 times the substrate) growing isotropically: rings (0, n) and
#: checkerboards (m, n) come first, the prismatic folds (m, 0) wrinkle later (g ~ 1.19 for
#: (12, 0) against ~ 1.048 for (0, 4)) and never within a scan's six earliest
FILM = Tube([Layer(1.03, shear_modulus=50.0), Layer(2.2)], length=1.0, stretch=1.0)
OPTIONS = ScanOptions((0, 14), (1, 8), extend=False, surface=False, torsional=False)


@pytest.mark.slow
def test_a_named_target_set_that_is_never_first_gives_its_closest_design():
    """docs/design.md: "not_reached" means no target mode is among the scanned modes at
    all; here the scans do examine the prismatic modes (they bifurcate, at finite g), so the
    answer is the closest design, "not_first", as for the single mode (12, 0) or a list of
    prismatic modes, which do give it (the same x, mode and margin, checked)."""
    d = prescribe(FILM, "growth[1]", "prismatic", ("length", 1.0, 1.1), points=2, options=OPTIONS)
    assert d.status == "not_first", d.status
    assert d.mode is not None and d.mode[1] == 0
    assert d.margin < 0
    direct = critical_value(FILM.at("length", d.x), *d.mode, "growth[1]", rtol=1e-12)
    assert math.isclose(d.value, direct.value, rel_tol=1e-8)
    listed = [(m, 0) for m in range(2, 15)]  # the same modes, listed: solved directly
    same = prescribe(FILM, "growth[1]", listed, ("length", 1.0, 1.1), points=2, options=OPTIONS)
    assert (same.status, same.mode) == (d.status, d.mode)
    assert same.x == pytest.approx(d.x, rel=1e-8) and same.margin == pytest.approx(d.margin)
