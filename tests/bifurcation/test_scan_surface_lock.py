"""A scan's short-wave (surface) check must not end the scan at a Gent lock far beyond the
first finite wrinkle.

A film 0.0038 thick with mu 4109 on a Gent core (jm = 79.19, Rbar 1 to 3.277), its hoop
growth increasing: prismatic folds come first, near m = 105 at g_theta = 1.0068 (single
critical values: (100, 0) 1.0068764, (107, 0) 1.0068424 on the three-layer twin below; the
flat film-on-substrate wavelength 2 pi t (mu_f / 3 mu_s)^(1/3) predicts m = 107), and
``ScanOptions(surface=False)`` finds them.

Found by probing: with the default surface check the scan raises ConvergenceError "base
state not resolved at growth[2].theta = 4.2495 while marching from 1 (no surface instability
before it)": the march for the short-wave limit runs on towards the substrate's lock instead
of stopping at the best finite mode's value. The same for every ScanOptions tried (default,
m 0..64) and on the three-layer tube of the probe (core split 1.036 / 2.520, g_theta 4.55).
"""

import dataclasses

import pytest

from electrogrowth import Layer, ScanOptions, Tube, gent, scan_modes

CORE = gent(79.1911)
FILM_ON_GENT = Tube(
    (Layer(3.2766482246969275, CORE), Layer(3.2804001750679137, CORE, 4108.780169865253)),
    length=10.0,
    stretch=1.0,
)
OPTIONS = ScanOptions(m_range=(2, 12), n_range=(1, 2))


@pytest.mark.slow
def test_surface_check_stops_at_the_first_wrinkle():
    without = scan_modes(
        FILM_ON_GENT, "growth[2].theta", options=dataclasses.replace(OPTIONS, surface=False)
    ).critical
    crit = scan_modes(FILM_ON_GENT, "growth[2].theta", options=OPTIONS).critical
    assert crit.kind == "bifurcation"
    assert (crit.m, crit.n) == (without.m, without.n)
    assert crit.value == pytest.approx(without.value, rel=1e-10)
