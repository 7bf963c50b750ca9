"""The analytic target: det(M2) of the basis carried from the inner face.

The kernel's bounded target f divides out the size of the carried basis M, which it
returns as log_norm (impedance.integrate_one): f exp(log_norm) must be det(M2) of the
linear Stroh system propagated from [I; 0], whichever charts the kernel passed through.
Checked against SciPy's propagation of that linear system, layer by layer (an independent
route: no Riccati form, no charts, no growth accounting). Near a root of a mode that lives
at the inner face (a thin stiff film's folds) f is a step of constant size while det(M2)
crosses zero linearly, which is why roots are refined on it (incremental/targets.py).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from electrogrowth import Layer, Tube, solve_base_state
from electrogrowth.incremental.impedance import ALL_PAIRS, impedance_scale, integrate_one
from electrogrowth.incremental.radial_table import build_table
from electrogrowth.incremental.stroh import stroh_matrix
from electrogrowth.incremental.targets import ImpedanceTarget, analytic_parts, wavenumber

_stroh = stroh_matrix.py_func


def _linear_det(state, m: float, k: float) -> float:
    """det(S(r_o) / s) of the solutions of d eta/dR = (dr/dR) G eta / r from [I; 0] at
    the inner face, layer by layer (dr/dR = g_r g_theta g_z R / (lambda_z r))."""
    tube, G = state.tube, np.empty((8, 8))
    y = np.vstack([np.eye(4), np.zeros((4, 4))]).ravel()
    inner = 1.0
    for layer in tube.layers:
        jg = float(np.prod(layer.growth))

        def rhs(R, y, jg=jg):
            r = float(state.radius(np.array(R), side="inner"))
            mod = np.ascontiguousarray(state.moduli(np.array(R), side="inner"), dtype=float)
            _stroh(mod, float(state.pressure(np.array(R), side="inner")), float(m), k * r, G)
            return (jg * R / (tube.stretch * r * r) * (G @ y.reshape(8, 4))).ravel()

        mid = 0.5 * (inner + layer.outer_radius)
        sol = solve_ivp(
            rhs, (inner, layer.outer_radius), y, method="DOP853", rtol=1e-12, atol=1e-14,
            first_step=1e-3 * (layer.outer_radius - inner),
        )  # fmt: skip
        assert sol.success, (mid, sol.message)
        y, inner = sol.y[:, -1], layer.outer_radius
    M = y.reshape(8, 4)
    return float(np.linalg.det(M[4:] / impedance_scale(m, k, state.r_o)))


CASES = [
    (Tube.uniform(1.4, 1.0, 1.2, 1.0, 0.4), 4, 5),
    (Tube.uniform(1.4, 1.0, 1.4, 1.0, 0.4), 0, 1),  # past its root: f < 0
    (Tube.uniform(2.0, 1.0, 1.5, 1.0, 0.3), 3, 2),
    # soft inside stiff: the kernel ends in chart 7, through switches that change det U~
    (Tube((Layer(1.2, shear_modulus=0.1, growth=1.1), Layer(1.6, shear_modulus=10.0)),
          length=1.0, voltage=0.05), 4, 3),
    (Tube((Layer(1.2, shear_modulus=0.1, growth=1.1), Layer(1.6, shear_modulus=10.0)),
          length=1.0, voltage=0.05), 0, 5),
]  # fmt: skip


@pytest.mark.parametrize("tube, m, n", CASES)
def test_f_times_the_norm_is_the_determinant_of_the_carried_basis(tube, m, n):
    state = solve_base_state(tube)
    k = wavenumber(tube, n)
    f, _, chart, status, _, log_norm = integrate_one(
        float(m), k, ALL_PAIRS, build_table(state), 1e-12, 20000, False
    )
    assert status == 0
    det = f * math.exp(log_norm)
    assert det == pytest.approx(_linear_det(state, m, k), rel=1e-9)


def test_the_layered_cases_do_switch_charts():
    """The growth accounting at a switch (log|det W1|) is exercised by the cases above."""
    tube, m, n = CASES[3]
    state = solve_base_state(tube)
    chart = integrate_one(float(m), wavenumber(tube, n), ALL_PAIRS, build_table(state),
                          1e-12, 20000, False)[2]  # fmt: skip
    assert chart != 0


FILM = Tube((Layer(1.002, growth=1.0), Layer(3.0, shear_modulus=1e-3)), length=1.0)
FOLD = np.array([[74.0, 0.0, 1.0]])  # the film's critical fold, prismatic
FILM_ROOT = 1.0293683529903823  # hoop growth of the film, from the scan (refined below)


def _film(delta):
    return solve_base_state(FILM.at("growth[1].theta", FILM_ROOT + delta))


def _det(state):
    """(f, det(M2)) of the film's fold, det(M2) in units of exp(230)."""
    f, log_norm = analytic_parts(state, FOLD)
    return f[0], f[0] * math.exp(log_norm[0] - 230.0)


