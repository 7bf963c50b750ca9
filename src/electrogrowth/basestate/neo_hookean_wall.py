"""The wall integrals of an ideal neo-Hookean layer with constant growth, in closed form
(docs/derivation-layered.md Sec. 8), in one compiled loop.

A layered state is found by Newton's method on T(r_i, lambda_z, c) = P_i - P_o (and the axial
balance), each residual a sum over layers of integrals through the wall (plies.Wall.integrals).
For a neo-Hookean layer with constant growth (g_r, g_theta, g_z) those integrals are
elementary: r^2 = A + B R^2 with B = J / lambda_z, A = r_a^2 - B a^2, and with x = ln(r_b^2 /
r_a^2), y = ln(b / a), dr2 = r_b^2 - r_a^2, h2 = b^2 - a^2,

    int l2^2 dr / r   = (B / g_theta^2) y,
    int l1^2 dr / r   = g_theta g_z / (2 lambda_z g_r) (x - A dr2 / (r_a^2 r_b^2)),
    int d^2 dr / r    = c^2 dr2 / (2 r_a^2 r_b^2),              int d dr = c x / 2,
    int l2^2 r dr     = (B / g_theta^2) (A y + B h2 / 2),
    int l1^2 r dr     = g_theta^2 g_z^2 / (2 lambda_z^2) (h2 - A x / B),
    int l3^2 r dr     = (lambda_z / g_z)^2 dr2 / 2,             int d^2 r dr = c^2 x / 2,

so that, summed over the layers, T = mu_k (int l2^2 - int l1^2) dr / r - c^2 Q_k, its scale
mu_k (int l2^2 + int l1^2) dr / r + c^2 Q_k (Q_k = dr2 / (2 eps_k r_a^2 r_b^2)), V = c x /
(2 eps_k) and N_int = pi [mu_k (2 int l3^2 - int l1^2 - int l2^2) r dr - c^2 x / (2 eps_k)].
The Gauss rule of plies.py computes the same four numbers by
quadrature; for these layers it is only exact to its rule's error and costs ~100 us per call
in NumPy against ~2 us here (a march solves its layered state by Newton at every step).
No subtraction of nearly equal numbers: dr2 = B (b - a) (b + a), x = log1p(dr2 / r_a^2),
2 y = log1p(b^2 / a^2 - 1), and the differences of these logarithms from their arguments,
z - log1p(z) (``excess``), are summed as series where they are small; each formula below is
rewritten so (the comments) for a layer of any thickness (tested down to 1e-3 R_i against the
Gauss rule and scipy's quad).
"""

from __future__ import annotations

import dataclasses
import math

import numba as nb
import numpy as np


@nb.njit(cache=True)
def excess(z):
    """z - log1p(z) >= 0 without cancellation (a series below |z| = 0.1)."""
    if abs(z) >= 0.1:
        return z - math.log1p(z)
    total, power = 0.0, z * z
    for k in range(2, 20):  # |z|^20 / 20 < 1e-21
        total += power / k if k % 2 == 0 else -power / k
        power *= z
    return total


@nb.njit(cache=True, inline="always")
def _terms(ra2, l, c, a, b, gr, gt, gz, mu, eps, out, i):
    """Add the layer [a, b]'s (T, scale, V, N_int) at r_a^2 = ra2, lambda_z = l, charge c
    to out[:, i] (NaN there where r_a^2 or l is not positive)."""
    if not (ra2 > 0.0 and l > 0.0):
        for j in range(4):
            out[j, i] = np.nan
        return
    w = (b - a) * (b + a) / (a * a)  # b^2 / a^2 - 1
    y = 0.5 * math.log1p(w)
    h2 = w * a * a
    B = gr * gt * gz / l
    d2 = B * h2  # r_b^2 - r_a^2
    rb2 = ra2 + d2
    Ba2 = B * a * a  # = r_a^2 - A
    z = d2 / ra2
    x = math.log1p(z)
    ez = excess(z)
    i2 = B / (gt * gt) * y
    # x - A d2 / (r_a^2 r_b^2) = z B b^2 / r_b^2 - (z - x)
    i1 = gt * gz / (2.0 * l * gr) * (z * (Ba2 + d2) / rb2 - ez)
    q = c * c / eps
    l3 = l / gz
    # A y + B h2 / 2 = r_a^2 y + B a^2 (w - log1p(w)) / 2
    r2 = B / (gt * gt) * (ra2 * y + 0.5 * Ba2 * excess(w))
    # h2 - A x / B = h2 B a^2 / r_a^2 + (A / B) (z - x), with d2 = B h2
    r1 = (gt * gz / l) ** 2 * 0.5 * (d2 * a * a / ra2 + (ra2 - Ba2) / B * ez)
    out[0, i] += mu * (i2 - i1) - 0.5 * q * d2 / (ra2 * rb2)
    out[1, i] += mu * (i2 + i1) + 0.5 * q * d2 / (ra2 * rb2)
    out[2, i] += 0.5 * c * x / eps
    out[3, i] += math.pi * (mu * (l3 * l3 * d2 - r1 - r2) - 0.5 * q * x)


@nb.njit(cache=True)
def ply_integrals(r_a2, lz, c, a, b, g, mu, eps, out):
    """Add one layer's (T, scale, V, N_int) at each point to ``out`` (4, n): r_a2, lz, c
    arrays (n,) (r_a^2 at the layer's inner face), faces a < b, growth g (3,),
    modulus mu, permittivity eps. NaN where a face radius is not positive or lz <= 0."""
    for i in range(r_a2.size):
        _terms(r_a2[i], lz[i], c[i], a, b, g[0], g[1], g[2], mu, eps, out, i)


@nb.njit(cache=True)
def ply_profile(R, ra2, lz, c, a, g, mu, eps):
    """(4, n): the integrals from the layer's inner face a to each radius R (n,) of one
    state; row 0, T(a -> R), is sigma_rr(R) - sigma_rr(a)."""
    out = np.zeros((4, R.size))
    for i in range(R.size):
        if R[i] > a:
            _terms(ra2, lz, c, a, R[i], g[0], g[1], g[2], mu, eps, out, i)
    return out


@dataclasses.dataclass(frozen=True)
class TractionProfile:
    """sigma_rr(R) - sigma_rr(a) through one neo-Hookean layer of constant growth of one
    state, in closed form (:func:`ply_profile`): it stands where the quadrature route keeps
    the Chebyshev antiderivative of (tau_2 - tau_1) / r (layered_state.LayeredState)."""

    ra2: float  # r^2 at the layer's inner face a
    lz: float
    c: float
    a: float
    growth: tuple[float, float, float]
    mu: float
    eps: float

    def profile(self, R) -> np.ndarray:
        """(4, n) integrals from a to each of the radii R (1-d)."""
        R = np.ascontiguousarray(R, dtype=float)
        g = np.asarray(self.growth, dtype=float)
        return ply_profile(R, self.ra2, self.lz, self.c, self.a, g, self.mu, self.eps)

    def __call__(self, R):
        R = np.asarray(R, dtype=float)
        out = self.profile(R.reshape(-1))[0]
        return out.reshape(R.shape) if R.ndim else float(out[0])
