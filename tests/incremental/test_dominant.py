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
    P = np.empty((8, 8))
    assert growing_projector(Q, P, Zi)
    np.testing.assert_allclose(P @ P, P, atol=1e-10)
    np.testing.assert_allclose(P @ Q, Q @ P, atol=1e-9)
    assert np.trace(P) == pytest.approx(4.0)


def _hamiltonian(N, seed, Q0=None):
    """A Hamiltonian 8x8 matrix with the eigenvalues of N and their negatives:
    Q0 = diag(N, -N^T) (or the Hamiltonian ``Q0`` given) under the symplectic similarity
    [[I, 0], [W, I]] [[I, V], [0, I]] (W, V symmetric)."""
    rng = np.random.default_rng(seed)
    W, V = (rng.standard_normal((4, 4)) for _ in range(2))
    T = np.block([[np.eye(4), np.zeros((4, 4))], [W + W.T, np.eye(4)]])
    T = T @ np.block([[np.eye(4), V + V.T], [np.zeros((4, 4)), np.eye(4)]])
    if Q0 is None:
        Q0 = np.block([[N, np.zeros((4, 4))], [np.zeros((4, 4)), -N.T]])
    return T @ Q0 @ np.linalg.inv(T)


def _spectrum(real, pair=None):
    """A real 4x4 matrix with eigenvalues ``real`` and, optionally, a +- i b = ``pair``."""
    N = np.diag(np.asarray(real, dtype=float))
    if pair is not None:
        a, b = pair
        N = np.zeros((4, 4))
        N[:2, :2] = [[a, b], [-b, a]]
        N[2, 2], N[3, 3] = real
    rng = np.random.default_rng(9)
    V = np.eye(4) + 0.3 * rng.standard_normal((4, 4))
    return V @ N @ np.linalg.inv(V)


@pytest.mark.parametrize(
    ("N", "rate"),
    [
        (_spectrum([0.3, 2.0, 3.5, 7.0]), 0.6),
        (_spectrum([-0.3, 2.0, 3.5, 7.0]), 0.6),  # the pairs' signs do not matter
        (_spectrum([2.0, 5.0], pair=(0.4, 1.5)), 0.8),  # a complex pair 0.4 +- 1.5 i
        (_spectrum([60.0, 60.1, 60.2, 60.25]), 120.0),  # a short wave's cluster
    ],
    ids=["real", "signs", "complex-pair", "cluster"],
)
def test_attraction_rate_of_a_known_hamiltonian_spectrum(N, rate):
    """The quartic in nu^2 (attraction_rate) against the spectrum it was built with."""
    Q = _hamiltonian(N, seed=4)
    assert attraction_rate(Q) == pytest.approx(rate, rel=1e-9, abs=1e-7)


def test_a_spectrum_on_the_imaginary_axis_attracts_at_rate_zero():
    """One pair +-i (the pair (U_0, S_0) oscillates, as where strong ellipticity is lost):
    mu = -1 is a simple root of the quartic and Re sqrt(mu) vanishes to rounding."""
    Q0 = np.diag([0.0, 1.0, 2.0, 3.0, 0.0, -1.0, -2.0, -3.0])
    Q0[0, 4], Q0[4, 0] = 1.0, -1.0
    assert attraction_rate(_hamiltonian(None, seed=4, Q0=Q0)) <= 1e-12
    assert not matrix_sign(Q0.copy(), np.empty((8, 8)))


