"""The crease onset of a pressurised tube pulled by an axial force (found by probing the
force-controlled designs, extension side). An inflated tube (P_i = 0.15, Rbar_o = 1.56,
free ends at F = 0) pulled in tension loses its inflated state where the axial force
thins the wall enough that P_i reaches the pressure threshold; the crease march bisects
for that loss and, at one of its midpoints, the base state's preparation raises a bare
ValueError of Brent's method ("f(a) and f(b) must have different signs") instead of a
BaseStateError. It escaped from the verdict of every scan, so ``electrogrowth critical
--solve-for force --side extension --outer-radius 1.56 --inner-pressure 0.15
--axial-force 0 --length 4 --mode 0 1`` ended in "internal error" (exit 1) and
``prescribe`` / ``mode_sequence`` along Rbar_o in [1.2, 1.8] crashed with a traceback,
while the wrinkle itself is fine: (0, 1) at F = 13.2130553."""

from __future__ import annotations

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, scan_modes
from electrogrowth.bifurcation.crease import crease_onset
from electrogrowth.errors import ElectrogrowthError

PULLED = Tube([Layer(1.56)], length=4.0, axial_force=0.0, inner_pressure=0.15)


def test_the_wrinkle_itself_is_found():
    c = critical_value(PULLED, 0, 1, "force", side="extension")
    assert c.value > 0


@pytest.mark.slow  # 10-15 s: the crease march in tension
def test_the_crease_onset_raises_no_bare_value_error():
    try:
        crease_onset(PULLED, "force", side="extension")
    except ElectrogrowthError:
        pass  # a failure the package names is acceptable; a bare ValueError is a bug


@pytest.mark.slow  # 5 s
def test_the_verdict_of_a_scan_in_tension_is_given():
    s = scan_modes(PULLED, "force", side="extension", options=ScanOptions((0, 4), (1, 3)))
    assert s.verdict.kind is not None
