"""The Koiter coefficient of a thin stiff film's fold (probe 9b D5, left out until now).

A film [1, 1.001], 1e4 times as stiff as its substrate (mu 1, to R = 2), growing in its hoop
direction, folds first in mode (70, 0) at g_theta = 1.0320382572 (the scan's mode). Its
coefficient raised ConvergenceError: `koiter_tube.singular_point` ran Newton's method on
the eigenvalue nearest zero of the saddle-point stiffness A = [[K, B^T], [B, 0]] (B the
incompressibility constraint), which there is a pressure mode (-6e-10 at |A| ~ 2e9: such
modes have eigenvalues ~ -s_B^2 / |K|), not the fold, and it stepped from 1.032 to -0.08.
The singular point is now that of K on ker B (`constrained_nearest_zero`), where the fold's
eigenvalue crosses zero cleanly, and A'[phi, phi] is differenced term by term on the
Lagrangian's coefficients (`koiter_tube.quadratic_part`), not on whole matrices of norm 2e9.
Its rounding floor (~1e-5 of the coefficient, 3.2e-5 on a later install) was the nodal
basis: the fold moves the film almost rigidly through its thickness, and each gradient
cancelled ~1e9 to leave ~1e3; each ring's values are now its inner value and differences
(incremental/ring_basis.py), and the singular point is refined on the energy
(`koiter_tube._on_the_energy`): the floor is ~1e-10.
"""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth import Layer, Tube, koiter_coefficient
from electrogrowth.bifurcation.control_derivative import Reach
from electrogrowth.bifurcation.koiter_film import FilmOnHalfSpace, _nearest_zero
from electrogrowth.bifurcation.koiter_tube import (
    constrained_nearest_zero,
    singular_point,
    tube_expansion,
)

THETA = "growth[1].theta"


def _saddle(c: float) -> np.ndarray:
    """[[K, B^T], [B, 0]]: K = diag(c - 1, 2, 1e9 c), B = [0, 0, 0.1] (the third
    displacement constrained). On ker B, K is diag(c - 1, 2), singular at c = 1; the
    saddle's eigenvalue nearest zero is the pressure mode's -0.01 / (1e9 c) ~ -1e-11,
    which moves with c and is never zero."""
    A = np.zeros((4, 4))
    A[0, 0], A[1, 1], A[2, 2] = c - 1.0, 2.0, 1e9 * c
    A[2, 3] = A[3, 2] = 0.1
    return A


def test_the_saddle_nearest_zero_is_a_pressure_mode_and_the_kernel_is_not():
    """At c = 1.2 the saddle's eigenvalue nearest zero belongs to a vector that is mostly
    pressure; on ker B the nearest is the displacement e_1 with sigma = c - 1."""
    sigma, v = _nearest_zero(_saddle(1.2))
    assert abs(sigma) < 1e-10 and abs(v[3]) > 0.99
    sigma, phi = constrained_nearest_zero(_saddle(1.2))
    assert sigma == pytest.approx(0.2, rel=1e-12)
    assert abs(phi[0]) == pytest.approx(1.0, rel=1e-12) and np.allclose(phi[1:], 0, atol=1e-12)


def test_newton_finds_the_kernel_singular_point():
    """Newton's method from c = 1.2 lands on c = 1 (before: on the pressure mode)."""
    c, phi = singular_point(_saddle, 1.2, "growth", Reach(1.0, lo=0.0))
    assert c == pytest.approx(1.0, abs=1e-12)
    assert abs(phi[0]) == pytest.approx(1.0, rel=1e-9)


def _stiff_film() -> Tube:
    return Tube((Layer(1.001, shear_modulus=1e4), Layer(2.0)), stretch=1.0, length=1.0)


def test_thin_stiff_film_fold_is_singular_at_the_impedance_value():
    """The 24-node expansion of (70, 0) (before: ConvergenceError, Newton on a pressure
    mode; at 18 nodes the saddle's Newton happened to find the fold): A(g) singular within
    1e-12 of the impedance route's critical value (measured 2.4e-14, 18 .. 48 nodes 2.1e-14
    .. 2.5e-14; in the nodal basis and on the matrices' eigenvalue 6.2e-10, up to 1.6e-9),
    and the coefficient g_2 = 1161.6907319 (18 .. 48 nodes 1161.69073185 .. 1161.69073189;
    in the nodal basis 1161.673 .. 1161.705) with its rounding sample `derivative_error`
    1.0e-7 (nodal: 1.5e-3)."""
    e = tube_expansion(_stiff_film(), 70, THETA, nodes=24)
    assert e.control_value == pytest.approx(e.impedance_value, rel=1e-12)
    assert e.coefficient == pytest.approx(1161.6907319, abs=1e-6)
    assert e.derivative_error < 1e-6
    assert e.inner_face == pytest.approx(0.99942, abs=1e-5)  # the peak is inside the film


