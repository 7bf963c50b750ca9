"""The compiled chopping of a radial table is its NumPy twin's, bit for bit (table_chop.py).

Both decide with the same comparisons of the same floating-point numbers, so every table,
and with it every target and critical value, is unchanged: checked on random coefficients
(repeated columns, signed zeros, NaN, tails at the threshold) and on the tables of random
base states of every kind (closed-form neo-Hookean, a numerical energy, layered).
"""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental import radial_table
from electrogrowth.incremental.table_chop import chop_and_merge
from electrogrowth.incremental.targets import ALL_PAIRS, U_TH, U_Z, Family, mode_pairs
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.materials import gent
from electrogrowth.model.moduli import neo_hookean_moduli


def _same(a, b) -> bool:
    """Equal to the last bit, shapes and dtypes included."""
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


def _random_units(rng):
    """Column sizes as a table's (radial_table._layer_units): some 0 (r, w), the others
    around the columns' own sizes, above and below them."""
    return np.where(rng.uniform(size=26) < 0.3, 0.0, 10.0 ** rng.uniform(-4, 3, size=26))


def _random_segment(rng, n):
    """(coef, values) of 26 functions at n nodes, as a table's: some columns repeated, some
    constant, tails at and around the chopping threshold, signed zeros."""
    values = rng.normal(size=(n, 26)) * 10.0 ** rng.integers(-3, 3, size=26)
    decay = rng.uniform(0.5, 4.0, size=26)
    coef = rng.normal(size=(n, 26)) * np.exp(-decay * np.arange(n)[:, None])
    for f in rng.choice(26, size=8, replace=False):  # repeats of other columns
        g = rng.integers(26)
        coef[:, f], values[:, f] = coef[:, g], values[:, g]
    for f in rng.choice(26, size=3, replace=False):  # constants, with signed zeros
        coef[1:, f] = rng.choice([0.0, -0.0], size=n - 1)
    return np.ascontiguousarray(coef), values


@pytest.mark.parametrize("seed", range(40))
@pytest.mark.parametrize("n", [17, 33, 65])
def test_chop_equals_numpy_on_random_coefficients(seed, n):
    rng = np.random.default_rng(seed)
    coef, values = _random_segment(rng, n)
    tol = 10.0 ** rng.uniform(-16, -8)
    unit = _random_units(rng)
    scale = np.maximum(np.abs(values).max(axis=0), np.maximum(1e-300, unit))
    f = rng.integers(26)  # one coefficient exactly at its threshold (kept small: <=)
    coef[n - 4, f] = tol * scale[f] * 8
    got = chop_and_merge(coef, values, tol, unit)
    want = radial_table._chop_numpy(coef, values, tol, unit)
    assert got[0] == want[0]
    assert _same(got[1], want[1]) and _same(got[2], want[2])


@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("n", [17, 33, 65])
def test_scaled_chop_equals_numpy(seed, n):
    """The DCT's scaling inside the compiled chop is _cheb_coefficients' to the last bit."""
    rng = np.random.default_rng(500 + seed)
    _, values = _random_segment(rng, n)
    tol = 10.0 ** rng.uniform(-16, -8)
    unit = _random_units(rng)
    got = radial_table._chop(values, tol, unit)
    want = radial_table._chop_numpy(radial_table._cheb_coefficients(values), values, tol, unit)
    assert got[0] == want[0]
    assert _same(got[1], want[1]) and _same(got[2], want[2])


def test_chop_equals_numpy_with_nan():
    rng = np.random.default_rng(7)
    coef, values = _random_segment(rng, 17)
    coef[5, 3], values[2, 9] = np.nan, np.nan
    unit = _random_units(rng)
    got = chop_and_merge(coef, values, 1e-12, unit)
    want = radial_table._chop_numpy(coef, values, 1e-12, unit)
    assert got[0] == want[0] is False
    np.testing.assert_array_equal(got[1], want[1])  # NaN == NaN here
    assert _same(got[2], want[2])


