"""How many eigenvalues of the pencil K z = lambda M z (M the mass of the displacements
alone) lie below a shift sigma: Sylvester's law of inertia for K - sigma M.

Far below the spectrum K - sigma M has exactly one negative eigenvalue per Lagrange
multiplier (the pressure's unknowns: no mass and no stiffness of their own, the negative
directions of the constraint's Schur complement); the stream function's unknowns, massless
too, form a positive block (the dielectric energy is a minimum in D). Each eigenvalue of the
pencil below sigma adds one negative eigenvalue, so

    (eigenvalues below sigma) = (negative eigenvalues of K - sigma M) - (multipliers).

The negative eigenvalues are counted on a symmetric factorisation L D L^T without pivoting
(SuperLU with its diagonal as pivots, L U = L D L^T), in a band-reducing order (reverse
Cuthill-McKee) with each multiplier moved after its neighbours, so that its zero diagonal
has been filled when it is eliminated. The sign of the determinant, read off an ordinary
pivoted LU, checks the count's parity; should the two disagree (an unstable elimination),
the parity alone is used (0 or 1), as before the count existed.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sps
import scipy.sparse.linalg as spla
from scipy.sparse.csgraph import reverse_cuthill_mckee


def multiplier_mask(K, M) -> np.ndarray:
    """The unknowns without mass or stiffness of their own (the Lagrange multipliers)."""
    massless = np.asarray(abs(M).sum(axis=1)).ravel() == 0
    return massless & (K.diagonal() == 0)


def count_below(A, multipliers: np.ndarray, lu=None) -> int:
    """The number of eigenvalues of the pencil below sigma, from A = K - sigma M (symmetric,
    sparse) and the mask of its multipliers; ``lu`` (splu of A) checks the parity."""
    lu = spla.splu(A.tocsc()) if lu is None else lu
    odd = _odd_below(lu, int(multipliers.sum()))
    try:
        count = _negative_eigenvalues(A, multipliers) - int(multipliers.sum())
    except RuntimeError:  # an exactly zero pivot: no symmetric count this time
        count = -1
    if count < 0 or (count % 2 == 1) != odd:
        return int(odd)
    return count


def _negative_eigenvalues(A, last: np.ndarray) -> int:
    """The negative eigenvalues of symmetric A, from L D L^T without pivoting in the order
    described above."""
    A = sps.csr_matrix(A)
    order = reverse_cuthill_mckee(A, symmetric_mode=True)
    position = np.empty(len(order))
    position[order] = np.arange(len(order))
    key = position.copy()
    for i in np.nonzero(last)[0]:
        neighbours = A.indices[A.indptr[i] : A.indptr[i + 1]]
        key[i] = position[neighbours].max() + 0.5
    perm = np.argsort(key, kind="stable")
    lu = spla.splu(
        A[perm][:, perm].tocsc(),
        permc_spec="NATURAL",
        diag_pivot_thresh=0.0,
        options={"SymmetricMode": True},
    )
    if np.any(lu.perm_r != np.arange(len(perm))):  # SuperLU pivoted after all: no L D L^T
        raise RuntimeError("pivoted")
    return int(np.count_nonzero(lu.U.diagonal() < 0))


def _odd_below(lu, multipliers: int) -> bool:
    """Whether an odd number of eigenvalues of the pencil lie below the shift of ``lu``,
    the LU factors of K - shift M: its determinant has the sign (-1)^multipliers far below
    the spectrum, and each eigenvalue below the shift flips it. The sign is read off the
    factors: the diagonal of U and the parities of the row and column permutations (L has
    a unit diagonal)."""
    negative = int(np.count_nonzero(lu.U.diagonal() < 0))
    flips = negative + _odd_permutation(lu.perm_r) + _odd_permutation(lu.perm_c)
    return (flips + multipliers) % 2 == 1


def _odd_permutation(perm: np.ndarray) -> int:
    """1 if ``perm`` is odd (its length minus its number of cycles is odd), else 0."""
    seen = np.zeros(len(perm), dtype=bool)
    cycles = 0
    for start in range(len(perm)):
        if not seen[start]:
            cycles += 1
            j = start
            while not seen[j]:
                seen[j] = True
                j = perm[j]
    return (len(perm) - cycles) % 2


__all__ = ["count_below", "multiplier_mask"]
