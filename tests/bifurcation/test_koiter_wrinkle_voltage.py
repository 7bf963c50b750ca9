"""The Koiter coefficient of a tube's wrinkles (m, n) under a radial voltage
(incremental/wall_dielectric_forms.py, docs/derivation-koiter.md "The radial voltage,
wrinkles (m, n)"): the base state is stationary with the potential as a field, A(c) is
singular at the package's critical value (growth and voltage controls), the forms are the
meridian dielectric ones at m = 0 and the plane dielectric ones at K = 0, and without a
voltage the potential decouples."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.koiter import koiter_coefficient
from electrogrowth.bifurcation.koiter_tube import SECOND as PLANE_SECOND
from electrogrowth.bifurcation.koiter_tube import axial_wavenumber, expand, onset_value
from electrogrowth.bifurcation.koiter_wall import (
    MODE,
    POTENTIAL,
    SECOND,
    wall_forms,
    wrinkle_expansion,
)
from electrogrowth.incremental.dielectric_forms import DielectricForms
from electrogrowth.incremental.meridian_dielectric_forms import MeridianDielectricForms
from electrogrowth.incremental.polar_forms import rings
from electrogrowth.incremental.wall_dielectric_forms import WallDielectricForms
from electrogrowth.model.layer import Layer
from electrogrowth.model.layers import Tube
from electrogrowth.model.materials import mooney_rivlin

THETA, AXIAL = "growth[1].theta", "growth[1].z"


def _tube(voltage: float, growth=(1, 1.0, 1), material=None, stretch=1.0) -> Tube:
    """The film [1, 1.1] (mu 1, permittivity 2) in a substrate to 2 (mu 0.2, permittivity
    0.5), L = 1."""
    kw = {"material": material} if material else {}
    return Tube(
        [
            Layer(1.1, shear_modulus=1.0, growth=growth, permittivity=2.0, **kw),
            Layer(2.0, shear_modulus=0.2, permittivity=0.5, **kw),
        ],
        length=1.0,
        stretch=stretch,
        voltage=voltage,
    )


def test_base_state_is_stationary_with_the_potential_as_a_field():
    """E1 vanishes on every field and harmonic at Vbar = 0.3 (Mooney-Rivlin, lambda_z =
    1.1): the multiplier p~0 = p0 - eps e^2 and E~_0 = s0 e are right in three dimensions."""
    tube = _tube(0.3, material=mooney_rivlin(0.4), stretch=1.1)
    forms = wall_forms(tube, (4, 1), SECOND + POTENTIAL[1], 12, charged=True)
    state = solve_base_state(tube.at(THETA, 1.6))
    g = forms.gradient(forms.lagrangian(state)[1], forms.fields(np.zeros(forms.size)))
    assert np.abs(g).max() < 1e-13


@pytest.mark.parametrize(
    "control, tube",
    [(THETA, _tube(0.2)), ("voltage", _tube(0.0, growth=(1, 1.6, 1)))],
    ids=["growth", "voltage"],
)
def test_singular_at_the_impedance_critical_value(control, tube):
    """A(c) of the charged forms is singular at the package's critical value of mode
    (4, 1) (its Stroh formulation with the potential, independent) to the eigenvalue's
    rounding floor: measured 2.8e-13 (growth under Vbar = 0.2)."""
    e = wrinkle_expansion(tube, (4, 1), control, nodes=16)
    assert e.control_value == pytest.approx(e.impedance_value, rel=3e-12)


def _meridian(h):  # (field, j) of meridian_dielectric_forms: U_r, U_z, q, phi
    return tuple(((0, 2, 3, 4)[f], 0, j) for f, j in h)


def _polar(h):  # (field, j) of dielectric_forms: U_r, U_th, q, phi
    return tuple(((0, 1, 3, 4)[f], j, 0) for f, j in h)


def _same_forms(wall, other, state):
    """A to 1e-13 and the cubic and quartic energies of a random field to 1e-12."""
    A, B = wall.stiffness(state), other.stiffness(state)
    assert np.abs(A - B).max() < 1e-13 * np.abs(B).max()
    v = np.random.default_rng(2).standard_normal(wall.size)
    Lw, Lo = wall.lagrangian(state), other.lagrangian(state)
    for k in (3, 4):
        ew, eo = wall.energy(Lw[k], wall.fields(v)), other.energy(Lo[k], other.fields(v))
        assert ew == pytest.approx(eo, rel=1e-12)


SECOND_E = PLANE_SECOND + ((3, 0), (3, 2))


def test_at_m_zero_the_forms_are_the_meridian_dielectric_forms():
    tube = _tube(0.3, growth=(1, 1, 1.2), material=mooney_rivlin(0.4), stretch=1.1)
    K = axial_wavenumber(tube, 3)
    cut = rings(tube, max(K, 1.0), 10)
    wall = WallDielectricForms.build(cut, 0, K, _meridian(SECOND_E))
    other = MeridianDielectricForms.build(cut, K, SECOND_E)
    _same_forms(wall, other, solve_base_state(tube.at(AXIAL, 1.2)))


def test_at_k_zero_the_forms_are_the_plane_dielectric_forms():
    tube = _tube(0.3, material=mooney_rivlin(0.4), stretch=1.1)
    cut = rings(tube, 12, 10)
    wall = WallDielectricForms.build(cut, 12, 0.0, _polar(SECOND_E))
    other = DielectricForms.build(cut, 12, SECOND_E)
    _same_forms(wall, other, solve_base_state(tube.at(THETA, 1.6)))


def test_without_a_voltage_the_potential_decouples():
    """At Vbar = 0 the charged forms give the uncharged coefficient of (4, 1) (to the
    floor of the finite-difference A'), and the door's voltage case reports a branch."""
    tube = _tube(0.0)
    start = onset_value(tube, (4, 1), THETA, None)
    charged = expand(
        tube,
        THETA,
        wall_forms(tube, (4, 1), MODE + POTENTIAL[0], 12, charged=True),
        wall_forms(tube, (4, 1), SECOND + POTENTIAL[1], 12, charged=True),
        start,
        "growth",
    )
    plain = wrinkle_expansion(tube, (4, 1), THETA, nodes=12)
    assert charged.coefficient == pytest.approx(plain.coefficient, rel=1e-8)
    r = koiter_coefficient(_tube(0.2), (4, 1), THETA)
    assert r.error_estimate < 1e-6 * abs(r.coefficient)
    assert r.branch == ("supercritical" if r.coefficient > 0 else "subcritical")


def test_two_controls_through_one_onset_point():
    """At the onset of (4, 1) in the voltage (hoop growth 1.6), V_2 = -g_2 dV_c/dg
    (docs/derivation-koiter.md, "Two controls through one onset point"), the slope from
    the package's critical voltages at g +- h, h = 0.01, 0.005, Richardson-extrapolated:
    measured 21.6079234827 against V_2 = 21.6079236244 (6.6e-9). This checks A'(Vbar) of
    the charged forms against the package's independent critical curve."""
    ev = wrinkle_expansion(_tube(0.0, growth=(1, 1.6, 1)), (4, 1), "voltage", nodes=16)
    eg = wrinkle_expansion(_tube(ev.control_value), (4, 1), THETA, nodes=16)
    assert eg.control_value == pytest.approx(1.6, rel=1e-10)

    def critical_voltage(g):
        return critical_value(_tube(0.0, growth=(1, g, 1)), 4, 1, "voltage", rtol=1e-12).value

    d = [(critical_voltage(1.6 + h) - critical_voltage(1.6 - h)) / (2 * h) for h in (0.01, 0.005)]
    slope = (4 * d[1] - d[0]) / 3
    assert -eg.coefficient * slope == pytest.approx(ev.coefficient, rel=1e-7)
