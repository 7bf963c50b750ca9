"""The options of a mode scan (:class:`ScanOptions`) and the caps they are checked against.

Apart from the scan (scan.py) so that a :class:`~.problem.Problem` can hold them without
importing the scan.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..errors import ParameterError
from ..incremental.modes import MODE_MAX

#: The largest m and n of a scan: those of a mode (incremental.modes.MODE_MAX, set by
#: the kernel's step budget); shorter waves tend to the exact short-wave limit.
M_CAP = N_CAP = MODE_MAX
#: Every m is scanned up to EVERY_M (the modes of small m are irregular); beyond it the
#: best m of an edge optimum's family row is searched coarse-to-fine (msearch.py).
EVERY_M = 64
TOP_MAX = 1000  # modes a scan reports: the critical one and runners-up


def _check_range(name, rng, lowest, highest):
    lo, hi = rng
    whole = all(isinstance(x, (int, float, np.number)) and np.isfinite(x) for x in rng)
    if not whole or int(lo) != lo or int(hi) != hi or lo < lowest or hi < lo or hi > highest:
        raise ParameterError(
            f"{name} range {list(rng)} is invalid; need integers "
            f"{lowest} <= {name}_min <= {name}_max <= {highest} (shorter waves tend to the"
            " exact short-wave limit, which every scan computes)"
        )


@dataclasses.dataclass(frozen=True)
class ScanOptions:
    """Which modes a scan examines and how much it reports: the defaults, written once.

    Parameters
    ----------
    m_range, n_range : (int, int)
        Inclusive starting ranges of the circumferential wavenumber m >= 0 and the axial
        half-wavenumber n >= 1 (up to M_CAP, N_CAP = 2000; m beyond EVERY_M = 64 is
        searched coarse-to-fine, not mode by mode).
    top : int
        Modes reported: the critical one and ``top - 1`` runners-up (top >= 1).
    extend : bool
        Probe short waves beyond the ranges and widen a range while the optimum sits on
        its upper edge (mode by mode at most DOUBLINGS times, m up to EVERY_M, n up to
        N_CAP; then m by the coarse-to-fine search up to M_CAP).
    surface : bool
        Compare with the exact short-wave limit (m, k -> infinity) at both faces, which is
        the result when it comes first (see the module docstring).
    prismatic : bool
        Also scan the prismatic modes (m, 0), k = 0, for max(2, m_min) <= m <= m_max:
        plane-strain wrinkles, admissible with sliding ends (the long-tube limit of n = 1).
    torsional : bool
        Also scan the torsional modes (0, n), u_th = U(r) cos kz, for n in n_range (when
        m_min = 0).
    """

    m_range: tuple[int, int] = (0, 12)
    n_range: tuple[int, int] = (1, 30)
    top: int = 5
    extend: bool = True
    surface: bool = True
    prismatic: bool = True
    torsional: bool = True

    def __post_init__(self):
        for name, lowest, highest in (("m", 0, M_CAP), ("n", 1, N_CAP)):
            rng = getattr(self, f"{name}_range")
            _check_range(name, rng, lowest, highest)
            object.__setattr__(self, f"{name}_range", (int(rng[0]), int(rng[1])))
        top = self.top
        if isinstance(top, bool) or int(top) != top or not 1 <= top <= TOP_MAX:
            raise ParameterError(
                f"top = {top!r} is invalid; need an integer from 1 to {TOP_MAX}"
                " (the modes a scan reports)"
            )
        object.__setattr__(self, "top", int(self.top))
        for name in ("extend", "surface", "prismatic", "torsional"):
            if not isinstance(getattr(self, name), bool):
                raise ParameterError(
                    f"{name} = {getattr(self, name)!r} is invalid; need True or False"
                )

    def with_maxima(self, m_max: int, n_max: int) -> ScanOptions:
        """These options with the ranges 0..m_max and 1..n_max (the CLI's --m-max, --n-max)."""
        return dataclasses.replace(self, m_range=(0, m_max), n_range=(1, n_max))
