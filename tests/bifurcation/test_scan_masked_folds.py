"""A scan must not stop at a low mode when a thin stiff film's folds, beyond the scanned
ranges and their probes, come first.

The scan widens its ranges (and searches m or n coarse-to-fine up to 2000) only when its
best mode sits on an edge or a short-wave probe (2 and 4 times the range) wins. A film
that folds at m or n in the hundreds to thousands is far from those probes, whose values
are much later; a low mode of the whole tube (Euler buckling (1, 1) of a long tube, the
collapse (2, 0) under an external pressure) that comes after the film's folds but before
the probes then ends the scan, and it is reported as the first mode with status OK.

Found by probing (round 5, mode choice of scans), each against single-mode solves:

* a neo-Hookean film [1, 1.001], 1000 times as stiff as its substrate to Rbar_o = 2.4,
  L = 28.7: under axial compression the scan reports (1, 1) at lambda_z = 0.98416 (strain
  1.6 %); the rings (0, 1300) buckle at lambda_z = 0.99306 (strain 0.69 %) and (0, 600)
  at 0.98941, both earlier. Under axial growth of the film (growth[1].z) the scan reports
  (1, 1) at g_z = 1.05188; the rings (0, 1317) at g_z = 1.00639 (the growth strain 8 times
  smaller). (Under isotropic growth a probe wins and the rings (0, 1316) are found.)
* a neo-Hookean film [1.999, 2], 100 times as stiff as its substrate [1, 1.999], L = 5,
  the inner pressure lowered (side compression, collapse): the scan reports (2, 0) at
  P_i = -0.39929; the folds (621, 0) come at P_i = -0.17518, at less than half the load
  (and (466, 0) at -0.0726 for Rbar_o = 1.5, where the scan reports (2, 0) at -0.0960).
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, scan_modes

LONG = Tube((Layer(1.001, shear_modulus=1000.0), Layer(2.4)), length=28.7, stretch=1.0)
SKINNED = Tube((Layer(1.999), Layer(2.0, shear_modulus=100.0)), length=5.0, stretch=1.0)


def test_rings_of_a_film_under_axial_compression_come_before_euler_buckling():
    ring = critical_value(LONG, 0, 1300, "stretch", side="compression")
    assert ring.value == pytest.approx(0.99305946, abs=1e-7)
    scan = scan_modes(LONG, "stretch", side="compression")
    assert scan.critical.value >= ring.value - 1e-9  # compression: reached first is larger


def test_rings_of_a_film_growing_axially_come_before_euler_buckling():
    ring = critical_value(LONG, 0, 1317, "growth[1].z")
    assert ring.value == pytest.approx(1.00639221, abs=1e-7)
    scan = scan_modes(LONG, "growth[1].z")
    assert scan.critical.value <= ring.value + 1e-9


def test_folds_of_a_film_under_external_pressure_come_before_collapse():
    fold = critical_value(SKINNED, 621, 0, "pressure", side="compression")
    assert fold.value == pytest.approx(-0.17517548, abs=1e-7)
    scan = scan_modes(SKINNED, "pressure", side="compression")
    assert scan.critical.value >= fold.value - 1e-9  # the pressure falls from 0
