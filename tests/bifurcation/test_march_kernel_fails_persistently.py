"""A march whose impedance kernel fails on every state must stop, not creep (probe round 8b,
D9).

One mode (0, 1) of a Fung-type tube grown from g = 1: the energy's elastic moduli grow like
exp((I1 - 3)^2) (3e13 at g = 3.95, I1 = 7.96, next to the electric K = 1), and from g ~ 3.93
on the kernel fails at every state (step size underflow, also at tighter tolerances), so
every evaluation went to the collocation fallback (incremental/targets.py ``_retry``, ~40 ms
a mode). Its target decays there like the inverse of the moduli (1e-7 at g = 3.98, 1e-12 at
g = 5.70), where the loose and the fine collocation values disagree in sign: the march took
every loose sample for a crossing that the fine one refused, examined a dip at every step,
and crept in steps of 1e-4 towards the range's end g = 6 (2456 fallbacks in 100 s; killed
after 10 minutes; `critical --mode 0 1` alike). The march now stops after KERNEL_FAILURE_RUN
consecutive states on which the kernel failed for every mode, with a ConvergenceError naming
where and why; an isolated failure still goes to collocation. ~10 s.
"""

import signal

import numpy as np
import pytest

from electrogrowth import ConvergenceError, Material, Tube, critical_value
from electrogrowth.bifurcation.march import KERNEL_FAILURE_RUN, KernelFailures
from electrogrowth.incremental import targets as targets_module
from electrogrowth.incremental.targets import Sample

FUNG = "(I1-3)/2 + I5/2 + 0.1*(exp((I1-3)**2) - 1)"
BUDGET = 90  # seconds: the unfixed march ran for over 10 minutes


class _TooLong(Exception):
    pass


def _stop(signum, frame):
    raise _TooLong(f"critical_value still running after {BUDGET} s")


def test_a_march_on_states_the_kernel_never_resolves_stops_with_a_named_error(monkeypatch):
    tube = Tube.uniform(1.5, length=1.0, material=Material("fung", FUNG))
    collocated, retry = [], targets_module._retry

    def counted(*args):
        out = retry(*args)
        collocated.append(out.collocated)
        return out

    monkeypatch.setattr(targets_module, "_retry", counted)
    old = signal.signal(signal.SIGALRM, _stop)
    signal.alarm(BUDGET)
    try:
        with pytest.raises(
            ConvergenceError, match="step size underflow, also at tighter tolerances, at each of"
        ):
            critical_value(tube, 0, 1, "growth")
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    assert 0 < sum(collocated) < 100  # 33 here; 2456 in 100 s before


class _FakeTarget:
    """A target whose kernel 'fails' (every mode goes to collocation) where fails(x)."""

    def __init__(self, fails):
        self.fails = fails

    def __call__(self, state, modes):
        return self.sample(state, modes).values

    def sample(self, state, modes):
        if self.fails(state):
            return Sample(np.ones(modes.shape[0]), modes.shape[0], "failed (fake)")
        return Sample(np.ones(modes.shape[0]))


def test_isolated_kernel_failures_keep_the_collocation_fallback():
    watch, modes = KernelFailures("growth"), np.array([[0.0, 1.0]])
    target = _FakeTarget(lambda x: x % 2 == 0)  # every other state fails
    for x in range(4 * KERNEL_FAILURE_RUN):
        assert watch.sample(target, x, modes, float(x))[0] == 1.0
        assert not watch.persistent()


def test_one_mode_of_many_failing_keeps_the_collocation_fallback():
    watch, modes = KernelFailures("growth"), np.array([[0.0, 1.0], [1.0, 1.0]])
    every = _FakeTarget(lambda x: True)

    class TargetOne(_FakeTarget):  # the kernel fails for the first mode only
        def sample(self, state, modes):
            return Sample(np.ones(modes.shape[0]), every.sample(state, modes[:1]).collocated)

    target_one = TargetOne(None)

    for x in range(4 * KERNEL_FAILURE_RUN):
        watch.sample(target_one, x, modes, float(x))
        assert not watch.persistent()


def test_a_run_of_kernel_failures_ends_the_march():
    watch, modes = KernelFailures("growth"), np.array([[0.0, 1.0], [1.0, 1.0]])
    target, last = _FakeTarget(lambda x: x >= 3), 3 + KERNEL_FAILURE_RUN - 1
    for x in range(last + 1):
        watch.sample(target, x, modes, float(x))
        assert watch.persistent() == (x == last)
    run = f"each of {KERNEL_FAILURE_RUN} consecutive states from growth = 3 to {last}"
    assert run in str(watch.error())
