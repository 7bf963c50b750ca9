"""The exact buckling condition of a homogeneously stretched incompressible neo-Hookean tube
with traction-free faces (Wilkes 1955; Haughton & Ogden), written from the incremental
equations with modified Bessel functions and nothing of the package (docs/design.md,
"An exact check: the stretched neo-Hookean tube").

The tube (reference radii 1 and R_o, length L, mu = 1) is stretched axially by lambda, so
r = lambda^(-1/2) R, and a mode u ~ (cos m theta cos kz, sin m theta cos kz, cos m theta
sin kz), k = n pi / (lambda L), bifurcates where the 6 x 6 determinant of the face
tractions of the six Bessel solutions vanishes.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq
from scipy.special import ive, ivp, kve, kvp


def _z(kind: str, m: int, x: float, d: int) -> float:
    """The d-th derivative (d = 0, 1, 2) of I_m or K_m at x, scaled by exp(-x) (I) or
    exp(x) (K): the scaling of a column leaves the determinant's roots alone."""
    if kind == "I":
        f = ive(m, x) if d == 0 else ivp(m, x, d) * math.exp(-x)
    else:
        f = kve(m, x) if d == 0 else kvp(m, x, d) * math.exp(x)
    return float(f)


def _column(family: str, kind: str, m: int, k: float, lam: float, r: float, scale: float):
    """The tractions (s_rr, s_rtheta, s_rz) at radius r of one solution (amplitudes of
    cos cos, sin cos, cos sin); ``scale`` the radius whose exponential scales the column."""
    c = 1.0 / lam  # lambda_r^2 = lambda_theta^2 = p (the base pressure), mu = 1
    q = lam**1.5 * k
    arg = k * r if family == "p" else q * r
    sarg = k * scale if family == "p" else q * scale
    e = math.exp(arg - sarg) if kind == "I" else math.exp(sarg - arg)
    z0, z1, z2 = (_z(kind, m, arg, d) * e for d in (0, 1, 2))
    if family == "p":  # p = Z(kr), u = grad p / (k^2 (c - lambda^2))
        kk = 1.0 / (k * k * (c - lam**2))
        return (
            2 * c * kk * k * k * z2 - z0,
            c * 2 * kk * m * (z0 / r**2 - k * z1 / r),
            c * (-2 * kk * k * k * z1),
        )
    if family == "a":  # u = curl(chi e_z), chi = Z(qr) sin m theta cos kz
        return (
            2 * c * (m * q * z1 / r - m * z0 / r**2),
            c * (-q * q * z2 - m * m * z0 / r**2 + q * z1 / r),
            c * (-k * m * z0 / r),
        )
    # u = curl curl(omega e_z), omega = Z(qr) cos m theta sin kz
    return (
        2 * c * k * q * q * z2,
        c * k * m * (-2 * q * z1 / r + 2 * z0 / r**2),
        c * (-(q**3) - k * k * q) * z1,
    )


def determinant(lam: float, m: int, n: int, outer_radius: float, length: float) -> float:
    """The buckling determinant at axial stretch lambda (zero at bifurcation)."""
    a, b = lam**-0.5, lam**-0.5 * outer_radius
    k = n * math.pi / (lam * length)
    fams = ("p", "b") if m == 0 else ("p", "a", "b")  # m = 0: the torsion decouples
    rows = (0, 2) if m == 0 else (0, 1, 2)
    cols = []
    for fam in fams:
        for kind, scale in (("I", b), ("K", a)):
            col = []
            for r in (a, b):
                t = _column(fam, kind, m, k, lam, r, scale)
                col += [t[i] for i in rows]
            cols.append(col)
    mat = np.array(cols).T
    mat /= np.linalg.norm(mat, axis=0)  # columns of unit length
    return float(np.linalg.det(mat))


def critical_stretch(m, n, outer_radius, length, *, lowest=0.3, step=2e-3) -> float:
    """The first lambda below 1 where the determinant changes sign (marched down from 1,
    then Brent to full precision)."""
    lam = 1.0 - 1e-6
    f = determinant(lam, m, n, outer_radius, length)
    while lam - step > lowest:
        nxt = lam - step
        g = determinant(nxt, m, n, outer_radius, length)
        if f * g < 0:
            return brentq(
                determinant, nxt, lam, args=(m, n, outer_radius, length), xtol=1e-15, rtol=1e-15
            )
        lam, f = nxt, g
    raise ValueError(f"no bifurcation of ({m}, {n}) above lambda = {lowest}")
