"""Plots of computed results: a critical curve, a mode shape, the 3D wrinkled tube.

The compute stages (bifurcation/, shapes/) return data; everything that draws lives in
figures/. Each function returns an off-screen matplotlib figure (or axes).
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib as mpl
import numpy as np
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d import proj3d
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from .._types import FloatArray
from ..atomic import write_figure
from ..bifurcation.curves import Curve
from ..outcomes import NO_MODE, Status
from ..shapes.mode_shape import ModeShape
from ..shapes.wall import Surface, wall_surface
from ..summary import tube_text
from .labels import axis_label
from .style import COLORS, STYLE, wrap


def plot_curve(
    curve: Curve, ax=None, *, color: str = "k", label: str | None = None, annotate: bool = True
):
    """Draw the curve on ``ax`` (a new figure when None) and return ``ax``.

    Each branch is labelled with its critical mode "(m, n)" (m circumferential, n axial;
    "m, n → ∞" for the short-wave limit, a surface instability) at its middle; a branch of
    one point is a marker. Switches (two modes equally critical) are filled dots, the ends
    of branches (a jump of the critical value, or no wrinkling beyond) open circles, the
    threshold where the axisymmetric state is lost a dashed line. Without ``ax`` the new
    axes get the legend of these marks (:func:`curve_legend`).
    """
    new = ax is None
    if new:
        with mpl.rc_context(STYLE):
            ax = Figure(figsize=(4.4, 3.3), layout="constrained").subplots()
    first, labels = True, []
    for (m, n), rows in curve.branches():
        x, v = curve.x[rows], curve.value[rows]
        if (m, n) == NO_MODE and not curve.surface[rows].all():  # the threshold
            ax.plot(x, v, "--", color=color, lw=0.9, marker="." if len(rows) == 1 else "")
            continue
        ax.plot(
            x,
            v,
            "-" if len(rows) > 1 else "s",
            color=color,
            ms=3.5,
            label=label if first else None,
        )
        first = False
        if annotate:
            i = len(rows) // 2
            xm, vm = (x[i], v[i]) if len(rows) > 2 else (x.mean(), v.mean())
            text = "m, n → ∞" if curve.surface[rows].all() else f"({m}, {n})"
            labels.append((text, xm, vm))
    _marks(ax, curve, color)
    _label_branches(ax, labels, color)
    ax.ticklabel_format(useOffset=False)
    ax.set_xlabel(axis_label(curve.along))
    ax.set_ylabel(axis_label(curve.solve_for, critical=True))
    if new:
        curve_legend(ax)
    return ax


#: a branch label's offset from its line, in points: above (to its baseline), below
ABOVE, BELOW = 4, -10


def _label_branches(ax, labels, color: str) -> None:
    """Each branch's label (text, x, value) at its middle, alternately below and above the
    line (neighbouring labels apart); one that would cross the axes' frame goes to the
    other side. Fig. 7's "m, n → ∞" at the lowest point of its curve sat on the x-axis
    line. The frame is the laid-out one (a layout pass without rendering)."""
    notes = [
        ax.annotate(
            text,
            (x, v),
            xytext=(0, ABOVE if k % 2 else BELOW),
            textcoords="offset points",
            ha="center",
            fontsize=7,
            color=color,
        )
        for k, (text, x, v) in enumerate(labels)
    ]
    if not notes:
        return
    ax.figure.draw_without_rendering()
    frame = ax.get_window_extent()
    for note in notes:
        box = note.get_window_extent()
        if box.y0 < frame.y0:
            note.xyann = (0, ABOVE)
        elif box.y1 > frame.y1:
            note.xyann = (0, BELOW)


def _marks(ax, curve: Curve, color: str) -> None:
    """Dots at the switches, open circles at the ends of branches: the located ends and the
    last point before (first after) a failed grid point."""
    taken = {h.get_label() for h in ax.get_lines()}
    if curve.switches:
        ax.plot(
            [s.x for s in curve.switches] * 2,
            [s.value for s in curve.switches] + [s.value_after for s in curve.switches],
            "o",
            color=color,
            ms=3,
            label=None if "switch" in taken else "switch",
        )
    xs, vs = [], []
    for s in curve.ends:
        for mode, v in ((s.mode_before, s.value), (s.mode_after, s.value_after)):
            if mode != NO_MODE or math.isfinite(v):
                xs.append(s.x)
                vs.append(v)
    failed = curve.kind == Status.FAILED
    for _, rows in curve.branches():
        for i in (rows[0] - 1, rows[-1] + 1):
            if 0 <= i < len(curve.x) and failed[i]:
                j = rows[0] if i < rows[0] else rows[-1]
                xs.append(curve.x[j])
                vs.append(curve.value[j])
    if xs:
        ax.plot(
            xs,
            vs,
            "o",
            mfc="white",
            mec=color,
            ms=4,
            zorder=3,
            label=None if "branch ends" in taken else "branch ends",
        )


def curve_legend(ax, **kwargs):
    """The legend of a curve plot, titled with what the branch labels are."""
    kwargs.setdefault("fontsize", 7)
    kwargs.setdefault("title_fontsize", 7)
    handles, labels = ax.get_legend_handles_labels()
    return ax.legend(handles, labels, title="branch label: critical mode (m, n)", **kwargs)


#: the symbols of a tube's numbers in figure titles (mathtext)
TEX_SYMBOLS = {
    "outer_radius": r"\bar R_o",
    "length": "L",
    "growth": "g",
    "stretch": r"\lambda_z",
    "voltage": r"\bar V",
    "layer_outer_radii": "R_k",
    "axial_force": "N",
    "inner_pressure": "P_i",
    "outer_pressure": "P_o",
}


def describe(shape: ModeShape) -> str:
    """One line: mode and tube, for titles and captions."""
    return rf"$(m, n) = ({shape.m}, {shape.n})$, " + tube_text(shape.params, TEX_SYMBOLS, tex=True)


def plot_mode_shape(shape: ModeShape):
    """U_r, U_th, U_z (left) and Phi (right) against the current radius r.

    Returns
    -------
    matplotlib.figure.Figure
        Off-screen (Agg) figure; save it with ``fig.savefig(path)``.
    """
    with mpl.rc_context(STYLE):
        fig = Figure(figsize=(7.0, 2.9), layout="constrained")
        left, right = fig.subplots(1, 2)
        for color, name, label in zip(
            COLORS[1:], ("U_r", "U_th", "U_z"), (r"$U_r$", r"$U_\theta$", r"$U_z$")
        ):
            left.plot(shape.r, getattr(shape, name), color=color, label=label)
        right.plot(shape.r, shape.Phi, color=COLORS[0], label=r"$\Phi$")
        if not shape.Phi.any():
            right.text(
                0.5,
                0.6,
                r"$\Phi \equiv 0$: no voltage, the potential decouples",
                transform=right.transAxes,
                ha="center",
                fontsize=8,
            )
        left.set_ylabel("displacement amplitude (max $|U| = 1$)")
        right.set_ylabel(r"potential amplitude $\Phi$")
        interfaces = getattr(shape.params, "radii", (1.0, 1.0))[1:-1]  # a layered Tube's
        for ax in (left, right):
            for R_k in interfaces:  # where the layers meet: U continuous, U' jumps
                ax.axvline(np.interp(R_k, shape.R, shape.r), color="0.6", lw=0.6, ls="--")
            ax.axhline(0.0, color="0.6", lw=0.5)
            ax.set_xlim(shape.r[0], shape.r[-1])
            ax.set_xlabel(r"current radius $r / R_i$")
            ax.tick_params(direction="in", top=True, right=True, labelsize=8)
            ax.legend(loc="best", fontsize=8)
        route = f"{shape.route} method" + (" (the impedance method failed)" if shape.note else "")
        fig.suptitle(wrap(f"mode shape, {describe(shape)}; {route}", 6.8, 8), fontsize=8)
    return fig


def _cells(surf: Surface, rgb: FloatArray) -> Poly3DCollection:
    """The grid cells of the surface as one collection of quadrilaterals, cell (i, j)
    coloured by its first corner: what ``plot_surface(facecolors=rgb, rstride=1,
    cstride=1)`` draws, built with arrays (plot_surface converts each of the ~27,000 face
    colours one by one: 1 s of the 2 s of a pattern)."""
    P = np.stack([surf.x, surf.y, surf.z], axis=-1)
    verts = np.stack([P[:-1, :-1], P[:-1, 1:], P[1:, 1:], P[1:, :-1]], axis=2)  # its order
    return Poly3DCollection(
        verts.reshape(-1, 4, 3),
        facecolors=rgb[:-1, :-1].reshape(-1, 4),
        linewidths=0,
        antialiased=False,
    )


def render_pattern(
    shape: ModeShape,
    *,
    amplitude: float = 0.1,
    path: str | Path | None = None,
    n_theta: int | None = None,
    n_z: int | None = None,
    dpi: int = 200,
):
    """A 3D picture of the wrinkled tube, coloured by the radial displacement u_r.

    The closed wall (outer face, top rim, inner face seen through the opening) is drawn as
    one shaded matplotlib mplot3d surface with equal axes, like the paper's Figs. 9B, 10B.

    Parameters
    ----------
    shape : ModeShape
    amplitude : float
        Largest displacement (units R_i; default 0.1).
    path : str or Path, optional
        Write a PNG there (parent directories created).
    n_theta, n_z : int, optional
        Grid resolution (see :func:`deformed_surface`).
    dpi : int
        Resolution of the PNG.

    Returns
    -------
    matplotlib.figure.Figure
    """
    surf = wall_surface(shape, amplitude=amplitude, n_theta=n_theta, n_z=n_z)
    side = 4.7  # inches: the square 3D axes
    title = (
        wrap(describe(shape), side / 0.84 - 0.2, 8) + f"\nwrinkle amplitude {amplitude:g} $R_i$"
    )
    top = 0.15 + 0.2 * (title.count("\n") + 1)  # inches of room for the title
    with mpl.rc_context(STYLE):
        fig = Figure(figsize=(side / 0.84, side))
        ax = fig.add_axes((0.0, 0.0, 0.84, 1.0), projection="3d")
        norm, cmap = draw_wall(ax, surf)
        _fit(fig, ax, surf, side, top)
        H = fig.get_size_inches()[1]
        cax = fig.add_axes((0.86, 0.5 * (1 - top / H) - 0.3, 0.025, 0.6))
        bar = fig.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=cmap), cax=cax)
        bar.set_label(r"radial displacement $u_r / R_i$", fontsize=8)
        bar.ax.tick_params(labelsize=7)
        fig.suptitle(
            title,
            fontsize=8,
            y=1.0 - 0.08 / H,
            va="top",
        )
    if path is not None:
        write_figure(fig, path, dpi=dpi)
    return fig


def draw_wall(ax, surf: Surface, *, elev: float = 28.0, azim: float = -60.0):
    """Draw the closed wall ``surf`` (shapes.wall.wall_surface) on the 3D axes ``ax``,
    shaded and coloured by u_r, with equal axes; return (norm, cmap) for a colour bar."""
    peak = float(np.abs(surf.u_r).max()) or 1.0
    norm, cmap = Normalize(-peak, peak), mpl.colormaps["RdBu_r"]
    half = 1.02 * float(max(np.abs(surf.x).max(), np.abs(surf.y).max()))
    rgb = cmap(norm(surf.u_r))
    rgb[..., :3] *= _lighting(surf, elev, azim)[..., None]
    ax.add_collection3d(_cells(surf, rgb))
    ax.set(xlim=(-half, half), ylim=(-half, half), zlim=(float(surf.z.min()), float(surf.z.max())))
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    ax.set_box_aspect((2 * half, 2 * half, float(np.ptp(surf.z))))
    return norm, cmap


def _fit(fig, ax, surf: Surface, side: float, top: float) -> None:
    """Zoom the (always square) 3D axes of ``side`` inches until the projected surface
    fills 95 % of its width or height, and crop the figure to the picture plus ``top``
    inches for the title: the axes may then reach beyond the figure's edges."""
    x, y, _ = proj3d.proj_transform(surf.x.ravel(), surf.y.ravel(), surf.z.ravel(), ax.get_proj())
    xy = ax.transAxes.inverted().transform(ax.transData.transform(np.column_stack([x, y])))
    lo, hi = xy.min(axis=0), xy.max(axis=0)  # axes fractions; zoom scales about 0.5
    zoom = 0.95 / float(max(hi - lo))
    ax.set_box_aspect(None if ax.get_box_aspect() is None else ax.get_box_aspect(), zoom=zoom)
    centre = 0.5 + zoom * (0.5 * (lo + hi) - 0.5)
    picture = side * zoom * (hi[1] - lo[1]) / 0.95  # inches, with a 2.5 % margin each side
    width, height = side / 0.84, picture + top
    fig.set_size_inches(width, height)
    left = side * (0.5 - centre[0])
    bottom = 0.5 * picture - side * centre[1]
    ax.set_position((left / width, bottom / height, side / width, side / height))


def _lighting(surf: Surface, elev: float, azim: float) -> FloatArray:
    """Soft Lambert shading: ambient + diffuse from a light above and to the left of the
    viewer, with the outward normals of the closed wall (d/dth x d/ds)."""
    P = np.stack([surf.x, surf.y, surf.z], axis=-1)
    n = np.cross(np.gradient(P, axis=0), np.gradient(P, axis=1))
    n /= np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-300)
    e, a = np.radians(elev + 25.0), np.radians(azim - 35.0)
    light = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    return 0.42 + 0.58 * np.clip(n @ light, 0.0, 1.0)
