"""The plot of a design (design/prescribe.py): the competing modes' critical values along
the design variable, the target's region shaded, switches and the best design marked; of a
two-variable design (design/prescribe_map.py): the map, and beside it the chosen design's
wrinkled tube in 3D."""

from __future__ import annotations

import math

import matplotlib as mpl
import numpy as np
from matplotlib.figure import Figure

from ..bifurcation.critical import critical_value
from ..outcomes import Kind
from ..shapes.mode_shape import ModeShape, mode_shape
from ..shapes.wall import wall_surface
from .labels import axis_label, symbol_text
from .plots import draw_wall
from .style import STYLE

#: heights tried for a region's label, as fractions of the way from the curve to the top
LIFTS = (0.45, 0.25, 0.7, 0.15, 0.85, 0.35, 0.6)


def plot_design(result, values: dict, xs) -> object:
    """Axes of a new figure: each mode's critical value (``values``: (m, n) -> array over
    ``xs``, from design.sequence.mode_values) labelled (m, n), the first mode's curve in
    black, the target's region shaded, the switches as dots and the best (or closest)
    design as a star."""
    seq = result.sequence
    with mpl.rc_context(STYLE):
        ax = Figure(figsize=(5.0, 3.6), layout="constrained").subplots()
    for iv in result.region:
        ax.axvspan(iv.lo, iv.hi, color="tab:green", alpha=0.15, lw=0)
    for k, (mode, v) in enumerate(values.items()):
        ok = np.isfinite(v)
        if not ok.any():
            continue
        (line,) = ax.plot(np.asarray(xs)[ok], v[ok], lw=0.9, alpha=0.8)
        i = np.flatnonzero(ok)[len(np.flatnonzero(ok)) // 2]
        ax.annotate(
            f"({mode[0]}, {mode[1]})",
            (xs[i], v[i]),
            xytext=(0, 4 if k % 2 else -10),
            textcoords="offset points",
            ha="center",
            fontsize=7,
            color=line.get_color(),
        )
    curve = seq.curve
    ok = np.isfinite(curve.value)
    ax.plot(curve.x[ok], curve.value[ok], "k-", lw=1.6, label="first mode")
    sw = [s for s in seq.switches if s.kind == "switch"]
    if sw:
        ax.plot([s.x for s in sw], [s.value for s in sw], "ko", ms=3.5, label="switch")
    if math.isfinite(result.x):
        ax.plot(
            [result.x],
            [result.value],
            "r*",
            ms=9,
            clip_on=False,
            zorder=5,
            label=f"design ({result.status})",
        )
    ax.plot([], [], color="tab:green", alpha=0.3, lw=6, label=f"target {result.target} first")
    ax.ticklabel_format(useOffset=False)
    ax.set_xlabel(axis_label(seq.key))
    ax.set_ylabel(axis_label(seq.solve_for, critical=True))
    ax.legend(fontsize=7)
    return ax


def plotted_modes(result) -> list:
    """The modes :func:`plot_design` draws: each first somewhere along the sequence, the
    design's target mode, the next one, and every mode that ties with it in setting the
    margin at the design (a kink of the margin): without these the star's margin is
    measured against a curve the figure does not show (probe 14e D4)."""
    seq = result.sequence
    modes = {iv.mode for iv in seq.intervals if iv.kind == "bifurcation"}
    modes |= {m for m in (result.mode, result.next_mode, *result.tied_with) if m is not None}
    return sorted(m for m in modes if isinstance(m, tuple))  # not "crease" nor "surface"


def _name(label) -> str:
    return f"({label[0]}, {label[1]})" if isinstance(label, tuple) else str(label)


def region_colours(count: int):
    """A colour map of ``count`` pale colours, all different up to 15 (Pastel1 and Pastel2
    without their greys; a map of patterns in (m, n) order gives neighbours different
    colours), then repeating."""
    pale = mpl.colormaps["Pastel1"].colors[:8] + mpl.colormaps["Pastel2"].colors[:7]
    return mpl.colors.ListedColormap([pale[k % len(pale)] for k in range(max(count, 2))])


def plot_map(result, *, pixels: int = 160, ax=None) -> object:
    """The mode map of a two-variable design (design/prescribe_map.py) on ``ax`` (default:
    a new figure's) with each region coloured and labelled (m, n) (the pattern of each
    pixel read off the traced boundaries, no solves), the boundaries drawn, triple points
    as dots, the target's region hatched and the best (or closest) design as a star.
    Returns the axes."""
    mmap = result.map
    (x0, x1), (y0, y1) = mmap.box
    xs, ys = np.linspace(x0, x1, pixels), np.linspace(y0, y1, pixels)
    raster = mmap.raster(xs, ys)
    patterns = mmap.patterns()
    index = {p: k for k, p in enumerate(patterns)}
    codes = np.vectorize(lambda p: index.get(p, -1), otypes=[float])(raster)
    if ax is None:
        with mpl.rc_context(STYLE):
            ax = Figure(figsize=(5.4, 4.2), layout="constrained").subplots()
    cmap = region_colours(len(patterns))
    ax.pcolormesh(xs, ys, codes.T, cmap=cmap, vmin=-0.5, vmax=len(patterns) - 0.5,
                  shading="nearest", rasterized=True)  # fmt: skip
    target = np.vectorize(lambda p: p in result.goal, otypes=[float])(raster)
    if target.any():
        ax.contourf(xs, ys, target.T, levels=[0.5, 1.5], colors="none", hatches=["////"])
    for k, p in enumerate(patterns):  # each region labelled at its pixels' centre
        sel = codes == k
        if sel.any():
            i, j = np.argwhere(sel).mean(axis=0).round().astype(int)
            if codes[i, j] != k:  # a non-convex region: one of its own pixels instead
                i, j = np.argwhere(sel)[len(np.argwhere(sel)) // 2]
            ax.annotate(_name(p), (xs[i], ys[j]), ha="center", va="center", fontsize=8)
    for b in mmap.boundaries:
        ax.plot(b.x, b.y, "k-", lw=1.1)
    if mmap.triple_points:
        ax.plot([t.x for t in mmap.triple_points], [t.y for t in mmap.triple_points], "ko",
                ms=4, label="triple point")  # fmt: skip
    if math.isfinite(result.x):
        ax.plot(
            [result.x],
            [result.y],
            "r*",
            ms=11,
            clip_on=False,
            zorder=5,
            label=f"design ({result.status})",
        )
    ax.plot([], [], "k-", lw=1.1, label="traced boundary")
    ax.fill([], [], facecolor="none", hatch="////", label=f"target {result.target} first")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.ticklabel_format(useOffset=False)
    ax.set_xlabel(axis_label(mmap.keys[0]))
    ax.set_ylabel(axis_label(mmap.keys[1]))
    ax.set_title(f"first pattern (m, n) by critical {symbol_text(mmap.solve_for)}", fontsize=9)
    ax.legend(fontsize=7, loc="best")
    return ax


def design_shape(result, tube, *, points: int = 41) -> ModeShape | None:
    """The mode shape of a two-variable design's mode at the design: ``tube`` (the map's
    tube) at (x, y), the target mode's critical value solved there again (so the picture is
    the onset of that mode, not a copy of the search's value); None without a design."""
    if result.mode is None or not math.isfinite(result.x):
        return None
    (kx, ky), mmap = result.keys, result.map
    at = tube.at(kx, result.x).at(ky, result.y)
    crit = critical_value(at, *result.mode, mmap.solve_for, side=mmap.side)
    if crit.kind != Kind.BIFURCATION:
        return None
    return mode_shape(crit, points=points)


def plot_map_pattern(result, tube, *, amplitude: float = 0.08, pixels: int = 160) -> Figure:
    """A figure of two panels: the map of :func:`plot_map` (left) and the chosen design's
    wrinkled tube in 3D, coloured by u_r (right; :func:`design_shape`, drawn as
    ``electrogrowth pattern`` draws it). Without a design the right panel says so."""
    with mpl.rc_context(STYLE):
        fig = Figure(figsize=(9.6, 4.2), layout="constrained")
        left = fig.add_subplot(1, 2, 1)
        plot_map(result, pixels=pixels, ax=left)
        right = fig.add_subplot(1, 2, 2, projection="3d")
        shape = design_shape(result, tube)
        if shape is None:
            right.set_axis_off()
            right.text2D(0.5, 0.5, "no design to draw", ha="center", transform=right.transAxes)
            return fig
        norm, cmap = draw_wall(right, wall_surface(shape, amplitude=amplitude))
        bar = fig.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=cmap), ax=right, shrink=0.6)
        bar.set_label(r"radial displacement $u_r / R_i$", fontsize=8)
        bar.ax.tick_params(labelsize=7)
        (kx, ky) = result.keys
        right.set_title(
            f"the design: mode (m, n) = ({shape.m}, {shape.n}) at {symbol_text(kx)} ="
            f" {result.x:.4g}, {symbol_text(ky)} = {result.y:.4g};\nwrinkle amplitude"
            f" {amplitude:g} $R_i$",
            fontsize=8,
        )
    return fig


