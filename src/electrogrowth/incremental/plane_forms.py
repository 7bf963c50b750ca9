"""The energy of a plane-strain, incompressible neo-Hookean stack, expanded about its
homogeneous base state and discretised spectrally: the quadratic form A(lambda) (the
linearised problem), its lambda-derivative A' and the cubic form C (the second-order
problem) that the Koiter coefficient needs (docs/derivation-koiter.md).

Geometry: a periodic cell 0 <= X < 2 pi / K of a stack of segments Y_b <= Y <= Y_t in the
reference (unstressed) configuration of the film; the base state is the homogeneous plane
strain x = F0 X, F0 = diag(l, 1/l) of a compressed segment (l = lambda, the control), with
sigma_22 = 0 (a free top face), so its Lagrange multiplier is p0 = mu / l^2. A segment held
unstressed under a compressed film (the film alone compressed) has its stress-free state
at diag(l, 1) of these coordinates, a "growth" F_g = F0 = diag(l, 1) (``_pieces``).
A displacement U(X, Y) from the base state and a pressure increment q give F = F0 + G,
G = grad_X U, and the Lagrangian per unit reference area of a compressed segment (exact,
no truncation: the energy is quadratic in F and the constraint det F = 1 in G)

    E(U, q) = E2 + E3,
    E2 = int mu/2 |G|^2 - p0 det G - q cof(F0) : G,   cof(F0) = diag(1/l, l),
    E3 = -int q det G.

The first variation of the base state's own terms vanishes (periodic U_1, S_22 = 0), so
w = (U, q) = 0 is the fundamental path for every l, and E has no quartic term.

Fields are expanded in harmonics of K X with the wrinkle's reflection symmetry (U_1 odd,
U_2 and q even in X): ``U1 = a_j(Y) sin(j K X)``, ``U2 = b_j(Y) cos(j K X)``,
``q = c_j(Y) cos(j K X)``. In each segment a_j, b_j are polynomials of degree N given by
their values at the N + 1 Chebyshev-Lobatto points (continuous across segments: one
shared value), c_j of degree N - 2 given at the N - 1 interior points (the P_N - P_{N-2}
pressure space of incremental/collocation.py, free of spurious pressure modes). The
integrals are done exactly in X (equispaced points, enough for the harmonics' products)
and by Gauss-Legendre quadrature in Y (exact for the polynomial integrands), so A and C are
the exact Hessian and third derivative of the discrete energy: symmetric, and the adjoint
of a mode is the mode itself.
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np

from .._types import FloatArray
from ..errors import ParameterError
from .chebyshev import chebyshev_lobatto

#: Quadrature points in X per period: exact for trigonometric products of degree <= 7
#: (the cubic form of harmonics 1, 1, 2 has degree 4).
_X_POINTS = 8


@dataclasses.dataclass(frozen=True)
class Segment:
    """One segment bottom <= Y <= top of a layer: shear modulus mu, ``nodes`` Lobatto points
    (polynomial degree nodes - 1); ``follows`` True when its base stretch along X is the
    control lambda (the whole stack compressed), False when it is unstressed."""

    bottom: float
    top: float
    mu: float
    follows: bool = True
    nodes: int = 24

    def __post_init__(self):
        if not self.top > self.bottom:
            raise ParameterError(f"segment [{self.bottom}, {self.top}] is empty")
        if not self.mu > 0:
            raise ParameterError(f"mu = {self.mu} must be > 0")
        if self.nodes < 4:
            raise ParameterError(f"nodes = {self.nodes} must be >= 4")


def _barycentric(nodes: FloatArray, points: FloatArray) -> FloatArray:
    """The matrix of the polynomial interpolation from ``nodes`` to ``points``."""
    diff = nodes[:, None] - nodes[None, :]
    np.fill_diagonal(diff, 1.0)
    w = 1.0 / diff.prod(axis=1)
    w /= np.abs(w).max()
    d = points[:, None] - nodes[None, :]
    exact = np.isclose(d, 0.0, atol=1e-15)
    d[exact] = 1.0
    c = w / d
    P = c / c.sum(axis=1, keepdims=True)
    rows = exact.any(axis=1)
    P[rows] = exact[rows].astype(float)
    return P


@dataclasses.dataclass(frozen=True)
class Space:
    """The unknowns of a set of harmonics on a stack: ``harmonics`` lists (field, j) with
    field 0 = a (U1, sin), 1 = b (U2, cos), 2 = c (q, cos). Displacements vanish at the
    bottom of the stack (clamped: the truncated half-space, or the gauge of harmonic 0).
    ``x_points`` equispaced points per period integrate trigonometric polynomials of degree
    below it exactly (8: the products of harmonics up to 2 in a cubic form)."""

    segments: tuple[Segment, ...]
    harmonics: tuple[tuple[int, int], ...]
    x_points: int = _X_POINTS

    @property
    def _layout(self):
        """Offsets: per (field, j) a slice of the global vector; displacement values are
        shared at segment joints and absent at the clamped bottom."""
        n_disp = sum(s.nodes - 1 for s in self.segments)  # minus the clamped bottom node
        n_pres = sum(s.nodes - 2 for s in self.segments)
        out, at = [], 0
        for field, _j in self.harmonics:
            size = n_pres if field == 2 else n_disp
            out.append(slice(at, at + size))
            at += size
        return out, at

    @property
    def size(self) -> int:
        return self._layout[1]


def _segment_maps(seg: Segment, quad: int):
    """Per segment: Gauss points Y_g, weights, and the maps from the segment's Lobatto
    values (bottom to top) to values and d/dY at Y_g, and from interior values to Y_g."""
    x, D = chebyshev_lobatto(seg.nodes)
    x, D = x[::-1], D[::-1, ::-1]  # increasing
    half = 0.5 * (seg.top - seg.bottom)
    g, w = np.polynomial.legendre.leggauss(quad)
    Y = seg.bottom + half * (g + 1.0)
    P = _barycentric(x, g)
    Pi = _barycentric(x[1:-1], g)
    return Y, w * half, P, P @ D / half, Pi


@dataclasses.dataclass
class Forms:
    """A(K, lambda), dA/dlambda, dA/dK and C of the discrete energy on ``space``.

    The energy is taken per unit length in X (the mean over a period, theta = K X), so the
    maps from the unknowns to G11 = dU1/dX and G21 = dU2/dX carry one factor K and every
    matrix is a polynomial in K (degree 2) and in 1/l, l: the lambda- and K-free pieces are
    built once and ``stiffness`` only adds them up."""

    space: Space
    maps: dict
    weight: FloatArray
    mu: FloatArray
    follows: FloatArray

    @classmethod
    def build(cls, space: Space) -> Forms:
        nx = space.x_points
        theta = 2 * np.pi * np.arange(nx) / nx
        slices, size = space._layout
        per_seg = [_segment_maps(s, max(2 * s.nodes, 8)) for s in space.segments]
        nY = sum(len(m[0]) for m in per_seg)
        wY = np.concatenate([m[1] for m in per_seg])
        mu = np.concatenate([np.full(len(m[0]), s.mu) for s, m in zip(space.segments, per_seg)])
        fo = np.concatenate(
            [np.full(len(m[0]), float(s.follows)) for s, m in zip(space.segments, per_seg)]
        )
        n_disp = sum(s.nodes - 1 for s in space.segments)
        n_pres = sum(s.nodes - 2 for s in space.segments)
        # Y maps: value / derivative of a displacement function, value of a pressure one
        Vd, Dd, Vp = np.zeros((nY, n_disp)), np.zeros((nY, n_disp)), np.zeros((nY, n_pres))
        row, col_d, col_p = 0, -1, 0  # col_d: global index of the segment's bottom node
        for s, (Y, _w, P, PD, Pi) in zip(space.segments, per_seg):
            rows = slice(row, row + len(Y))
            cols = np.arange(col_d, col_d + s.nodes)
            keep = cols >= 0  # the stack's bottom node is clamped
            Vd[rows, cols[keep]] += P[:, keep]
            Dd[rows, cols[keep]] += PD[:, keep]
            Vp[rows, col_p : col_p + s.nodes - 2] = Pi
            row += len(Y)
            col_d += s.nodes - 1
            col_p += s.nodes - 2
        npts = nx * nY
        maps = {k: np.zeros((npts, size)) for k in ("G11", "G12", "G21", "G22", "q")}
        for (field, j), sl in zip(space.harmonics, slices):
            c, s_ = np.cos(j * theta), np.sin(j * theta)
            if field == 0:  # U1 = a sin(jKX): G11 = K j a cos, G12 = a' sin
                maps["G11"][:, sl] += np.kron(j * c[:, None], Vd)
                maps["G12"][:, sl] += np.kron(s_[:, None], Dd)
            elif field == 1:  # U2 = b cos(jKX): G21 = -K j b sin, G22 = b' cos
                maps["G21"][:, sl] += np.kron(-j * s_[:, None], Vd)
                maps["G22"][:, sl] += np.kron(c[:, None], Dd)
            else:
                maps["q"][:, sl] += np.kron(c[:, None], Vp)
        weight = np.tile(wY, nx) / nx
        return cls(space, maps, weight, np.tile(mu, nx), np.tile(fo, nx))

    @functools.cached_property
    def _pieces(self) -> dict:
        """The Hessian of E2 as a sum of lambda- and K-free pieces: keys (scale, K power),
        scale the function of lambda that multiplies it ("1", "1/l", "1/l2", "l").

        A compressed segment (follows): F0 = diag(l, 1/l), no growth, p0 = mu / l^2:
            mu/2 |G|^2 - (mu / l^2) det G - q (G11 / l + l G22).
        An unstressed segment bonded to a compressed film (fixed): its stress-free state is
        diag(l, 1) of the film's reference coordinates, F0 = F_g = diag(l, 1), p0 = mu,
        energy J_g mu/2 |F F_g^-1|^2 per unit film reference area, J_g = l:
            mu / (2 l) (G11^2 + G21^2) + mu l / 2 (G12^2 + G22^2) - mu det G - q (G11 + l G22)."""
        mu, f = self.mu, self.follows
        fx = 1.0 - f
        one = np.ones_like(mu)
        terms = [  # (scale, coefficient, pair)
            ("1", f * mu / 2, ("G11", "G11")),
            ("1", f * mu / 2, ("G12", "G12")),
            ("1", f * mu / 2, ("G21", "G21")),
            ("1", f * mu / 2, ("G22", "G22")),
            ("1/l2", -f * mu, ("G11", "G22")),
            ("1/l2", f * mu, ("G12", "G21")),
            ("1/l", -f * one, ("q", "G11")),
            ("l", -f * one, ("q", "G22")),
            ("1/l", fx * mu / 2, ("G11", "G11")),
            ("1/l", fx * mu / 2, ("G21", "G21")),
            ("l", fx * mu / 2, ("G12", "G12")),
            ("l", fx * mu / 2, ("G22", "G22")),
            ("1", -fx * mu, ("G11", "G22")),
            ("1", fx * mu, ("G12", "G21")),
            ("1", -fx * one, ("q", "G11")),
            ("l", -fx * one, ("q", "G22")),
        ]
        out: dict = {}
        for scale, coeff, (a, b) in terms:
            if not coeff.any():
                continue
            power = sum(x in ("G11", "G21") for x in (a, b))
            M = self.maps[a].T @ ((coeff * self.weight)[:, None] * self.maps[b])
            key = (scale, power)
            out[key] = out.get(key, 0.0) + M + M.T  # the Hessian (2 M when a = b)
        return out

    def stiffness(self, K: float, lam: float, *, wrt: str = "") -> FloatArray:
        """A(K, lambda), the Hessian of E2, or its derivative ``wrt`` "lambda" or "K"
        (docs/derivation-koiter.md; the two kinds of segment in ``_pieces``)."""
        scale = {"1": 1.0, "1/l": 1 / lam, "1/l2": lam**-2, "l": lam}
        dscale = {"1": 0.0, "1/l": -(lam**-2), "1/l2": -2 * lam**-3, "l": 1.0}
        n = self.space.size
        A = np.zeros((n, n))
        for (name, power), M in self._pieces.items():
            if wrt == "lambda":
                c = dscale[name] * K**power
            elif wrt == "K":
                c = scale[name] * power * K ** (power - 1) if power else 0.0
            else:
                c = scale[name] * K**power
            if c:
                A += c * M
        return A

    def fields(self, v: FloatArray, K: float) -> dict:
        """G11, G12, G21, G22 and q of the unknowns v at the quadrature points."""
        out = {k: M @ v for k, M in self.maps.items()}
        out["G11"] *= K
        out["G21"] *= K
        return out

    def cubic_gradient(self, fa: dict, fb: dict, K: float) -> FloatArray:
        """C[a, b, .] as a vector, C the third derivative of E3 = -int q det G:
        C[a,b,c] = -int q_a 2D(G_b,G_c) + q_b 2D(G_a,G_c) + q_c 2D(G_a,G_b), with
        2D(G,H) = G11 H22 + H11 G22 - G12 H21 - H12 G21."""
        w, M = self.weight, self.maps
        out = -(M["q"].T @ (w * _two_d(fa, fb)))
        for qx, g in ((fa["q"], fb), (fb["q"], fa)):  # q_x 2D(G_y, G_c), linear in c
            out -= K * (M["G11"].T @ (w * qx * g["G22"])) + M["G22"].T @ (w * qx * g["G11"])
            out += M["G12"].T @ (w * qx * g["G21"]) + K * (M["G21"].T @ (w * qx * g["G12"]))
        return out

    def cubic_hessian(self, fa: dict, K: float) -> FloatArray:
        """The matrix C[a, ., .]: the Jacobian at w = a of the cubic term C[w, w, .] / 2 of
        the equilibrium equations (a Newton solve of the full discrete problem)."""
        w, M = self.weight, self.maps
        G = {k: (K * M[k] if k in ("G11", "G21") else M[k]) for k in ("G11", "G12", "G21", "G22")}
        qw = (w * fa["q"])[:, None]
        # q_a 2D(G_b, G_c)
        H = G["G11"].T @ (qw * G["G22"]) - G["G12"].T @ (qw * G["G21"])
        H = H + H.T
        # q_b 2D(G_a, G_c) + q_c 2D(G_a, G_b)
        L = fa["G11"][:, None] * G["G22"] + fa["G22"][:, None] * G["G11"]
        L -= fa["G12"][:, None] * G["G21"] + fa["G21"][:, None] * G["G12"]
        T = M["q"].T @ (w[:, None] * L)
        return -(H + T + T.T)


def _two_d(a: dict, b: dict) -> FloatArray:
    return a["G11"] * b["G22"] + b["G11"] * a["G22"] - a["G12"] * b["G21"] - b["G12"] * a["G21"]
