"""Mode families and methods: which modes exist, what each keeps, and how they are solved.

The names behind ``family`` and ``method`` and the checks of a mode (m, n), apart from the
kernels that solve them (targets.py, impedance.py, collocation.py): the command line's
options and a scan's options read them without loading the compiled kernels. Every mode
belongs to one :class:`Family` (docs/derivation-families.md; targets.py's docstring); a
family keeps a subset of the four pairs (U_j, S_j) of the Stroh vector (``U_R`` ... bits).
"""

from __future__ import annotations

import enum
import math

import numpy as np

from ..errors import ParameterError

#: The largest m and n of a mode: what the kernel resolves, with a decade to spare. A short
#: wave starts near the outer end of each layer from its dominant subspace
#: (short_wave_start.py), so its steps no longer grow with m: ~100 at rtol 1e-5 and
#: 130-1400 at 1e-12 for every m from 2e3 to 1e10 through Rbar_o = 100 or a lining 1e-3
#: thick (docs/derivation-film.md, "What a large m costs the kernel"). Its first failures
#: are step underflows at decay rates |(m / r, k)| of 1e9 to 1e10 (n = 1e8 of tubes L =
#: 0.01, (1e9, 0) in a march at 1e-12); below 1e6 only the loose 1e-5 of a march failed, for
#: (1e5, 1e5) of a film L = 0.01 (k = 3e7), and its retry at a tighter rtol resolved it
#: (targets._tighter). A scan searches no further than its tube's thinnest layer needs
#: (bifurcation/options.mode_caps); shorter waves tend to the exact short-wave limit.
MODE_MAX = 10**6

#: Bits of the Stroh pairs (U_j, S_j): U_r / r Sigma_rr, U_th / r Sigma_rth,
#: U_z / r Sigma_rz, r Delta_r / -Phi (collocation: U_r and P, U_th, U_z, Phi).
U_R, U_TH, U_Z, PHI = 1, 2, 4, 8
#: every pair kept: the paper's ansatz (the kernel's own ALL_PAIRS, impedance.py, equal)
ALL_PAIRS = U_R | U_TH | U_Z | PHI


class Method(enum.StrEnum):
    """How the incremental problem is solved: the one choice behind every ``method``."""

    IMPEDANCE = "impedance"
    COLLOCATION = "collocation"


METHODS = tuple(m.value for m in Method)


class Family(enum.StrEnum):
    """A family of incremental modes (module docstring): the one name behind ``family``."""

    WRINKLE = "wrinkle"  # the paper's ansatz, m >= 0, n >= 1 (m = 0: axisymmetric)
    PRISMATIC = "prismatic"  # n = 0, m >= 2: plane strain, the in-plane part at k = 0
    TORSIONAL = "torsional"  # m = 0, n >= 1: u_th = U_th(r) cos kz

    @property
    def code(self) -> int:
        """The number standing for the family in a ``modes`` array (third column)."""
        return _CODES[self]

    def pairs(self, m: int) -> int:
        """The Stroh pairs kept for mode number m (bitmask, see ``U_R`` ...)."""
        if self is Family.PRISMATIC:
            return ALL_PAIRS & ~U_Z
        if self is Family.TORSIONAL:
            return U_TH
        return ALL_PAIRS if m != 0 else ALL_PAIRS & ~U_TH


FAMILIES = tuple(f.value for f in Family)
_CODES = {f: i for i, f in enumerate(Family)}
_BY_CODE = tuple(Family)


def check_method(method: str) -> Method:
    """The Method named ``method``, or ParameterError listing the valid names."""
    try:
        return Method(method)
    except ValueError:
        raise ParameterError(f"method = {method!r} is unknown; choose one of {METHODS}") from None


def check_family(family: str) -> Family:
    """The Family named ``family``, or ParameterError listing the valid names."""
    try:
        return Family(family)
    except ValueError:
        raise ParameterError(f"family = {family!r} is unknown; choose one of {FAMILIES}") from None


def natural_family(m: int, n: int) -> Family:
    """The family of (m, n) when none is named: prismatic for n = 0, else wrinkle."""
    return Family.PRISMATIC if n == 0 else Family.WRINKLE


def check_mode(m, n, family: str | None = None) -> Family:
    """The family of mode (m, n) (``family``, or the natural one), or ParameterError.

    Valid: wrinkle m >= 0, n >= 1; prismatic n = 0, m >= 2 ((0, 0) is the breathing mode,
    the base state's own limit point; (1, 0) a rigid translation); torsional m = 0, n >= 1;
    m, n <= MODE_MAX.

    >>> check_mode(3, 0)
    <Family.PRISMATIC: 'prismatic'>
    """
    whole = all(
        not isinstance(x, bool)
        and isinstance(x, (int, float, np.integer, np.floating))
        and math.isfinite(x)
        and int(x) == x
        for x in (m, n)
    )
    if not whole or m < 0 or n < 0 or m > MODE_MAX or n > MODE_MAX:
        raise ParameterError(
            f"mode (m, n) = ({m}, {n}) is invalid; need integers 0 <= m <= {MODE_MAX},"
            f" 0 <= n <= {MODE_MAX} (n = 0: prismatic, m >= 2; the kernel resolves no"
            " shorter waves, which tend to the exact short-wave limit every scan computes)"
        )
    fam = natural_family(m, n) if family is None else check_family(family)
    where = f"mode (m, n) = ({m:g}, {n:g})"
    if fam is Family.WRINKLE and n < 1:
        raise ParameterError(
            f"{where} is not a wrinkle (n >= 1); n = 0 is the prismatic family (m >= 2)"
        )
    if fam is Family.PRISMATIC:
        if n != 0:
            raise ParameterError(f"{where} is not prismatic; prismatic modes have n = 0, m >= 2")
        if m < 2:
            why = (
                "the breathing mode, the base state's own limit point"
                if m == 0
                else "a rigid translation of the cross-section"
            )
            raise ParameterError(
                f"{where} is invalid: it is {why}; prismatic modes (n = 0) need m >= 2"
            )
    if fam is Family.TORSIONAL and (m != 0 or n < 1):
        raise ParameterError(
            f"{where} is invalid for the torsional family; torsional modes have m = 0, n >= 1"
        )
    return fam


def mode_families(modes: np.ndarray) -> np.ndarray:
    """Family codes of the rows of ``modes``: the third column, or the natural family."""
    if modes.shape[1] > 2:
        return modes[:, 2].astype(np.int64)
    return np.where(modes[:, 1] == 0, Family.PRISMATIC.code, Family.WRINKLE.code)


def row_family(row) -> Family:
    """The Family of one row (m, n) or (m, n, code) of a ``modes`` array."""
    if len(row) > 2:
        return _BY_CODE[int(row[2])]
    return natural_family(row[0], row[1])


#: the family codes, read once (mode_pairs runs at every evaluation of a march)
_PRISMATIC, _TORSIONAL = Family.PRISMATIC.code, Family.TORSIONAL.code


def mode_pairs(modes: np.ndarray) -> np.ndarray:
    """The Stroh pairs kept by each row of ``modes`` (int64 bitmasks)."""
    code = mode_families(modes)
    pairs = np.where(modes[:, 0] == 0, ALL_PAIRS & ~U_TH, ALL_PAIRS).astype(np.int64)
    pairs[code == _PRISMATIC] = ALL_PAIRS & ~U_Z
    pairs[code == _TORSIONAL] = U_TH
    return pairs


def with_family(m: int, n: int, family: str) -> np.ndarray:
    """The one-row ``modes`` array of mode (m, n) of ``family``."""
    return np.array([[m, n, Family(family).code]], dtype=float)