def _text_box(text, renderer):
    """The box of a text or an annotation's text, without its arrow, where it is drawn."""
    from matplotlib.text import Text

    if hasattr(text, "update_positions"):
        text.update_positions(renderer)
    return Text.get_window_extent(text, renderer)


def place_labels(ax, labels, *, avoid=()) -> list:
    """Annotate ``ax`` with each label at the first of its candidate places whose box
    lies inside the axes and overlaps no label placed before it (nor the ``ax.texts``
    already there); the first candidate if none does. ``labels``: [(text, [annotate
    keyword dicts, each with ``xy`` and optionally ``xytext``/``textcoords``,
    ``rotation``, ...])]; ``avoid``: points (x, y) in data coordinates no label may cover
    (markers). The boxes are measured after a layout pass. Returns the annotations."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.transforms import Bbox

    fig = ax.figure
    if not hasattr(fig.canvas, "get_renderer"):
        FigureCanvasAgg(fig)
    fig.draw_without_rendering()
    renderer = fig.canvas.get_renderer()
    taken = [_text_box(t, renderer) for t in ax.texts]
    for x, y in avoid:  # a marker: a box of 3 points around it
        px, py = ax.transData.transform((x, y))
        r = 3 * fig.dpi / 72
        taken.append(Bbox.from_extents(px - r, py - r, px + r, py + r))
    frame = ax.get_window_extent(renderer)
    placed = []
    for text, candidates in labels:
        chosen = None
        for kw in candidates:
            ann = ax.annotate(text, **{"ha": "center", "va": "center", "fontsize": 8, **kw})
            box = _text_box(ann, renderer).expanded(1.1, 1.15)
            inside = frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0
            if inside and box.y1 <= frame.y1 and not any(box.overlaps(t) for t in taken):
                chosen = (ann, box)
                break
            ann.remove()
        if chosen is None:  # nowhere free: the first place
            ann = ax.annotate(text, **{"ha": "center", "va": "center", "fontsize": 8,
                                       **candidates[0]})  # fmt: skip
            chosen = (ann, _text_box(ann, renderer))
        taken.append(chosen[1])
        placed.append(chosen[0])
    return placed


def plot_growth_voltage(gv, *, ax=None, top: float | None = None) -> object:
    """The growth-voltage map (design/growth_voltage.py) on ``ax`` (default: a new
    figure's): the onset curve g_cr(Vbar) in black, below it the unwrinkled tube, above it
    one coloured region per first mode, labelled (m, n), bounded by the switch voltages
    (dotted, each switch a dot with its Vbar). ``top``: the growth at the top of the axes
    (default: 40 % of the curve's range above its highest point). Returns the axes."""
    if ax is None:
        with mpl.rc_context(STYLE):
            ax = Figure(figsize=(5.2, 3.8), layout="constrained").subplots()
    onset = np.array([g for r in gv.regions for g in r.growth], float)
    g0, g1 = float(np.nanmin(onset)), float(np.nanmax(onset))
    top = g1 + 0.4 * max(g1 - g0, 1e-3) if top is None else top
    bottom = g0 - 0.25 * max(g1 - g0, 1e-3)
    modes = sorted({r.mode for r in gv.regions if r.kind == Kind.BIFURCATION})
    colours = mpl.colormaps["Pastel1"].colors[:8]  # the ninth is the grey of "no wrinkle"
    narrow = 0.1 * (gv.hi - gv.lo)  # a strip narrower than this: its label stands upright
    labels = []
    for r in gv.regions:
        v, g = np.asarray(r.voltage), np.asarray(r.growth)
        ok = np.isfinite(g)
        if r.kind != Kind.BIFURCATION or not ok.any():
            continue
        ax.fill_between(v[ok], g[ok], top, color=colours[modes.index(r.mode) % 8], lw=0)
        ax.plot(v[ok], g[ok], "k-", lw=1.6)
        mid = 0.5 * (r.lo + r.hi)
        y = float(np.interp(mid, v[ok], g[ok]))
        spots = [{"xy": (mid, y + f * (top - y)), "rotation": 90 if r.hi - r.lo < narrow else 0}
                 for f in LIFTS]  # fmt: skip
        labels.append((_name(r.mode), spots))
    curve = sorted((v, g) for r in gv.regions for v, g in zip(r.voltage, r.growth, strict=True))
    v, g = np.array(curve).T
    ok = np.isfinite(g)
    ax.fill_between(v[ok], bottom, g[ok], color="0.92", lw=0)  # one piece: no seams
    groups: list[list] = []  # switches within 2 % of the range share one label
    for s in (s for s in gv.switches if s.kind == "switch"):
        ax.plot([s.x, s.x], [s.value, top], "k:", lw=0.9)
        ax.plot([s.x], [s.value], "ko", ms=3.5)
        if groups and s.x - groups[-1][-1].x < 0.02 * (gv.hi - gv.lo):
            groups[-1].append(s)
        else:
            groups.append([s])
    for group in groups:
        s = group[0]
        spots = [{"xy": (s.x, s.value), "xytext": (dx, dy), "textcoords": "offset points",
                  "fontsize": 7, "ha": "left" if dx > 0 else "right"}
                 for dy in (-10, -20, -30, -40, -50) for dx in (4, -4)]  # fmt: skip
        labels.append((r"$\bar V$ = " + ", ".join(f"{w.x:.4f}" for w in group), spots))
    ax.text(0.03, 0.04, "no wrinkle (axisymmetric)", transform=ax.transAxes, fontsize=7,
            color="0.3")  # fmt: skip
    ax.set_xlim(gv.lo, gv.hi)
    ax.set_ylim(bottom, top)
    ax.set_xlabel(axis_label("voltage"))
    ax.set_ylabel(axis_label(gv.growth))
    ax.set_title("first wrinkle (m, n) above the onset growth, by voltage", fontsize=9)
    place_labels(ax, labels, avoid=[(s.x, s.value) for s in gv.switches if s.kind == "switch"])
    return ax


#: where a branch's label may go, in points from its middle (the nearest first)
BRANCH_SPOTS = ((0, 7), (0, -9), (-16, 10), (16, -12), (-26, 18), (26, -20), (-38, 26),
                (38, -28), (-50, 34), (50, -36))  # fmt: skip


def label_branches(ax, curve, *, color: str = "k") -> list:
    """Label each branch of a critical curve (``plot_curve(..., annotate=False)``) with its
    mode (m, n) near its middle, no two labels overlapping (:func:`place_labels`); a label
    moved away from its branch points at it with a thin line. Returns the annotations."""
    labels = []
    for (m, n), rows in curve.branches():
        x, v = curve.x[rows], curve.value[rows]
        if (m, n) == (-1, -1) and not curve.surface[rows].all():
            continue  # the threshold: the dashed line, not a mode
        order = np.argsort(x, kind="stable")  # the middle of the branch along x
        xm = 0.5 * (x.min() + x.max())
        vm = float(np.interp(xm, x[order], v[order]))
        text = "m, n → ∞" if curve.surface[rows].all() else f"({m}, {n})"
        spots = [
            {"xy": (xm, vm), "xytext": d, "textcoords": "offset points", "fontsize": 7,
             "color": color,
             **({"arrowprops": {"arrowstyle": "-", "lw": 0.5, "color": color}}
                if abs(d[0]) > 0 else {})}
            for d in BRANCH_SPOTS
        ]  # fmt: skip
        labels.append((text, spots))
    marks = [(s.x, s.value) for s in curve.switches + curve.ends]
    return place_labels(ax, labels, avoid=[p for p in marks if math.isfinite(p[1])])
