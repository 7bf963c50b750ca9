"""Chebyshev collocation of the incremental problem: an independent onset criterion.

The Stroh/Riccati engine eliminates the incremental pressure and works with an 8x8 Stroh
matrix. This module does neither: it discretises the displacement-pressure-potential
equations of paper Sec. 3.2 directly, assembled from the full moduli tensors A_piqj,
Gamma_piq, K_pq, so a match between the two certifies the Stroh derivation.

Increments (paper eq. incremental-solutions), collocated in the current radius
r_i <= r <= r_o (moduli and p taken at R(r) = sqrt(1 + lambda_z (r^2 - r_i^2) / g^3))::

    u_r = U_r cos(m th) cos(kz),  u_th = U_th sin(m th) cos(kz),  u_z = U_z cos(m th) sin(kz),
    pdot = P cos(m th) cos(kz),   phidot = Phi cos(m th) cos(kz),  k = n pi / (lambda_z L).

They are assembled as u = (U_r, -i U_th, -i U_z) e^{i(m th + k z)}: cos <-> 1, sin <-> -i,
so the rows of the theta and z components, multiplied by i, are exactly the real
cos/sin equations. Equations (docs/conventions.md, lengths in units of the current
half-thickness h = (r_o - r_i)/2, so the matrix is invariant under isotropic growth):

    L_jq = du_j/dx_q (paper eq. 52),    E = -grad phidot,
    D    = K^{-1} (E - Gamma_qjp L_jq)                        (eq16-1_2 solved for D),
    S_pi = A_piqj L_jq + Gamma_piq D_q + p L_pi - pdot delta_pi (eq16-1_1),
    div S = 0 on the first index (eq. incremental-constitutive3), div D = 0
    (eq. incremental-Maxwell), tr L = 0 (eq. incremental-incompressibility),
    S_rr = S_rth = S_rz = Phi = 0 at r = r_i, r_o (eq. 57).

The moduli vary with r and are never differentiated: the fluxes S_rr, S_rth, S_rz, D_r
are built at the nodes as linear maps of the unknowns and the differentiation matrix is
applied to them ("differentiate the flux"). The pressure lives on the interior nodes
(P_N - P_{N-2}), which keeps the discrete system free of a spurious pressure mode.
Details, validation and convergence: docs/collocation.md.

Mode families: ``pairs`` selects the block of unknowns and equations that decouples
(collocation_layout.py). ALL_PAIRS (default) is the paper's ansatz; at m = 0 the theta
block (torsion) decouples, at k = 0 (n = 0, prismatic) the z block (anti-plane shear);
nothing divides by k, so k = 0 needs no special case. The pieces: chebyshev.py (nodes,
differentiation), nodal_law.py (the law at the nodes), collocation_impedance.py (z(r_o)).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from .._types import FloatArray
from ..basestate.tube import solve_base_state
from ..errors import CollocationTooLarge, ConvergenceError, NoBifurcationFound, ParameterError
from ..model.layers import Tube
from ..model.moduli import MODULI_INDEX
from .chebyshev import chebyshev_lobatto, interior_interpolation
from .collocation_layout import (
    _FIELDS,
    ALL_PAIRS,
    _block_indices,
    _layout,
    check_pairs,
    stable_det_sign,
)
from .dense_algebra import equilibrated, equilibration, one_blas_thread
from .nodal_law import Operator, _fluxes_at, _Grid


def _grid(state, n: float, nodes: int) -> _Grid:
    if not (isinstance(nodes, (int, np.integer)) and nodes >= 6):
        raise ParameterError(f"nodes = {nodes!r} is invalid; need an integer >= 6")
    x, Dx = chebyshev_lobatto(int(nodes))
    h = 0.5 * (state.r_o - state.r_i)
    r = 0.5 * (state.r_o + state.r_i) + h * x
    k = n * math.pi / state.current_length
    return _Grid(r=r, rh=r / h, Dx=Dx, kh=k * h, h=h)


def _fluxes(state, grid: _Grid, m: float, layer: int = 0) -> tuple[Operator, Operator, Operator]:
    """Nodal maps of L, the incremental stress S_pi and displacement D_q in ``layer``."""
    return _fluxes_at(*_layer_fields(state, layer, grid.r), grid, m)


def _layer_grid(state, k: int, n: float, nodes: int) -> _Grid:
    """The grid of layer k of a LayeredState: Lobatto points on [r_{k-1}, r_k] (outer
    face first), lengths in units of the half-thickness h of the whole wall."""
    x, Dx = chebyshev_lobatto(int(nodes))
    h = 0.5 * (state.r_o - state.r_i)
    a, b = state.radii[k], state.radii[k + 1]
    hk = 0.5 * (b - a)
    r = 0.5 * (a + b) + hk * x
    k_ax = n * math.pi / state.current_length
    return _Grid(r=r, rh=r / h, Dx=Dx * (h / hk), kh=k_ax * h, h=h)


def _layer_fields(state, k: int, r: FloatArray) -> tuple[FloatArray, FloatArray]:
    """(moduli, p) of layer k at current radii r (its end nodes on the layer's side)."""
    a, b = state.tube.radii[k], state.tube.radii[k + 1]
    R = np.clip(state.reference_radius(r, layer=k), a, b)
    outer_end = R >= b
    mod, p = np.empty(R.shape + (len(MODULI_INDEX),)), np.empty(R.shape)
    for side, sel in (("outer", ~outer_end), ("inner", outer_end)):
        if sel.any():
            mod[sel] = state.moduli(R[sel], side=side)
            p[sel] = state.pressure(R[sel], side=side)
    return mod, p


#: the most memory one collocation target may take: every prismatic mode up to the scan's
#: cap m = 2000 of a tube of up to four layers at rtol 1e-12 (251 nodes a layer, 0.9 GB)
#: fits, while a short axial wave through a thick wall, (0, 1000) of Rbar_o = 100 (2681
#: nodes, tens of GB), is refused before numpy asks for its arrays: unbounded, its 4.8 GiB
#: maps got the process OOM-killed on a shared machine (probe 12b, D5)
MEMORY_BUDGET = 1 << 30

#: complex (nodes, 5 nodes - 2) arrays alive at once at the peak, per layer and once: each
#: layer keeps L and S (9 each) and D (3), and the assembly of S (nodal_law._fluxes_at)
#: holds its terms; tracemalloc's peaks for 1, 2, 3 layers at 60 and 120 nodes were 38,
#: 79, 125 such arrays with the real matrix of :func:`collocation_bytes` besides
MAPS_PER_LAYER, MAPS_ONCE = 34, 2


def collocation_bytes(nodes: int, layers: int) -> int:
    """Peak bytes of one collocation target at ``nodes`` per layer, from its arrays' shapes:
    the layers' nodal maps (complex, nodes x width, width = 5 nodes - 2) and the real
    matrix (layers width)^2 that LAPACK factors; within 1 % above tracemalloc's peaks."""
    width = 5 * nodes - 2
    maps = 16 * nodes * width * (MAPS_PER_LAYER * layers + MAPS_ONCE)
    return maps + 8 * (layers * width) ** 2


def check_budget(state, m: float, n: float, nodes: int) -> None:
    """CollocationTooLarge where mode (m, n) at ``nodes`` per layer exceeds MEMORY_BUDGET."""
    need = collocation_bytes(int(nodes), _layers(state))
    if need > MEMORY_BUDGET:
        raise CollocationTooLarge(
            f"collocation would need {int(nodes)} nodes a layer for mode (m, n) = ({m:g},"
            f" {n:g}) of this {_layers(state)}-layer tube, about {need / 2**30:.3g} GiB of"
            f" arrays at its peak, beyond its budget of {MEMORY_BUDGET / 2**30:g} GiB"
        )


def _segments(state, m: float, n: float, nodes: int) -> list:
    """[(grid, L, S, D)] of every layer, inner layer first."""
    _grid(state, n, nodes)  # validates ``nodes``
    check_budget(state, m, n, nodes)  # before any array of the nodes' size
    out = []
    for k in range(len(state.tube.layers)):
        grid = _layer_grid(state, k, n, nodes)
        out.append((grid, *_fluxes(state, grid, m, k)))
    return out


def collocation_matrix(
    state, m: int, n: float, *, nodes: int = 40, pairs: int = ALL_PAIRS
) -> FloatArray:
    """The real square matrix of the collocated incremental boundary-value problem.

    Unknowns: U_r, U_th, U_z, Phi at the ``nodes`` Chebyshev-Lobatto points of the
    current wall and P at the ``nodes - 2`` interior ones (P_N - P_{N-2}: the pressure is
    a polynomial two degrees lower, extended to the faces by interpolation), lengths
    scaled by the half-thickness h, Phi also in units of h. Row blocks (outer face first):

    * r, theta, z equilibrium (paper eq. incremental-constitutive3, fluxes differentiated
      by the Chebyshev matrix) at every node, end rows replaced by S_rr, S_rth, S_rz = 0;
    * Maxwell div D = 0 (eq. incremental-Maxwell), end rows replaced by Phi = 0;
    * incompressibility tr L = 0 at the interior nodes (the pressure has no boundary
      condition, so neither has its constraint).

    Parameters
    ----------
    state : State
        The axisymmetric base state (``electrogrowth.basestate.tube.solve_base_state``): needs
        ``params``, ``r_i``, ``r_o``, ``current_length``, ``face_pressures``, ``moduli(R)``
        and ``pressure(R)`` (or a layered.LayeredState).
    m : int
        Circumferential wavenumber.
    n : float
        Axial half-wavenumber, k = n pi / (lambda_z L).
    nodes : int, keyword-only
        Chebyshev-Lobatto points per field (default 40, at least 6).
    pairs : int, keyword-only
        The blocks kept (module docstring): ALL_PAIRS (default) the whole matrix; a
        family's block (rows and columns of the kept unknowns and equations, in order)
        where it decouples (the theta block at m = 0, the z block at n = 0).

    Returns
    -------
    ndarray, shape (5 nodes - 2, 5 nodes - 2) for ALL_PAIRS
        Singular exactly when (m, n) is a bifurcation of the discrete problem.

    Examples
    --------
    >>> from electrogrowth.basestate.tube import solve_base_state
    >>> state = solve_base_state(Tube.uniform(outer_radius=1.5, length=3.0))
    >>> collocation_matrix(state, 2, 1, nodes=20).shape
    (98, 98)
    >>> collocation_target(state, 2, 1, nodes=20) > 0  # the unloaded tube is stable
    True
    """
    pairs = check_pairs(pairs)
    M = _complex_matrix(state, m, n, nodes).real
    if pairs == ALL_PAIRS:
        return M.copy()
    rows, cols = _block_indices(int(nodes), pairs, _layers(state))
    return M[np.ix_(rows, cols)]


def _complex_matrix(state, m: float, n: float, nodes: int) -> Operator:
    """The matrix before dropping its imaginary part, which vanishes identically."""
    return _assemble(state, m, n, nodes)[0]


def _assemble(state, m: float, n: float, nodes: int):
    """(complex matrix, S, D, grid) with the maps S, D and the grid of the outermost layer.

    Layer blocks of unknowns and equations, inner layer first. The end rows of each
    layer's r, theta, z and Maxwell equations carry its face or interface conditions
    (docs/derivation-layered-modes.md): on a face the follower-pressure traction
    S_ri = P L_ri (P = 0: traction free) and Phi = 0; at an interface the outer end of
    the inner layer carries the continuity of U_r, U_th, U_z, Phi, the inner end of the
    outer layer that of S_rr, S_rth, S_rz and D_r.
    """
    segs = _segments(state, m, n, nodes)
    nn, width = int(nodes), 5 * int(nodes) - 2
    total = width * len(segs)
    cols = _layout(nn)
    M = np.zeros((total, total), complex)
    rows_of = []  # per layer: global row indices of the r, theta, z, Maxwell end rows
    for k, (grid, L, S, Dq) in enumerate(segs):
        D, ir, ik, im = grid.Dx, 1.0 / grid.rh[:, None], 1j * grid.kh, 1j * m
        eq_r = D @ S[0, 0] + im * ir * S[1, 0] + ir * (S[0, 0] - S[1, 1]) + ik * S[2, 0]
        eq_t = D @ S[0, 1] + im * ir * S[1, 1] + ir * (S[1, 0] + S[0, 1]) + ik * S[2, 1]
        eq_z = D @ S[0, 2] + im * ir * S[1, 2] + ir * S[0, 2] + ik * S[2, 2]
        maxwell = D @ Dq[0] + ir * (im * Dq[1] + Dq[0]) + ik * Dq[2]
        incompressible = L[0, 0] + L[1, 1] + L[2, 2]
        # theta and z rows carry sin factors: times i they are the real cos/sin equations
        block = np.vstack([eq_r, 1j * eq_t, 1j * eq_z, maxwell, incompressible[1:-1]])
        M[k * width : (k + 1) * width, k * width : (k + 1) * width] = block
        rows_of.append(k * width + np.arange(4)[:, None] * nn + np.array([0, nn - 1]))

    def traction(k, node, P):  # rows S_ri - P L_ri (times 1, i, i), global columns
        _, L, S, _ = segs[k]
        out = np.zeros((3, total), complex)
        for i, c in enumerate((1.0, 1j, 1j)):
            out[i, k * width : (k + 1) * width] = c * (S[0, i][node] - P * L[0, i][node])
        return out

    def unknown(k, field, node):  # the row picking one nodal unknown
        out = np.zeros(total)
        out[k * width + cols[field].start + node] = 1.0
        return out

    def radial_d(k, node):
        out = np.zeros(total, complex)
        out[k * width : (k + 1) * width] = segs[k][3][0][node]
        return out

    P_i, P_o = state.face_pressures
    last, fields = len(segs) - 1, ("U_r", "U_th", "U_z", "Phi")
    inner, outer = rows_of[0][:, 1], rows_of[last][:, 0]
    M[inner[:3]], M[inner[3]] = traction(0, nn - 1, P_i), unknown(0, "Phi", nn - 1)
    M[outer[:3]], M[outer[3]] = traction(last, 0, P_o), unknown(last, "Phi", 0)
    for k in range(last):  # interface k | k + 1: node 0 of k is node nn - 1 of k + 1
        below, above = rows_of[k][:, 0], rows_of[k + 1][:, 1]
        for row, f in zip(below, fields):
            M[row] = unknown(k, f, 0) - unknown(k + 1, f, nn - 1)
        M[above[:3]] = traction(k, 0, 0.0) - traction(k + 1, nn - 1, 0.0)
        M[above[3]] = radial_d(k, 0) - radial_d(k + 1, nn - 1)
    grid, _, S, Dq = segs[last]
    return M, S, Dq, grid


def _layers(state) -> int:
    return len(state.tube.layers)


def collocation_target(
    state, m: int, n: float, *, nodes: int = 40, pairs: int = ALL_PAIRS
) -> float:
    """f = s0 sign(det M) sigma_min(M) / sigma_max(M), the bifurcation criterion, M the
    collocation matrix :func:`equilibrated` (the same roots and signs).

    Continuous in the parameters (det M, continuous, changes sign only through
    sigma_min = 0), free of poles, |f| <= 1, and zero exactly where M is singular, i.e. at
    a bifurcation (m, n). s0 = sign of det M on the unloaded tube (g = 1, lambda_z = 1,
    Vbar = 0), which is stable in every mode, makes f > 0 on the stable side: with the row
    and column order of :func:`collocation_matrix`, det M < 0 there (s0 = -1) at every
    ``nodes`` and mode, and so on every state reached from it without crossing a
    bifurcation (tested); a family block (``pairs``) has the sign of
    :func:`stable_det_sign`. For a layered tube s0 = 1: the sign on the stable side is read
    off its unloaded tube by the march (as it is for every method). Roots of even
    multiplicity are not seen.

    Where blocks decouple (m = 0 or n = 0), det M is exactly the product of the blocks'
    determinants, but sigma_min / sigma_max of M is not the product of the blocks' ratios:
    sigma(M) is the union of the blocks' singular values, so near a root of one block f is
    that block's f times a non-zero factor, and the whole matrix has the roots of every
    block (docs/derivation-families.md).

    Parameters are those of :func:`collocation_matrix`.
    """
    pairs = check_pairs(pairs)
    with one_blas_thread() as linalg:
        with np.errstate(over="ignore", invalid="ignore"):  # moduli next to the double range
            raw = collocation_matrix(state, m, n, nodes=nodes, pairs=pairs)
        if not np.isfinite(raw).all():  # an overflow: NaN, as before, without NaN
            return math.nan  # arithmetic's warnings or LAPACK on a NaN matrix
        M = equilibrated(raw)
        sign, _ = np.linalg.slogdet(M)
        s = linalg.svdvals(M, check_finite=False)
    s0 = stable_det_sign(pairs, nodes) if _layers(state) == 1 else 1.0
    return float(s0 * sign * s[-1] / s[0])


def critical_collocation(
    params: Tube,
    m: int,
    n: float,
    solve_for: str,
    bracket: tuple[float, float],
    *,
    nodes: int = 40,
    xtol: float = 1e-13,
    base_state: Callable | None = None,
    pairs: int = ALL_PAIRS,
) -> float:
    """Critical value of one control parameter for mode (m, n): root of the target.

    Parameters
    ----------
    params : Tube
        The tube; the field named by ``solve_for`` is varied with ``dataclasses.replace``.
    m, n : int
        Circumferential and axial mode numbers.
    solve_for : {'growth', 'stretch', 'voltage'}
        The control parameter g, lambda_z or Vbar.
    bracket : (float, float)
        Interval over which :func:`collocation_target` changes sign once.
    nodes, xtol : keyword-only
        Collocation points per field (default 40); absolute tolerance of ``brentq``.
    base_state : callable, keyword-only
        ``params -> BaseState``; default ``electrogrowth.basestate.tube.solve_base_state``.
    pairs : int, keyword-only
        The block of a mode family (see :func:`collocation_matrix`; default all).

    Raises
    ------
    ParameterError
        Unknown ``solve_for``.
    NoBifurcationFound
        The target has the same sign at both ends of ``bracket``.
    ConvergenceError
        ``brentq`` did not converge.

    Examples
    --------
    Axial compression of the unloaded tube (exact Bessel value 0.8024795851541):

    >>> params = Tube.uniform(outer_radius=1.5, length=3.0)
    >>> round(critical_collocation(params, 2, 1, "stretch", (0.79, 0.81), nodes=24), 10)
    0.8024795852
    """
    params.check_control(solve_for)  # any control of the tube, named if unknown
    base_state = base_state or solve_base_state

    def target(value: float) -> float:
        state = base_state(params.at(solve_for, value))
        return collocation_target(state, m, n, nodes=nodes, pairs=pairs)

    a, b = map(float, bracket)
    fa, fb = target(a), target(b)
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if np.sign(fa) == np.sign(fb):
        raise NoBifurcationFound(
            f"no sign change of the collocation target for {solve_for} in [{a}, {b}] "
            f"(mode m={m}, n={n}); widen or move the bracket"
        )
    import scipy.optimize

    root, info = scipy.optimize.brentq(target, a, b, xtol=xtol, full_output=True)
    if not info.converged:
        raise ConvergenceError(
            f"the bracketed root solve did not converge for {solve_for} in [{a}, {b}]: {info.flag}"
        )
    return float(root)


def mode_shape_collocation(
    state, m: int, n: float, *, nodes: int = 40, pairs: int = ALL_PAIRS
) -> dict[str, FloatArray]:
    """Null vector of the collocation matrix at a (near-)critical state.

    Returns arrays over the current radius ``r`` (inner face first) of the amplitudes
    ``U_r, U_th, U_z, Phi`` and ``P`` of paper eq. incremental-solutions, normalised so
    that max |U| = 1 over the three displacement components, with the largest
    displacement entry positive. It is the right singular vector of the smallest
    singular value, so it is meaningful only where the target is (close to) zero. With
    ``pairs`` (a family's block) the left-out unknowns are exactly zero.
    """
    with one_blas_thread():
        # the null vector of the equilibrated matrix, as the onset target's (dense_algebra)
        M, cols = equilibration(collocation_matrix(state, m, n, nodes=nodes, pairs=pairs))
        null = cols * np.linalg.svd(M)[2][-1]
    nn, layers = int(nodes), _layers(state)
    width = 5 * nn - 2
    v = np.zeros(width * layers)
    v[_block_indices(nn, check_pairs(pairs), layers)[1]] = null
    grids = [_layer_grid(state, k, n, nn) for k in range(layers)]
    cols = _layout(nn)
    pieces = []
    for k, grid in enumerate(grids):  # inner layer first
        parts = {f: v[k * width + cols[f].start : k * width + cols[f].stop] for f in _FIELDS}
        parts["P"] = interior_interpolation(nn) @ parts["P"]
        for f in ("U_r", "U_th", "U_z", "Phi"):
            parts[f] = parts[f] * grid.h  # back from units of h
        parts = {f: a[::-1] for f, a in parts.items()}
        parts["r"] = grid.r[::-1].copy()
        pieces.append(parts)
    parts = {f: np.concatenate([p[f] for p in pieces]) for f in _FIELDS + ("r",)}
    disp = np.concatenate([parts["U_r"], parts["U_th"], parts["U_z"]])
    scale = disp[np.argmax(np.abs(disp))]
    out = {f: parts[f] / scale for f in _FIELDS}
    out["r"] = parts["r"]
    return out
