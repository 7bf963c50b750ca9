"""The gallery of layered tubes (figures/gallery.py): each example in quick mode, its headline
number checked by an independent route (the other method, the single-layer solver, an exact
identity, the base-state branch)."""

import dataclasses
import math

import numpy as np
import pytest

from electrogrowth import Tube, critical_value
from electrogrowth.basestate.layered import (
    layered_threshold,
    pressure_response,
    solve_layered_state,
)
from electrogrowth.figures import GALLERY
from electrogrowth.figures.gallery import (
    bilayer,
    mucosal_folding,
    one_layer_growth,
    pressurised_dielectric,
)
from electrogrowth.model.layers import Layer


def _case(result, case):
    return next(o for o in result.onsets if o.case == case)


def test_registry_names_every_example():
    assert list(GALLERY) == ["mucosal_folding", "one_layer_growth", "pressurised_dielectric"]


@pytest.fixture(scope="module")
def one_layer():
    return one_layer_growth(quick=True)


def test_axial_growth_is_an_axial_compression_of_the_ungrown_tube(one_layer):
    """(g_z; lambda_z = 1, L) == (1; 1 / g_z, g_z L) (docs/derivation-layered.md Sec. 7): the
    critical axial growth is 1 / the critical stretch of the ungrown single-layer tube of length
    g_z L, solved by the single-layer solver, same mode."""
    o = _case(one_layer, "g_z, fixed stretch")
    assert o.critical.kind == "bifurcation"
    g, (m, n) = o.value, o.mode
    ungrown = Tube.uniform(2.0, length=g)
    assert critical_value(ungrown, m, n, "stretch").value == pytest.approx(1.0 / g, rel=1e-8)
    assert one_layer.headline["g_z_fixed_Ro2"] == g


def test_hoop_growth_of_one_layer_at_fixed_stretch_is_reported_as_none(one_layer):
    o = _case(one_layer, "g_theta, fixed stretch")
    assert o.critical is None and math.isnan(o.value)
    assert "no mode bifurcates" in o.note
    assert one_layer.table[0][8] == "none"


def test_folds_under_hoop_growth_ignore_the_axial_constraint():
    """Neo-Hookean layers, no voltage or pressure: the plane-strain (prismatic) problem at any
    lambda_z is the one at lambda_z = 1 rescaled, so fixed stretch and free ends give the same
    critical hoop growth for the fold mode though their base states differ."""
    fixed = critical_value(bilayer(), 11, 0, "growth[1].theta")
    free = critical_value(bilayer(axial_force=0.0), 11, 0, "growth[1].theta")
    assert free.value == pytest.approx(fixed.value, rel=1e-10)


def test_stiff_mucosal_layer_solves_and_equals_collocation():
    """mu_1/mu_2 = 100 (the gallery's stiff point, whose base state once failed "not resolved
    by Chebyshev degree 512"): the base state and the critical hoop growth of its mode (4, 1)
    solve, collocation agrees, and the neighbouring modes come later."""
    tube = bilayer(mu=100.0)
    crit = critical_value(tube, 4, 1, "growth[1].theta")
    grown = Tube((Layer(1.1, shear_modulus=100.0, growth=(1.0, crit.value, 1.0)), Layer(2.0)))
    state = solve_layered_state(grown)
    assert state.quadrature_error < 1e-10  # the independent per-layer quadrature's residual
    # the stiff ring nearly reaches its grown circumference: a hoop compression of ~1 %
    assert 0.98 * crit.value < state.lambda_i < crit.value
    other = critical_value(tube, 4, 1, "growth[1].theta", family=crit.family, method="collocation")
    assert other.value == pytest.approx(crit.value, rel=1e-8)
    for m, n in ((3, 1), (5, 1), (4, 2)):
        assert critical_value(tube, m, n, "growth[1].theta").value > crit.value


@pytest.mark.slow
def test_mucosal_folding_headline_by_collocation():
    result = mucosal_folding(quick=True)
    head = result.headline
    assert (head["m_cr"], head["n_cr"]) == (11, 0)
    crit = result.points[0][1]
    other = critical_value(
        bilayer(), crit.m, crit.n, "growth[1].theta", family=crit.family, method="collocation"
    )
    assert other.value == pytest.approx(head["hoop_growth"], rel=1e-8)


@pytest.mark.slow
def test_pressurised_dielectric_headlines():
    result = pressurised_dielectric(quick=True)
    o = _case(result, "voltage vs pressure")
    other = critical_value(
        Tube((Layer(1.4),), inner_pressure=0.1), *o.mode, "voltage", method="collocation"
    )
    assert other.value == pytest.approx(result.headline["voltage_P0.1"], rel=1e-8)
    # the closed-end limit point is the maximum of its inflation branch at zero axial force
    limit = result.headline["limit_closed"]
    tube = Tube((Layer(1.4),), axial_force=0.0, closed_ends=True)
    row = next(r for r in result.table if r[0] == "limit point, closed ends")
    lam = float(row[9].split("= ")[1])
    near = pressure_response(tube, [lam * (1 - 1e-3), lam * (1 + 1e-3)])["inner_pressure"]
    assert np.all(near < limit)
    # the long axisymmetric mode of the open-ended tube, by collocation
    long = Tube((Layer(1.4),), axial_force=0.0, length=20.0)
    other = critical_value(long, 0, 1, "pressure", method="collocation")
    assert other.value == pytest.approx(result.headline["bulge_L20_open"], rel=1e-8)
    # ... is close to the limit point of the closed-ended tube carrying the same total axial
    # load N + pi r_i^2 P (the long-wave bulging condition, docs/patterns.md): they coincide at
    # L = inf, and the gap is quadratic in the distance (6.7e-4 at L = 20) from it
    p20 = other.value
    open_state = solve_layered_state(dataclasses.replace(long, inner_pressure=p20))
    force = -math.pi * open_state.r_i**2 * p20
    closed = layered_threshold(
        Tube((Layer(1.4),), axial_force=force, closed_ends=True), "pressure"
    )
    assert closed.kind == "limit point"
    assert closed.value == pytest.approx(p20, abs=1e-5)
