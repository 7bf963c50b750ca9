"""The Koiter coefficient of a tube's wrinkles (m, n) under follower pressures on its faces
(incremental/wall_pressure_forms.py, docs/derivation-koiter.md "Pressures on the faces,
wrinkles (m, n)"): the load's first order balances the wall's, A(c) with the load's
stiffness is singular at the package's critical value, the load's potential is the plane
section's at K = 0 and the volume of revolution's at m = 0, equal pressures on both faces
change nothing, and Newton's method on the full equations with the load gives the same
curvature."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.koiter import koiter_coefficient
from electrogrowth.bifurcation.koiter_film import _nearest_zero
from electrogrowth.bifurcation.koiter_loads import energies, loaded_expansion
from electrogrowth.bifurcation.koiter_tube import SECOND as PLANE_SECOND
from electrogrowth.bifurcation.koiter_tube import axial_wavenumber
from electrogrowth.bifurcation.koiter_wall import MODE, wall_forms, wrinkle_expansion
from electrogrowth.incremental.meridian_forms import MeridianForms
from electrogrowth.incremental.polar_forms import PolarForms, rings
from electrogrowth.incremental.pressure_forms import FaceForms
from electrogrowth.incremental.wall_forms import WallForms
from electrogrowth.incremental.wall_pressure_forms import WallFaceForms

from .koiter_newton import branch_curvature, onset_floor, peak_row, richardson, richardson_floor
from .test_koiter_wrinkle import FULL, THETA, _film_tube, _full_equations, _meridian, _polar


def _loaded(inner=0.02, outer=0.05, growth=(1, 1.0, 1)):
    return dataclasses.replace(_film_tube(growth), inner_pressure=inner, outer_pressure=outer)


def test_the_load_balances_the_wall_at_the_base_state():
    """E1 of the wall and the load together vanishes on every harmonic (below 1e-13),
    while the load's alone is ~0.1: its first order has the right sign and size."""
    tube = _loaded()
    second = energies(tube, (4, 1), THETA, 12)[1]
    state = solve_base_state(tube.at(THETA, 1.6))
    zero = np.zeros(second.wall.size)
    wall = second.wall.gradient(second.wall.lagrangian(state)[1], second.wall.fields(zero))
    load = second.face.gradient(second.face.potential(state)[1], second.face.fields(zero))
    assert np.abs(wall + load).max() < 1e-13 < 1e-2 < np.abs(load).max()


@pytest.mark.parametrize(
    "tube, control, side",
    [(_loaded(), THETA, None), (_loaded(0.0, 0.0, (1, 1.6, 1)), "pressure", "compression")],
    ids=["growth", "pressure"],
)
def test_singular_at_the_impedance_critical_value(tube, control, side):
    """A(c) with the load's stiffness is singular at the package's critical value (its
    follower-pressure condition on the faces, an independent formulation) of (4, 1):
    measured 7e-13 (growth, P_i = 0.02, P_o = 0.05)."""
    e = loaded_expansion(tube, (4, 1), control, nodes=16, side=side)
    assert e.control_value == pytest.approx(e.impedance_value, rel=3e-12)


def test_the_load_is_the_plane_and_the_meridian_one():
    """At K = 0 the faces' potential is FaceForms' plane section (orders 1, 2; no cubic
    term), at m = 0 its volume of revolution (orders 1 to 3), on a random field to 1e-12."""
    tube = _loaded()
    state = solve_base_state(tube.at(THETA, 1.6))
    cut = rings(tube, 12, 10)
    K = axial_wavenumber(tube, 3)
    cases = [
        (
            WallForms.build(cut, 12, 0.0, _polar(PLANE_SECOND)),
            PolarForms.build(cut, 12, PLANE_SECOND),
            "prismatic",
            12,
        ),
        (
            WallForms.build(cut, 0, K, _meridian(PLANE_SECOND)),
            MeridianForms.build(cut, K, PLANE_SECOND),
            "axisymmetric",
            K,
        ),
    ]
    for wall, other, family, number in cases:
        ours, theirs = WallFaceForms.of(wall), FaceForms.build(other, family, number)
        v = np.random.default_rng(3).standard_normal(wall.size)
        Lo, Lt = ours.potential(state), theirs.potential(state)
        for k in (1, 2, 3):
            eo, et = ours.energy(Lo[k], ours.fields(v)), theirs.energy(Lt[k], theirs.fields(v))
            assert eo == pytest.approx(et, rel=1e-12, abs=1e-14)


