"""The tube forms' radial basis (incremental/ring_basis.py): each ring's inner value and its
other nodes' differences from it span the same polynomials as the nodal values, the
constant carries exactly 1 and derivative exactly 0, and the conversions to nodal values
and face values agree with the maps."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth.incremental.chebyshev import chebyshev_lobatto
from electrogrowth.incremental.polar_forms import Ring, peak_on_rings
from electrogrowth.incremental.ring_basis import (
    face_rows,
    nodal_values,
    potential_maps,
    radial_maps,
)

#: a thin film on two substrate rings, of different node counts
RINGS = (Ring(1.0, 1.001, 0, 9), Ring(1.001, 1.2, 1, 7), Ring(1.2, 2.0, 1, 11))


def _nodes(rings_) -> np.ndarray:
    """The Lobatto nodes of the rings, increasing, the shared interface nodes once."""
    out = [np.array([rings_[0].inner])]
    for r in rings_:
        x = chebyshev_lobatto(r.nodes)[0][::-1]
        out.append(r.inner + 0.5 * (x[1:] + 1.0) * (r.outer - r.inner))
    return np.concatenate(out)


def _unknowns(rings_, x: np.ndarray) -> np.ndarray:
    """The basis' unknowns of nodal values x: each ring's differences from its inner node."""
    y, at = np.array(x, dtype=float), 0
    for r in rings_:
        y[at + 1 : at + r.nodes] = x[at + 1 : at + r.nodes] - x[at]
        at += r.nodes - 1
    return y


def test_the_basis_spans_the_nodal_polynomials():
    """u = R^3 - 2 R (a cubic on every ring) from its nodal values: its value and
    R-derivative at the quadrature points to rounding; nodal_values and face_rows undo the
    differences."""
    R_nodes = _nodes(RINGS)
    x = R_nodes**3 - 2 * R_nodes
    y = _unknowns(RINGS, x)
    R, _wR, _layer, V, D, _P = radial_maps(RINGS)
    assert V @ y == pytest.approx(R**3 - 2 * R, rel=1e-13, abs=1e-13)
    assert D @ y == pytest.approx(3 * R**2 - 2, rel=1e-9)  # d/dR of a film 1e-3 thick
    assert nodal_values(RINGS, y) == pytest.approx(x, rel=1e-14)
    assert face_rows(RINGS) @ y == pytest.approx([x[0], x[-1]], rel=1e-14)
    assert peak_on_rings(RINGS, y)[1] == pytest.approx(2.0**3 - 4.0, rel=1e-12)


def test_a_constant_is_one_unknown_with_exactly_zero_derivative():
    """A rigid radial translation is the first unknown alone: value exactly 1 and
    derivative exactly 0 at every point, so no derivative cancels ~N^2 / h against it (the
    thin stiff film's fold moves almost rigidly through its thickness)."""
    _R, _wR, _layer, V, D, _P = radial_maps(RINGS)
    one = np.zeros(V.shape[1])
    one[0] = 1.0
    assert np.all(V @ one == 1.0) and np.all(D @ one == 0.0)
    assert np.all(nodal_values(RINGS, one) == 1.0)


def test_the_potential_keeps_its_nodal_interior_values():
    """A potential zero on both faces: its interior nodal values map to its value and
    R-derivative (phi = (R - 1)(2 - R))."""
    R_nodes = _nodes(RINGS)
    R = radial_maps(RINGS)[0]
    E, DE = potential_maps(RINGS)
    e = ((R_nodes - 1) * (2 - R_nodes))[1:-1]
    assert E @ e == pytest.approx((R - 1) * (2 - R), abs=1e-13)
    assert DE @ e == pytest.approx(3 - 2 * R, rel=1e-9, abs=1e-9)
