"""One engine for energies that are polynomials in local fields (the gradient of the
displacement, the pressure increment, the potential's gradient): a polynomial is a list of
monomials (coefficient at the quadrature points, field names); the discrete forms map the
unknowns to each field at the quadrature points (``maps``) and integrate with ``weight``.
Used by meridian_forms.py and dielectric_forms.py (docs/derivation-koiter.md)."""

from __future__ import annotations

import itertools

import numpy as np

from .._types import FloatArray


def product(*factors: dict) -> dict:
    """The product of polynomials given as {sorted field names: coefficient}."""
    out: dict = {(): 1.0}
    for factor in factors:
        nxt: dict = {}
        for (k1, c1), (k2, c2) in itertools.product(out.items(), factor.items()):
            key = tuple(sorted(k1 + k2))
            nxt[key] = nxt.get(key, 0.0) + c1 * c2
        out = nxt
    return out


def by_degree(*terms: tuple[float | FloatArray, dict]) -> dict[int, list]:
    """sum of coefficient * polynomial, split by degree into monomial lists."""
    total: dict = {}
    for scale, poly in terms:
        for key, c in poly.items():
            total[key] = total.get(key, 0.0) + scale * c
    out: dict[int, list] = {}
    for key, c in total.items():
        out.setdefault(len(key), []).append((c, key))
    return out


class MonomialForms:
    """Integral, gradient and Hessian of monomial lists on ``maps`` (field -> matrix from
    the unknowns to the field at the quadrature points), ``weight`` and ``size``."""

    maps: dict
    weight: FloatArray
    size: int

    def fields(self, v: FloatArray) -> dict:
        return {k: M @ v for k, M in self.maps.items()}

    def energy(self, monomials, f: dict) -> float:
        """The integral of the monomials at the local fields ``f``."""
        return float(
            sum(self.weight @ (k * np.prod([f[x] for x in xs], axis=0)) for k, xs in monomials)
        )

    def gradient(self, monomials, f: dict) -> FloatArray:
        """The derivative of ``energy`` with respect to the unknowns, at the fields ``f``."""
        out = np.zeros(self.size)
        for k, xs in monomials:
            for i in range(len(xs)):
                rest = [f[x] for j, x in enumerate(xs) if j != i]
                value = np.prod(rest, axis=0) if rest else 1.0
                out += self.maps[xs[i]].T @ (self.weight * k * value)
        return out

    def hessian(self, monomials, f: dict | None = None) -> FloatArray:
        """The second derivative of ``energy`` (for quadratic monomials ``f`` is unused).
        The weights of each pair of fields are summed first, so that each pair costs one
        product of maps (the energy of a general material has many monomials per pair)."""
        pairs = pair_weights(monomials, self.weight, f)
        H = np.zeros((self.size, self.size))
        for (a, b), w in pairs.items():
            M = self.maps[a].T @ (w[:, None] * self.maps[b])
            H += M + M.T  # the pair (a, b) and (b, a)
        return H


def pair_weights(monomials, weight, f: dict | None = None) -> dict:
    """{(a, b): w}, a <= b: the weights at the quadrature points of the product of fields
    a and b in the second derivative of the monomials' energy (each coefficient k times
    the quadrature ``weight`` and the other fields' values ``f``; for quadratic monomials
    ``f`` is unused), summed over the monomials, so that each pair costs one product of
    maps (the energy of a general material has many monomials per pair)."""
    pairs: dict = {}
    for k, xs in monomials:
        for i, j in itertools.combinations(range(len(xs)), 2):
            rest = [f[x] for n, x in enumerate(xs) if n not in (i, j)] if f else []
            w = weight * k * (np.prod(rest, axis=0) if rest else 1.0)
            key = tuple(sorted((xs[i], xs[j])))
            pairs[key] = pairs.get(key, 0.0) + w
    return pairs


class Polynomial:
    """A polynomial as its coefficients by field names ({sorted names: coefficient at the
    quadrature points}): the quadratic part of a Lagrangian at one value of the control,
    which central differences subtract term by term. A'(c)[phi, phi] from differences of
    the coefficients carries the rounding of each coefficient; from differences of whole
    matrices it carried the rounding of A, ~1e-16 |A| |phi|^2 / h, which on a thin stiff
    film's fold (|A| ~ 2e9) moved the Koiter coefficient by 1e-5 relative."""

    def __init__(self, terms: dict):
        self.terms = terms

    @classmethod
    def of(cls, monomials) -> Polynomial:
        """The polynomial of a monomial list [(coefficient, names), ...]."""
        terms: dict = {}
        for k, xs in monomials:
            terms[xs] = terms.get(xs, 0.0) + k
        return cls(terms)

    def monomials(self) -> list:
        return [(k, xs) for xs, k in self.terms.items()]

    def __sub__(self, other: Polynomial) -> Polynomial:
        keys = self.terms.keys() | other.terms.keys()
        return Polynomial({x: self.terms.get(x, 0.0) - other.terms.get(x, 0.0) for x in keys})

    def __mul__(self, scale: float) -> Polynomial:
        return Polynomial({x: k * scale for x, k in self.terms.items()})

    __rmul__ = __mul__

    def __truediv__(self, scale: float) -> Polynomial:
        return Polynomial({x: k / scale for x, k in self.terms.items()})
