"""A mode shape by the paper's two-step surface-impedance method (eq. two_Riccati).

The impedance z(R) of the solutions that meet one face's condition (S = z U) is integrated
across the wall from that face's z = z_P(P) (0 on a traction-free face) by the Riccati
equation (SciPy DOP853, dense output), layer by layer: eta, hence z, is continuous across
a bonded interface. This is done from each face; the face displacement U on the other face
spans the null space of z - z_P(P) there, taken from the z for which that matrix is the
more nearly singular: a mode that lives at one face (a stiff inner film's folds) is
exponentially small on the other, where its condition is not singular to working
accuracy. U is carried back by dU/dR = (dr/dR)(1/r)(G1 + G2 z) U, towards the face z
started from (the stable direction), and S = z U. A pole of z inside the wall in both
directions stops the route (:class:`_PoleError`); mode_shape.py then falls back to
collocation (null_vector.py).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from .._types import FloatArray, State
from ..errors import ConvergenceError
from ..incremental.impedance import ALL_PAIRS, face_impedance, impedance_scale
from ..incremental.impedance_reference import kept_pairs, layer_fields
from ..incremental.stroh import stroh_matrix


class _RouteFailed(ConvergenceError):
    """The impedance route gave no shape; mode_shape.py falls back to collocation."""


class _PoleError(_RouteFailed):
    """The Riccati integration for z stopped (a pole of the impedance inside the wall)."""


def stroh_at(state: State, R: float, m: float, k: float) -> FloatArray:
    """The Stroh matrix G (8x8) at reference radius R (moduli and p of the base state)."""
    G = np.empty((8, 8))
    r = float(state.radius(R))
    mod = np.ascontiguousarray(state.moduli(np.array(R)), dtype=float)
    stroh_matrix(mod, float(state.pressure(np.array(R))), float(m), k * r, G)
    return G


def impedance_shape(
    state: State,
    m: int,
    k: float,
    R: FloatArray,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
) -> FloatArray:
    """Un-normalised eta at R by the paper's two-step impedance method (eq. two_Riccati),
    layer by layer (eta, hence z = S U^-1, is continuous across a bonded interface), from
    the face where the mode lives:

    1. dz/dR = w (G3 + G4 z - z G1 - z G2 z), w = (dr/dR) / r, from one face's
       z = z_P(P) (0 on a traction-free face) across the wall (dense), for each face;
    2. U on the other face: right singular vector of the smallest singular value of
       z - z_P there, from the z whose z - z_P is the more nearly singular (relative to
       its largest singular value; ``_null_face``);
    3. dU/dR = w (G1 + G2 z) U from that face back across the wall; S = z U.

    Why both faces: a mode that lives at one face (a stiff film's folds) decays across the
    wall like (r_i / r)^m, so on the far face it is exponentially small and z - z_P there
    is singular only within an exponentially narrow window of the critical value; the
    null vector must be taken on the face where the mode is. Step 3 runs towards the face
    z started from, the stable direction (tests/shapes/test_mode_shape.py).

    On the block of the kept ``pairs`` (a mode family); the other components are 0.
    Raises _PoleError when both profiles have a pole in the wall, _RouteFailed when the
    null vector carries no displacement (a backstop: mode_shape.py then uses collocation).
    """
    keep = kept_pairs(pairs)
    faces = [zp[np.ix_(keep, keep)] for zp in face_impedances(state, m, k)]
    ends = (1.0, state.tube.outer_radius)
    z, start = _null_face(state, m, k, faces, rtol=rtol, pairs=pairs)
    U_0 = np.linalg.svd(z(ends[1 - start]) - faces[1 - start])[2][-1]
    order = slice(None, None, -1 if start == 0 else 1)  # R in the order of integration
    span = (ends[1 - start], ends[start])
    U = transport(state, m, k, z, U_0, span, R[order], rtol=rtol, pairs=pairs)[:, order]
    S = np.stack([z(x) @ U[:, j] for j, x in enumerate(R)], axis=1)
    eta = np.zeros((8, R.size))
    eta[keep], eta[[4 + j for j in keep]] = U, S
    if not np.abs(eta[:3]).max() > 0:
        # the null vector is a decoupled pair's (the potential of an uncharged tube): not
        # the mode, whose condition is then not singular on that face to working accuracy
        raise _RouteFailed(
            f"the impedance route's null vector on the {('inner', 'outer')[1 - start]} face"
            " carries no displacement"
        )
    return eta


def _null_face(state: State, m: int, k: float, faces, *, rtol: float, pairs: int):
    """(z, start): the impedance profile z started on face ``start`` (0 inner, 1 outer)
    whose z - z_P on the other face has the smaller ratio of smallest to largest singular
    value (the mode's condition is singular there; at a critical point of a mode spread
    through the wall both ratios are small, either route is then accurate). A profile
    with a pole in the wall is not a candidate; both with a pole raise _PoleError."""
    ends = (1.0, state.tube.outer_radius)
    best, poles = None, []
    for start in (0, 1):
        try:
            z = impedance_profile(state, m, k, rtol=rtol, pairs=pairs, start=start)
        except _PoleError as exc:
            poles.append(f"from the {('inner', 'outer')[start]} face, {exc}")
            continue
        sv = np.linalg.svd(z(ends[1 - start]) - faces[1 - start], compute_uv=False)
        ratio = sv[-1] / sv[0] if sv[0] > 0 else 0.0
        if best is None or ratio < best[0]:
            best = (ratio, z, start)
    if best is None:
        raise _PoleError("; ".join(poles))
    return best[1], best[2]


def _stroh_blocks(pairs: int):
    """A function (fields, m, k, R) -> (w, G1, G2, G3, G4): the Stroh matrix's blocks on the
    kept ``pairs`` at R, times nothing, and w = (dr/dR) / r of the layer of ``fields``."""
    keep = kept_pairs(pairs)
    rows, d = np.array(keep + [4 + j for j in keep]), len(keep)
    G = np.empty((8, 8))

    def blocks(fields, m, k, R):
        mod, p, r, w = fields(R)
        stroh_matrix(np.ascontiguousarray(mod, dtype=float), p, float(m), k * r, G)
        Gk = G[np.ix_(rows, rows)]
        return w, Gk[:d, :d], Gk[:d, d:], Gk[d:, :d], Gk[d:, d:]

    return blocks


def impedance_profile(
    state: State,
    m: int,
    k: float,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
    start: int = 0,
):
    """z(R) for R in [1, R_N]: the Riccati equation (paper eq. Riccati) integrated by SciPy
    DOP853 from z = z_P(P) on the inner face (``start`` 0, outwards) or the outer face
    (``start`` 1, inwards), layer by layer (z continuous at interfaces), as a callable
    R -> symmetric d x d (dense output), d the number of kept ``pairs`` (4 for the paper's
    ansatz). Started on the outer face, z is the impedance of the solutions that meet the
    outer face's condition: the same equation, integrated the other way."""
    keep = kept_pairs(pairs)
    d = len(keep)
    scale = impedance_scale(float(m), float(k), float(state.r_o))
    blocks = _stroh_blocks(pairs)
    z0 = face_impedances(state, m, k)[start][np.ix_(keep, keep)].ravel()
    segments = layer_fields(state)
    pieces = []
    for a, b, fields in segments if start == 0 else segments[::-1]:

        def rhs(R, y, fields=fields):
            w, G1, G2, G3, G4 = blocks(fields, m, k, R)
            z = y.reshape(d, d)
            return (w * (G3 + G4 @ z - z @ G1 - z @ G2 @ z)).ravel()

        span = (a, b) if start == 0 else (b, a)
        with np.errstate(all="ignore"):
            ric = solve_ivp(
                rhs, span, z0, method="DOP853", rtol=rtol, atol=1e-3 * rtol, dense_output=True
            )
        big = np.abs(ric.y).max() if ric.y.size else np.inf
        if ric.status != 0 or not np.isfinite(big) or big > 1e8 * scale**2:
            r_stop = float(state.radius(min(max(ric.t[-1], a), b), side="outer"))
            raise _PoleError(
                f"the impedance z has a pole near r = {r_stop:.6g}"
                f" (Riccati integration stopped: {ric.message})"
            )
        pieces.append((b, ric.sol))
        z0 = ric.y[:, -1]
    pieces.sort(key=lambda piece: piece[0])  # by the layers' outer ends, whichever way
    ends = np.array([b for b, _ in pieces])

    def z(x: float) -> FloatArray:
        sol = pieces[min(int(np.searchsorted(ends, x)), len(pieces) - 1)][1]
        zx = sol(x).reshape(d, d)
        return 0.5 * (zx + zx.T)  # symmetric exactly (docs/derivation-stroh.md, sec. 4)

    return z


def transport(
    state: State,
    m: int,
    k: float,
    z,
    U0: FloatArray,
    span: tuple[float, float],
    R_eval: FloatArray,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
) -> FloatArray:
    """Solve dU/dR = w (G1 + G2 z) U (paper eq. two_Riccati, second part) from
    U(span[0]) = U0 to span[1], layer by layer (U continuous at interfaces); U at ``R_eval``
    (in the order of integration), (d, len), on the block of the kept ``pairs`` (d of
    them; 4 for the paper's ansatz).

    Stable towards the face z started from (for z from the inner face: inwards,
    span = (R_N, 1)); the other way errors grow like exp(2 k (r_o - r_i)).
    """
    blocks = _stroh_blocks(pairs)
    start, end = span
    sense = 1.0 if end > start else -1.0
    R_eval = np.asarray(R_eval, float)
    out = np.empty((len(U0), R_eval.size))
    segments = layer_fields(state)
    U = np.asarray(U0, float)
    for a, b, fields in segments if sense > 0 else segments[::-1]:
        lo, hi = max(a, min(span)), min(b, max(span))
        if not lo < hi:
            continue
        t0, t1 = (lo, hi) if sense > 0 else (hi, lo)

        def rhs(x, U, fields=fields):
            w, G1, G2, _, _ = blocks(fields, m, k, x)
            return w * ((G1 + G2 @ z(x)) @ U)

        here = np.flatnonzero(((R_eval - t0) * sense >= 0) & ((R_eval - t1) * sense <= 0))
        sol = solve_ivp(
            rhs, (t0, t1), U, method="DOP853", dense_output=True, rtol=rtol, atol=1e-3 * rtol
        )
        if sol.status != 0:
            raise _PoleError(f"the integration of U failed: {sol.message}")
        if here.size:
            out[:, here] = sol.sol(R_eval[here])
        U = sol.y[:, -1]
    return out


# -- collocation route -----------------------------------------------------------------------


def face_impedances(state, m: float, k: float):
    """z_P of the inner and outer face (incremental/impedance.py ``face_impedance``; zero on
    a traction-free face)."""
    return tuple(
        face_impedance(P, float(m), k * r, ALL_PAIRS, 1.0)
        for P, r in zip(state.face_pressures, (state.r_i, state.r_o))
    )
