"""Regression tests of issue 14's failures, each at its root (docs/reliability.md)."""

import math

import numpy as np
import pytest
import sympy as sp

from electrogrowth import Tube
from electrogrowth.basestate import voltage
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.cli import app as cli
from electrogrowth.errors import MaterialError
from electrogrowth.incremental.charts import right_divide
from electrogrowth.incremental.targets import collocation_targets, impedance_targets
from electrogrowth.model.materials import I1, I4, I5, I6, Material, gent, reference_moduli


@pytest.mark.parametrize("growth", np.arange(1.30, 1.42, 0.01))
def test_gent_node_count_is_found_near_the_locking_stretch(growth):
    """Was: "quadrature not converged to rtol = 1e-12 with 384 nodes" where the probe
    3 lambda_i0 fell just inside Gent's locking stretch (Jm = 10, Rbar_o = 1.4)."""
    info = voltage._threshold(gent(10), 1.4, float(growth), 1.0, 1e-12)
    assert info.kind == "locking" and info.nodes <= 64


def test_failed_mode_is_retried_not_fatal():
    """Was: "step size underflow" for mode (3, 11) under the scan's loose rtol 1e-5."""
    p = Tube.uniform(1.895, 0.753, 1.7814756661232656, 0.806, 0.012)
    state = solve_base_state(p)
    f = impedance_targets(state, np.array([[3.0, 11.0]]), rtol=1e-5)[0]
    assert np.isfinite(f) and np.sign(f) == np.sign(collocation_targets(state, [[3, 11]])[0])


def test_right_divide_matches_numpy_and_reports_singular():
    rng = np.random.default_rng(14)
    out = np.empty((4, 4))
    for _ in range(20):
        a, b = rng.normal(size=(4, 4)), rng.normal(size=(4, 4))
        assert right_divide(b, a, out)
        np.testing.assert_allclose(out, b @ np.linalg.inv(a), rtol=1e-9, atol=1e-12)
    assert not right_divide(b, np.zeros((4, 4)), out)
    a[2, 1] = np.nan
    assert not right_divide(b, a, out)


@pytest.mark.parametrize(
    "energy, which",
    [((I1 - 3) + I5 / 2, "shear modulus mu"), ((I1 - 3) / 2 + I5 / 4, "permittivity eps")],
)
def test_energy_in_other_units_is_refused_or_normalized(energy, which):
    with pytest.raises(MaterialError, match=f"{which}.* = 2 in the reference state, not 1"):
        Material("mine", energy)
    scaled = Material.normalized("mine", energy)
    assert reference_moduli(scaled.energy) == (1.0, 1.0)
    kept = Material("mine", energy, check_units=False)  # a deliberately scaled energy
    assert kept.energy == sp.sympify(energy)


def test_normalized_energy_has_the_same_physics_in_units():
    """mu Omega'(F, D / sqrt(mu eps)) = Omega(F, D): stresses scale by mu."""
    mu, eps = 3, sp.Rational(1, 2)
    raw = mu * (I1 - 3) / 2 + I5 / (2 * eps) + I6 / 10 + I4 / 7
    unit = Material.normalized("x", raw)
    assert reference_moduli(unit.energy) == pytest.approx((1.0, 1.0), rel=1e-14)
    d = 0.3
    a = Material("x", raw, check_units=False).stress(1.2, 1 / 1.2, 1.0, d)
    scale = float(mu * reference_moduli(raw)[1])  # mu eps
    b = unit.stress(1.2, 1 / 1.2, 1.0, d / math.sqrt(scale))
    np.testing.assert_allclose(a, mu * b, rtol=1e-12)


@pytest.mark.parametrize(
    "argv, words",
    [
        ("--solve-for voltage --outer-radius 1.4 --growth 1e-9 --voltage 0.4", "g = 1e-09"),
        ("--solve-for growth --outer-radius 1.4 --stretch 1e-6 --voltage 0.4", "lambda_z / g"),
        ("--solve-for voltage --outer-radius 1.4 --stretch 1e-6", "lambda_z / g = 1e-06"),
        ("--solve-for growth --outer-radius 1.4 --m-max 1e20", "'1e20' is not a whole number"),
        ("--solve-for growth --outer-radius 1.4 --n-max " + "9" * 400, "from 1 to 1000000"),
        ("--solve-for growth --outer-radius 1.4 --mode " + "9" * 400 + " 1", "from 0 to 1000000"),
        ("--solve-for growth --outer-radius 1.4 --m-max 1000001", "from 0 to 1000000"),
        ("--solve-for growth --outer-radius 1e6", "Rbar_o = 1e+06 is outside"),
        ("--solve-for voltage --outer-radius 1.4 --length 1e-6", "L = 1e-06 is outside"),
        ("--solve-for growth --outer-radius 1.4 --growth 1e20", "g = 1e+20 is outside"),
        ("--solve-for growth --outer-radius 1.4 --top 0", "--top: '0' is not a whole"),
        ("--solve-for growth --outer-radius 1.4 --top -1", "--top: '-1' is not a whole"),
        ("--solve-for growth --outer-radius -inf", "'-inf' is not a finite number"),
        ("--solve-for stretch --outer-radius 1.4 --growth 1e-9", "g = 1e-09 is outside"),
    ],
)
def test_bad_input_is_one_line_naming_value_and_range(argv, words, capsys):
    assert cli.main(["critical", *argv.split()]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("electrogrowth: error: ")
    assert words in err and "range" in err or "whole number" in err or "finite" in err
