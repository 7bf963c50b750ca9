"""The options of a mode scan (:class:`ScanOptions`) and the caps they are checked against.

Apart from the scan (scan.py) so that a :class:`~.problem.Problem` can hold them without
importing the scan.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import ParameterError
from ..incremental.modes import MODE_MAX

#: The smallest caps of a scan's searches in m and n, whatever its tube (:func:`mode_caps`
#: raises them for a thin layer): m = 2000 brackets a film's folds down to h ~ 1e-3 R
#: (docs/derivation-film.md), and every uniform or thick-layered tube keeps its scans.
M_CAP = N_CAP = 2000
#: The largest k h of a layer's first fold that a scan searches for: a stiff film folds at
#: k h < 1.4 (the flat film, docs/derivation-film.md), a soft lining 1e-3 thick, 1e4 times
#: softer than its tube, at k h = m h / R ~ 6 to 13 (check round 34: (6000, 0), (13000, 0)),
#: where its substrate's pull, ~exp(-2 k h), balances the O(1 / m) curvature terms by
#: which its face's limit is reached from below, so k h grows only like ln m. Five times
#: the largest seen: the samples past it cost one state each (msearch's geometric ones).
FOLD_KH = 64
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
            f"{lowest} <= {name}_min <= {name}_max <= {highest} (the kernel resolves no"
            " shorter waves, which tend to the exact short-wave limit every scan computes)"
        )


@dataclasses.dataclass(frozen=True)
class ScanOptions:
    """Which modes a scan examines and how much it reports: the defaults, written once.

    Parameters
    ----------
    m_range, n_range : (int, int)
        Inclusive starting ranges of the circumferential wavenumber m >= 0 and the axial
        half-wavenumber n >= 1 (up to MODE_MAX = 1e6, what the kernel resolves; m beyond
        EVERY_M = 64 is searched coarse-to-fine, not mode by mode).
    top : int
        Modes reported: the critical one and ``top - 1`` runners-up (top >= 1).
    extend : bool
        Probe short waves beyond the ranges and widen a range while the optimum sits on
        its upper edge (mode by mode at most DOUBLINGS times, m up to EVERY_M, n up to
        the n cap; then m by the coarse-to-fine search up to the m cap: the tube's
        :func:`mode_caps`, at least M_CAP = N_CAP = 2000).
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
        for name, lowest, highest in (("m", 0, MODE_MAX), ("n", 1, MODE_MAX)):
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


def mode_caps(tube) -> tuple[int, int]:
    """The largest m and n the searches of a scan of ``tube`` reach (at least M_CAP, N_CAP,
    at most MODE_MAX): those of a fold with k h = FOLD_KH in its thinnest layer, m = FOLD_KH
    R / h (R its outer radius) and n = FOLD_KH L / (pi h), in the reference configuration.
    A uniform tube keeps M_CAP, N_CAP: it has no layer thin against its wall, and its short
    waves tend to its faces' limits, which the scan computes.

    >>> from electrogrowth import Layer, Tube
    >>> mode_caps(Tube((Layer(1.001, shear_modulus=1e-4), Layer(2.0)), length=3.0))
    (64064, 61115)
    """
    if tube.is_uniform:
        return M_CAP, N_CAP
    radii = tube.radii
    m = max(FOLD_KH * b / (b - a) for a, b in zip(radii, radii[1:]))
    n = max(FOLD_KH * tube.length / (math.pi * (b - a)) for a, b in zip(radii, radii[1:]))
    return (
        min(max(M_CAP, round(m)), MODE_MAX),
        min(max(N_CAP, round(n)), MODE_MAX),
    )
