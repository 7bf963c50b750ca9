"""The thin-film limit of a designed thickness (issue: pattern prescription, checks).

A stiff film [1, 1 + h] (mu = 1, hoop growth g) on a softer substrate to R = 3 (mu = 0.2,
ratio 5) folds into m prismatic folds for h between the switches m|m+1 and m-1|m of the
design sequence over the film's thickness. As h -> 0 the film is a flat film on an
unstressed half-space, which folds at the reference wavenumber K_c H = k_c h lambda_c^2
(tools/derive_film.py, docs/derivation-film.md: k h in the compressed film, whose
in-plane stretch is lambda and thickness H / lambda). A fold of the tube has the reference
wavenumber m / g (the film's stress-free hoop length 2 pi g at R = 1), so at the switch
between m and m + 1, where the two modes are equally critical on either side of the flat
optimum, (m + 1/2) h / g -> K_c H, with an error like h / R (the wall's curvature; the
asymmetry of the flat critical curve about its optimum adds only O(h^2)).

Measured (rtol 1e-12): X = (m + 1/2) h_s / g_s = 0.6718656 (m = 42, h_s = 0.019762),
0.6630941 (84, 0.0095768), 0.6588850 (168, 0.0047179): errors 0.01707, 0.00830, 0.00409
against K_c H = 0.6547935 (ratios 2.06, 2.03), and the extrapolation linear in h of the
last two 0.654798 (7e-6 from the flat value). The switch of the design sequence equals the
root of g_m(h) - g_(m+1)(h) found by Brent's method outside the design code to 1e-12.
"""

from __future__ import annotations

import pytest
from scipy.optimize import brentq

from electrogrowth import Layer, ScanOptions, Tube, critical_value
from electrogrowth.design.sequence import mode_sequence

#: the flat film on an unstressed half-space, mu_f / mu_s = 5, exact (tools/derive_film.py):
#: the optimal k h (h the current film thickness) and the film's critical stretch
FLAT_KH, FLAT_LAMBDA = 0.9323423285, 0.8380395060
FLAT_KH_REF = FLAT_KH * FLAT_LAMBDA**2  # K_c H in the film's stress-free reference
THETA = "growth[1].theta"
KEY = "layers[1].outer_radius"


def film(h: float) -> Tube:
    return Tube(
        [Layer(1 + h, shear_modulus=1.0, growth=(1, 1.0, 1)), Layer(3.0, shear_modulus=0.2)],
        length=1.0,
        stretch=1.0,
    )


def switch_guess(m: int) -> float:
    """Where m|m+1 should lie: the flat relation with its O(h) corrections of the measured
    trend (only to place a bracket 0.6 / m wide; the switch is found, not assumed)."""
    h = FLAT_KH_REF * 1.1932 / (m + 0.5)
    for _ in range(20):
        h = FLAT_KH_REF * (1 + 1.3 * h) * (1.1932 + 2.9 * h) / (m + 0.5)
    return h


def designed_switch(m: int) -> tuple[float, float]:
    """(h, g) of the switch m + 1 | m of the design sequence over the film's thickness."""
    guess = switch_guess(m)
    lo, hi = (1 + guess * (1 - s * 0.3 / (m + 0.5)) for s in (1, -1))
    options = ScanOptions((m - 1, m + 2), (1, 1), extend=False, surface=False, torsional=False)
    seq = mode_sequence(film(guess), THETA, (KEY, lo, hi), options=options, points=2)
    assert len(seq.switches) == 1, [s.as_dict() for s in seq.switches]
    sw = seq.switches[0]
    assert {tuple(sw.mode_before), tuple(sw.mode_after)} == {(m, 0), (m + 1, 0)}
    return sw.x - 1, sw.value


@pytest.mark.slow
def test_designed_thickness_tends_to_the_flat_film():
    rows = [(m, *designed_switch(m)) for m in (42, 84, 168)]
    x = [(m + 0.5) * h / g for m, h, g in rows]
    err = [v - FLAT_KH_REF for v in x]
    assert all(e > 0 for e in err)
    assert err[0] / err[1] == pytest.approx(2.0, abs=0.15)  # linear in h (h halves)
    assert err[1] / err[2] == pytest.approx(2.0, abs=0.15)
    (_, h1, _), (_, h2, _) = rows[1], rows[2]
    extrapolated = x[2] - (x[1] - x[2]) * h2 / (h1 - h2)
    assert extrapolated == pytest.approx(FLAT_KH_REF, rel=1e-4)


@pytest.mark.slow
def test_designed_switch_is_the_root_of_the_two_modes_difference():
    """The design's switch against Brent's method on g_m(h) - g_(m+1)(h), solved here."""
    m = 42
    h, g = designed_switch(m)

    def gap(hh):
        a = critical_value(film(hh), m, 0, THETA, rtol=1e-12).value
        return a - critical_value(film(hh), m + 1, 0, THETA, rtol=1e-12).value

    root = brentq(gap, h * 0.99, h * 1.01, xtol=1e-15, rtol=1e-14)
    assert root == pytest.approx(h, rel=1e-10)
    assert critical_value(film(root), m, 0, THETA, rtol=1e-12).value == pytest.approx(g, rel=1e-10)
