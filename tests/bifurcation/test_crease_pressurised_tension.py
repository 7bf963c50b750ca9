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
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.crease import crease_onset
from electrogrowth.errors import BaseStateError
from electrogrowth.outcomes import Kind

PULLED = Tube([Layer(1.56)], length=4.0, axial_force=0.0, inner_pressure=0.15)


def test_the_wrinkle_itself_is_found():
    c = critical_value(PULLED, 0, 1, "force", side="extension")
    assert c.value == pytest.approx(13.2130553, rel=1e-8)


@pytest.mark.slow  # 30 s: the crease march in tension, bisecting for the loss
def test_no_crease_before_the_inflated_state_is_lost():
    """The faces do not crease before the pull thins the wall until P_i = 0.15 is the
    pressure threshold; the loss is located where the states end: one just before it
    solves, one just after raises BaseStateError (a state within the threshold's accuracy
    of P_i, r_i ~ 1e4 in the scan's tail, is one too)."""
    onset = crease_onset(PULLED, "force", side="extension")
    assert onset.kind == Kind.NONE and 13.2130553 < onset.threshold < 13.3
    below = PULLED.at("force", onset.threshold * (1 - 1e-6))
    assert solve_base_state(below).r_i > 1.0
    with pytest.raises(BaseStateError):
        solve_base_state(PULLED.at("force", onset.threshold * (1 + 1e-6)))


@pytest.mark.slow  # 5 s
def test_the_verdict_of_a_scan_in_tension_is_given():
    s = scan_modes(PULLED, "force", side="extension", options=ScanOptions((0, 4), (1, 3)))
    assert s.verdict.kind is not None
