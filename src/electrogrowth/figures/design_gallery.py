"""The gallery of designed tubes (docs/design.md): a gut-like bilayer designed for
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

from ..atomic import write_text
from ..bifurcation.options import ScanOptions
from ..continuation.contour import MAX_POINTS
from ..design.map_record import ModeMap
from ..design.mode_map import mode_map
from ..design.prescribe_map import MapDesign, prescribe_map, stored_design
from ..design.targets import Target
from ..model.layers import Layer, Tube
from .design import plot_map

CONTROL = "growth[1].theta"
FOLDS = (8, 12, 16)
#: the full map: the interface radius 1 + h from 1.065 to 1.14 (the outer radius kept at
#: 2), mu_1/mu_2 from 5 to 30, every m from 0 to 18 with n = 0 (prismatic) and n = 1 (and
#: the torsional (0, 1)). Complete for this box: full scans (m from 0 to 24 and beyond,
#: n to 30, short waves, the short-wave limit) at 81 designs and on the boundaries find
#: only these first (tools/gut_window_check.py, docs/design.md); (0, 1) .. (3, 1) are first
#: in the thick, stiff corner, so the window starts at m = 0
FULL_BOX = (("layers[1].outer_radius", 1.065, 1.14), ("layers[1].shear_modulus", 5.0, 30.0))
FULL_OPTIONS = ScanOptions((0, 18), (1, 1), top=3, extend=False, surface=False)
#: grid nodes a variable, points certified a boundary (all: a curve has fewer), max step
FULL_POINTS, FULL_CERTIFY, FULL_STEP = 5, MAX_POINTS, 0.5
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
        steps = {} if quick else {"max_step": FULL_STEP}
        mmap = mode_map(
            tube, CONTROL, box, options=options, points=2 if quick else FULL_POINTS,
            certify=1 if quick else FULL_CERTIFY, progress=progress, **steps,
        )  # fmt: skip
    designs = {
        m: prescribe_map(tube, folds(m), mmap, options=options)
        for m in ((12,) if quick else FOLDS)
    }
    return FoldDesigns(mmap, designs, draw_folds(designs))


def draw_folds(designs: dict) -> object:
    """The map of the design for 12 folds (hatched, red star), the other designs found as
    blue stars."""
    ax = plot_map(designs[12] if 12 in designs else next(iter(designs.values())))
    mark_designs(ax, designs)
    return ax


def mark_designs(ax, designs: dict) -> None:
    """The designs other than the one for 12 folds (the map's own red star) as blue stars
    labelled with their fold number (open stars: the closest design of a target never
    first)."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    for m, d in designs.items():
        if m != 12 and d.status in ("found", "not_first"):
            face = "tab:blue" if d.status == "found" else "none"
            ax.plot([d.x], [d.y], "*", mfc=face, mec="tab:blue", ms=10, clip_on=False)
            word = "" if d.status == "found" else " (closest)"
            # the text towards the box's inside, clear of the title; along the bottom edge
            # (past the crowded labels of the thin, soft corner) for a design on it
            dx = 16 if d.x < 0.5 * (x0 + x1) else -16
            dy = 18 if d.y < 0.5 * (y0 + y1) else -18
            if d.y - y0 < 0.02 * (y1 - y0):
                dx, dy = 3.5 * dx, 4
            ax.annotate(
                f"{m} folds{word}", (d.x, d.y), xytext=(dx, dy), textcoords="offset points",
                fontsize=7, color="tab:blue", ha="left" if dx > 0 else "right",
                va="bottom" if dy > 0 else "top",
                arrowprops={"arrowstyle": "-", "lw": 0.6, "color": "tab:blue"},
            )  # fmt: skip
    ax.set_title("gut-like bilayer: first folds (m, n) by critical hoop growth", fontsize=8)


def write_fold_designs(path, *, progress=None, workers: int = 1, map_path=None) -> FoldDesigns:
    """Trace the full map, design it for 8, 12 and 16 folds and write both as JSON to
    ``path`` (the map's :meth:`~ModeMap.as_dict`, each design's ``as_dict`` by fold
    number, the seconds each took): the input of the gallery's page, which cannot afford
    the tracing (tools/gut_fold_designs.py). ``workers`` processes trace and design;
    ``map_path``: where the map alone is written as soon as it is traced."""
    import json
    import time

    start = time.perf_counter()
    tube = gut_bilayer(FULL_BOX[0][1] - 1.0, FULL_BOX[1][1])
    mmap = mode_map(
        tube, CONTROL, FULL_BOX, options=FULL_OPTIONS, points=FULL_POINTS,
        certify=FULL_CERTIFY, max_step=FULL_STEP, progress=progress, workers=workers,
    )  # fmt: skip
    if map_path is not None:
        write_text(map_path, json.dumps(mmap.as_dict(), indent=1) + "\n")
    return design_and_write(path, mmap, time.perf_counter() - start, progress, workers)


def _design(task) -> tuple[dict, float]:
    """One fold number's design in the map (a pool's task: m, the map): its record and
    the seconds it took."""
    import time

    m, mmap = task
    start = time.perf_counter()
    tube = gut_bilayer(FULL_BOX[0][1] - 1.0, FULL_BOX[1][1])
    design = prescribe_map(tube, folds(m), mmap, options=FULL_OPTIONS)
    return design.as_dict(), time.perf_counter() - start


def design_and_write(
    path, mmap: ModeMap, map_seconds: float, progress=None, workers: int = 1
) -> FoldDesigns:
    """Design the traced full map ``mmap`` for 8, 12 and 16 folds (``workers`` at once)
    and write map and designs to ``path`` (:func:`write_fold_designs`)."""
    import json

    from ..pool import run_tasks

    designs, seconds = {}, {"map": map_seconds}
    for k, (record, took) in run_tasks(
        _design, [(m, mmap) for m in FOLDS], workers=workers, name="design"
    ):
        m = FOLDS[k]
        if progress is not None:
            progress(f"designed for {m} folds in {took / 60:.0f} min")
        designs[m] = stored_design(record, mmap, folds(m))
        seconds[f"{m} folds"] = took
    designs = {m: designs[m] for m in FOLDS}
    record = {
        "tube": "gut_bilayer (figures/design_gallery.py)",
        "control": CONTROL,
        "map": mmap.as_dict(),
        "designs": {str(m): d.as_dict() for m, d in designs.items()},
        "seconds": seconds,
    }
    write_text(path, json.dumps(record, indent=1) + "\n")
    return FoldDesigns(mmap, designs, draw_folds(designs))


def read_fold_designs(path) -> tuple[FoldDesigns, dict]:
    """The map and designs written by :func:`write_fold_designs` (no solves), and the
    seconds each took."""
    import json
    from pathlib import Path

    record = json.loads(Path(path).read_text(encoding="utf-8"))
    mmap = ModeMap.from_dict(record["map"])
    designs = {int(m): stored_design(d, mmap, folds(int(m))) for m, d in record["designs"].items()}
    return FoldDesigns(mmap, designs, draw_folds(designs)), record["seconds"]
