"""The gallery of designed tubes (docs/design-gallery.md): a gut-like bilayer designed for
8, 12 and 16 folds over the thickness and the modulus ratio of its growing inner layer.

The tube is the mucosal bilayer of the patterns gallery (figures/gallery.py ``bilayer``):
a stiff inner layer R = 1 .. 1 + h of shear modulus mu_1 grows in the hoop direction inside
an ungrown neo-Hookean substrate 1 + h .. 2 (mu_2 = 1), lambda_z = 1, L = 1. The map over
(h, mu_1/mu_2) is a :func:`~electrogrowth.design.mode_map` (boundaries traced, certified),
and each design the widest-margin one of :func:`~electrogrowth.design.prescribe_map` for the
target "m folds" (any (m, n) with that m).
"""

from __future__ import annotations

import dataclasses

from ..bifurcation.options import ScanOptions
from ..design.map_record import ModeMap
from ..design.mode_map import mode_map
from ..design.prescribe_map import MapDesign, prescribe_map
from ..design.targets import Target
from ..model.layers import Layer, Tube
from .design import plot_map

CONTROL = "growth[1].theta"
FOLDS = (8, 12, 16)
#: the full map: the interface radius 1 + h from 1.05 to 1.13 (the outer radius kept at 2),
#: mu_1/mu_2 from 5 to 20, every m from 6 to 18
FULL_BOX = (("layers[1].outer_radius", 1.05, 1.13), ("layers[1].shear_modulus", 5.0, 20.0))
FULL_OPTIONS = ScanOptions((6, 18), (1, 1), top=3)
#: the quick map (tests): a small box across the 12 | 11 boundary near h = 0.1, mu = 10
QUICK_BOX = (("layers[1].outer_radius", 1.09, 1.096), ("layers[1].shear_modulus", 9.5, 10.5))
QUICK_OPTIONS = ScanOptions((11, 12), (1, 1), top=2, extend=False, surface=False)


def gut_bilayer(h: float = 0.1, mu: float = 10.0) -> Tube:
    """The gut-like bilayer (module docstring)."""
    return Tube((Layer(1.0 + h, shear_modulus=mu), Layer(2.0)))


def folds(m: int) -> Target:
    """The target "m folds": every mode (m, n)."""
    return Target(f"{m} folds", lambda mm, n, m=m: mm == m)


@dataclasses.dataclass(frozen=True)
class FoldDesigns:
    """The map, the design for each fold number, and the figure's axes."""

    map: ModeMap
    designs: dict[int, MapDesign]
    ax: object


def designed_folds(
    *, quick: bool = False, progress=None, mmap: ModeMap | None = None
) -> FoldDesigns:
    """The gut-like bilayer's map over (h, mu_1/mu_2) and its designs for 8, 12 and 16 folds
    (quick: a small box near h = 0.1, mu = 10, designed for 12 folds). ``mmap``: a map
    already computed (the full one takes ~1 h on a busy two-core machine)."""
    box, options = (QUICK_BOX, QUICK_OPTIONS) if quick else (FULL_BOX, FULL_OPTIONS)
    tube = gut_bilayer(box[0][1] - 1.0, box[1][1])
    if mmap is None:
        mmap = mode_map(
            tube, CONTROL, box, options=options, points=2 if quick else 4,
            certify=1 if quick else 2, progress=progress,
        )  # fmt: skip
    designs = {
        m: prescribe_map(tube, folds(m), mmap, options=options)
        for m in ((12,) if quick else FOLDS)
    }
    first = designs[12]
    ax = plot_map(first)
    for m, d in designs.items():
        if m != 12 and d.status == "found":
            ax.plot([d.x], [d.y], "*", color="tab:blue", ms=10)
            ax.annotate(f"{m} folds", (d.x, d.y), xytext=(4, 4), textcoords="offset points",
                        fontsize=7, color="tab:blue")  # fmt: skip
    ax.set_title("gut-like bilayer: first folds (m, n) by critical hoop growth", fontsize=8)
    return FoldDesigns(mmap, designs, ax)
