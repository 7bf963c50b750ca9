"""The mode march far along a path with no threshold (march.FAR, predict.far_waits).

A one-layer tube whose energy stiffens with an I4 coupling has no voltage threshold: its
path runs to 1e3 voltage scales (model/controls.py). Its mode (6, 2) never bifurcates there;
the march and the short-wave march of the mode's ray (critical._surface_window) took steps
of at most 0.05 of the scale: 40008 base states, 267 s. Past FAR_FROM scales the steps now
grow to FAR of the distance marched where the target's last three samples allow it.
Targets that turn back toward zero far out are found as before: synthetic targets of the
voltage alone on the same path, whose roots are known in closed form.
"""

import dataclasses
import math

import numpy as np
import pytest

import electrogrowth.bifurcation.along as along
from electrogrowth import Material, Tube, critical_value
from electrogrowth.bifurcation.march import (
    FAR_FROM,
    MODE_STEPS,
    ONE_MODE_STEPS,
    first_bifurcations,
)
from electrogrowth.continuation.predict import closes_half, far_waits
from electrogrowth.errors import NoBifurcationFound

STIFF = Material("stiff", "(I1-3)/2 + 0.4*I5 + 0.1*I4")
#: free ends (the force 0): the reproducer of docs/reliability.md
TUBE = dataclasses.replace(Tube.uniform(1.38, material=STIFF), stretch=None, axial_force=0.0)
#: base states the march and the short-wave march may solve: the fix's 324 (was 40008)
BUDGET = 500


@pytest.fixture
def states(monkeypatch):
    """The voltages of the base states solved along the path."""
    solved = []
    solve = along.solve_base_state

    def counted(tube, *args, **kwargs):
        solved.append(float(tube.voltage))
        assert len(solved) <= 20 * BUDGET, "a runaway march"  # fails, rather than hangs
        return solve(tube, *args, **kwargs)

    monkeypatch.setattr(along, "solve_base_state", counted)
    return solved


def test_a_mode_that_never_bifurcates_reaches_the_far_end_in_few_states(states):
    """The answer is unchanged: no root up to the path's end, 1e3 voltage scales (1 here)."""
    with pytest.raises(NoBifurcationFound, match="between 0 and 1000"):
        critical_value(TUBE, 6, 2, "voltage")
    assert len(states) <= BUDGET
    assert max(states) == pytest.approx(1e3)


class VoltageTarget:
    """A synthetic target: a function of the voltage alone, the same for every mode row."""

    def __init__(self, g):
        self.g = g

    def __call__(self, state, modes):
        return np.full(len(modes), self.g(float(state.tube.voltage)))


def _march(g, steps, rows=1):
    modes = np.array([[1, 1]] * rows)
    return first_bifurcations(TUBE, "voltage", None, modes, VoltageTarget(g), steps=steps)


def rises_then_crosses(v):
    """Recedes from zero up to v = 250, turns back and crosses it at 250 + sqrt(72500)."""
    return 1.0 + v / 20.0 - (v / 100.0) ** 2


def window(v):
    """Falls toward zero from the start, negative on [598, 602] only: a window 4 scales wide
    where a step grown to FAR of the distance marched would be 60."""
    return ((v - 600.0) ** 2 - 4.0) / 3.6e5


@pytest.mark.parametrize("steps", [ONE_MODE_STEPS, MODE_STEPS])
@pytest.mark.parametrize(
    "g, root", [(rises_then_crosses, 250.0 + math.sqrt(72500.0)), (window, 598.0)]
)
def test_a_target_that_turns_back_far_out_is_found(states, g, root, steps):
    """Far from the start, the grown steps still find the first root, to Brent's tolerance,
    and shrink where the target closes on zero: the samples next to the root are dense."""
    res = first_bifurcations(
        TUBE, "voltage", None, np.array([[1, 1]]), VoltageTarget(g), steps=steps
    )
    assert res.found[0].value == pytest.approx(root, rel=1e-12)
    near = [v for v in states if 0 < root - v < 10.0]
    assert len(near) >= 3  # not one long step over the root


def test_the_grown_steps_find_the_root_the_old_steps_find(states):
    """A target that recedes, turns back and crosses zero at 30 scales, marched with and
    without the far steps (far = 0: the old rule, steps <= 0.05 of the scale): one root, to
    Brent's tolerance, in fewer states."""

    def g(v):
        return 1.0 + v / 10.0 - (v / 15.0) ** 2  # zero at 11.25 + 18.75

    new = _march(g, ONE_MODE_STEPS).found[0].value
    grown = len(states)
    states.clear()
    old = _march(g, dataclasses.replace(ONE_MODE_STEPS, far=0.0)).found[0].value
    assert new == pytest.approx(old, rel=1e-13)
    assert new == pytest.approx(30.0, rel=1e-13)
    assert grown < len(states) - 300  # 0.05 steps from FAR_FROM to 30: ~500 more


