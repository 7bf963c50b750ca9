"""The meridian model (axisymmetric modes (0, n), postbuckle/meridian.py) against the package:
its base state (basestate/: closed-form kinematics and quadrature), its onset (the
Stroh/impedance route of bifurcation/critical.py, an independent method), the consistency
of its energy, residual and tangent, and the convergence of the branch's initial curvature."""

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.basestate.tube import solve_base_state  # noqa: E402
from electrogrowth.bifurcation.critical import critical_value  # noqa: E402
from electrogrowth.model.layers import Layer, Tube  # noqa: E402
from electrogrowth.postbuckle.api import initial_curvature  # noqa: E402
from electrogrowth.postbuckle.meridian import Meridian, meridian_size  # noqa: E402
from electrogrowth.postbuckle.newton import loaded  # noqa: E402
from electrogrowth.postbuckle.onset import fe_onset  # noqa: E402
from electrogrowth.postbuckle.wall import MeshSize  # noqa: E402

#: a stiff inner layer growing axially on a soft outer one: axisymmetric wrinkles, critical
#: n = 5 for L = 2 (n = 4: 1.17684, n = 5: 1.17097, n = 6: 1.17960)
BILAYER = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0, length=2.0)
CONTROL = "growth[1].z"
N = 5
#: every load at once: anisotropic growth, axial stretch, both pressures, voltage, contrasts
LOADED = Tube(
    (Layer(1.5, growth=(1.05, 1.1, 1.02)), Layer(2.0, shear_modulus=2.0, permittivity=3.0)),
    stretch=1.1,
    voltage=0.3,
    inner_pressure=0.3,
    outer_pressure=0.1,
    length=2.0,
)


def base_errors(tube, density, n=4):
    """Largest differences of the faces' radii, of sigma_rr, sigma_tt, sigma_zz (every
    quadrature point), and the largest |sigma_rz| and |u_Z|, on one element along the
    window L / n (the state does not depend on Z; n sets the elements' aspect ratio)."""
    mer = Meridian(tube, n, meridian_size(tube, n, density, axial=1))
    x = loaded(mer, tube, steps=3)
    state = solve_base_state(tube)
    radius = 0.0
    for face, R in (("inner", 1.0), ("outer", tube.radii[-1])):
        dofs, _ = mer.face_dofs(face)
        radius = max(radius, np.abs(R + x[dofs] - state.radius(R)).max())
    sigma = mer.stresses(x)
    exact = state.stresses(mer.R.ravel())
    stress = max(np.abs(sigma[i, i].ravel() - s).max() for i, s in enumerate(exact))
    return radius, stress, np.abs(sigma[0, 2]).max(), np.abs(mer.nodal(x, "u_Z")).max()


def test_base_state_matches_the_package():
    """Measured: radii 2.3e-7, 1.5e-8 (fourth order at the nodes), stresses 3.2e-4, 8.5e-5
    (second order: the pressure is linear per element) at 8 and 16 elements across the
    unit wall."""
    r1, s1, shear, uz = base_errors(LOADED, 8)
    assert r1 < 1e-6
    assert s1 < 2e-3
    assert shear < 1e-9 and uz < 1e-12  # the axisymmetric state: no shear, no u_Z
    r2, s2, _, _ = base_errors(LOADED, 16)
    assert r2 < r1 / 4
    assert s2 < s1 / 2.5


@pytest.mark.slow
def test_base_state_stresses_converge_to_1e_6():
    """Stresses to 1e-6 at 320 elements across the unit wall; the window L / 16 keeps the
    elements' aspect ratio at 40."""
    r, s, _, _ = base_errors(LOADED, 320, n=16)
    assert r < 1e-9
    assert s < 1e-6


def test_residual_and_tangent_are_the_energy_derivatives():
    """On a perturbed state of the loaded tube (pressures on both faces, voltage): the
    residual is the energy's gradient and the tangent the residual's (central differences),
    so the follower pressures' volume potential and the hoop stretch's kinematics are
    consistent, and the tangent is symmetric."""
    mer = Meridian(LOADED, 4, MeshSize((2, 2), 2))
    rng = np.random.default_rng(1)
    x = loaded(mer, LOADED, steps=2)
    x = x + mer.expand(1e-2 * rng.standard_normal(mer.unknowns))
    r, K = mer.residual(x), mer.tangent(x).toarray()
    dx = mer.expand(rng.standard_normal(mer.unknowns))
    h = 1e-6
    slope = (mer.energy(x + h * dx) - mer.energy(x - h * dx)) / (2 * h)
    assert slope == pytest.approx(r @ dx, rel=1e-6)
    dr = mer.restrict((mer.residual(x + h * dx) - mer.residual(x - h * dx)) / (2 * h))
    assert np.abs(dr - mer.restrict(K @ dx)).max() < 1e-6 * np.abs(dr).max()
    assert np.abs(K - K.T).max() < 1e-10 * np.abs(K).max()


def fe_onset_and_curvature(k: int):
    """The FE onset and initial curvature of mode (0, 5) on (2k, 9k) x 4k elements."""
    mer = Meridian(BILAYER, N, MeshSize((2 * k, 9 * k), 4 * k))
    linear = critical_value(BILAYER, 0, N, CONTROL).value
    onset = fe_onset(mer, BILAYER, CONTROL, linear)
    _, _, curvature, face, _ = initial_curvature(mer, BILAYER, CONTROL, onset)
    curvature = curvature.value
    assert face == "inner"
    return (onset.value - linear) / linear, curvature


@pytest.mark.slow
def test_onset_and_curvature_converge():
    """Uniform refinement h, h/2, h/3 (measured): onset 5.07e-5, 1.25e-5, 2.87e-6 above the
    package's (second order or better); curvature d g_z / d a^2 13.4808, 13.6844, 13.6960
    (docs/postbuckling.md)."""
    (e1, c1), (e2, c2), (e3, c3) = (fe_onset_and_curvature(k) for k in (1, 2, 3))
    assert 0 < e3 < e2 < e1 < 1e-4
    assert e2 < e1 / 3  # second order: a factor 4 per halving of h
    assert c1 > 0 and c2 > 0 and c3 > 0  # supercritical
    assert abs(c3 - c2) < abs(c2 - c1) / 4  # converging (a factor 17 measured)


@pytest.mark.slow
def test_curvature_against_the_koiter_coefficient():
    """The Koiter coefficient of mode (0, n) (bifurcation/koiter_tube.py: the meridian forms
    on Chebyshev collocation, an independent discretisation and method; skipped until it is
    on this branch), in the FE's amplitude (its eps is the mode's peak |u_r|, the FE's a the
    inner face's cos(k z) coefficient). Measured with it: 13.698635 (16, 24, 32 nodes agree
    to 1e-9) against the FE's 13.4808, 13.6844, 13.6960: gaps 1.6e-2, 1.0e-3, 1.9e-4."""
    koiter_tube = pytest.importorskip("electrogrowth.bifurcation.koiter_tube")
    if not hasattr(koiter_tube, "axisymmetric_expansion"):
        pytest.skip("the Koiter coefficient of the axisymmetric family is not here yet")
    e = koiter_tube.axisymmetric_expansion(BILAYER, N, CONTROL, nodes=24)
    c2 = e.coefficient / e.inner_face**2
    gaps = [abs(fe_onset_and_curvature(k)[1] - c2) / c2 for k in (1, 2)]
    assert gaps[1] < gaps[0] / 4
    assert gaps[1] < 2e-3
