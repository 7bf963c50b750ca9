"""Where each unknown and equation sits in the collocation matrix, and the blocks of it
that a mode family keeps (collocation.py).

``pairs`` (bit j set: kept) selects the unknowns and equations of a block that decouples
exactly: bit 0 U_r and P with the r equilibrium and tr L = 0, bit 1 U_th with the theta
equilibrium, bit 2 U_z with the z equilibrium, bit 3 Phi with div D = 0 (the same bits as
the Stroh pairs of the impedance kernel; docs/derivation-families.md).
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError

_FIELDS = ("U_r", "U_th", "U_z", "P", "Phi")


#: every block kept: the paper's ansatz (bit 0 U_r and P, 1 U_th, 2 U_z, 3 Phi)
ALL_PAIRS = 0b1111


#: the unknowns and the equations (row blocks) of each bit of ``pairs``
_BIT_FIELDS = (("U_r", "P"), ("U_th",), ("U_z",), ("Phi",))


_BIT_ROWS = (("r", "incompressible"), ("theta",), ("z",), ("maxwell",))


#: the blocks that decouple: all; m = 0 without / with only the torsion (theta) block;
#: k = 0 without / with only the anti-plane (z) block
BLOCKS = (ALL_PAIRS, 0b1101, 0b0010, 0b1011, 0b0100)


_SINGLE = (0b0010, 0b0100)  # one displacement field, one second-order equation


def _layout(nn: int) -> dict[str, slice]:
    """Column ranges of the unknowns: nn values of U_r, U_th, U_z, Phi; nn - 2 of P."""
    sizes = {"U_r": nn, "U_th": nn, "U_z": nn, "P": nn - 2, "Phi": nn}
    out, start = {}, 0
    for f in _FIELDS:
        out[f] = slice(start, start + sizes[f])
        start += sizes[f]
    return out


def _row_layout(nn: int) -> dict[str, slice]:
    """Row ranges of the equations, in the order of :func:`collocation_matrix`."""
    return {
        "r": slice(0, nn),
        "theta": slice(nn, 2 * nn),
        "z": slice(2 * nn, 3 * nn),
        "maxwell": slice(3 * nn, 4 * nn),
        "incompressible": slice(4 * nn, 5 * nn - 2),
    }


def check_pairs(pairs) -> int:
    """``pairs`` as an int, one of BLOCKS, else ParameterError."""
    if isinstance(pairs, bool) or pairs not in BLOCKS:
        raise ParameterError(
            f"pairs = {pairs!r} is invalid; choose a block that decouples:"
            f" one of {BLOCKS} (bits: U_r + P, U_th, U_z, Phi)"
        )
    return int(pairs)


def stable_det_sign(pairs: int, nodes: int) -> float:
    """Sign of det M of the block ``pairs`` on the unloaded tube (stable in every mode).

    -1 for the whole matrix. A block that decouples has a sign alternating with ``nodes``:
    the lone theta or z block (a scalar second-order problem, nodes x nodes) has
    -(-1)^nodes, its complement (-1)^nodes, so their product is the whole matrix's -1
    (moving a block of nodes rows past blocks of nodes rows is an even permutation).
    Measured for nodes = 6..40, every mode and tube tried (tests/incremental/test_targets.py).
    """
    if pairs == ALL_PAIRS:
        return -1.0
    alt = -1.0 if nodes % 2 else 1.0
    return -alt if pairs in _SINGLE else alt


def block_indices(nn: int, pairs: int) -> tuple[np.ndarray, np.ndarray]:
    """(rows, columns) of the collocation matrix kept by ``pairs``, in their order."""
    cols, rows = _layout(nn), _row_layout(nn)
    c = [
        np.arange(5 * nn - 2)[cols[f]]
        for j in range(4)
        if (pairs >> j) & 1
        for f in _BIT_FIELDS[j]
    ]
    r = [
        np.arange(5 * nn - 2)[rows[e]] for j in range(4) if (pairs >> j) & 1 for e in _BIT_ROWS[j]
    ]
    return np.sort(np.concatenate(r)), np.sort(np.concatenate(c))


def _block_indices(nn: int, pairs: int, layers: int) -> tuple[np.ndarray, np.ndarray]:
    """:func:`block_indices` of every layer block, with the layers' offsets."""
    rows, cols = block_indices(nn, pairs)
    width = 5 * nn - 2
    offsets = width * np.arange(layers)[:, None]
    return (rows + offsets).ravel(), (cols + offsets).ravel()
