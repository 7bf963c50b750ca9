"""The slow twin of the compiled kernel: the paper's Riccati equation with SciPy.

Plain and obviously correct: ``scipy.integrate.solve_ivp`` (DOP853) of

    dz/dR = (dr/dR) (1/r) (G3 + G4 z - z G1 - z G2 z),  z(R=1) = 0,

with the moduli taken straight from the base state (no Chebyshev table) and the Stroh
matrix from the pure-Python version of ``stroh_matrix``. It uses the impedance chart only,
so it stops with an error when z has a pole inside the wall; the compiled kernel
(impedance.py) must agree with it wherever it runs.

A mode family that keeps only some pairs (U_j, S_j) (``pairs``, bit j set: pair j kept;
incremental/targets.py) is integrated here on its own block: the rows and columns of G of
the kept pairs, z of size (kept x kept). No zero padding, no constant entries: the
independent check of the kernel's masking.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from ..errors import ConvergenceError
from .impedance import ALL_PAIRS, impedance_scale
from .stroh import stroh_matrix

_stroh = stroh_matrix.py_func


def kept_pairs(pairs: int) -> list[int]:
    """Indices j of the pairs (U_j, S_j) kept by the bitmask ``pairs``."""
    return [j for j in range(4) if (pairs >> j) & 1]


def impedance_rhs(state, m: float, k: float, pairs: int = ALL_PAIRS):
    """Right-hand side of the Riccati equation in R for ``solve_ivp`` (z flattened), on the
    block of the kept ``pairs``."""
    g, lz = state.tube.growth, state.tube.stretch
    a = g**3 / lz
    G = np.empty((8, 8))
    keep = kept_pairs(pairs)
    d = len(keep)
    rows = np.array(keep + [4 + j for j in keep])

    def rhs(R, y):
        z = y.reshape(d, d)
        r = float(state.radius(R))
        mod = state.moduli(np.array(R))
        _stroh(
            np.ascontiguousarray(mod, dtype=float),
            float(state.pressure(np.array(R))),
            float(m),
            k * r,
            G,
        )
        Gk = G[np.ix_(rows, rows)]
        G1, G2, G3, G4 = Gk[:d, :d], Gk[:d, d:], Gk[d:, :d], Gk[d:, d:]
        return (a * R / r**2 * (G3 + G4 @ z - z @ G1 - z @ G2 @ z)).ravel()

    return rhs


def impedance_reference(
    state, m: float, k: float, *, pairs: int = ALL_PAIRS, rtol: float = 1e-11, atol: float = 1e-13
) -> np.ndarray:
    """Conditional impedance z(r_o) of mode (m, k): the paper's method, unscaled; the block
    of the kept ``pairs`` (4x4 for the paper's ansatz)."""
    ro = state.tube.outer_radius
    d = len(kept_pairs(pairs))
    sol = solve_ivp(
        impedance_rhs(state, m, k, pairs),
        (1.0, ro),
        np.zeros(d * d),
        method="DOP853",
        rtol=rtol,
        atol=atol,
    )
    if not sol.success or not np.all(np.isfinite(sol.y[:, -1])):
        raise ConvergenceError(
            f"reference Riccati integration failed for mode m={m}, "
            f"k={k}: {sol.message} (a pole of the impedance?)"
        )
    return sol.y[:, -1].reshape(d, d)


def target_reference(state, m: float, k: float, *, pairs: int = ALL_PAIRS, **kwargs) -> float:
    """Pole-free target det z / sqrt(det(I + z^T z)) with S scaled like the kernel."""
    z = impedance_reference(state, m, k, pairs=pairs, **kwargs)
    s = impedance_scale(float(m), float(k), float(state.r_o))
    z = z / s
    return float(np.linalg.det(z) / np.sqrt(np.linalg.det(np.eye(len(z)) + z.T @ z)))


# -- orthonormalised shooting: the target without an impedance, through layers -------------


def layer_fields(state):
    """[(a, b, fields(R) -> (moduli, p, r, w))] per layer; w = dr/dR / r and the fields of
    the layer itself at its ends."""
    tube = state.tube
    out = []
    for k, (a, b) in enumerate(zip(tube.radii, tube.radii[1:])):
        layer = tube.layers[k]

        def fields(R, a=a, b=b, layer=layer):
            side = "inner" if R >= b else "outer"  # the ends belong to this layer
            Rv = np.array([R])
            r = float(state.radius(Rv, side=side)[0])
            J = float(np.prod(layer.growth_at(Rv)))
            mod = state.moduli(Rv, side=side)[0]
            return mod, float(state.pressure(Rv, side=side)[0]), r, J * R / (state.stretch * r * r)

        out.append((a, b, fields))
    return out


def shooting_target(state, m: float, k: float, *, pairs: int = ALL_PAIRS, pieces: int = 40):
    """The kernel's target det(M2 - z_P M1) / sqrt(det(M^T M)) of the propagated basis M,
    computed without any impedance: the linear Stroh system d eta/dR = w G eta (S scaled by
    the kernel's s) for the kept pairs, from [I; z_P(P_i)] on the inner face through every
    layer (eta continuous at interfaces), re-orthonormalised by QR on ``pieces`` sub-intervals
    of each layer with the signs of det R kept; z_P(P_o) applied on the outer face. A slow,
    independent twin of impedance.integrate_one for layered and pressurised tubes."""
    from .impedance import face_impedance  # the face condition, written once (compiled)

    keep = kept_pairs(pairs)
    rows = np.array(keep + [4 + j for j in keep])
    d = len(keep)
    P_i, P_o = state.face_pressures
    s = impedance_scale(float(m), float(k), float(state.r_o))
    zi = face_impedance(P_i, float(m), k * state.r_i, pairs, s)[np.ix_(keep, keep)]
    zo = face_impedance(P_o, float(m), k * state.r_o, pairs, s)[np.ix_(keep, keep)]
    M = np.vstack([np.eye(d), zi])
    sign, G = 1.0, np.empty((8, 8))
    scale = np.r_[np.ones(d), np.full(d, s)]  # eta = diag(scale) eta~

    for a, b, fields in layer_fields(state):

        def rhs(R, y, fields=fields):
            mod, p, r, w = fields(R)
            _stroh(np.ascontiguousarray(mod, dtype=float), p, float(m), k * r, G)
            Gt = G[np.ix_(rows, rows)] * scale[None, :] / scale[:, None]
            return (w * (Gt @ y.reshape(2 * d, d))).ravel()

        edges = np.linspace(a, b, pieces + 1)
        for x0, x1 in zip(edges, edges[1:]):
            sol = solve_ivp(rhs, (x0, x1), M.ravel(), method="DOP853", rtol=1e-12, atol=1e-14)
            if not sol.success:
                raise ConvergenceError(f"shooting failed for mode m={m}, k={k}: {sol.message}")
            Q, Rq = np.linalg.qr(sol.y[:, -1].reshape(2 * d, d))
            sign *= np.sign(np.prod(np.diag(Rq)))
            M = Q
    return float(sign * np.linalg.det(M[d:] - zo @ M[:d]))
