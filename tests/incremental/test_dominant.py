"""The dominant subspace (incremental/dominant.py) and the kernel's short-wave start.

A short wave's integration may restart near the outer face from the dominant subspace of
the frozen Stroh system, with the orientation of the carried one: its targets must equal
those of the integration through the whole wall (sign included, at every magnitude),
also where the inner face is next to its own short-wave instability (a thick tube near
the voltage threshold), where an orientation read off the frozen system at the inner
face is wrong.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from electrogrowth import Tube, solve_base_state
from electrogrowth.incremental.dominant import (
    attraction_rate,
    dominant_impedance,
    growing_projector,
    matrix_sign,
)
from electrogrowth.incremental.impedance import ALL_PAIRS, integrate_one
from electrogrowth.incremental.radial_table import build_table
from electrogrowth.model.layers import Layer


def test_matrix_sign_of_a_known_spectrum():
    rng = np.random.default_rng(3)
    V = rng.standard_normal((8, 8))
    nu = np.array([3.0, 0.5, 2.0, 7.0, -1.0, -4.0, -0.3, -2.5])
    Q = V @ np.diag(nu) @ np.linalg.inv(V)
    Z, Zi = Q.copy(), np.empty((8, 8))
    assert matrix_sign(Z, Zi)
    np.testing.assert_allclose(Z, V @ np.diag(np.sign(nu)) @ np.linalg.inv(V), atol=1e-10)
    assert attraction_rate(Q) == pytest.approx(2 * 0.3, rel=1e-10)
    P = np.empty((8, 8))
    assert growing_projector(Q, P, Zi)
    np.testing.assert_allclose(P @ P, P, atol=1e-10)
    np.testing.assert_allclose(P @ Q, Q @ P, atol=1e-9)
    assert np.trace(P) == pytest.approx(4.0)


def test_a_spectrum_on_the_imaginary_axis_has_no_sign():
    Q = np.zeros((8, 8))
    Q[0, 1], Q[1, 0] = 1.0, -1.0  # eigenvalues +-i
    for j in range(2, 8):
        Q[j, j] = 1.0 if j % 2 else -1.0
    assert attraction_rate(Q) == 0.0
    assert not matrix_sign(Q.copy(), np.empty((8, 8)))


def test_dominant_impedance_is_the_graph_of_the_growing_subspace():
    rng = np.random.default_rng(5)
    z = rng.standard_normal((4, 4))
    z = z + z.T
    w = rng.standard_normal((4, 4))
    w = w + w.T
    V = np.block([[np.eye(4), np.eye(4)], [z, w]])
    Q = V @ np.diag([1.0, 2.0, 3.0, 4.0, -1.0, -2.0, -3.0, -4.0]) @ np.linalg.inv(V)
    P, out = np.empty((8, 8)), np.empty((4, 4))
    assert growing_projector(Q, P, np.empty((8, 8)))
    assert dominant_impedance(P, out)
    np.testing.assert_allclose(out, z, atol=1e-9)


def _targets(state, modes, rtol):
    table = build_table(state)
    out = []
    for m, n in modes:
        k = n * math.pi / state.current_length
        full = integrate_one(float(m), k, ALL_PAIRS, table, 1e-12, 200000, False)
        short = integrate_one(float(m), k, ALL_PAIRS, table, rtol, 200000, True)
        plain = integrate_one(float(m), k, ALL_PAIRS, table, rtol, 200000, False)
        assert full[3] == short[3] == plain[3] == 0
        out.append((full[0], short[0], plain[0], short[4], plain[4]))
    return np.array(out)


MODES = [(1, 12), (1, 18), (2, 18), (5, 20), (1, 30), (20, 30), (12, 40), (3, 8)]


@pytest.mark.parametrize(
    "params",
    [
        # near the voltage threshold: the inner face is next to its short-wave limit
        Tube.uniform(2.0, 1.0, voltage=0.796063),
        Tube.uniform(2.0, 1.0, growth=2.11, voltage=0.3),
        Tube.uniform(1.4, 0.5, growth=1.888, voltage=0.4),
    ],
    ids=["thick-near-threshold", "thick-grown", "short"],
)
@pytest.mark.parametrize("rtol", [1e-5, 1e-8])
def test_short_wave_start_keeps_every_target_and_its_sign(params, rtol):
    t = _targets(solve_base_state(params), MODES, rtol)
    full, short, plain = t[:, 0], t[:, 1], t[:, 2]
    assert np.all(np.sign(short) == np.sign(full))
    # errors of the size the whole-wall integration makes at the same rtol
    assert np.abs(short - full).max() <= 10 * np.abs(plain - full).max()
    assert np.abs(short - full).max() <= 10 * rtol
    assert t[:, 3].sum() < 0.7 * t[:, 4].sum()  # and it was taken: fewer steps


def test_short_wave_start_in_the_outer_layer_of_a_pressurised_bilayer():
    inner = Layer(1.3, growth=(1.0, 1.4, 1.0), shear_modulus=3.0)
    outer = Layer(2.2, growth=1.1)
    tube = Tube((inner, outer), length=1.0, stretch=1.0, voltage=0.2, inner_pressure=0.1)
    t = _targets(solve_base_state(tube), MODES, 1e-6)
    assert np.all(np.sign(t[:, 1]) == np.sign(t[:, 0]))
    assert np.abs(t[:, 1] - t[:, 0]).max() <= 1e-5
    assert t[:, 3].sum() < t[:, 4].sum()
