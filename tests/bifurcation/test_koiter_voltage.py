"""The Koiter coefficient of a tube's prismatic modes under a radial voltage
(bifurcation/koiter_tube.py ``dielectric_expansion``, incremental/dielectric_forms.py,
docs/derivation-koiter.md "The radial voltage"): the base state is stationary in the
energy with the potential as a field, A(c) is singular at the package's impedance critical
value (two permittivities: the scaling of each layer's electric energy), the voltage-free
limit is the polar forms' coefficient, and Newton's method on the full discrete equations
gives the same curvature of the branch."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.koiter import koiter_coefficient
from electrogrowth.bifurcation.koiter_film import MODE, _nearest_zero
from electrogrowth.bifurcation.koiter_tube import SECOND, dielectric_expansion, tube_expansion
from electrogrowth.incremental.dielectric_forms import DielectricForms
from electrogrowth.incremental.polar_forms import rings
from electrogrowth.model.layer import Layer
from electrogrowth.model.layers import Tube
from tests.bifurcation.koiter_newton import peak_row

THETA = "growth[1].theta"


def _tube(voltage: float, eps=(1.0, 1.0)) -> Tube:
    """A film [1, 1.1] (mu = 1, hoop growth) in a substrate to 2 (mu = 0.2), L = 1."""
    return Tube(
        [
            Layer(1.1, shear_modulus=1.0, growth=(1, 1.0, 1), permittivity=eps[0]),
            Layer(2.0, shear_modulus=0.2, permittivity=eps[1]),
        ],
        length=1.0,
        stretch=1.0,
        voltage=voltage,
    )


def test_base_state_is_stationary_with_the_potential_as_a_field():
    """The linear term vanishes on every field and harmonic (radial equilibrium and Gauss's
    law of the base state), with the multiplier p~0 = p0 - eps_k e^2 of the energy written
    on the constraint (J -> J_g)."""
    tube = _tube(0.3, (2.0, 0.5))
    forms = DielectricForms.build(rings(tube, 12, 16), 12, SECOND + ((3, 0),) + MODE + ((3, 1),))
    state = solve_base_state(tube.at(THETA, 1.5))
    zero = {k: np.zeros_like(forms.R) for k in forms.maps}
    assert np.abs(forms.gradient(forms.lagrangian(state)[1], zero)).max() < 1e-13


def test_singular_at_the_impedance_critical_value():
    """A(g) with the potential is singular where the package's impedance route puts the
    critical hoop growth of mode (12, 0) under Vbar = 0.2, the layers' permittivities 2 and
    0.5 (measured 1.7e-13 apart); the branch is supercritical."""
    e = dielectric_expansion(_tube(0.2, (2.0, 0.5)), 12, THETA, nodes=16)
    assert e.control_value == pytest.approx(e.impedance_value, rel=1e-10)
    assert e.coefficient > 0


def test_no_voltage_is_the_polar_coefficient():
    """At Vbar = 0 the potential decouples: the same g_2 as the polar forms (measured
    8.8789470488 against 8.8789470560, the finite-difference floor of A')."""
    polar = tube_expansion(_tube(0.0), 12, THETA, nodes=16)
    dielectric = dielectric_expansion(_tube(0.0), 12, THETA, nodes=16)
    assert dielectric.coefficient == pytest.approx(polar.coefficient, rel=1e-8)


@pytest.mark.slow
def test_branch_curvature_from_a_direct_nonlinear_solve():
    """Newton's method on the full discrete equations (every order of the energy,
    harmonics 0-3 of every field, the control unknown, u_r of harmonic 1 prescribed at the
    mode's largest node): (g(eps) - g_c) / eps^2 extrapolated in eps^2 equals the
    expansion's g_2 at Vbar = 0.3 (where the voltage changes g_2 fivefold) to 1e-6
    (measured 45.673842 against 45.673864; 16 points a period: exact for the quartic
    products of harmonics up to 3)."""
    tube, m, N = _tube(0.3), 12, 16
    e = dielectric_expansion(tube, m, THETA, nodes=N)
    harmonics = ((0, 0), (2, 0), (3, 0))
    harmonics += tuple((f, j) for j in (1, 2, 3) for f in range(4))
    full = DielectricForms.build(rings(tube, m, N), m, harmonics, theta_points=16)
    first = DielectricForms.build(rings(tube, m, N), m, MODE + ((3, 1),))
    one = dict(zip(harmonics, full.slices))
    phi = _nearest_zero(first.stiffness(solve_base_state(tube.at(THETA, e.control_value))))[1]
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    a = phi[first.slices[0]]
    row = peak_row(first.rings, a, one[(0, 1)].start, full.size)
    peak = row[one[(0, 1)]] @ a  # the mode's u_r at that node
    zero = {k: np.zeros_like(full.R) for k in full.maps}

    def residual(c, w):
        L, f = full.lagrangian(solve_base_state(tube.at(THETA, c))), full.fields(w)
        return sum(full.gradient(L[k], f) for k in (1, 2, 3, 4)) - full.gradient(L[1], zero)

    def branch(eps):
        w = np.zeros(full.size)
        for f, sl in zip((0, 1, 2, 3), first.slices):
            w[one[(f, 1)]] = eps * phi[sl]
        c, size = e.control_value, full.size
        for _ in range(30):
            L, f = full.lagrangian(solve_base_state(tube.at(THETA, c))), full.fields(w)
            h = 1e-3 * c
            J = np.zeros((size + 1, size + 1))
            J[:size, :size] = sum(full.hessian(L[k], f) for k in (2, 3, 4))
            J[:size, size] = (residual(c + h, w) - residual(c - h, w)) / (2 * h)
            J[size, :size] = row
            rhs = np.concatenate([residual(c, w), [row @ w - eps * peak]])
            step = np.linalg.solve(J, rhs)
            w, c = w - step[:size], c - step[size]
            if abs(step[size]) < 1e-13:
                break
        return c

    # the branch bends fast here (g_4 ~ -2e4: d / eps^2 = 45.598, 45.361 at eps = 0.002,
    # 0.004), so Richardson removes the eps^2 and eps^4 terms of d(eps) / eps^2
    D = [(branch(x) - e.control_value) / x**2 for x in (0.001, 0.002, 0.004)]
    R1 = [(4 * D[0] - D[1]) / 3, (4 * D[1] - D[2]) / 3]
    assert (16 * R1[0] - R1[1]) / 15 == pytest.approx(e.coefficient, rel=1e-6)


def test_door_covers_the_voltage_for_prismatic_modes():
    """koiter_coefficient takes a prismatic mode under a voltage (24 against 18 points a
    segment agree to 1e-6)."""
    r = koiter_coefficient(_tube(0.1), (12, 0), THETA)
    assert r.branch == "supercritical"
    assert r.error_estimate < 1e-6 * r.coefficient