def test_attraction_rate_of_stroh_matrices_is_that_of_their_eigenvalues():
    """On the frozen Stroh matrices a scan meets (long and short waves, m up to 2000, a
    thick charged tube and a stiff-on-soft bilayer) the quartic agrees with the
    eigenvalues of Q itself; it loses digits only where the mu nearly coincide."""
    from electrogrowth.incremental.impedance import impedance_scale
    from electrogrowth.incremental.riccati_step import _new_work
    from electrogrowth.incremental.short_wave_start import frozen_matrix

    film = Tube((Layer(1.02, growth=(1.0, 1.03, 1.0), shear_modulus=50.0), Layer(2.0)),
                length=1.0, stretch=1.0, voltage=0.1)  # fmt: skip
    worst = 0.0
    for tube in (Tube.uniform(2.0, 1.0, growth=2.0, voltage=0.3), film):
        table = build_table(solve_base_state(tube))
        work = _new_work(table)
        for seg in range(table.coef.shape[0]):
            a, b = table.bounds[seg], table.bounds[seg + 1]
            for m, n in [(0, 1), (2, 0), (1, 12), (30, 40), (300, 0), (0, 200), (2000, 3)]:
                k = n * math.pi
                s = impedance_scale(float(m), k, b)
                for R in (a, 0.5 * (a + b), b):
                    Q = np.empty((8, 8))
                    frozen_matrix(R, float(m), k, s, table, seg, work, Q)
                    exact = 2 * np.abs(np.linalg.eigvals(Q).real).min()
                    worst = max(worst, abs(attraction_rate(Q) - exact) / exact)
    assert worst <= 1e-6


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
    """(whole wall at 1e-12, short-wave start, whole wall) at ``rtol`` and the two step
    counts, for rows (m, n) of the paper's block or (m, n, kept pairs) of a family's."""
    table = build_table(state)
    out = []
    for m, n, *family in modes:
        keep = family[0] if family else ALL_PAIRS
        k = n * math.pi / state.current_length
        full = integrate_one(float(m), k, keep, table, 1e-12, 400000, False)
        short = integrate_one(float(m), k, keep, table, rtol, 400000, True)
        plain = integrate_one(float(m), k, keep, table, rtol, 400000, False)
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


#: the families' blocks (incremental/modes.py): axisymmetric wrinkles (0, n) without the
#: torsion pair, prismatic modes (m, 0) without the axial one, torsional modes (0, n) alone
M0, PRISMATIC, TORSION = 0b1101, 0b1011, 0b0010
FAMILY_ROWS = [
    (0, 12, M0), (0, 40, M0), (0, 160, M0),
    (30, 0, PRISMATIC), (120, 0, PRISMATIC), (400, 0, PRISMATIC),
    (0, 20, TORSION), (0, 80, TORSION),
]  # fmt: skip


@pytest.mark.parametrize(
    "params",
    [
        Tube.uniform(2.0, 1.0, voltage=0.796063),  # next to the voltage threshold
        Tube.uniform(2.0, 1.0, growth=2.11, voltage=0.3),
        Tube.uniform(2.5, 1.0, stretch=3.3, voltage=0.3),
    ],
    ids=["thick-near-threshold", "thick-grown", "thick-stretched"],
)
@pytest.mark.parametrize("rtol", [1e-5, 1e-8])
def test_short_wave_start_of_a_family_keeps_every_target_and_its_sign(params, rtol):
    """A family's block starts near the outer face too, its left-out pairs held on their
    constant line (dominant.hold_left_out): the same signs as the whole wall at 1e-12,
    errors no larger than the whole wall's at the same rtol (up to 10x, over the rows as
    in the test above: one row's error at a loose rtol depends on the step sequence after
    the restart, which the step size carried into it sets; (0, 40) of the grown tube at
    1e-8 is off by 2.4e-13 or 7.8e-13 as the checks before the restart move, the whole
    wall by 4.8e-14, all far below rtol), and fewer steps."""
    t = _targets(solve_base_state(params), FAMILY_ROWS, rtol)
    full, short, plain = t[:, 0], t[:, 1], t[:, 2]
    assert np.all(np.sign(short) == np.sign(full))
    assert np.abs(short - full).max() <= 10 * np.abs(plain - full).max()
    assert np.all(np.abs(short - full) <= 10 * rtol * np.maximum(np.abs(full), 1e-3))
    assert t[:, 3].sum() < 0.7 * t[:, 4].sum()