def test_a_film_fold_is_a_step_for_f_and_a_line_for_the_determinant():
    deltas = (-1e-4, -1e-6, 1e-6, 1e-4)
    states = [_film(d) for d in deltas]
    f, det = np.array([_det(s) for s in states]).T
    # f: the same size on both sides, 1e-6 and 1e-4 from the root alike
    assert np.all(np.sign(f) == np.sign(det))
    assert np.ptp(np.abs(f)) < 1e-6 * np.abs(f).max()
    # det(M2): proportional to the distance from the root, times a smooth factor (its
    # log changes by ~50 per unit of growth here)
    slopes = det / np.array(deltas)
    assert np.ptp(slopes[1:3]) < 1e-3 * abs(slopes[1])
    assert np.ptp(slopes) < 0.05 * abs(slopes[1])
    # so a secant step through +-1e-8 lands on the root (the march's, Brent's on det(M2))
    lo, hi = (_det(_film(d))[1] / det[1] for d in (-1e-8, 1e-8))
    root = FILM_ROOT + 1e-8 - hi * 2e-8 / (hi - lo)
    assert root == pytest.approx(FILM_ROOT, abs=1e-13)


def test_the_analytic_target_has_the_signs_of_f():
    """Same zeros, same signs, over many modes and families of a state past its first
    roots (a few of them negative)."""
    state = solve_base_state(Tube.uniform(1.4, 1.0, 1.6, 1.0, 0.4))
    modes = np.array(
        [(m, n, 0) for m in range(0, 9) for n in range(1, 7)]
        + [(m, 0, 1) for m in range(2, 9)] + [(0, n, 2) for n in range(1, 5)], float
    )  # fmt: skip
    f = ImpedanceTarget(1e-12)(state, modes)
    g, log_norm = ImpedanceTarget(1e-12).parts(state, modes)
    assert (f < 0).any() and (f > 0).any()
    assert np.isfinite(log_norm).all()
    np.testing.assert_array_equal(np.sign(g), np.sign(f))
    # the same f, to the tolerance: integrated through the whole wall, no restart
    np.testing.assert_allclose(g, f, rtol=1e-8, atol=1e-12)


def test_the_film_fold_is_refined_in_a_few_evaluations(monkeypatch):
    """Its critical value in a bracket of +-1e-7: Brent's method on det(M2) and the second
    resolution's secant, 10 evaluations (at most 20 here). On f it took 65: 31 fine ones
    for Brent's method, a bisection on a step, and 34 coarse ones for the second
    resolution, whose secant finds no sign change on a step and falls back to its window
    search."""
    from electrogrowth import critical_value
    from electrogrowth.incremental import targets

    calls = []
    parts = targets.analytic_parts

    def counted(state, modes, **kw):
        calls.append(kw["rtol"])
        return parts(state, modes, **kw)

    monkeypatch.setattr(targets, "analytic_parts", counted)
    w = 1e-7
    point = critical_value(
        FILM, 74, 0, "growth[1].theta", family="prismatic", bracket=(FILM_ROOT - w, FILM_ROOT + w)
    )
    assert point.value == pytest.approx(FILM_ROOT, abs=2e-13)
    assert point.status.name == "OK" and point.error_estimate < 1e-10
    assert 0 < len(calls) <= 20


def test_a_failed_integration_goes_to_the_retries_without_being_repeated(monkeypatch):
    # below FORGET_RTOL the kernel's bounded target keeps the basis' size as det(M2)'s
    # does: the same integration, the same failure (forced here by max_steps=3)
    from electrogrowth.incremental import targets
    from tests.incremental.test_retry_sign_layered import BILAYER

    state = solve_base_state(BILAYER.at("stretch", 1.05))
    row = np.array([[2.0, 1.0]])
    expected = targets.impedance_targets(state, row, rtol=1e-12, max_steps=3)  # as before
    integrated, serial = [], targets.rows_serial

    def counted(*args):
        integrated.append(args[0].shape[0])
        return serial(*args)

    monkeypatch.setattr(targets, "rows_serial", counted)
    f, log_norm = analytic_parts(state, row, rtol=1e-12, max_steps=3)
    assert integrated == []  # was [1]: the failed integration again
    assert f == expected and np.isnan(log_norm).all()
