"""The energy density of the cross-section's finite-element model, and its derivatives.

Plane strain at the axial stretch lambda_z, written in the reference polar frame
(e_R, e_Theta): the in-plane deformation gradient F (2x2, columns the reference directions R
and Theta), the Lagrangian field Grad phi = (phi_R, phi_Theta / R) and the pressure p. Per
unit reference volume, for one layer (units mu = eps = R_i = 1, docs/postbuckling.md):

    psi = mu_k J_g / 2 (sum_ij F_ij^2 / g_j^2 + lambda_z^2 / g_z^2 - 3)   (neo-Hookean in F G^-1)
          - p (lambda_z det F - J_g)                                  (incompressible: det F_e = 1)
          - eps_k / 2 lambda_z det F |F^-T Grad phi|^2                (ideal dielectric)

with G = diag(g_R, g_Theta, g_z), J_g = g_R g_Theta g_z. Its gradient gives the first
Piola stress P = d psi / dF, the constraint and Gauss's law; its Hessian the consistent
tangent. Both are derived once by sympy and evaluated on arrays of quadrature points.
"""

from __future__ import annotations

import functools

import numpy as np
import sympy as sp

#: the state variables at a quadrature point, in the order of the gradient and Hessian
VARIABLES = ("F11", "F12", "F21", "F22", "e1", "e2", "p")
#: the parameters at a quadrature point
PARAMETERS = ("mu", "eps", "lz", "gR", "gT", "gz")


def density_expression() -> tuple[sp.Expr, tuple[sp.Symbol, ...], tuple[sp.Symbol, ...]]:
    """psi(F, Grad phi, p; mu, eps, lambda_z, g_R, g_Theta, g_z) as a sympy expression."""
    F11, F12, F21, F22, e1, e2, p = xs = sp.symbols(VARIABLES, real=True)
    mu, eps, lz, gR, gT, gz = ps = sp.symbols(PARAMETERS, positive=True)
    Jg = gR * gT * gz
    det = F11 * F22 - F12 * F21
    i1e = (F11**2 + F21**2) / gR**2 + (F12**2 + F22**2) / gT**2 + lz**2 / gz**2
    # F^-T e = adj(F)^T e / det F, adj(F) = [[F22, -F12], [-F21, F11]]
    E1 = (F22 * e1 - F21 * e2) / det
    E2 = (-F12 * e1 + F11 * e2) / det
    psi = mu * Jg / 2 * (i1e - 3) - p * (lz * det - Jg) - eps / 2 * lz * det * (E1**2 + E2**2)
    return psi, xs, ps


@functools.cache
def derivatives():
    """(gradient, hessian): functions of (state (7, ...), params (6, ...)) returning arrays of
    shape (7, ...) and (7, 7, ...); ``gradient.density`` is psi itself."""
    psi, xs, ps = density_expression()
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


def cauchy_stress(state, params) -> np.ndarray:
    """The in-plane Cauchy stress sigma = P F^T / J (J = lambda_z det F), shape (2, 2, ...),
    in the frame (e_R, e_Theta) of the reference point (the current polar frame when the
    point has not turned, as in the axisymmetric state)."""
    gradient, _ = derivatives()
    g = gradient(state, params)
    P = np.array([[g[0], g[1]], [g[2], g[3]]])
    F = np.array([[state[0], state[1]], [state[2], state[3]]])
    J = params[2] * (F[0, 0] * F[1, 1] - F[0, 1] * F[1, 0])
    return np.einsum("ik...,jk...->ij...", P, F) / J
