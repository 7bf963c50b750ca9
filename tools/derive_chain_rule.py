"""Derive the energy-independent chain rule of materials.py and write it as Python (dev tool).

Run ``PYTHONPATH=src .venv/bin/python tools/derive_chain_rule.py`` to (re)write
``src/electrogrowth/model/_chain_rule.py``; ``--check`` only says whether that file is
current (exit 1 if not). The package imports the generated file, never this one, so that
no process pays the derivation (seconds of sympy) at run time; the tests load this file to
check that regenerating gives the same file and that the generated functions equal the
sympy expressions at random points.

The forms: the principal stress tau_i = sigma_ii + p, the radial field E_1 and the 23
updated moduli (``moduli.MODULI_NAMES``) at F = diag(l1, l2, l3), D~ = (d / l1, 0, 0), as
functions of (l1, l2, l3, d, w, W), w[k] = dOmega/dI_k and W[5 k + l] = d2Omega/dI_k dI_l,
k, l over (I1, I2, I4, I5, I6). The invariants are polynomials in F and D~, so their
gradients and Hessians at that point are small exact expressions; the energy enters only
through w and W. The code is sympy's own ``lambdify`` output (the numpy printer, common
subexpressions for the moduli), so the generated functions do the same floating-point
operations, in the same order, as the lambdified forms the package used before.
"""

from __future__ import annotations

import argparse
import inspect
import pathlib
import re
import sys

import sympy as sp

try:
    from electrogrowth.model.moduli import MODULI_NAMES
except ImportError:  # pragma: no cover - run without PYTHONPATH=src
    sys.path.insert(0, "src")
    from electrogrowth.model.moduli import MODULI_NAMES

TARGET = pathlib.Path(__file__).resolve().parents[1] / "src/electrogrowth/model/_chain_rule.py"

#: The generated functions' names, in the order of :func:`derive`'s forms.
NAMES = ("stress", "field", "moduli")


def _index(name: str) -> tuple[int, ...]:
    return tuple(int(c) - 1 for c in name[1:])


def derive():
    """(args, (tau, E1, moduli)): the sympy forms and their arguments
    (l1, l2, l3, d, [w0..w4], [W00..W44] row by row, W symmetric)."""
    F = sp.Matrix(3, 3, sp.symbols("F0:9", real=True))
    Dt = sp.Matrix(sp.symbols("Dt0:3", real=True))
    C = F.T * F
    inv = [
        C.trace(),
        (C.trace() ** 2 - (C * C).trace()) / 2,
        (Dt.T * Dt)[0],
        (Dt.T * C * Dt)[0],
        (Dt.T * C * C * Dt)[0],
    ]
    X = list(F) + list(Dt)
    l1, l2, l3, d = sp.symbols("l1 l2 l3 d", positive=True)
    point = {s: 0 for s in X}
    point.update({F[0, 0]: l1, F[1, 1]: l2, F[2, 2]: l3, Dt[0]: d / l1})
    grad = [sp.Matrix([sp.diff(I, x) for x in X]).subs(point) for I in inv]
    hess = [sp.hessian(I, X).subs(point) for I in inv]
    w = sp.symbols("w0:5", real=True)
    W = sp.Matrix(5, 5, lambda a, b: sp.Symbol(f"W{min(a, b)}{max(a, b)}", real=True))
    dO = sum((w[k] * grad[k] for k in range(5)), sp.zeros(12, 1))
    d2O = sum((w[k] * hess[k] for k in range(5)), sp.zeros(12, 12))
    d2O += sum(
        (W[a, b] * grad[a] * grad[b].T for a in range(5) for b in range(5)), sp.zeros(12, 12)
    )
    Fd = sp.diag(l1, l2, l3)
    fi = lambda i, a: 9 + a if i is None else 3 * i + a  # noqa: E731  F_{i alpha} -> X
    # tau_ij = F_ia dOmega/dF_ja ; E_i = F^-1_ai dOmega/dD~_a (diagonal F)
    tau = [sp.simplify(Fd[i, i] * dO[fi(i, i)]) for i in range(3)]
    E1 = sp.simplify(dO[9] / l1)
    comps = []
    for name in MODULI_NAMES:
        idx = _index(name)
        if name[0] == "A":
            p, i, q, j = idx  # F_pa F_qb A_{a i b j}, diagonal F: a = p, b = q
            comps.append(Fd[p, p] * Fd[q, q] * d2O[fi(i, p), fi(j, q)])
        elif name[0] == "G":
            p, i, q = idx  # F_pa F^-1_bq Gamma_{a i b}
            comps.append(Fd[p, p] / Fd[q, q] * d2O[fi(i, p), 9 + q])
        else:
            p, q = idx
            comps.append(d2O[9 + p, 9 + q] / (Fd[p, p] * Fd[q, q]))
    args = (l1, l2, l3, d, list(w), list(W))
    return args, (tau, E1, [sp.expand(c) for c in comps])


def render(args, forms) -> str:
    """The text of the generated module: each form's lambdify source, renamed."""
    parts = [_HEADER.format(version=sp.__version__)]
    for name, form in zip(NAMES, forms):
        f = sp.lambdify(args, form, "numpy", cse=name == "moduli")
        source = inspect.getsource(f)
        dummies = list(dict.fromkeys(re.findall(r"_Dummy_\d+", source)))
        if len(dummies) != 2:  # w and W, the two list arguments
            raise RuntimeError(f"unexpected lambdify source for {name}: {dummies}")
        for dummy, new in zip(dummies, ("w", "W")):
            source = re.sub(rf"\b{dummy}\b", new, source)
        source = source.replace("def _lambdifygenerated(", f"def {name}(", 1)
        if re.search(r"[A-Za-z_]\w*\(", source.split("\n", 1)[1]):
            raise RuntimeError(f"{name} calls a function; the module imports nothing")
        parts.append("\n\n" + source.rstrip() + "\n")
    return "".join(parts)


_HEADER = '''"""The chain rule of materials.py: stress, field and moduli from dOmega/dI_k.

GENERATED by tools/derive_chain_rule.py with sympy {version}; do not edit (run the tool).
Plain arithmetic of (l1, l2, l3, d, w, W): the principal elastic stretches, the radial
current electric displacement d, w[k] = dOmega/dI_k and W[5 k + l] = d2Omega/dI_k dI_l for
k, l over (I1, I2, I4, I5, I6). ``stress``: tau_i = sigma_ii + p (i = r, theta, z);
``field``: E_1; ``moduli``: the 23 updated moduli in moduli.MODULI_NAMES order.
"""

# fmt: off
# ruff: noqa
'''


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--check", action="store_true", help="exit 1 if the file is stale")
    opts = parser.parse_args(argv)
    text = render(*derive())
    if opts.check:
        current = TARGET.read_text() if TARGET.exists() else ""
        print("current" if current == text else f"stale: rerun {__file__}")
        return 0 if current == text else 1
    TARGET.write_text(text)
    print(f"wrote {TARGET}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
