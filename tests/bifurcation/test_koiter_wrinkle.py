"""The Koiter coefficient of a tube's wrinkles (m, n), m, n >= 1 (incremental/wall_forms.py,
bifurcation/koiter_wall.py, docs/derivation-koiter.md "The tube's general family (m, n)"):
the base state is stationary in the three-dimensional energy, A(c) is singular at the
package's own critical value, the forms are the meridian ones at m = 0 and the polar ones
at K = 0 (so are the coefficients), the cubic term vanishes on the mode, the coefficient
converges in the nodes, and Newton's method on the full nonlinear equations (written from
W's first derivatives at the full F, not from the expansion) gives the same curvature."""

from __future__ import annotations

import dataclasses
import types

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.koiter import koiter_coefficient, with_branch
from electrogrowth.bifurcation.koiter_film import MODE as PLANE_MODE
from electrogrowth.bifurcation.koiter_film import _nearest_zero
from electrogrowth.bifurcation.koiter_tube import (
    SECOND as PLANE_SECOND,
)
from electrogrowth.bifurcation.koiter_tube import (
    axial_wavenumber,
    axisymmetric_expansion,
    expand,
    onset_value,
    tube_expansion,
)
from electrogrowth.bifurcation.koiter_wall import MODE, SECOND, wall_forms, wrinkle_expansion
from electrogrowth.errors import ParameterError
from electrogrowth.incremental.meridian_forms import MeridianForms
from electrogrowth.incremental.polar_forms import PolarForms, rings
from electrogrowth.incremental.wall_forms import ENTRIES, WallForms
from electrogrowth.model.layer import Layer
from electrogrowth.model.layers import Tube
from electrogrowth.model.materials import gent, mooney_rivlin, neo_hookean

from .koiter_newton import branch_curvature, peak_row, richardson
from .test_koiter_energies import _base, _local_gradient

THETA, AXIAL = "growth[1].theta", "growth[1].z"
HOOP, AXIAL_GROWTH = (1, 1.0, 1), (1, 1, 1.0)


def _film_tube(growth=HOOP, material=None, *, stretch=1.0) -> Tube:
    """A film [1, 1.1] (mu = 1, growing) bonded inside a substrate to 2 (mu = 0.2), L = 1."""
    material = material or neo_hookean()
    return Tube(
        [
            Layer(1.1, shear_modulus=1.0, growth=growth, material=material),
            Layer(2.0, shear_modulus=0.2, material=material),
        ],
        length=1.0,
        stretch=stretch,
    )


@pytest.mark.parametrize("material", [neo_hookean(), gent(4.0)], ids=["neo-hookean", "gent"])
def test_base_state_is_stationary(material):
    """E1's gradient on every harmonic of the correction vanishes (a hoop-grown film at
    lambda_z = 1.1): the polynomial's first order is the package's stress."""
    tube = _film_tube(material=material, stretch=1.1)
    forms = wall_forms(tube, (4, 1), SECOND, 12)
    state = solve_base_state(tube.at(THETA, 1.6))
    g = forms.gradient(forms.lagrangian(state)[1], forms.fields(np.zeros(forms.size)))
    assert np.abs(g).max() < 1e-13


@pytest.mark.parametrize("mode", [(4, 1), (1, 1)])
def test_singular_at_the_impedance_critical_value(mode):
    """The discrete energy's A(g) is singular at the package's critical growth (Stroh /
    Riccati, an independent formulation) to the eigenvalue's rounding floor: measured
    1.3e-12 (4, 1) and 5e-13 (1, 1) relative at 16 points, wandering without a trend
    between 3e-14 and 2.9e-12 at 12 to 32 points; and the cubic form vanishes on the
    mode (c_1 = 0: E3(phi) is a mean of products of three first harmonics) while the
    correction's forcing does not."""
    tube = _film_tube()
    e = wrinkle_expansion(tube, mode, THETA, nodes=16)
    assert e.control_value == pytest.approx(e.impedance_value, rel=3e-12)
    first = wall_forms(tube, mode, MODE, 16)
    second = wall_forms(tube, mode, SECOND, 16)
    state = solve_base_state(tube.at(THETA, e.control_value))
    phi = _nearest_zero(first.stiffness(state))[1]
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    f = first.fields(phi)
    L = second.lagrangian(state)
    assert abs(first.energy(L[3], f)) < 1e-12
    assert np.abs(second.gradient(L[3], f)).max() > 1e-2


# ---- the families it contains -----------------------------------------------------------


def _meridian(h):  # (field, j) of meridian_forms: a, b = U_z, c = q
    return tuple((0 if f == 0 else 2 if f == 1 else 3, 0, j) for f, j in h)


