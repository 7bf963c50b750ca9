"""The energy density of the finite-element models (cross-section and meridian), and its
derivatives.

Both models are a plane of the reference cylindrical frame with one stretch out of it: the
cross-section the plane (R, Theta) at the axial stretch lambda_z (a parameter), the
meridian the plane (R, Z) with the hoop stretch s = r / R (a variable: it follows u_R).
In the plane, the deformation gradient F (2x2, columns the two reference directions), the
Lagrangian electric displacement D = (d_1, d_2) (divergence-free: the models write it as the
curl of a stream function) and the pressure p; out of it the stretch s. Per unit reference
volume, for one layer (units mu = eps = R_i = 1, docs/postbuckling.md):

    psi = mu_k J_g / 2 (sum_ij F_ij^2 / g_j^2 + s^2 / g_3^2 - 3)   (neo-Hookean in F G^-1)
          - p (s det F - J_g)                                  (incompressible: det F_e = 1)
          + |F D|^2 / (2 eps_k s det F)                         (ideal dielectric)

with G = diag(g_1, g_2, g_3) (the growth along the plane's two directions and out of it),
J_g = g_1 g_2 g_3. The last term is the package's I5 / (2 eps_k) (d = F D / J): a minimum
in D, so the whole energy is a minimum in (u, D) on the incompressible displacements, and
a conforming discretisation cannot lose stability before the continuum does (the
potential's form, a maximum in phi, can: docs/postbuckling.md, "Why the electric
displacement"). Its gradient gives the first Piola stress P = d psi / dF (and, for the
meridian, the hoop stress d psi / ds), the constraint and the Lagrangian field
E = d psi / dD = -Grad phi; its Hessian the consistent tangent. Both are derived once by
sympy and evaluated on arrays of quadrature points.
"""

from __future__ import annotations

import functools

import numpy as np
import sympy as sp

#: the state variables at a quadrature point, in the order of the gradient and Hessian, and
#: the parameters, of each model: the cross-section's out-of-plane stretch is lambda_z (a
#: parameter; growth (g_R, g_Theta) in the plane, g_z out of it), the meridian's the hoop
#: stretch s (a variable; growth (g_R, g_Z) in the plane, g_Theta out of it)
VARIABLES = {
    "section": ("F11", "F12", "F21", "F22", "d1", "d2", "p"),
    "meridian": ("F11", "F12", "F21", "F22", "d1", "d2", "p", "s"),
}
PARAMETERS = {
    "section": ("mu", "eps", "lz", "gR", "gT", "gz"),
    "meridian": ("mu", "eps", "gR", "gZ", "gT"),
}


def plane_density(F, d, p, s, mu, eps, g):
    """psi of the in-plane F = (F11, F12, F21, F22), electric displacement d = (d1, d2),
    pressure p, out-of-plane stretch s and growth g = (g_1, g_2, g_3) (sympy expressions)."""
    F11, F12, F21, F22 = F
    d1, d2 = d
    g1, g2, g3 = g
    Jg = g1 * g2 * g3
    det = F11 * F22 - F12 * F21
    i1e = (F11**2 + F21**2) / g1**2 + (F12**2 + F22**2) / g2**2 + s**2 / g3**2
    # F D, the current displacement times J (D has no out-of-plane part)
    FD1 = F11 * d1 + F12 * d2
    FD2 = F21 * d1 + F22 * d2
    return mu * Jg / 2 * (i1e - 3) - p * (s * det - Jg) + (FD1**2 + FD2**2) / (2 * eps * s * det)


def density_expression(
    kind: str = "section",
) -> tuple[sp.Expr, tuple[sp.Symbol, ...], tuple[sp.Symbol, ...]]:
    """psi(variables; parameters) of model ``kind`` as a sympy expression, with the symbols
    of its variables and parameters (:data:`VARIABLES`, :data:`PARAMETERS`)."""
    xs = sp.symbols(VARIABLES[kind], real=True)
    ps = sp.symbols(PARAMETERS[kind], positive=True)
    if kind == "section":
        mu, eps, lz, gR, gT, gz = ps
        psi = plane_density(xs[:4], xs[4:6], xs[6], lz, mu, eps, (gR, gT, gz))
    else:
        mu, eps, gR, gZ, gT = ps
        psi = plane_density(xs[:4], xs[4:6], xs[6], xs[7], mu, eps, (gR, gZ, gT))
    return psi, xs, ps


@functools.cache
def derivatives(kind: str = "section"):
    """(gradient, hessian) of model ``kind``: functions of (state (nv, ...), params
    (np, ...)) returning arrays of shape (nv, ...) and (nv, nv, ...); ``gradient.density``
    is psi itself."""
    psi, xs, ps = density_expression(kind)
    grad = [sp.diff(psi, x) for x in xs]
    hess = [[sp.diff(g, y) for y in xs] for g in grad]
    g_fun = sp.lambdify(xs + ps, grad, modules="numpy", cse=True)
    p_fun = sp.lambdify(xs + ps, psi, modules="numpy", cse=True)
    h_fun = sp.lambdify(xs + ps, hess, modules="numpy", cse=True)

    def gradient(state, params):
        shape = np.shape(state[0])
        return np.array([np.broadcast_to(v, shape) for v in g_fun(*state, *params)])

    def density(state, params):
        return np.broadcast_to(p_fun(*state, *params), np.shape(state[0]))

    def hessian(state, params):
        shape = np.shape(state[0])
        rows = h_fun(*state, *params)
        return np.array([[np.broadcast_to(v, shape) for v in row] for row in rows])

    gradient.density = density
    return gradient, hessian


def _out_of_plane_stretch(state, params, kind: str):
    return params[2] if kind == "section" else state[7]


def cauchy_stress(state, params, kind: str = "section") -> np.ndarray:
    """The in-plane Cauchy stress sigma = P F^T / J (J = s det F), shape (2, 2, ...), in the
    frame of the reference point (the current frame when the point has not turned, as in
    the axisymmetric state): (e_R, e_Theta) for the cross-section, (e_R, e_Z) for the
    meridian."""
    gradient, _ = derivatives(kind)
    g = gradient(state, params)
    P = np.array([[g[0], g[1]], [g[2], g[3]]])
    F = np.array([[state[0], state[1]], [state[2], state[3]]])
    J = _out_of_plane_stretch(state, params, kind) * (F[0, 0] * F[1, 1] - F[0, 1] * F[1, 0])
    return np.einsum("ik...,jk...->ij...", P, F) / J


def hoop_stress(state, params) -> np.ndarray:
    """The meridian's hoop Cauchy stress sigma_theta_theta = s (d psi / d s) / J."""
    gradient, _ = derivatives("meridian")
    s = state[7]
    J = s * (state[0] * state[3] - state[1] * state[2])
    return gradient(state, params)[7] * s / J
