"""Figures 9 and 10 of the paper (Sec. 4.4): the critical growth factor against the axial
stretch and against the voltage, with the representative points of the paper's panels B.

Built like Figures 6-8 (:mod:`.critical`: a :class:`~.critical.ModeFigure`, curves from
:func:`curves.critical_curve`, the same CSV columns); the representative points (critical
states and their modes, for rendering 3D patterns) are written to ``fig<N>_points.csv``.
"""

from __future__ import annotations

import numpy as np

from ..bifurcation.curves import Curve
from ..bifurcation.scan import scan_modes
from ..model.layers import Tube
from ..model.materials import Material, neo_hookean
from .critical import NUDGE, ModeFigure, PatternPoint, _curve, _finite, _modes, _table, _title
from .plots import curve_legend, plot_curve
from .style import COLORS, new_figure


def representative_points(curve: Curve, prefix: str, count: int = 4) -> tuple[PatternPoint, ...]:
    """``count`` points of a growth curve as the paper picks them: the two ends of the
    curve, and between them the middles of the longest branches whose modes differ from
    each other and from the ends' (the middle of the range if the curve has too few)."""
    rows = [r for _, r in curve.branches() if curve.m[r[0]] >= 0]
    ok = np.nonzero(_finite(curve) & (curve.m >= 0))[0]
    first, last = int(ok[0]), int(ok[-1])
    ends = {(curve.m[first], curve.n[first]), (curve.m[last], curve.n[last])}
    inner = []
    for r in sorted(rows, key=lambda r: curve.x[r[-1]] - curve.x[r[0]], reverse=True):
        mode = (curve.m[r[0]], curve.n[r[0]])
        if mode in ends or first in r or last in r:
            continue
        inner.append(int(r[len(r) // 2]))
        ends.add(mode)
        if len(inner) == count - 2:
            break
    while len(inner) < count - 2:  # too few branches: evenly spaced grid rows
        frac = (len(inner) + 1) / (count - 1)
        target = curve.x[first] + frac * (curve.x[last] - curve.x[first])
        cand = [i for i in ok if i not in inner and i not in (first, last)]
        if not cand:
            break
        inner.append(int(min(cand, key=lambda i: abs(curve.x[i] - target))))
    chosen = sorted([first, *inner, last], key=lambda i: curve.x[i])
    out = []
    for k, i in enumerate(chosen, 1):
        params = curve.params.at(curve.along, curve.x[i]).at(curve.solve_for, curve.value[i])
        out.append(PatternPoint(f"{prefix}{k}", params, int(curve.m[i]), int(curve.n[i])))
    return tuple(out)


def _mark(ax, pts, color, along):
    for p in pts:
        x, y = p.params.value_of(along), p.params.growth
        ax.plot([x], [y], "o", mfc="white", mec=color, ms=4, zorder=3)
        ax.annotate(
            f"${p.name[0]}_{p.name[1:]}$",
            (x, y),
            xytext=(3, -9),
            textcoords="offset points",
            fontsize=7,
            color=color,
        )


def figure9(
    *,
    outer_radius: float = 1.4,
    length: float = 1.0,
    voltages=(0.4, 0.6),
    points: int | None = None,
    material: Material | None = None,
    quick: bool = False,
    progress=None,
) -> ModeFigure:
    """Critical growth factor against the axial stretch for Vbar = 0.4, 0.6 (paper Fig. 9).

    Rbar_o = 1.4, L = 1. For each voltage the lambda_z grid runs between the critical
    compressive and extensional stretches of the ungrown tube (g = 1), moved inside by a
    relative 1e-6 (at the ends the tube is exactly critical at g = 1). ``points`` per curve:
    default 30, or 3 when ``quick``. Representative points N1..N4 (Vbar = 0.4) and M1..M4
    (0.6): :func:`representative_points`.

    Returns
    -------
    ModeFigure
        Headline ``lambda_compression_V{V}``, ``lambda_extension_V{V}`` (the ends, g = 1,
        from mode scans of the stretch), ``g_start_V{V}`` and ``g_end_V{V}`` (the curve's
        values there), ``g_max_V{V}``.
    """
    material = material or neo_hookean()
    points = points or (3 if quick else 30)
    fig, axes = new_figure(4.6, 3.2, 1, 1)
    ax = axes[0, 0]
    curves, headline = [], {}
    pts: list[PatternPoint] = []
    for color, V, prefix in zip(COLORS, voltages, "NMKJ"):
        p = Tube.uniform(outer_radius=outer_radius, length=length, voltage=V, material=material)
        lo = scan_modes(p, "stretch", side="compression", options=_modes(quick)).critical
        hi = scan_modes(p, "stretch", side="extension", options=_modes(quick)).critical
        grid = np.linspace(lo.value * (1 + NUDGE), hi.value * (1 - NUDGE), points)
        c = _curve(p, "growth", "stretch", grid, quick, progress=progress)
        curves.append(c)
        plot_curve(c, ax, color=color, label=rf"$\bar V = {V:g}$")
        chosen = representative_points(c, prefix)
        pts += chosen
        _mark(ax, chosen, color, "stretch")
        ok = _finite(c)
        headline.update(
            {
                f"lambda_compression_V{V:g}": lo.value,
                f"lambda_extension_V{V:g}": hi.value,
                f"g_start_V{V:g}": float(c.value[ok][0]),
                f"g_end_V{V:g}": float(c.value[ok][-1]),
                f"g_max_V{V:g}": float(c.value[ok].max()),
            }
        )
    _title(ax, rf"$\bar R_o = {outer_radius:g}$, $L = {length:g}$")
    curve_legend(ax, loc="upper left")
    cols, table = _table(curves)
    return ModeFigure(9, cols, table, fig, headline, tuple(curves), tuple(pts))


def figure10(
    *,
    outer_radius: float = 1.4,
    length: float = 1.0,
    stretches=(1.0, 1.1),
    points: int | None = None,
    material: Material | None = None,
    quick: bool = False,
    progress=None,
) -> ModeFigure:
    """Critical growth factor against the voltage for lambda_z = 1.0, 1.1 (paper Fig. 10).

    Rbar_o = 1.4, L = 1. For each lambda_z the Vbar grid runs from 0 to the critical voltage
    of the ungrown tube (g = 1; moved inside by a relative 1e-6), denser towards that end.
    ``points`` per curve: default 30, or 3 when ``quick``. Representative points P1..P4
    (lambda_z = 1.0) and Q1..Q4 (1.1): :func:`representative_points`.

    Returns
    -------
    ModeFigure
        Headline ``V_cr_lz{lambda_z}`` (g = 1, from a voltage scan), ``g_start_lz{..}``
        (Vbar = 0), ``g_end_lz{..}`` (the last point), ``g_max_lz{..}``,
        ``V_at_g_max_lz{..}``.
    """
    material = material or neo_hookean()
    points = points or (3 if quick else 30)
    fig, axes = new_figure(4.6, 3.2, 1, 1)
    ax = axes[0, 0]
    curves, headline = [], {}
    pts: list[PatternPoint] = []
    for color, lz, prefix in zip(COLORS, stretches, "PQRS"):
        p = Tube.uniform(outer_radius=outer_radius, length=length, stretch=lz, material=material)
        vcr = scan_modes(p, "voltage", options=_modes(quick)).critical
        t = np.linspace(0.0, 1.0, points)  # denser towards Vbar_cr, where g_cr falls fast
        grid = vcr.value * (1 - NUDGE) * (1 - (1 - t) ** 2)
        c = _curve(p, "growth", "voltage", grid, quick, progress=progress)
        curves.append(c)
        plot_curve(c, ax, color=color, label=rf"$\lambda_z = {lz:g}$")
        chosen = representative_points(c, prefix)
        pts += chosen
        _mark(ax, chosen, color, "voltage")
        ok = _finite(c)
        i = int(np.argmax(np.where(ok, c.value, -np.inf)))
        headline.update(
            {
                f"V_cr_lz{lz:g}": vcr.value,
                f"g_start_lz{lz:g}": float(c.value[ok][0]),
                f"g_end_lz{lz:g}": float(c.value[ok][-1]),
                f"g_max_lz{lz:g}": float(c.value[i]),
                f"V_at_g_max_lz{lz:g}": float(c.x[i]),
            }
        )
    _title(ax, rf"$\bar R_o = {outer_radius:g}$, $L = {length:g}$")
    curve_legend(ax, loc="lower left")
    cols, table = _table(curves)
    return ModeFigure(10, cols, table, fig, headline, tuple(curves), tuple(pts))
