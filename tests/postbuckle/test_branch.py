"""The branch follower's bookkeeping (without a mesh): secant predictions, early stop, and a
Ctrl-C that keeps the finished points."""

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.interrupts import Interrupted  # noqa: E402
from electrogrowth.postbuckle.branch import AmplitudeBranch, BranchPoint  # noqa: E402


class _Section:
    def energy(self, x):
        return float(x @ x)


def _branch(solve):
    branch = object.__new__(AmplitudeBranch)
    branch.section = _Section()
    branch.solve = solve
    branch.eigenvalues = False
    return branch


def test_secant_prediction_is_exact_on_a_straight_branch():
    guesses = []

    def solve(x, c, amplitude):  # the branch c = 1 + a, x = (a, 2a)
        guesses.append((x.copy(), c))
        return np.array([amplitude, 2 * amplitude]), 1 + amplitude, 0

    start = BranchPoint(1.0, 0.0, 0.0, np.zeros(2))
    pts = _branch(solve).follow(start, [0.1, 0.2, 0.3], direction=np.array([1.0, 2.0]))
    assert [p.control for p in pts] == pytest.approx([1.1, 1.2, 1.3])
    x2, c2 = guesses[2]
    assert c2 == pytest.approx(1.3) and x2 == pytest.approx([0.3, 0.6])


def test_ctrl_c_keeps_the_finished_points():
    calls = []

    def solve(x, c, amplitude):
        calls.append(amplitude)
        if len(calls) == 3:
            raise KeyboardInterrupt
        return x, c, 0

    start = BranchPoint(1.0, 0.0, 0.0, np.zeros(2))
    with pytest.raises(Interrupted) as stop:
        _branch(solve).follow(start, [0.1, 0.2, 0.3, 0.4])
    assert [p.amplitude for p in stop.value.partial] == [0.1, 0.2]


def test_a_failed_step_is_halved():
    from electrogrowth.errors import ConvergenceError

    def solve(x, c, amplitude):
        if amplitude - x[0] > 0.15:  # converges only from within 0.15 of the target
            raise ConvergenceError("too far")
        return np.array([amplitude, 0.0]), 1 + amplitude, 0

    start = BranchPoint(1.0, 0.0, 0.0, np.zeros(2))
    pts = _branch(solve).follow(start, [0.2])
    assert [p.amplitude for p in pts] == [0.1, 0.2]


# -- requested amplitudes (probe 12a D2) --------------------------------------------------


@pytest.mark.slow
def test_every_requested_amplitude_is_on_the_branch():
    """probe 12a D2 (about 30 s): the amplitudes up to the curvature's points (2e-3 by
    default) were dropped without a word (amplitude 0.003, points 3 gave a = 0 and 0.003;
    amplitude 1e-6 the onset alone, ``ended`` empty). Now they are solved from the onset."""
    from electrogrowth.model.layers import Layer, Tube
    from electrogrowth.postbuckle.api import postbuckle

    mucosa = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0)
    r = postbuckle(mucosa, 12, "growth[1].theta", amplitude=0.003, points=3, density=10, hoop=4)
    assert r.amplitude[1:] == pytest.approx([0.001, 0.002, 0.003], rel=1e-9)
    assert r.ended == "" and np.all(np.diff(r.control) > 0)  # supercritical: rising
    tiny = postbuckle(mucosa, 12, "growth[1].theta", amplitude=1e-6, points=1, density=10, hoop=4)
    assert tiny.amplitude == pytest.approx([0.0, 1e-6], abs=1e-15) and tiny.ended == ""
    # c - c_c = c_2 a^2 = 7e-12 (c_2 = 6.78 on this mesh), below Newton's tolerance
    assert tiny.control[1] == pytest.approx(tiny.control[0], abs=1e-9)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"amplitude": 1e9}, "amplitude = 1000000000.0 is out of range; valid range: > 0 and < 2"),
        ({"amplitude": 2.0}, "valid range: > 0 and < 2"),
        ({"density": 0.0}, "density = 0.0 is out of range; valid range: > 0 and <= 2000"),
    ],
    ids=["amplitude-1e9", "amplitude-outer-radius", "density-0"],
)
def test_out_of_range_amplitude_and_density_are_one_line(kwargs, message):
    """probe 12a doubts 1 and 7: amplitude 1e9 ran (exit 0, a branch ended at a point not
    in the table); density 0 was refused with "valid range: 0 to 2000"."""
    from electrogrowth.errors import ParameterError
    from electrogrowth.model.layers import Layer, Tube
    from electrogrowth.postbuckle.api import postbuckle

    mucosa = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0)
    with pytest.raises(ParameterError) as caught:
        postbuckle(mucosa, 12, "growth[1].theta", **{"amplitude": 0.01, **kwargs})
    assert message in str(caught.value) and "\n" not in str(caught.value)
