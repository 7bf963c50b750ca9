"""The plot of a design (design/prescribe.py): the competing modes' critical values along
the design variable, the target's region shaded, switches and the best design marked."""

from __future__ import annotations

import math

import matplotlib as mpl
import numpy as np
from matplotlib.figure import Figure

from .labels import axis_label
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


def plot_map(result, *, pixels: int = 160) -> object:
    """Axes of a new figure: the mode map of a two-variable design (design/prescribe_map.py)
    with each region coloured and labelled (m, n) (the pattern of each pixel read off the
    traced boundaries, no solves), the boundaries drawn, triple points as dots, the
    target's region hatched and the best (or closest) design as a star."""
    mmap = result.map
    (x0, x1), (y0, y1) = mmap.box
    xs, ys = np.linspace(x0, x1, pixels), np.linspace(y0, y1, pixels)
    raster = mmap.raster(xs, ys)
    patterns = mmap.patterns()
    index = {p: k for k, p in enumerate(patterns)}
    codes = np.vectorize(lambda p: index.get(p, -1), otypes=[float])(raster)
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
    ax.set_title(f"first pattern (m, n) by critical {mmap.solve_for}", fontsize=9)
    ax.legend(fontsize=7, loc="best")
    return ax
