"""The closed-form wall integrals of neo-Hookean layers with constant growth
(basestate/neo_hookean_wall.py) against the Gauss rule they replace and scipy's quad."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from electrogrowth.basestate.plies import Wall
from electrogrowth.model.layers import Layer, LinearGrowth, Tube
from electrogrowth.model.materials import mooney_rivlin


def random_wall(rng):
    """2-3 neo-Hookean layers, anisotropic growth, moduli 1e-4..1e4, thicknesses 1e-3..1."""
    R, layers = 1.0, []
    for _ in range(rng.integers(2, 4)):
        R += 10 ** rng.uniform(-3, 0)
        layers.append(
            Layer(
                R,
                shear_modulus=10 ** rng.uniform(-4, 4),
                permittivity=10 ** rng.uniform(-1, 1),
                growth=tuple(rng.uniform(0.8, 1.6, 3)),
            )
        )
    return Tube(tuple(layers), length=1.0, stretch=rng.uniform(0.7, 1.5))


def gauss(wall, r_i, lz, c, nodes=96):
    """The Gauss rule of plies.py, with enough nodes to be exact to rounding."""
    return Wall.build(wall.tube, nodes).integrals(r_i, lz, c)


def test_closed_form_equals_the_gauss_rule():
    rng = np.random.default_rng(7)
    worst = 0.0
    for _ in range(40):
        tube = random_wall(rng)
        wall = Wall.build(tube, 8)
        assert wall.closed_form.all()
        r_i = rng.uniform(0.5, 2.0, 5)
        lz = np.full(5, tube.stretch)
        c = rng.uniform(0.0, 2.0, 5) * math.sqrt(min(lay.shear_modulus for lay in tube.layers))
        got, ref = wall.integrals(r_i, lz, c, compiled=True), gauss(wall, r_i, lz, c)
        scale = np.maximum(abs(ref), got[1])  # T and N_int cancel within the stress scale
        worst = max(worst, float((abs(got - ref) / scale).max()))
    assert worst < 3e-14, worst  # measured 8.4e-15 (300 walls)


def test_quad_in_the_current_radius():
    """T = int (tau_2 - tau_1) dr / r and N_int by quad in r, for a thin stiff film on a soft
    substrate (h = 1e-3, mu 1e3 on 1)."""
    film = Layer(1.001, shear_modulus=1e3, growth=(1.0, 1.3, 1.1))
    tube = Tube((film, Layer(2.5, growth=(1.1, 1.0, 1.2))), length=1.0, stretch=1.1)
    r_i, lz, c = 1.2, 1.1, 0.7
    wall = Wall.build(tube, 8)
    got = wall.integrals(np.array([r_i]), np.array([lz]), np.array([c]), compiled=True)[:, 0]
    T = N = 0.0
    r_a2 = r_i * r_i
    for a, layer in zip(tube.radii, tube.layers):
        b, (gr, gt, gz), mu = layer.outer_radius, layer.growth, layer.shear_modulus
        J = gr * gt * gz
        r_b2 = r_a2 + J * (b * b - a * a) / lz

        def fields(r, r_a2=r_a2, a=a, J=J, gt=gt, gz=gz, mu=mu, eps=layer.permittivity):
            R = math.sqrt(a * a + lz * (r * r - r_a2) / J)
            l2, l3 = r / (gt * R), lz / gz
            tau1 = mu / (l2 * l3) ** 2 + (c / r) ** 2 / eps
            return tau1, mu * l2 * l2, mu * l3 * l3

        lo, hi = math.sqrt(r_a2), math.sqrt(r_b2)
        T += quad(lambda r: (fields(r)[1] - fields(r)[0]) / r, lo, hi, epsabs=0, epsrel=1e-13)[0]
        N += (
            math.pi
            * quad(
                lambda r: (2 * fields(r)[2] - fields(r)[0] - fields(r)[1]) * r,
                lo,
                hi,
                epsabs=0,
                epsrel=1e-13,
            )[0]
        )
        r_a2 = r_b2
    assert got[0] == pytest.approx(T, rel=1e-12, abs=1e-12 * got[1])
    assert got[3] == pytest.approx(N, rel=1e-12)


def test_not_a_wall_gives_nan():
    tube = Tube((Layer(1.1), Layer(2.0)), length=1.0)
    out = Wall.build(tube, 8).integrals([1.0, 0.0], [-1.0, 1.0], 0.0, compiled=True)
    assert np.isnan(out).all()


def test_mixed_wall_takes_the_closed_form_only_where_it_holds():
    """A neo-Hookean film, a Mooney-Rivlin layer and a graded neo-Hookean layer: the first
    by the closed form, the others by the Gauss rule, the sum the Gauss rule's."""
    tube = Tube(
        (
            Layer(1.01, shear_modulus=50.0, growth=(1.0, 1.2, 1.0)),
            Layer(1.4, material=mooney_rivlin(0.3), growth=1.1),
            Layer(
                1.9,
                shear_modulus=0.2,
                growth=LinearGrowth(1.4, 1.9, (1.0, 1.1, 1.0), (1.0, 1.3, 1.0)),
            ),
        ),
        length=1.0,
        stretch=1.05,
    )
    wall = Wall.build(tube, 64)
    assert wall.closed_form.tolist() == [True, False, False]
    r_i, lz, c = np.array([1.1, 1.3]), np.array([1.05, 1.05]), np.array([0.0, 0.4])
    got, ref = wall.integrals(r_i, lz, c, compiled=True), wall.integrals(r_i, lz, c)
    np.testing.assert_allclose(got, ref, rtol=1e-13, atol=1e-13 * abs(ref[1]).max())
