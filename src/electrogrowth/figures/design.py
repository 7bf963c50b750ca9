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


def _name(label) -> str:
    return f"({label[0]}, {label[1]})" if isinstance(label, tuple) else str(label)


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
    cmap = mpl.colormaps["Pastel1"].resampled(max(len(patterns), 2))
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
