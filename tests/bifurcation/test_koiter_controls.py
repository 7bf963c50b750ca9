"""The Koiter coefficient of a tube's mode in controls other than a growth
(bifurcation/koiter_controls.py, docs/derivation-koiter.md "Other controls"): the voltage at
fixed growth (prismatic modes), the axial stretch (prismatic, under a voltage, and
axisymmetric). For each: the base state is stationary, A(c) is singular at the package's
critical value, the coefficient converges in the node count, Newton's method on the full
equations gives the same curvature, and the coefficients of two controls at the same onset
point obey c2_a = -c2_b dc_a/dc_b along the package's critical curve."""

from __future__ import annotations

import functools

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.koiter import koiter_coefficient, with_branch
from electrogrowth.bifurcation.koiter_film import MODE, _nearest_zero
from electrogrowth.bifurcation.koiter_tube import (
    SECOND,
    axial_wavenumber,
    axisymmetric_expansion,
    tube_expansion,
)
from electrogrowth.errors import ParameterError
from electrogrowth.incremental.dielectric_forms import DielectricForms
from electrogrowth.incremental.meridian_forms import MeridianForms
from electrogrowth.incremental.polar_forms import rings
from electrogrowth.model.layer import Layer
from electrogrowth.model.layers import Tube
from tests.bifurcation.koiter_newton import peak_row
from tests.bifurcation.test_koiter_axisymmetric import _jacobian, _residual


def _tube(growth, voltage: float = 0.0) -> Tube:
    """A film [1, 1.1] (mu = 1, permittivity 2) in a substrate to 2 (mu = 0.2,
    permittivity 0.5), L = 1, lambda_z = 1."""
    return Tube(
        [
            Layer(1.1, shear_modulus=1.0, growth=growth, permittivity=2.0),
            Layer(2.0, shear_modulus=0.2, permittivity=0.5),
        ],
        length=1.0,
        stretch=1.0,
        voltage=voltage,
    )


#: name: (tube, mode, control, side, the growth control through the same onset point)
CASES = {
    "voltage": (_tube((1, 1.5, 1)), (12, 0), "voltage", None, "growth[1].theta"),
    "stretch-prismatic": (
        _tube((1, 1.5, 1), 0.5),
        (12, 0),
        "stretch",
        "extension",
        "growth[1].theta",
    ),
    "stretch-axisymmetric": (_tube((1, 1, 1.2)), (0, 3), "stretch", None, "growth[1].z"),
}


@functools.cache
def _expansion(name: str, nodes: int = 16, control: str | None = None):
    """The expansion of case ``name`` in its control, or in ``control`` at its onset."""
    tube, mode, own, side, _ = CASES[name]
    if control is not None:
        tube, side = tube.at(own, _expansion(name, 24).control_value), None
    control = control or own
    if mode[1] == 0:
        return tube_expansion(tube, mode[0], control, nodes=nodes, side=side)
    return axisymmetric_expansion(tube, mode[1], control, nodes=nodes, side=side)


def _forms(tube, mode, harmonics, nodes=16, points=8):
    """The forms the expansion of ``mode`` uses (dielectric for prismatic modes here: the
    voltage control and the stretch under a voltage), on ``harmonics`` (and for prismatic
    modes the potential at each harmonic of u_r)."""
    if mode[1] == 0:
        extra = tuple((3, j) for f, j in harmonics if f == 0)
        cut = rings(tube, mode[0], nodes)
        return DielectricForms.build(cut, mode[0], harmonics + extra, theta_points=points)
    K = axial_wavenumber(tube, mode[1])
    return MeridianForms.build(rings(tube, max(K, 1.0), nodes), K, harmonics, z_points=points)


@pytest.mark.parametrize("name", CASES)
def test_base_state_is_stationary(name):
    """The first variation of the discrete energy vanishes at the onset's base state on
    every field and harmonic (measured below 1e-14)."""
    tube, mode, control, _, _ = CASES[name]
    forms = _forms(tube, mode, SECOND + MODE)
    state = solve_base_state(tube.at(control, _expansion(name).control_value))
    zero = {k: np.zeros_like(forms.R) for k in forms.maps}
    assert np.abs(forms.gradient(forms.lagrangian(state)[1], zero)).max() < 1e-13