@pytest.mark.slow
def test_thin_stiff_film_coefficient_converges_within_its_estimate():
    """koiter_coefficient (18, 24, 32 nodes: 1161.6907318522, estimate 1.1e-7, 1e-10 of
    it) against 40 and 48 nodes (1161.6907318784, 1161.6907318885): within the door's
    estimate plus the other's own rounding sample (its derivative_error). In the nodal basis
    the estimate was set by the numerator's rounding (the energy 2 A2[psi, psi] of
    componentwise condition 5e10: 0.0146, then 0.0369 = 3.2e-5 on a later install, over the
    bound); every critical value lies within 1e-8 of the impedance route's (measured
    2.5e-14)."""
    r = koiter_coefficient(_stiff_film(), (70, 0), THETA)
    assert r.branch == "supercritical"
    for nodes in (40, 48):
        e = tube_expansion(_stiff_film(), 70, THETA, nodes=nodes)
        assert abs(e.coefficient - r.coefficient) <= r.error_estimate + e.derivative_error
        assert e.control_value == pytest.approx(e.impedance_value, rel=1e-8)
    assert r.error_estimate < 3e-5 * r.coefficient


def _film(ratio: float, h: float) -> Tube:
    """A film [1, 1 + h] of modulus ``ratio`` bonded inside a substrate (mu 1) to R = 2."""
    return Tube((Layer(1 + h, shear_modulus=ratio), Layer(2.0)), stretch=1.0, length=1.0)


def _scaled(ratio: float, h: float, flat) -> float:
    """g_2 / (m f)^2 of the film's mode nearest the flat critical wavenumber (m = K_c g / h,
    g = 1 / lambda_c), f the free (inner) face's share of the peak of u_r: -lambda_2 of the
    flat film alone compressed as h -> 0 (docs/derivation-koiter.md, "The thin-film
    limit")."""
    m = round(flat.wavenumber / flat.critical_value / h)
    e = tube_expansion(_film(ratio, h), m, THETA, nodes=18)
    return e.coefficient / (m * e.inner_face) ** 2


@pytest.mark.slow
def test_stiff_film_tends_to_the_flat_film_on_a_half_space():
    """mu_f / mu_s = 1e4: the flat film alone compressed (unstressed half-space 400 film
    thicknesses deep, K searched in [0.01, 1]) has K_c = 0.066833, lambda_c = 0.998880,
    lambda_2 = -0.2500920. The tube's g_2 / (m f)^2 at h = 1e-3, 5e-4, 2.5e-4 (m = 67,
    134, 268): 0.237646, 0.243862, 0.246974, linear in h (steps 0.00622, 0.00311); their
    extrapolation 0.250086 is the flat 0.250092 to 2.3e-5."""
    flat = koiter_coefficient(
        FilmOnHalfSpace(1e4, substrate="unstressed", depth=400.0, wavenumbers=(0.01, 1.0))
    )
    assert flat.coefficient == pytest.approx(-0.2500920, abs=1e-6)
    values = [_scaled(1e4, h, flat) for h in (1e-3, 5e-4, 2.5e-4)]
    assert values[0] < values[1] < values[2] < -flat.coefficient
    assert 2 * values[2] - values[1] == pytest.approx(-flat.coefficient, rel=2e-4)


@pytest.mark.slow
@pytest.mark.parametrize(("ratio", "branch"), [(1.01, "subcritical"), (1.2, "supercritical")])
def test_thin_film_branch_follows_the_flat_threshold(ratio, branch):
    """A film grown on its substrate is the flat film alone compressed on an unstressed
    half-space, whose branch changes sign at mu_f / mu_s = 1.05669 (Cao & Hutchinson's
    1.74 is the bilayer compressed together, which a grown film is not). h = 1e-3
    (m = 1278, 1193): g_2 / (m f)^2 = -0.029682, 0.061274 against the flat -lambda_2 =
    -0.029186, 0.061359 (1.7 %, 0.14 %)."""
    flat = koiter_coefficient(FilmOnHalfSpace(ratio, substrate="unstressed"))
    tube = _scaled(ratio, 1e-3, flat)
    assert flat.branch == branch
    assert (tube > 0) == (branch == "supercritical")
    assert tube == pytest.approx(-flat.coefficient, rel=0.03)
