"""The post-buckled branch drawn: the control against the fold amplitude, and a strip of
the folding cross-section along the branch (the whole ring, layers shaded)."""

from __future__ import annotations

import numpy as np
from matplotlib.collections import PolyCollection

from ..postbuckle.shape import whole
from .labels import axis_label
from .style import new_figure, wrapped_title

#: the shade of each layer, innermost first (repeated beyond)
LAYER_COLOURS = ("#c0504d", "#9bbbd9", "#e3c97a", "#8fbf8f")


def plot_branch(result):
    """The control against the amplitude (units R_i), the onsets marked; a Figure."""
    fig, axes = new_figure(4.2, 3.2, 1, 1)
    ax = axes[0, 0]
    ax.plot(result.amplitude, result.control, "-", lw=1.2, color="k", label="FE branch")
    unstable = result.eigenvalue < 0
    ax.plot(result.amplitude[~unstable], result.control[~unstable], "o", ms=3, color="k")
    if unstable.any():
        ax.plot(
            result.amplitude[unstable],
            result.control[unstable],
            "o",
            ms=4,
            mfc="w",
            color="C3",
            label="unstable (lowest eigenvalue < 0)",
        )
    ax.axhline(result.onset_linear, color="C0", ls="--", lw=1, label="linear onset")
    a = np.linspace(0, result.amplitude.max(), 50)
    ax.plot(
        a,
        result.onset_fe + result.curvature * a**2,
        color="C1",
        lw=1,
        ls=":",
        label="onset + curvature a$^2$",
    )
    wave = "cos m$\\theta$" if result.n == 0 else "cos kz"
    ax.set_xlabel(f"fold amplitude a / $R_i$ ({result.face} face, {wave})", fontsize=8)
    ax.set_ylabel(axis_label(result.solve_for), fontsize=8)
    ax.legend(fontsize=7, frameon=False)
    wrapped_title(ax, f"post-buckled branch of mode (m, n) = ({result.m}, {result.n})")
    return fig


def plot_folding(result, count: int = 5):
    """A strip of ``count`` shapes along the branch (first to last point), each the whole
    ring (a prismatic mode) or the whole longitudinal section (an axisymmetric mode) in its
    current shape; a Figure."""
    picks = np.unique(np.linspace(0, len(result.states) - 1, count).round().astype(int))
    fig, axes = new_figure(1.9 * len(picks), 2.3, 1, len(picks))
    section = result.section
    extent = top = 0.0
    for ax, k in zip(axes[0], picks):
        section.set_tube(result.tube.at(result.solve_for, result.control[k]))
        pts, cells, layer = whole(section, result.states[k])
        polys = pts.T[cells]
        colours = [LAYER_COLOURS[i % len(LAYER_COLOURS)] for i in layer]
        ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors="none"))
        extent = max(extent, np.abs(pts).max())
        top = max(top, pts[1].max())
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(
            f"a = {result.amplitude[k]:.3g}\n{result.solve_for} = {result.control[k]:.5g}",
            fontsize=7,
        )
    for ax in axes[0]:
        ax.set_xlim(-1.05 * extent, 1.05 * extent)
        if result.n == 0:
            ax.set_ylim(-1.05 * extent, 1.05 * extent)
        else:  # the longitudinal section, z from 0 to the current length
            ax.set_ylim(-0.02 * top, 1.02 * top)
    what = "folding" if result.n == 0 else "wrinkling"
    fig.suptitle(f"{what} of mode (m, n) = ({result.m}, {result.n}), current shapes", fontsize=8)
    return fig