@pytest.mark.parametrize("name", CASES)
def test_singular_at_the_package_critical_value(name):
    """A(c) is singular where the package's impedance route (Stroh/Riccati, independent)
    puts the critical value (measured 4e-14, 5e-14 and 7e-14 apart)."""
    e = _expansion(name)
    assert e.control_value == pytest.approx(e.impedance_value, rel=1e-12)


@pytest.mark.parametrize("name", CASES)
def test_coefficient_converges_in_the_nodes(name):
    """12, 16 and 24 points a segment: the change from 16 to 24 is below 1e-8 relative and
    at most a tenth of that from 12 (measured V_2 = 25.0891111550, 25.0891105572,
    25.0891105569; lz_2 = 66.2627372, 66.26273564, 66.26273564 and -13.5922796,
    -13.59228059, -13.59228067: a floor of ~6e-9 relative, the finite-difference A' of
    base states in lambda_z)."""
    c12, c16, c24 = (_expansion(name, n).coefficient for n in (12, 16, 24))
    assert abs(c16 - c24) < 1e-8 * abs(c24)
    assert abs(c16 - c24) < abs(c12 - c24) / 10


@pytest.mark.parametrize("name", CASES)
def test_two_controls_at_one_onset_point(name):
    """At one onset point the branch is one curve in (control, growth, eps): the eps^2
    level of the bifurcation set is the critical curve shifted, so c2 = -g2 dc_c/dg, the
    slope from the package's critical values at g +- h (Richardson, h = 0.01, 0.005),
    g2 the growth control's coefficient through the same point (measured 3e-8, 2e-10,
    5e-9 apart)."""
    tube, mode, control, side, growth = CASES[name]
    g = _expansion(name, 24, growth)
    grown = tube.layers[0].growth[2 if mode[0] == 0 else 1]
    assert g.control_value == pytest.approx(grown, rel=1e-11)

    def critical(h):
        at = tube.at(growth, g.control_value + h)
        return critical_value(at, *mode, control, side=side, rtol=1e-12).value

    d = [(critical(h) - critical(-h)) / (2 * h) for h in (0.01, 0.005)]
    slope = (4 * d[1] - d[0]) / 3
    assert _expansion(name, 24).coefficient == pytest.approx(-g.coefficient * slope, rel=1e-6)


def _newton_curvature(name, residual, jacobian, full, first, eps_values):
    """(c(eps) - c_c) / eps^2 on the branch of Newton's method on ``residual`` (the control
    unknown, u_r of harmonic 1 prescribed at the mode's largest node), for each eps."""
    tube, _, control, _, _ = CASES[name]
    e = _expansion(name)
    one = dict(zip(full.harmonics, full.slices))
    phi = _nearest_zero(first.stiffness(solve_base_state(tube.at(control, e.control_value))))[1]
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    a = phi[first.slices[0]]
    row = peak_row(first.rings, a, one[(0, 1)].start, full.size)
    peak = row[one[(0, 1)]] @ a  # the mode's u_r at that node

    def branch(eps):
        w = np.zeros(full.size)
        for (f, _), sl in zip(first.harmonics, first.slices):
            w[one[(f, 1)]] = eps * phi[sl]
        c, size = e.control_value, full.size
        for _ in range(30):
            h = 1e-3 * max(1.0, abs(c))
            J = np.zeros((size + 1, size + 1))
            J[:size, :size] = jacobian(c, w)
            J[:size, size] = (residual(c + h, w) - residual(c - h, w)) / (2 * h)
            J[size, :size] = row
            rhs = np.concatenate([residual(c, w), [row @ w - eps * peak]])
            step = np.linalg.solve(J, rhs)
            w, c = w - step[:size], c - step[size]
            if abs(step[size]) < 1e-14:
                break
        return c

    return [(branch(x) - e.control_value) / x**2 for x in eps_values]


