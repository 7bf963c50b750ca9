"""Modes the impedance kernel cannot integrate (incremental/targets.py ``_retry``): a batch
whose sample fails again at a tighter tolerance goes to collocation at once, at the nodes
that resolve each mode, with the kernel's signs where the kernel can still say."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth import Tube, gent, solve_base_state
from electrogrowth.errors import CollocationTooLarge, ConvergenceError
from electrogrowth.incremental import targets
from electrogrowth.incremental.targets import RETRY_SAMPLE, CollocationTarget, impedance_targets

#: an ungrown Gent tube (J_m 4) compressed axially towards its lock at lambda_z = LOCK
#: (tests/bifurcation/test_surface_to_lock.py): its incremental moduli (~1 / margin^2) make
#: short axial waves (n >= 25) stiff for the explicit kernel. 1e-3 above the lock they fail
#: at rtol 1e-5 (too many steps) and integrate at 1e-7; 6e-7 above it (the margin
#: 1 - (I1 - 3) / J_m is 1e-6, the last state a march reads) they fail at every tolerance
LOCK = 0.28916854644830997
NEAR_LOCK = Tube.uniform(3.0, material=gent(4.0))
MODES = np.array([[0.0, 27.0], [2.0, 28.0], [4.0, 29.0], [6.0, 30.0], [1.0, 26.0], [3.0, 30.0]])


def _counted(monkeypatch) -> list:
    tried = []
    serial = targets._serial

    def counted(state, modes, tables, rtol, max_steps):
        tried.append(modes.shape[0])
        return serial(state, modes, tables, rtol, max_steps)

    monkeypatch.setattr(targets, "_serial", counted)
    return tried


def test_a_batch_the_tighter_tolerance_rescues_is_integrated_whole(monkeypatch):
    state = solve_base_state(NEAR_LOCK.at("stretch", LOCK * (1 + 1e-3)))
    tried = _counted(monkeypatch)
    f = impedance_targets(state, MODES, rtol=1e-5)
    assert tried == [RETRY_SAMPLE, len(MODES) - RETRY_SAMPLE]
    # the kernel's own values at 1e-7 (not collocation's, which are normalised otherwise)
    assert np.isfinite(f).all() and (f > 0).all()
    assert (f != [CollocationTarget(1e-7)(state, row[None])[0] for row in MODES]).all()


def test_a_hopeless_batch_skips_the_tighter_tolerances(monkeypatch):
    state = solve_base_state(NEAR_LOCK.at("stretch", LOCK * (1 + 6e-7)))
    tried = _counted(monkeypatch)
    f = impedance_targets(state, MODES, rtol=1e-5)
    # the sample of the first tighter tolerance, and nothing more: every one failed again
    assert tried == [RETRY_SAMPLE]
    expected = [CollocationTarget(1e-5)(state, row[None])[0] for row in MODES]
    np.testing.assert_array_equal(f, expected)
    assert (f > 0).all()  # the modes are stable next to the lock (no face wrinkles, J_m 4)


def test_a_step_size_underflow_is_not_integrated_again_at_the_same_tolerance(monkeypatch):
    # rtol 1e-12: both tighter levels are the floor 1e-14, the second with 5 times the
    # steps. The integration is deterministic: only a run that ran out of steps can end
    # otherwise with more of them (1e-5 above the lock these modes do, at 500000 steps)
    state = solve_base_state(NEAR_LOCK.at("stretch", LOCK * (1 + 6e-7)))
    tried = _counted(monkeypatch)
    with pytest.raises(CollocationTooLarge, match="step size underflow, also at tighter"):
        impedance_targets(state, MODES[:1], rtol=1e-12)  # its moduli's table needs more
    assert tried == [1]  # was [1, 0, 1, 0]: the underflow at 1e-14 integrated again


def test_a_wall_the_axes_call_elliptic_but_the_field_does_not_is_refused(monkeypatch):
    # past growth 2.029 the dielectric bilayer's inner layer has a negative hoop
    # permittivity (tests/incremental/test_halfspace.py) while its six shear moduli stay
    # above 0.17 of its own: the fallback collocated mode (7, 4) there, its sign changing
    # with the nodes, and the critical value ended "inaccurate" at 2.2773 after 190 s
    # (check round 24, D2)
    from tests.incremental.test_halfspace import CONTROL, DIELECTRIC_BILAYER

    state = solve_base_state(DIELECTRIC_BILAYER.at(CONTROL, 2.2965))
    asked = []
    monkeypatch.setattr(targets, "collocation_targets", lambda *a, **k: asked.append(a))
    with pytest.raises(ConvergenceError, match="not strongly elliptic .layer 1 at R = 1: a real"):
        impedance_targets(state, np.array([[7.0, 4.0]]), rtol=1e-12)
    assert asked == []  # no collocation read where no target means anything
