"""The short-wave start that keeps det(M2) (impedance.KEEP_SIZE; short_wave_start.keep_plan,
keep_restart; docs/derivation-dominant.md, "Roots").

Roots are refined on det(M2) = f exp(log_norm) of the basis carried from the inner face. A stiff
short wave's whole wall costs steps in proportion to |(m, k r)| (explicit steps at the edge of
stability); the restart near the outer face from the dominant subspace W+ makes that cost
independent of the mode. It must keep what a root is: the zeros and signs of det(M2). It
multiplies det(M2) by a positive factor (the frozen W+'s growth instead of the true one's),
which must be smooth in the parameters, so that finite differences of det(M2) (design
sensitivities) and Brent's method see an analytic function.

Checked against the whole wall at rtol 1e-12 (impedance.WHOLE_WALL): the bounded targets, the
roots of det(M2) along a control, the smoothness of the factor, and the step counts.
"""

import functools
import math

import numpy as np
import pytest

from electrogrowth import Layer, Tube, critical_value, solve_base_state
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.brent import brentq
from electrogrowth.incremental.impedance import KEEP_SIZE, SHORT_WAVE, WHOLE_WALL, integrate_one
from electrogrowth.incremental.mode_rows import row_pairs
from electrogrowth.incremental.radial_table import build_table

THICK = Tube.uniform(2.0, 1.0, voltage=0.5)
NEAR_THRESHOLD = Tube.uniform(2.0, 1.0, voltage=0.796)
#: a stiff film inside (its folds live at the inner face: the bounded target is a step there)
INNER_FILM = Tube((Layer(1.001, shear_modulus=10.0), Layer(2.0)), length=5.0, stretch=1.0)
#: a pressurised, anisotropically growing bilayer: the restart in its outer layer
BILAYER = Tube(
    (Layer(1.3, growth=(1.0, 1.4, 1.0), shear_modulus=3.0), Layer(2.2, growth=1.1)),
    length=1.0, stretch=1.0, voltage=0.2, inner_pressure=0.1,
)  # fmt: skip
SHORT = [(400, 0), (2000, 0), (0, 200), (0, 2000), (2000, 2000), (30, 40), (1, 30), (5, 20)]


def _run(state, m, n, rtol, forget):
    """(f, log_norm, steps) of mode (m, n) (its natural family) on ``state``."""
    table = build_table(state)
    k = n * math.pi / state.current_length
    keep = row_pairs(np.array([[m, n]], float), 0)
    f, _, _, status, steps, log_norm = integrate_one(
        float(m), k, keep, table, rtol, 400000, forget
    )
    assert status == 0
    return f, log_norm, steps


@pytest.mark.parametrize(
    "tube", [THICK, NEAR_THRESHOLD, BILAYER], ids=["thick", "near", "bilayer"]
)
def test_targets_and_sizes_are_the_whole_walls(tube):
    state = solve_base_state(tube)
    saved = 0
    for m, n in SHORT:
        f0, l0, s0 = _run(state, m, n, 1e-12, WHOLE_WALL)
        f1, l1, s1 = _run(state, m, n, 1e-12, KEEP_SIZE)
        assert math.copysign(1, f1) == math.copysign(1, f0)
        assert abs(f1 - f0) <= 1e-11 * abs(f0), (m, n, f0, f1)
        # the size: the frozen W+ grows like the true dominant subspace up to O(1) in log
        assert abs(l1 - l0) <= 1.0, (m, n, l0, l1)
        saved += s0 - s1
    assert saved > 0


def test_the_cost_does_not_grow_with_the_mode():
    """Steps of the shortest waves at rtol 1e-12: whole wall ~ |(m, k r)|, restarted flat."""
    state = solve_base_state(THICK)
    whole = {mode: _run(state, *mode, 1e-12, WHOLE_WALL)[2] for mode in [(200, 0), (2000, 0)]}
    kept = {
        mode: _run(state, *mode, 1e-12, KEEP_SIZE)[2]
        for mode in [(200, 0), (2000, 0), (0, 200), (0, 2000), (2000, 2000)]
    }
    assert whole[(2000, 0)] > 3 * whole[(200, 0)]  # the whole wall grows with m
    assert max(kept.values()) <= 400
    assert kept[(2000, 0)] <= 1.5 * kept[(200, 0)]
    assert kept[(0, 2000)] <= 1.5 * kept[(0, 200)]