@pytest.mark.slow
@pytest.mark.parametrize(
    ("name", "eps"),
    [("voltage", (0.000125, 0.00025, 0.0005)), ("stretch-prismatic", (0.000125, 0.00025, 0.0005))],
)
def test_prismatic_branch_curvature_from_newton(name, eps):
    """Newton's method on the full discrete equations (every order of the energy with the
    potential, harmonics 0-3 of every field, 16 points a period), the voltage or the
    stretch the unknown control: the curvature, Richardson-extrapolated twice in eps
    (eps^2 and eps^4 terms), equals the expansion's c_2 to 1e-6. Under the voltage
    control the branch bends fast (the breathing of the wall softens towards the
    voltage's threshold, 0.725: (V - V_c) / eps^2 = 25.109, 25.170, 25.414, 26.397 at
    eps = 1.25e-4 to 1e-3, V_4 ~ 1.3e6), hence the small amplitudes; extrapolated
    25.0891108 against 25.0891106."""
    tube, mode, control, _, _ = CASES[name]
    harmonics = ((0, 0), (2, 0)) + tuple((f, j) for j in (1, 2, 3) for f in range(3))
    full = _forms(tube, mode, harmonics, points=16)
    first = _forms(tube, mode, MODE)
    zero = {k: np.zeros_like(full.R) for k in full.maps}

    def residual(c, w):
        L, f = full.lagrangian(solve_base_state(tube.at(control, c))), full.fields(w)
        return sum(full.gradient(L[k], f) for k in (1, 2, 3, 4)) - full.gradient(L[1], zero)

    def jacobian(c, w):
        L, f = full.lagrangian(solve_base_state(tube.at(control, c))), full.fields(w)
        return sum(full.hessian(L[k], f) for k in (2, 3, 4))

    D = _newton_curvature(name, residual, jacobian, full, first, eps)
    R1 = [(4 * D[0] - D[1]) / 3, (4 * D[1] - D[2]) / 3]
    assert (16 * R1[0] - R1[1]) / 15 == pytest.approx(_expansion(name).coefficient, rel=1e-6)


@pytest.mark.slow
def test_axisymmetric_stretch_curvature_from_newton():
    """Newton's method on the full meridian equations written from det F directly (not
    from the expansion's orders: test_koiter_axisymmetric's ``_residual``), the axial
    stretch the unknown control: the same lambda_2 to 1e-6."""
    name = "stretch-axisymmetric"
    tube, mode, control, _, _ = CASES[name]
    harmonics = ((0, 0), (2, 0)) + tuple((f, j) for j in (1, 2, 3) for f in range(3))
    full = _forms(tube, mode, harmonics, points=16)
    first = _forms(tube, mode, MODE)

    def residual(c, w):
        return _residual(full, solve_base_state(tube.at(control, c)), w)

    def jacobian(c, w):
        return _jacobian(full, solve_base_state(tube.at(control, c)), w)

    d1, d2 = _newton_curvature(name, residual, jacobian, full, first, (0.002, 0.004))
    assert (4 * d1 - d2) / 3 == pytest.approx(_expansion(name).coefficient, rel=1e-6)


def test_door_and_branch_direction():
    """koiter_coefficient takes the voltage and the stretch; the branch is read in the
    control's direction: lambda_2 < 0 on the compression side (the default) is
    supercritical, lambda_2 > 0 on the extension side too; other controls and families
    are refused in one line."""
    tube, mode, control, side, _ = CASES["stretch-axisymmetric"]
    r = koiter_coefficient(tube, mode, control)
    assert r.coefficient < 0 and r.branch == "supercritical"
    assert r.error_estimate < 1e-7 * abs(r.coefficient)
    tube, mode, control, side, _ = CASES["stretch-prismatic"]
    r = koiter_coefficient(tube, mode, control, side=side)
    assert r.coefficient > 0 and r.branch == "supercritical"
    with pytest.raises(ParameterError, match="axisymmetric family's amplitude equation covers"):
        koiter_coefficient(_tube((1, 1, 1.2)), (0, 3), "force")
    with pytest.raises(ParameterError, match="covers growth, voltage, stretch"):
        koiter_coefficient(_tube((1, 1.5, 1)), (12, 0), "force")


def test_with_branch_fills_the_voltage_verdict():
    """The CLI's route: the critical point's verdict gains the branch of the voltage
    control (the same coefficient as the door's)."""
    tube, mode, control, _, _ = CASES["voltage"]
    point = critical_value(tube, *mode, control, rtol=1e-12)
    verdict, why = with_branch(point.verdict, tube, control)
    assert why is None and verdict.branch == "supercritical"
    assert verdict.koiter == pytest.approx(_expansion("voltage", 24).coefficient, rel=1e-8)
