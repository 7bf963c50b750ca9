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
        ax.plot([result.x], [result.value], "r*", ms=9, label=f"design ({result.status})")
    ax.plot([], [], color="tab:green", alpha=0.3, lw=6, label=f"target {result.target} first")
    ax.ticklabel_format(useOffset=False)
    ax.set_xlabel(axis_label(seq.key))
    ax.set_ylabel(axis_label(seq.solve_for, critical=True))
    ax.legend(fontsize=7)
    return ax
