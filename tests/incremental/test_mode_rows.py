"""The kernel over the rows of a modes array (incremental/mode_rows.py) is the per-member
kernel fed by NumPy's m, k and kept pairs (impedance.target_serial, target_batch), bit for
bit: its pairs are modes.mode_pairs row by row, its targets and statuses identical on random
states and modes of every family, one thread or many."""

from __future__ import annotations

import math

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental.impedance import target_batch, target_serial
from electrogrowth.incremental.mode_rows import row_pairs, rows_parallel, rows_serial
from electrogrowth.incremental.modes import Family, mode_pairs
from electrogrowth.incremental.radial_table import build_table, stack_tables
from electrogrowth.incremental.targets import impedance_targets
from electrogrowth.model.layers import Layer, Tube


def _rows(rng, count, coded):
    """Random modes: m 0..12, n 0..12 (n = 0 rows prismatic, so m >= 2 there), with the
    family codes of every family when ``coded``."""
    m = rng.integers(0, 13, size=count).astype(float)
    n = rng.integers(0, 13, size=count).astype(float)
    m[n == 0] = np.maximum(m[n == 0], 2.0)
    if not coded:
        return np.column_stack([m, n])
    fam = np.where(n == 0, Family.PRISMATIC.code, Family.WRINKLE.code)
    torsional = (rng.uniform(size=count) < 0.3) & (n > 0)
    m[torsional], fam[torsional] = 0.0, Family.TORSIONAL.code
    return np.column_stack([m, n, fam.astype(float)])


@pytest.mark.parametrize("coded", [False, True])
def test_row_pairs_are_mode_pairs(coded):
    modes = _rows(np.random.default_rng(5), 400, coded)
    want = mode_pairs(modes)
    assert [row_pairs(modes, b) for b in range(len(modes))] == want.tolist()


def _states():
    rng = np.random.default_rng(11)
    out = []
    for _ in range(6):
        tube = Tube.uniform(
            outer_radius=rng.uniform(1.05, 2.5),
            length=rng.uniform(0.5, 5.0),
            growth=rng.uniform(1.0, 1.3),
            stretch=rng.uniform(0.8, 1.2),
            voltage=rng.uniform(0.0, 0.3),
        )
        out.append(solve_base_state(tube))
    bilayer = Tube((Layer(1.1, shear_modulus=10.0, growth=1.1), Layer(2.0)), voltage=0.2)
    out.append(solve_base_state(bilayer))
    return out


@pytest.mark.parametrize("rtol", [1e-12, 1e-8, 1e-5])
def test_rows_equal_the_member_kernel(rtol):
    rng = np.random.default_rng(int(-math.log10(rtol)))
    for i, state in enumerate(_states()):
        modes = _rows(rng, 24, coded=i % 2 == 1)
        tables = stack_tables([build_table(state, tol=1e-15)])
        k = modes[:, 1] * math.pi / state.current_length
        m = np.ascontiguousarray(modes[:, 0])
        index = np.zeros(len(modes), dtype=np.int64)
        for rows, member in ((rows_serial, target_serial), (rows_parallel, target_batch)):
            f, status = rows(modes, state.current_length, tables, rtol, 20000)
            want_f, want_status, _ = member(m, k, mode_pairs(modes), index, tables, rtol, 20000)
            assert f.tobytes() == want_f.tobytes()
            assert status.tolist() == want_status.tolist()


def test_impedance_targets_take_any_layout():
    """A row, a column slice and a transposed copy give the same targets as the C array."""
    state = solve_base_state(Tube.uniform(outer_radius=1.4, voltage=0.4, growth=1.2))
    modes = np.array([[2.0, 1.0], [0.0, 3.0], [3.0, 0.0]])
    want = impedance_targets(state, modes, rtol=1e-8)
    assert impedance_targets(state, np.asfortranarray(modes), rtol=1e-8).tobytes() == (
        want.tobytes()
    )
    assert impedance_targets(state, modes[1], rtol=1e-8).tobytes() == want[1:2].tobytes()
    wide = np.column_stack([modes, np.zeros(3)])[:, :2]  # not contiguous
    assert impedance_targets(state, wide, rtol=1e-8).tobytes() == want.tobytes()
