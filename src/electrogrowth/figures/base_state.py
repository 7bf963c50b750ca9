"""Figures 4 and 5 of the paper (Sec. 4.1): the base state of the grown, charged tube.

Each figure is a pure function returning a :class:`~.style.FigureResult` (data table,
matplotlib figure, headline numbers); ``FigureResult.save`` writes ``fig<N>.png`` and
``fig<N>.csv``.
"""

from __future__ import annotations

import numpy as np

from ..basestate.tube import solve_base_state, voltage_curve, voltage_threshold
from ..errors import BaseStateError
from ..model.layers import Tube
from ..model.materials import Material, neo_hookean
from .style import COLORS, FigureResult, new_figure


def figure4(
    *,
    outer_radius: float = 2.0,
    growths=(1.0, 1.1, 1.2),
    stretches=(0.9, 1.0, 1.2),
    material: Material | None = None,
    points: int | None = None,
    max_lambda_i: float = 5.0,
    quick: bool = False,
) -> FigureResult:
    """lambda_i against Vbar for several g and lambda_z (paper Fig. 4).

    One panel per lambda_z; one curve per growth factor g (g = 1, no growth, dotted). Each
    curve is Vbar(lambda_i) for lambda_i0 <= lambda_i <= ``max_lambda_i``; the threshold is a
    vertical dashed line (asymptote: lambda_i -> inf as Vbar -> Vbar_inf) or a dot (limit point).
    ``points`` per curve: default 200, or 40 when ``quick``.

    Returns
    -------
    FigureResult
        Columns g, lambda_z, Vbar, lambda_i, Vbar_threshold; headline
        ``threshold_g{g}_lz{lambda_z}`` for every curve.
    """
    material = material or neo_hookean()
    points = points or (40 if quick else 200)
    fig, axes = new_figure(7.0, 2.6, 1, len(stretches))
    rows, headline = [], {}
    for ax, lz in zip(axes[0], stretches):
        for color, g in zip(COLORS, growths):
            p = Tube.uniform(outer_radius=outer_radius, growth=g, stretch=lz, material=material)
            thr, kind, lam_thr = voltage_threshold(p)
            if kind in ("closing", "unresolved"):  # no charged state followed: nothing to draw
                continue
            lam0 = solve_base_state(p).lambda_i
            top = min(max_lambda_i, lam_thr * (1 - 1e-9))  # a limit point or locking
            lam = lam0 + (top - lam0) * np.linspace(0.0, 1.0, points) ** 2
            v = voltage_curve(p, lam)
            rows.append(
                np.column_stack(
                    [np.full_like(v, g), np.full_like(v, lz), v, lam, np.full_like(v, thr)]
                )
            )
            headline[f"threshold_g{g:g}_lz{lz:g}"] = thr
            style = ":" if g == 1.0 else "-"
            ax.plot(v, lam, style, color=color, label=f"$g = {g:g}$")
            if kind == "asymptote":
                ax.axvline(thr, color=color, lw=0.7, ls="--", alpha=0.7)
            elif kind == "limit point":
                ax.plot([thr], [lam_thr], "o", color=color, ms=4)
        ax.set_title(rf"$\lambda_z = {lz:g}$", fontsize=9)
        ax.set_xlabel(r"voltage $\bar V$ (–)")
    if not rows:
        raise BaseStateError(
            f"{material.name}: no charged state at any of these growths and stretches (its"
            " field closes the bore: voltage threshold 0, kind closing)"
        )
    right = 1.08 * max(np.max(r[:, 2]) for r in rows)
    for ax in axes[0]:
        ax.set_xlim(0.0, right)
        ax.set_ylim(min(0.8, min(np.min(r[:, 3]) for r in rows) - 0.1), max_lambda_i)
    axes[0, 0].set_ylabel(r"inner stretch $\lambda_i$ (–)")
    axes[0, 0].plot([], [], "k--", lw=0.7, label="threshold")
    axes[0, 0].legend(loc="upper left", fontsize=8)
    fig.suptitle(rf"$\bar R_o = {outer_radius:g}$, {material.name}", fontsize=9)
    return FigureResult(
        4,
        ("g", "lambda_z", "Vbar", "lambda_i", "Vbar_threshold"),
        np.concatenate(rows),
        fig,
        headline,
    )


def figure5(
    *,
    outer_radius: float = 2.0,
    growths=(1.0, 1.1),
    voltages=(0.0, 0.4, 0.8),
    stretches=(0.9, 1.2),
    material: Material | None = None,
    points: int | None = None,
    quick: bool = False,
) -> FigureResult:
    """sigma_rr, sigma_tt, sigma_zz through the wall for several g, Vbar, lambda_z (Fig. 5).

    Rows: growth factors g; columns: the three principal Cauchy stresses against the reference
    radius R in [1, Rbar_o]. Colour: Vbar; line style: lambda_z (solid, dashed, ...).
    ``points`` across the wall: default 101, or 21 when ``quick``.

    Returns
    -------
    FigureResult
        Columns g, lambda_z, Vbar, R, r, sigma_rr, sigma_tt, sigma_zz; headline
        ``sigma_tt_inner_g{g}_lz{lz}_V{V}`` (sigma_tt at R = 1) for every state.
    """
    material = material or neo_hookean()
    points = points or (21 if quick else 101)
    fig, axes = new_figure(7.0, 2.3 * len(growths) + 0.3, len(growths), 3)
    dashes = ("-", "--", "-.", ":")
    names = (r"$\sigma_{rr}$", r"$\sigma_{\theta\theta}$", r"$\sigma_{zz}$")
    rows, headline = [], {}
    for row, g in zip(axes, growths):
        for dash, lz in zip(dashes, stretches):
            for color, V in zip(COLORS, voltages):
                p = Tube.uniform(
                    outer_radius=outer_radius, growth=g, stretch=lz, voltage=V, material=material
                )
                prof = solve_base_state(p).profiles(points)
                comps = (prof["sigma_rr"], prof["sigma_tt"], prof["sigma_zz"])
                for ax, s in zip(row, comps):
                    ax.plot(
                        prof["R"],
                        s,
                        dash,
                        color=color,
                        label=rf"$\bar V = {V:g}$, $\lambda_z = {lz:g}$",
                    )
                rows.append(
                    np.column_stack(
                        [
                            np.full(points, g),
                            np.full(points, lz),
                            np.full(points, V),
                            prof["R"],
                            prof["r"],
                            *comps,
                        ]
                    )
                )
                headline[f"sigma_tt_inner_g{g:g}_lz{lz:g}_V{V:g}"] = float(prof["sigma_tt"][0])
        for ax, name in zip(row, names):
            ax.set_title(rf"{name}, $g = {g:g}$", fontsize=9)
            ax.axhline(0.0, color="0.6", lw=0.5)
            ax.set_xlim(1.0, outer_radius)
        row[0].set_ylabel(r"Cauchy stress / $\mu$ (–)")
    for ax in axes[-1]:
        ax.set_xlabel(r"radius $R / R_i$ (–)")
    fig.legend(
        *axes[0, 0].get_legend_handles_labels(),
        loc="outside lower center",
        ncol=len(stretches),
        fontsize=8,
    )  # one column per lambda_z
    fig.suptitle(rf"$\bar R_o = {outer_radius:g}$, {material.name}", fontsize=9)
    return FigureResult(
        5,
        ("g", "lambda_z", "Vbar", "R", "r", "sigma_rr", "sigma_tt", "sigma_zz"),
        np.concatenate(rows),
        fig,
        headline,
    )
