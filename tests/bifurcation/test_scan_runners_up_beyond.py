"""The runners-up of a scan are the modes that come next, not the next of the scanned grid.

Found by probing (round 5): a neo-Hookean film [1, 1.005], 128 times as stiff as its
substrate to Rbar_o = 2.4, L = 28.7, under axial compression. The scan's first mode (1, 1)
at lambda_z = 0.98297 is right; its runners-up are (1, 2) at 0.93460, the probes (0, 120)
at 0.92890 and (1, 120), and (0, 60), while the film's rings (0, 500) buckle at 0.97296,
before every one of them (the command line prints them as "next:"). The rings lie beyond
the n range (30) and its probes, which are marched only up to the first mode, so the list
is the next modes of the grid, said to be the next modes of the tube.
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, scan_modes

TUBE = Tube((Layer(1.005, shear_modulus=128.0), Layer(2.4)), length=28.7, stretch=1.0)


def test_the_first_runner_up_is_not_later_than_the_films_rings():
    scan = scan_modes(TUBE, "stretch", side="compression")
    assert (scan.critical.m, scan.critical.n) == (1, 1)
    ring = critical_value(TUBE, 0, 500, "stretch", side="compression")
    assert ring.value == pytest.approx(0.97296235, abs=1e-7)
    assert scan.runners_up[0].value >= ring.value - 1e-9  # compression: next is larger