def _polar(h):  # (field, j) of polar_forms: a, b = U_th, c = q
    return tuple((3 if f == 2 else f, j, 0) for f, j in h)


def test_at_m_zero_the_forms_are_the_meridian_forms():
    """At m = 0 (no Theta dependence, no U_th) every order of the Lagrangian, and so A and
    the coefficient of the axisymmetric mode (0, 3) of a Gent film, are the meridian
    family's (the same discrete energy: agreement to rounding and the finite-difference
    floor of A')."""
    tube = _film_tube(AXIAL_GROWTH, gent(4.0), stretch=1.1)
    K = axial_wavenumber(tube, 3)
    cut = rings(tube, max(K, 1.0), 12)
    wall = WallForms.build(cut, 0, K, _meridian(PLANE_SECOND))
    meridian = MeridianForms.build(cut, K, PLANE_SECOND)
    state = solve_base_state(tube.at(AXIAL, 1.25))
    A, B = wall.stiffness(state), meridian.stiffness(state)
    assert np.abs(A - B).max() < 1e-13 * np.abs(B).max()
    v = np.random.default_rng(1).standard_normal(wall.size)
    Lw, Lm = wall.lagrangian(state), meridian.lagrangian(state)
    for k in (3, 4):
        ew, em = wall.energy(Lw[k], wall.fields(v)), meridian.energy(Lm[k], meridian.fields(v))
        assert ew == pytest.approx(em, rel=1e-12)
    ours = expand(
        tube,
        AXIAL,
        WallForms.build(cut, 0, K, _meridian(PLANE_MODE)),
        wall,
        onset_value(tube, (0, 3), AXIAL, None),
        "axial growth",
    )
    theirs = axisymmetric_expansion(tube, 3, AXIAL, nodes=12)
    assert ours.coefficient == pytest.approx(theirs.coefficient, rel=1e-9)


def test_with_the_axial_harmonic_switched_off_the_forms_are_the_polar_forms():
    """At K = 0 (no Z dependence, no U_z) A and the coefficient of the prismatic mode
    (12, 0) of a Mooney-Rivlin film at lambda_z = 1.1 are the polar family's."""
    tube = _film_tube(HOOP, mooney_rivlin(0.4), stretch=1.1)
    cut = rings(tube, 12, 12)
    wall = WallForms.build(cut, 12, 0.0, _polar(PLANE_SECOND))
    polar = PolarForms.build(cut, 12, PLANE_SECOND)
    state = solve_base_state(tube.at(THETA, 1.6))
    A, B = wall.stiffness(state), polar.stiffness(state)
    assert np.abs(A - B).max() < 1e-13 * np.abs(B).max()
    start = onset_value(tube, (12, 0), THETA, None)
    ours = expand(tube, THETA, WallForms.build(cut, 12, 0.0, _polar(PLANE_MODE)), wall, start, "g")
    theirs = tube_expansion(tube, 12, THETA, nodes=12)
    assert ours.coefficient == pytest.approx(theirs.coefficient, rel=1e-9)


# ---- convergence and the door -----------------------------------------------------------


def test_coefficient_converges_and_the_door_reports_it():
    """g_2 of mode (4, 1) at 6, 8, 10 points a segment against 20, spectral: errors 2.8e-3,
    3.9e-4, 3.5e-6 (12 points reach the floor of the finite-difference A', ~2e-9
    relative: 15.78259875 +- 3e-8 at 12 to 32 points); the door's estimate (24 against
    18) is below 1e-6 relative and its branch follows the sign (growth: g_2 > 0 is
    supercritical)."""
    tube = _film_tube()
    g2 = [wrinkle_expansion(tube, (4, 1), THETA, nodes=n).coefficient for n in (6, 8, 10, 20)]
    err = [abs(g - g2[-1]) for g in g2[:-1]]
    assert err[2] < 0.1 * err[1] < 0.1 * err[0] and err[2] < 1e-5
    r = koiter_coefficient(tube, (4, 1), THETA)
    assert r.error_estimate < 1e-6 * abs(r.coefficient)
    assert r.coefficient == pytest.approx(g2[-1], rel=1e-8)
    assert r.wavenumber == pytest.approx(np.pi)
    assert r.branch == ("supercritical" if r.coefficient > 0 else "subcritical")


def test_uncovered_wrinkles_are_refused_in_one_line():
    tube = _film_tube()
    cases = [
        (tube, (3, 1), "force"),
        (
            dataclasses.replace(tube, stretch=None, axial_force=0.0, inner_pressure=0.1),
            (3, 1),
            THETA,
        ),
        (tube, (1, 0), THETA),
    ]
    for t, mode, control in cases:
        with pytest.raises(ParameterError) as err:
            koiter_coefficient(t, mode, control)
        assert "\n" not in str(err.value)