def test_equal_pressures_change_nothing():
    """P_i = P_o = 0.3: -P (V_i - V_o) is P times the wall's volume, P int det F, which
    only shifts the multiplier: the unpressurised critical value and coefficient (measured
    15.7825987533 against 15.7825987467, 4e-10); the door takes the loaded route."""
    plain = wrinkle_expansion(_film_tube(), (4, 1), THETA, nodes=12)
    equal = loaded_expansion(_loaded(0.3, 0.3), (4, 1), THETA, nodes=12)
    assert equal.control_value == pytest.approx(plain.control_value, rel=1e-11)
    assert equal.coefficient == pytest.approx(plain.coefficient, rel=1e-8)
    r = koiter_coefficient(_loaded(), (4, 1), THETA)
    assert r.error_estimate < 1e-6 * abs(r.coefficient)


@pytest.mark.slow
def test_branch_curvature_from_a_direct_nonlinear_solve():
    """Newton's method on the full equations with the load (the wall's from W's first
    derivatives at the full F, the load's from its exactly cubic potential), mode (4, 1),
    P_i = 0.02, P_o = 0.05, 12 points a segment: the same curvature to 1e-6 and the
    rounding floor of the onset. That floor is no longer small here: A(c) (norm 747) has
    an eigenvalue slope of only 0.01, so c_c and each Newton c carry ~3e-12 (measured
    departures up to 7e-12), which Richardson's D at eps = 0.001 can turn into 2e-5; measured
    agreement 1.6e-7 and 1.3e-6 on two machines. (The onset-free fits of c(eps) do no
    better: the branch's c_4 ~ 2900 leaves the larger eps to truncation.)"""
    tube = _loaded()
    first, _ = energies(tube, (4, 1), THETA, 12)
    e = loaded_expansion(tube, (4, 1), THETA, nodes=12)
    full = wall_forms(tube, (4, 1), FULL, 12, angular_points=16)
    face = WallFaceForms.of(full, angular_points=16)
    phi = _nearest_zero(first.stiffness(solve_base_state(tube.at(THETA, e.control_value))))[1]
    phi = phi / first.wall.peak_radial(phi, first.wall.slices[0])[1]
    where = dict(zip(full.harmonics, full.slices))
    mode_vector = np.zeros(full.size)
    for h, sl in zip(MODE, first.wall.slices):
        mode_vector[where[h]] = phi[sl]
    radial = phi[first.wall.slices[0]]
    row = peak_row(first.wall.rings, radial, where[0, 1, 1].start, full.size)
    wall_residual, wall_jacobian = _full_equations(full, tube, THETA)

    def residual(c, w):  # both less their value at w = 0 (which cancel: the balance)
        P = face.potential(solve_base_state(tube.at(THETA, c)))
        f = face.fields(w)
        return wall_residual(c, w) + sum(face.gradient(P[k], f) for k in (2, 3))

    def jacobian(c, w):
        P = face.potential(solve_base_state(tube.at(THETA, c)))
        f = face.fields(w)
        return wall_jacobian(c, w) + face.hessian(P[2]) + face.hessian(P[3], f)

    D = branch_curvature(
        e.control_value, mode_vector, row, residual, jacobian, (0.001, 0.002, 0.004)
    )
    floor = onset_floor(
        lambda c: first.stiffness(solve_base_state(tube.at(THETA, c))), e.control_value
    )
    assert abs(richardson(D) - e.coefficient) <= 1e-6 * e.coefficient + richardson_floor(
        floor, 0.001
    )