def _states():
    rng = np.random.default_rng(3)
    out = []
    for _ in range(12):  # the paper's tube, closed form, random loads
        ro, g, lz = rng.uniform(1.05, 3.0), rng.uniform(1.0, 1.6), rng.uniform(0.7, 1.5)
        tube = Tube.uniform(outer_radius=ro, growth=g, stretch=lz)
        out.append(solve_base_state(tube.at("voltage", 0.5 * rng.uniform() * _vmax(tube))))
    out.append(solve_base_state(Tube.uniform(outer_radius=1.4, voltage=0.4, growth=1.3,
                                             material=gent(10.0))))  # fmt: skip
    mucosa = Tube(
        (Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)),
        length=3.0,
        voltage=0.3,
        inner_pressure=0.05,
    )
    out.append(solve_base_state(mucosa))
    return out


def _vmax(tube):
    from electrogrowth.basestate.tube import threshold

    return min(threshold(tube).value, 2.0)


@pytest.fixture(scope="module")
def states():
    return _states()


@pytest.mark.parametrize("tol", [1e-15, 1e-14, 1e-12, 1e-9])
def test_build_table_equals_the_numpy_twin(states, tol, monkeypatch):
    compiled = [radial_table.build_table(s, tol=tol) for s in states]
    monkeypatch.setattr(
        radial_table,
        "_chop",
        lambda vals, tol, unit: radial_table._chop_numpy(
            radial_table._cheb_coefficients(vals), vals, tol, unit
        ),
    )
    twin = [radial_table.build_table(s, tol=tol) for s in states]
    for a, b in zip(compiled, twin):
        assert all(_same(x, y) for x, y in zip(a, b))


def test_uniform_table_fields_are_the_three_calls(states):
    for state in states:
        if not hasattr(state, "table_fields"):
            continue
        R = np.linspace(1.0, state.tube.outer_radius, 23)
        r, moduli, p = state.table_fields(R)
        assert _same(r, state.radius(R)) and _same(moduli, state.moduli(R))
        assert _same(p, state.pressure(R))


def test_closed_form_moduli_in_the_table(states):
    """The table of the closed-form state holds the neo-Hookean moduli it was built from."""
    state = states[0]
    R = np.linspace(1.0, state.tube.outer_radius, 9)
    _, _, stretches, d = state._local(R)
    np.testing.assert_array_equal(state.table_fields(R)[1], neo_hookean_moduli(*stretches, d))


def test_mode_pairs_as_before():
    """mode_pairs (np.where and masks) equals its former np.select form on every family."""
    rows = [[m, n, fam.code] for fam in Family for m in range(4) for n in range(3)]
    modes = np.array(rows, dtype=float)
    code = modes[:, 2].astype(np.int64)
    wrinkle = np.where(modes[:, 0] == 0, ALL_PAIRS & ~U_TH, ALL_PAIRS)
    old = np.select(
        [code == Family.PRISMATIC.code, code == Family.TORSIONAL.code],
        [ALL_PAIRS & ~U_Z, U_TH],
        wrinkle,
    ).astype(np.int64)
    assert _same(mode_pairs(modes), old)
    natural = np.array([[0, 1], [3, 0], [2, 2], [0, 0]], dtype=float)
    assert mode_pairs(natural).tolist() == [ALL_PAIRS & ~U_TH, ALL_PAIRS & ~U_Z, ALL_PAIRS,
                                            ALL_PAIRS & ~U_Z]  # fmt: skip


def test_one_table_stack_is_the_padded_stack(states):
    """stack_tables of one table (its arrays as views) equals the padded stack of several,
    field by field, in dtype and layout too (another layout would compile the kernel again)."""
    for state in states:
        table = radial_table.build_table(state, tol=1e-12)
        rows = [table.coef[s, : table.n_funcs[s]] for s in range(table.coef.shape[0])]
        padded_rows = np.zeros_like(table.coef)  # the padding by hand
        for s, c in enumerate(rows):
            padded_rows[s, : c.shape[0]] = c
        assert _same(table.coef, padded_rows) and table.coef.flags.c_contiguous
        one = radial_table.stack_tables([table])
        padded = radial_table.stack_tables([table, table])
        for a, b in zip(one, padded):
            b = b[:1]
            assert a.dtype == b.dtype and a.shape == b.shape and _same(a, b)
            assert a.flags.c_contiguous and a.flags.writeable


def test_the_families_pairs_are_the_kernels():
    """modes.py (no kernel loaded) and the kernel mean the same bits by 'every pair'."""
    from electrogrowth.incremental import impedance, modes

    assert modes.ALL_PAIRS == impedance.ALL_PAIRS == ALL_PAIRS
