"""The compiled closed-form fields of the paper's tube equal the NumPy route bit for bit
(basestate/closed_form_fields.py): r, the 23 moduli and p at any radii of random states, and
the radial table's block [moduli, p, r, w] that UniformState.table_block writes in one pass."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state, threshold
from electrogrowth.errors import ParameterError
from electrogrowth.model.layers import Tube
from electrogrowth.model.materials import gent


def _random_state(rng):
    ro, g, lz = rng.uniform(1.01, 4.0), rng.uniform(0.8, 2.0), rng.uniform(0.5, 3.0)
    tube = Tube.uniform(outer_radius=ro, growth=g, stretch=lz, length=rng.uniform(0.5, 5))
    vmax = min(threshold(tube).value, 3.0)
    voltage = 0.0 if rng.uniform() < 0.2 else rng.uniform(0.0, 0.99) * vmax
    return solve_base_state(tube.at("voltage", voltage))


@pytest.mark.parametrize("seed", range(60))
def test_compiled_fields_equal_numpy(seed):
    rng = np.random.default_rng(seed)
    state = _random_state(rng)
    ro = state.tube.outer_radius
    R = np.concatenate([[1.0, ro], rng.uniform(1.0, ro, size=int(rng.integers(1, 40)))])
    r, moduli, p = state.table_fields(R)
    for got, want in ((r, state.radius(R)), (moduli, state.moduli(R)), (p, state.pressure(R))):
        assert got.shape == want.shape and got.tobytes() == want.tobytes()


def _numpy_block(state, R, J):
    """[moduli, p, r, w] by the three NumPy calls, w = J R / (lambda_z r^2), stacked as the
    radial table stacked them before the compiled block."""
    r = state.radius(R)
    return np.column_stack(
        [state.moduli(R), state.pressure(R), r, J * R / (state.stretch * r * r)]
    )


@pytest.mark.parametrize("seed", range(60))
def test_table_block_equals_numpy(seed):
    rng = np.random.default_rng(1000 + seed)
    state = _random_state(rng)
    ro = state.tube.outer_radius
    R = np.concatenate([[1.0, ro], rng.uniform(1.0, ro, size=int(rng.integers(1, 40)))])
    J = state.tube.growth**3
    got, want = state.table_block(R, J), _numpy_block(state, R, J)
    assert got.shape == want.shape and got.flags.c_contiguous
    assert got.tobytes() == want.tobytes()


def test_table_block_of_another_energy_is_the_numpy_route():
    state = solve_base_state(Tube.uniform(outer_radius=1.4, voltage=0.4, material=gent(10.0)))
    R = np.linspace(1.0, 1.4, 17)
    assert state.table_block(R, 1.0).tobytes() == _numpy_block(state, R, 1.0).tobytes()


def test_compiled_fields_refuse_radii_outside_the_wall():
    state = solve_base_state(Tube.uniform(outer_radius=1.4, voltage=0.4))
    with pytest.raises(ParameterError, match="outside the wall"):
        state.table_fields(np.array([1.0, 1.5]))
    with pytest.raises(ParameterError, match="outside the wall"):
        state.table_block(np.array([1.0, 1.5]), 1.0)