def _det(at, mode, forget, x, ref):
    """det(M2) of ``mode`` at control value x, in units of exp(ref)."""
    f, log_norm, _ = _run(at.state(x), *mode, 1e-12, forget)
    return f * math.exp(log_norm - ref)


@pytest.mark.parametrize(
    "tube, control, mode, bracket",
    [
        (INNER_FILM, "growth[1].theta", (640, 0), (1.1220, 1.1228)),  # a fold at the inner face
        (INNER_FILM, "growth[1].theta", (2000, 0), (1.3178, 1.3186)),
        (THICK, "voltage", (2000, 2000), (0.8050, 0.8060)),  # at the outer face
        (THICK, "voltage", (0, 2000), (0.7955, 0.7965)),
    ],
    ids=["film-640", "film-2000", "thick-2000-2000", "thick-0-2000"],
)
def test_roots_of_det_m2_are_the_whole_walls(tube, control, mode, bracket):
    at = TubeAt(tube, control)
    roots = {}
    for forget in (WHOLE_WALL, KEEP_SIZE):
        ref = _run(at.state(bracket[0]), *mode, 1e-12, forget)[1]
        det = functools.partial(_det, at, mode, forget, ref=ref)
        roots[forget] = brentq(det, *bracket, xtol=1e-15, rtol=1e-15)
    assert abs(roots[KEEP_SIZE] - roots[WHOLE_WALL]) <= 2e-12 * roots[WHOLE_WALL], roots
    # and the restart was taken at the root itself, where det A = 0
    state = at.state(roots[KEEP_SIZE])
    steps = {forget: _run(state, *mode, 1e-12, forget)[2] for forget in (WHOLE_WALL, KEEP_SIZE)}
    assert steps[KEEP_SIZE] < 0.5 * steps[WHOLE_WALL], steps


@pytest.mark.parametrize(
    "tube, control, mode, x",
    [
        (INNER_FILM, "growth[1].theta", (640, 0), 1.1223),
        (THICK, "voltage", (2000, 2000), 0.6),
        (NEAR_THRESHOLD, "voltage", (0, 200), 0.79),
    ],
    ids=["film", "thick", "near"],
)
def test_the_factor_is_smooth_in_the_parameter(tube, control, mode, x):
    """log(det(M2) restarted / det(M2) of the whole wall) at x + j h: its second differences
    are those of a smooth function (a jump of the plan's radii with the step sequence would
    show as a first difference of the jump's size)."""
    at = TubeAt(tube, control)
    h = 1e-6 * x
    logs = []
    for j in range(-2, 3):
        f0, l0, _ = _run(at.state(x + j * h), *mode, 1e-12, WHOLE_WALL)
        f1, l1, _ = _run(at.state(x + j * h), *mode, 1e-12, KEEP_SIZE)
        logs.append(l1 - l0 + math.log(f1 / f0))
    logs = np.array(logs)
    assert np.abs(np.diff(logs)).max() <= 1e-6
    assert np.abs(np.diff(logs, 2)).max() <= 1e-8


def test_loose_signs_restart_next_to_a_root_of_the_inner_face():
    """Next to a root of det A (a short wave of the inner face) the orientation-only
    restart's remnant ||X- A^-1|| is unbounded: each loose evaluation of (2000, 2000) within
    1e-9 of its root integrated the whole wall (~2900 steps). Once X- has decayed
    (keep_distance), the remnant relative to A's size decides; the signs are the whole
    wall's."""
    at = TubeAt(NEAR_THRESHOLD, "voltage")
    for mode in [(0, 2000), (2000, 2000)]:
        root = critical_value(NEAR_THRESHOLD, *mode, "voltage").value
        for offset in (-1e-6, -1e-9, -1e-12, 1e-12, 1e-9, 1e-6):
            state = at.state(root + offset)
            f0, _, s0 = _run(state, *mode, 1e-8, WHOLE_WALL)
            f1, _, s1 = _run(state, *mode, 1e-8, SHORT_WAVE)
            assert math.copysign(1, f1) == math.copysign(1, f0)
            if abs(offset) >= 1e-9:  # the loose target's root is within ~1e-10 of the fine one
                assert math.copysign(1, f0) == -math.copysign(1, offset)
            assert abs(f1 - f0) <= 1e-7 * abs(f0)
            assert s1 < 0.1 * s0, (mode, offset, s0, s1)