# ---- a second route: Newton's method on the full equations -----------------------------


def _full_equations(forms, tube, control):
    """residual(c, w) and jacobian(c, w) of the full discrete energy on ``forms``: the
    local gradient dL/dF from W's first derivatives at the full F (test_koiter_energies),
    its local Hessian by central differences, contracted with the forms' blocks."""
    n_ang = forms.weight.shape[0]
    points = types.SimpleNamespace(R=np.tile(forms.R, n_ang), layer=np.tile(forms.layer, n_ang))
    names = [*ENTRIES, "q"]

    def local(c, w, shift=None):
        base = _base(points, solve_base_state(tube.at(control, c)))
        f = {k: v.ravel() for k, v in forms.fields(w).items()}
        if shift:
            f = {**f, shift[0]: f[shift[0]] + shift[1]}
        g = _local_gradient(base, tube.layers, points.layer, ENTRIES, f)
        return {k: v.reshape(forms.weight.shape) for k, v in g.items()}

    def residual(c, w):
        g0, g = local(c, np.zeros_like(w)), local(c, w)
        return forms.contract({k: forms.weight * (g[k] - g0[k]) for k in names})

    def jacobian(c, w, h=1e-6):
        pairs = {}
        for b in names:
            up, down = local(c, w, (b, h)), local(c, w, (b, -h))
            for a in names:
                pairs[a, b] = forms.weight * (up[a] - down[a]) / (2 * h)
        return forms.pair_matrices(pairs)

    return residual, jacobian


#: harmonics 0-3 of both directions that the mode (1, 1) reaches: j, l both even or odd
FULL = tuple(
    (f, j, l)
    for j in range(4)
    for l in range(4)
    if j % 2 == l % 2
    for f in range(4)
    if not ((f == 1 and j == 0) or (f == 2 and l == 0))
)


def _newton(material):
    """(the expansion's g_2, Newton's curvature) of mode (4, 1) of the hoop-grown film
    (lambda_z = 1, 12 points a segment): Newton's method on the full equations (harmonics
    0-3 of Theta and Z, 16 points a period in each, the growth unknown, u_r of harmonic
    (1, 1) prescribed at the mode's largest node), Richardson-extrapolated twice from
    eps = 0.001, 0.002, 0.004."""
    tube = _film_tube(HOOP, material)
    e = wrinkle_expansion(tube, (4, 1), THETA, nodes=12)
    full = wall_forms(tube, (4, 1), FULL, 12, angular_points=16)
    first = wall_forms(tube, (4, 1), MODE, 12)
    phi = _nearest_zero(first.stiffness(solve_base_state(tube.at(THETA, e.control_value))))[1]
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    where = dict(zip(full.harmonics, full.slices))
    mode_vector = np.zeros(full.size)
    for h, sl in zip(MODE, first.slices):
        mode_vector[where[h]] = phi[sl]
    row = peak_row(first.rings, phi[first.slices[0]], where[0, 1, 1].start, full.size)
    residual, jacobian = _full_equations(full, tube, THETA)
    D = branch_curvature(
        e.control_value, mode_vector, row, residual, jacobian, (0.001, 0.002, 0.004)
    )
    return e.coefficient, richardson(D)


@pytest.mark.parametrize(
    "material",
    [
        neo_hookean(),
        pytest.param(mooney_rivlin(0.7), marks=pytest.mark.slow),
        pytest.param(gent(10.0), marks=pytest.mark.slow),
    ],
    ids=["neo-hookean", "mooney-rivlin", "gent"],
)
def test_branch_curvature_from_a_direct_nonlinear_solve(material):
    """The expansion's g_2 against Newton's method on the full equations (``_newton``): the
    same curvature to 1e-6. Measured (expansion / Newton): neo-Hookean 15.7825987467 /
    15.7825982218 (3.3e-8), Mooney-Rivlin alpha = 0.7 48.5686971114 / 48.5686993894
    (4.7e-8), Gent J_m = 10 23.8946866000 / 23.8946864523 (6.2e-9)."""
    expansion, newton = _newton(material)
    assert newton == pytest.approx(expansion, rel=1e-6)


def test_with_branch_fills_a_wrinkle_verdict():
    """The verdict of a wrinkle (m, n) gets its branch (it used to be refused)."""
    tube = _film_tube()
    point = critical_value(tube, 4, 1, THETA, rtol=1e-12)
    assert (point.verdict.wrinkle.m, point.verdict.wrinkle.n) == (4, 1)
    v, note = with_branch(point.verdict, tube, THETA)
    assert note is None and v.branch in ("supercritical", "subcritical")
    assert v.koiter == pytest.approx(koiter_coefficient(tube, (4, 1), THETA).coefficient)
