"""The 23 updated electro-elastic moduli of a principal state: their names and order (the
last axis of every moduli array), and the ideal neo-Hookean dielectric's in closed form.
"""

from __future__ import annotations

import numpy as np

#: Order of the moduli returned by :meth:`Material.moduli` (indices 1 = r, 2 = theta,
#: 3 = z; ``G`` stands for Gamma_0). ``Apiqj`` multiplies L_jq = du_j/dx_q in the updated
#: incremental nominal stress S_pi; ``Gpiq`` multiplies D_q; ``Kpq`` gives E_p.
MODULI_NAMES = (
    "A1111",
    "A2222",
    "A3333",
    "A1122",
    "A1133",
    "A2233",
    "A1212",
    "A2121",
    "A1313",
    "A3131",
    "A2323",
    "A3232",
    "A1221",
    "A1331",
    "A2332",
    "G111",
    "G221",
    "G331",
    "G122",
    "G133",
    "K11",
    "K22",
    "K33",
)
MODULI_INDEX = {name: i for i, name in enumerate(MODULI_NAMES)}


def neo_hookean_moduli(l1, l2, l3, d):
    """Closed-form moduli of the ideal neo-Hookean dielectric (paper Sec. 4.2).

    A_0piqj = delta_ij (B_pq + D_p D_q), Gamma_0 from I5/2 and K_0 = I, derived in
    docs/derivation-stroh.md; used as a fast path and to test the generic route.
    """
    l1, l2, l3, d = np.broadcast_arrays(*(np.asarray(x, float) for x in (l1, l2, l3, d)))
    out = np.zeros(l1.shape + (len(MODULI_NAMES),))
    b1, b2, b3, d2 = l1**2, l2**2, l3**2, d**2
    for name, val in (
        ("A1111", b1 + d2),
        ("A1212", b1 + d2),
        ("A1313", b1 + d2),
        ("A2121", b2),
        ("A2222", b2),
        ("A2323", b2),
        ("A3131", b3),
        ("A3232", b3),
        ("A3333", b3),
        ("G111", 2 * d),
        ("G122", d),
        ("G133", d),
        ("K11", 1.0),
        ("K22", 1.0),
        ("K33", 1.0),
    ):
        out[..., MODULI_INDEX[name]] = val
    return out
