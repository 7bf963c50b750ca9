"""A voltage march whose branch ends at a Gent lock must still find an earlier wrinkle.

A stiff film (mu = 1) on a soft Gent substrate (mu = 0.01, jm = 27) under a radial voltage:
the voltage branch has no limit point, it runs to the substrate's lock (threshold kind
"locking"), where the base-state profile cannot be tabulated. Mode (11, 0) bifurcates well
before that, at Vbar = 0.146609015590: an independent solver (radial equilibrium of the
ideal dielectric by quadrature, Dorfmann-Ogden incremental equations in principal-stretch
moduli, shooting with Godunov orthonormalisation; it reproduces the paper's g_cr =
1.26611156226 of Tube.uniform(1.4, voltage=0.4)) puts its root at 0.14660901559012715, and
the package agrees to 1e-13 when given the bracket (0.12, 0.15).

Found by probing: without the bracket the march stepped past the root (the mode's target,
far from zero at the start, is sampled rarely) towards states next to the lock that no
rule resolves, and the ConvergenceError ended it ("base-state profile on [1.02, 3.6] not
resolved by Chebyshev degree 512"); scan_modes failed the same way. The march now takes its
last look at the last state it can resolve (bisected back from the first it cannot).
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, gent, scan_modes

FILM_ON_GENT = Tube((Layer(1.02), Layer(3.6, shear_modulus=0.01, material=gent(27.0))), length=3.6)


def test_wrinkle_before_the_lock_is_found():
    crit = critical_value(FILM_ON_GENT, 11, 0, "voltage")
    assert crit.kind == "bifurcation"
    assert crit.value == pytest.approx(0.14660901559012715, rel=1e-9)


def test_scan_before_the_lock_finds_the_first_wrinkle():
    # the scan's first mode is its own critical value, below (11, 0)'s: (1, 1) at
    # 0.114372965455 (collocation 0.114372965545, and the single mode agreed before). Until
    # 2026-12-05 the scan reported (4, 0) at 0.144125897376, then (0, 1) at 0.124561964718
    # (and so did this test): the voltage march's scale was 1 whatever the moduli, and it
    # sampled each mode every 0.25 in Vbar on a wall whose own voltage scale is 0.16
    # (model/controls.voltage_scale), missing (1, 1)'s window; before that, a pack of roots
    # crossed in one step ended (0, 1) unexamined (continuation/events._later_before)
    crit = scan_modes(FILM_ON_GENT, "voltage").critical
    assert (crit.m, crit.n, crit.kind) == (1, 1, "bifurcation")
    assert crit.value == pytest.approx(critical_value(FILM_ON_GENT, 1, 1, "voltage").value)
    assert crit.value == pytest.approx(0.114372965545, rel=1e-9)  # collocation's
    assert crit.value < critical_value(FILM_ON_GENT, 0, 1, "voltage").value < 0.146609015590
