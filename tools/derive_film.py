"""The flat limit of a thin film: a pre-compressed incompressible neo-Hookean film bonded to
an unstressed neo-Hookean half-space, plane strain (docs/derivation-film.md).

Derives with sympy the 6 x 6 bifurcation determinant of the film (thickness h, shear modulus
mu_f, in-plane stretch lam < 1 along the wave, 1 / lam across it) on the half-space (mu_s),
for the incremental wave u ~ exp(i k x1), and solves it numerically: for each k h the
largest lam (the first reached as the film is compressed) at which it vanishes, minimised
over k h. Run it to print the table of docs/derivation-film.md:

    python tools/derive_film.py
"""

from __future__ import annotations

import math

import mpmath as mp
import sympy as sp
from scipy.optimize import minimize_scalar

k, h, lam, mu_f, mu_s, y = sp.symbols("k h lam mu_f mu_s y", positive=True)
I = sp.I


def fields(f, mu, l2):
    """u1, u2 and the tractions t1, t2 on y = const of the stream function psi = f(y) e^{ikx}
    (u1 = psi_y, u2 = -psi_x) in a neo-Hookean layer with stretches (1 / l2, l2) and base
    pressure p0 = mu l2^2 (sigma_22 = 0). Incremental nominal stress (Ogden):
    S_2i = mu l2^2 u_i,2 + p0 u_2,i - p delta_2i; the pressure increment from the x1
    equation mu (l1^2 u1_11 + l2^2 u1_22) = p_1."""
    l1 = 1 / l2
    u1 = sp.diff(f, y)
    u2 = -I * k * f
    p = mu * (l1**2 * (-(k**2)) * u1 + l2**2 * sp.diff(u1, y, 2)) / (I * k)
    p0 = mu * l2**2
    t1 = mu * l2**2 * sp.diff(u1, y) + p0 * I * k * u2
    t2 = mu * l2**2 * sp.diff(u2, y) + p0 * sp.diff(u2, y) - p
    return [u1, u2, t1, t2]


def determinant():
    """The 6 x 6 matrix of the film (y in [0, h], top y = h free) on the half-space y < 0."""
    c = sp.symbols("c0:6")
    q = k * lam**2  # the film's second decay rate: k lambda1 / lambda2
    film = (
        c[0] * sp.exp(k * y) + c[1] * sp.exp(-k * y) + c[2] * sp.exp(q * y) + c[3] * sp.exp(-q * y)
    )
    sub = (c[4] + c[5] * y) * sp.exp(k * y)  # the unstressed half-space: a double rate k
    F = fields(film, mu_f, 1 / lam)
    S = fields(sub, mu_s, sp.Integer(1))
    eqs = [F[2].subs(y, h), F[3].subs(y, h)]  # the free top face
    eqs += [(F[i] - S[i]).subs(y, 0) for i in range(4)]  # u and traction continuous
    M = sp.Matrix([[sp.diff(e, ci) for ci in c] for e in eqs])
    return sp.simplify(M)


MATRIX = determinant()
_F = sp.lambdify((lam, k, h, mu_f, mu_s), MATRIX, "mpmath")


def target(lam_, kh, ratio):
    """The determinant at film stretch lam_, k h = kh, mu_f / mu_s = ratio (k = 1), each row
    scaled to a largest entry 1: i times a real number (rows 2, 4 and 6 carry the factor i
    of u2 = -i k f), whose real part is returned."""
    mp.mp.dps = 30
    M = mp.matrix(_F(mp.mpf(lam_), 1, mp.mpf(kh), mp.mpf(ratio), 1))
    for i in range(M.rows):
        s = max(abs(M[i, j]) for j in range(M.cols))
        for j in range(M.cols):
            M[i, j] /= s
    d = mp.det(M) / 1j
    assert abs(mp.im(d)) <= 1e-20 * (1 + abs(d))
    return mp.re(d)


def critical_stretch(kh, ratio):
    """The largest lam < 1 at which mode k h bifurcates (the first as lam falls from 1)."""
    # finer next to 1: a stiff film's root lies there (1 - 1.1e-3 at mu_f / mu_s = 1e4)
    grid = [1 - 1e-4 * 2**j for j in range(6)] + [1 - 0.005 * i for i in range(1, 199)]
    prev = target(grid[0], kh, ratio)
    for a, b in zip(grid, grid[1:]):
        cur = target(b, kh, ratio)
        if mp.sign(cur) != mp.sign(prev):
            return float(mp.findroot(lambda x: target(x, kh, ratio), (b, a), solver="anderson"))
        prev = cur
    return float("nan")


def optimum(ratio):
    """(k h, lam) of the first mode to bifurcate for mu_f / mu_s = ratio: the largest
    critical stretch over k h (golden search in ln k h about the small-strain guess)."""
    guess = math.log((3 / ratio) ** (1 / 3))
    res = minimize_scalar(
        lambda t: -critical_stretch(math.exp(t), ratio),
        bracket=(guess - 0.5, guess, guess + 0.5),
        method="brent",
        options={"xtol": 1e-10},
    )
    return math.exp(res.x), -res.fun


if __name__ == "__main__":
    print("ratio mu_f/mu_s | k h | lambda_cr | strain 1 - lambda | small-strain strain, k h")
    for ratio in (2.0, 5.0, 10.0, 1000.0):
        kh, lam_cr = optimum(ratio)
        small = (0.25 * (3 / ratio) ** (2 / 3), (3 / ratio) ** (1 / 3))
        row = f"{ratio:g} | {kh:.10f} | {lam_cr:.10f} | {1 - lam_cr:.10f}"
        print(f"{row} | {small[0]:.6f}, {small[1]:.6f}")