def test_far_waits_grow_only_on_the_parabolas_evidence():
    """far_waits: a steadily receding target may wait ``longest`` (at most twice its sample
    spacing); one whose parabola turns back toward zero waits less, down to ``base``; one
    with fewer than three samples waits ``base``."""
    x = np.array([[10.0, 10.0, 10.0, 10.0], [9.0, 9.0, 9.0, 9.0], [8.0, 8.0, 8.0, np.nan]])
    g = np.array([[3.0, 1.0, 1.0, 1.0], [2.0, 1.0, 1.2, 1.0], [1.0, 1.0, 1.2, np.nan]])
    # rising; flat; falling and curving down (q(t) = 1 - 0.3 t - 0.1 t^2); no third sample
    got = far_waits(x, g, 1.0, longest=1.5, base=0.05)
    assert got[0] == 1.5 and got[1] == 1.5 and got[3] == 0.05
    # the third: q falls by 0.675 > 1/2 over 1.5, by 0.28 over 0.75
    assert got[2] == 0.75 and not closes_half(x[:, 2:3], g[:, 2:3], 1.0, got[2:3])[0]
    assert closes_half(x[:, 2:3], g[:, 2:3], 1.0, np.array([1.5]))[0]
    assert FAR_FROM >= 5.0  # a growth path (5 scales) keeps its old steps


def noisy(v):
    """A loose target at the noise: the fine one below (~1e-7, positive everywhere) plus a
    wiggle of 3e-7, negative at every few samples (a stiffening tube's short waves far
    along its voltage path read so at the loose tolerance)."""
    return faint(v) + 3e-7 * math.sin(7.3 * v)


def faint(v):
    """The fine target: positive, falling slowly toward zero, no root."""
    return 1e-7 * (1.0 + 10.0 / (1.0 + v))


def test_a_loose_sign_at_the_noise_neither_ends_nor_holds_the_march(states):
    """A loose sample below zero where the fine value is not (events.first_roots: None) is
    recorded by its fine value, and the mode is sampled by its fine values from then on
    (march.Views.doubted), as is one whose loose dip the fine values do not show. Recorded
    as it was, its zero lay behind the march and held every later step at the smallest:
    a scan of the stiffening tube crept at Vbar ~ 35 (1e-4 of the scale a step, ~1e5 states
    to the end). No root: the path's end, 1e3, in a few hundred states."""
    modes = np.array([[1, 1], [2, 1]])
    with pytest.raises(NoBifurcationFound, match="between 0 and 1000"):
        first_bifurcations(
            TUBE, "voltage", None, modes, VoltageTarget(noisy), steps=MODE_STEPS,
            brent_targets=VoltageTarget(faint),
        )  # fmt: skip
    assert max(states) == pytest.approx(1e3)
    assert len(states) <= 2 * BUDGET


def test_far_from_the_start_a_function_is_sampled_once_half_its_wait_has_passed():
    """EventWatch.needs: up to ``far_from`` a function is sampled at its due point; from
    there on once half its wait has passed (early samples keep the due points together:
    a step ends at the next one due)."""
    from electrogrowth.continuation.predict import EventWatch

    w = EventWatch(0.0, np.array([1.0, 1.0]), 1.0, 1.0, far=0.1, far_from=5.0)
    w.x[0], w.due = np.array([10.0, 10.0]), np.array([12.0, 14.0])
    w.g[:] = 1.0  # flat: no predicted zero
    w._distance = None
    assert w.needs(11.5).tolist() == [True, False]  # 12 - 10 = 2: half of it passed
    assert w.needs(12.1).tolist() == [True, True]
    near = EventWatch(0.0, np.array([1.0]), 1.0, 1.0, far=0.1, far_from=50.0)
    near.x[0], near.due, near.g[:] = 10.0, np.array([12.0]), 1.0
    near._distance = None
    assert near.needs(11.5).tolist() == [False]  # before far_from: at its due point


def test_a_state_lost_within_a_far_step_is_approached_again_in_the_scale_s_steps():
    """Stepper.far_lost: a far step (longer than ``largest``) that loses the state is not
    bisected; the march goes on from its last state in the scale's steps, far ones no more.
    A step of the old length is bisected as before (False)."""
    from electrogrowth.continuation.path import ControlPath, Stepper

    step = Stepper(ControlPath(0.0, 1e3, 1.0), MODE_STEPS, 1.0)
    step.x, step.step = 100.0, 10.0  # 0.1 of 100 scales marched
    assert step.propose() == pytest.approx(110.0)
    assert step.far_lost() and step.step == MODE_STEPS.largest and step.policy.far == 0.0
    step.propose()
    assert not step.far_lost()  # a step of the old length: its loss is located
    assert step.policy.largest_at(100.0) == MODE_STEPS.largest
