"""The built-in energies' generated derivatives (model/_builtin_energies.py, written by
tools/derive_energies.py): the committed file is what the tool writes, its functions give the
same doubles as sympy's lambdified forms (bit for bit) at random parameters and points and
agree with sympy's exact derivatives to 1e-14, and a process using built-in energies alone
never imports sympy."""

from __future__ import annotations

import functools
import importlib.util
import json
import pathlib
import pickle
import subprocess
import sys

import numpy as np
import pytest
import sympy as sp

from electrogrowth.model import _builtin_energies
from electrogrowth.model.builtin_energies import BuiltinEnergy, printed
from electrogrowth.model.invariants import (
    INVARIANTS,
    _energy_derivatives,
    _energy_gradient,
    _energy_value,
    energy_kind,
)
from electrogrowth.model.materials import Material, gent, mooney_rivlin, neo_hookean

ROOT = pathlib.Path(__file__).resolve().parents[2]


@functools.cache
def _tool():
    spec = importlib.util.spec_from_file_location(
        "derive_energies", ROOT / "tools" / "derive_energies.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_generated_energies_are_what_the_tool_writes():
    """Regenerating gives the committed file (with the sympy that wrote it)."""
    text = pathlib.Path(_builtin_energies.__file__).read_text()
    if f"with sympy {sp.__version__};" not in text:
        pytest.skip(f"_builtin_energies.py was written by another sympy than {sp.__version__}")
    assert _tool().render() == text


def _parameters(rng):
    """Built-in energies over every generated form: Gent jm as floats over 11 decades, every
    integer 1..300 and large ones, Mooney-Rivlin alpha over (0, 1] with tiny values and 1."""
    floats = 10 ** rng.uniform(-3, 8, size=60)
    integers = [*range(1, 301), 1024, 99991, 10**6, 2**40 - 1, 2**40, 2**53 - 1]
    alphas = [*rng.uniform(0, 1, size=40), *(10 ** rng.uniform(-12, 0, size=10)), 0.5, 0.3, 1.0]
    return (
        [BuiltinEnergy("neo-hookean")]
        + [BuiltinEnergy("gent", float(x)) for x in [*floats, 97.2, 0.1, 3.0000001]]
        + [BuiltinEnergy("gent", float(n)) for n in integers]
        + [BuiltinEnergy("mooney-rivlin", float(a)) for a in alphas if a > 0]
    )


def _invariant_points(rng, energy: BuiltinEnergy, n: int = 7, reach: float = 1 - 1e-9):
    """(I1, I2, I4, I5, I6) arrays inside the energy's domain (Gent: I1 < 3 + reach jm)."""
    top = 3 + reach * min(energy.parameter, 50.0) if energy.family == "gent" else 50.0
    I1 = rng.uniform(3.0, top, size=n)
    return (I1, *rng.uniform(0.0, 20.0, size=(4, n)))


def _same(a, b) -> bool:
    """The same doubles (a constant form may be a number where the other is an array)."""
    a, b = np.broadcast_arrays(np.asarray(a, float), np.asarray(b, float))
    return a.tobytes() == b.tobytes()


def test_generated_forms_equal_lambdified_sympy_bit_for_bit(rng):
    """The generated value, gradient and Hessian are the doubles sympy's lambdify gives for
    the same energy (what the package computed before): every result is unchanged."""
    for energy in _parameters(rng):
        expr = energy.expression()
        inv = _invariant_points(rng, energy)
        if energy.form() is None:  # through sympy, as a user's energy
            assert energy.parameter >= 2**40
            continue
        value, gradient, derivatives = energy.numeric()
        assert _same(value(*inv), _energy_value(expr)(*inv)), energy
        assert all(map(_same, gradient(*inv), _energy_gradient(expr)(*inv))), energy
        (w, W), (ws, Ws) = derivatives(*inv), _energy_derivatives(expr)(*inv)
        assert all(map(_same, w, ws)), energy
        assert all(_same(x, y) for r, s in zip(W, Ws) for x, y in zip(r, s)), energy


def test_generated_forms_equal_exact_derivatives(rng):
    """The generated derivatives equal sympy's exact ones (substituted, 30 digits) to 1e-14
    relative, times the condition number of Gent's 1 + 3/jm - I1/jm, at random parameters and
    points: the independent check of the generated maths. That subtraction magnifies the
    rounding of sympy's 15-digit constants by (3 + jm) / (3 + jm - I1) (6000 at jm = 0.001),
    the same in the lambdified sympy the package evaluated before."""
    for energy in [e for e in _parameters(rng) if e.form() is not None][::7]:
        expr = energy.expression()
        inv = _invariant_points(rng, energy, n=2, reach=0.5)
        w, W = energy.numeric()[2](*inv)
        for i in range(2):
            at = {s: sp.Float(float(x[i]), 30) for s, x in zip(INVARIANTS, inv)}
            jm = energy.parameter
            rel = 1e-14 * ((3 + jm) / (3 + jm - inv[0][i]) if energy.family == "gent" else 1)
            for a, s in enumerate(INVARIANTS):
                exact = float(sp.N(sp.diff(expr, s).xreplace(at), 30))
                assert np.broadcast_to(w[a], (2,))[i] == pytest.approx(exact, rel=rel, abs=0)
                for b, t in enumerate(INVARIANTS):
                    exact = float(sp.N(sp.diff(expr, s, t).xreplace(at), 30))
                    got = np.broadcast_to(np.asarray(W[a][b], float), (2,))[i]
                    assert got == pytest.approx(exact, rel=rel, abs=1e-300)


def test_every_parameter_gives_its_forms_code(rng):
    """sympy's lambdify code for other parameters is the committed template (the numbers
    named the same way): the forms are not fitted to the samples the tool used."""
    tool = _tool()
    for energy in [e for e in _parameters(rng) if e.form() is not None][::5]:
        name, numbers = energy.form()
        sample, names = tool.FORMS[name]
        assert tool.template(energy, names) == tool.template(sample, names), energy


@pytest.mark.parametrize(
    "x",
    [0.1, 48.6, 1 / 97.2, 1 + 3 / 97.2, 0.5 / 97.2, 1234567890123455.0, 5e-10, 2.0**-1074 * 3],
)
def test_printed_is_sympys_literal(x, rng):
    for y in [x, -x, *(rng.uniform(0.5, 2) * x for _ in range(20))]:
        assert printed(y) == float(sp.pycode(sp.Float(y))), y


def test_builtin_kinds_are_sympys():
    """kind and linearity known without sympy agree with sympy's answers."""
    for make in (neo_hookean, gent, lambda: gent(30), lambda: mooney_rivlin(0.3)):
        mat = make()
        assert mat.kind() == energy_kind(mat.energy), mat.name
        elastic = sp.expand(mat.energy - sp.Symbol("I5", real=True) / 2)
        assert mat.definition.linear == elastic.is_polynomial(*INVARIANTS), mat.name
    assert mooney_rivlin(1).kind() == energy_kind(mooney_rivlin(1).energy) == "neo-hookean"


def test_builtin_material_is_the_sympy_material():
    """A built-in Material computes what the same energy given as sympy computes, compares
    by family and parameter, pickles, and still shows its sympy expression."""
    point = (np.array([0.8, 1.1]), np.array([1.3, 0.95]), np.array([0.96, 0.9]), 0.4)
    for mat in (gent(), gent(30.0), mooney_rivlin(0.3)):
        user = Material(mat.name, mat.energy)
        assert _same(mat.moduli(*point), user.moduli(*point))
        assert _same(mat.stress(*point), user.stress(*point))
        assert pickle.loads(pickle.dumps(mat)) == mat
    assert gent(30) == gent(30.0) and gent(30) != gent(30.5)
    assert str(neo_hookean().energy) == "I1/2 + I5/2 - 3/2"


_PROBE = """
import json, sys
from electrogrowth.cli.app import main
status = main(sys.argv[1:])
print(json.dumps([status, "sympy" in sys.modules, "scipy.optimize" in sys.modules]))
"""


@pytest.mark.parametrize(
    ("argv", "sympy"),
    [
        (["critical", "--solve-for", "growth", "--outer-radius", "1.4", "--length", "1",
          "--voltage", "0.4", "--mode", "0", "1", "--json"], False),
        (["critical", "--solve-for", "growth", "--outer-radius", "1.4", "--length", "1",
          "--voltage", "0.4", "--mode", "0", "1", "--material", "gent", "--json"], False),
        (["state", "--outer-radius", "1.4", "--growth", "1.2", "--material", "mooney-rivlin",
          "--json"], False),
        (["state", "--tube", "examples/bilayer.toml", "--json"], False),
        (["state", "--outer-radius", "1.4", "--growth", "1.2", "--energy",
          "(I1 - 3)/2 + I5/2", "--json"], True),
    ],
    ids=["critical", "critical-gent", "state-mooney-rivlin", "state-bilayer", "user-energy"],
)  # fmt: skip
def test_builtin_energies_never_import_sympy(argv, sympy):
    """A fresh process with built-in energies computes a critical value or a state without
    sympy (0.5-0.6 s of its start) and without scipy.optimize (electrogrowth.brent); a user's
    energy text still goes through sympy."""
    done = subprocess.run(
        [sys.executable, "-c", _PROBE, *argv], capture_output=True, text=True, cwd=ROOT
    )
    assert done.returncode == 0, done.stderr
    status, imported, optimize = json.loads(done.stdout.strip().splitlines()[-1])
    assert status == 0
    assert imported is sympy
    assert not optimize
