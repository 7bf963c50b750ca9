"""The gallery: worked examples of layered, growing, pressurised tubes (docs/patterns.md).

Each example is a pure function ``name(*, quick=False, mapper=map)`` returning a
:class:`~.gallery_base.GalleryFigure` (a :class:`~.style.FigureResult` named instead of
numbered): the onsets it computed, one row per tube, a figure, headline numbers, and the
critical points whose 3D patterns ``electrogrowth reproduce --gallery`` renders. Every onset
is one :func:`scan_modes` of the tube (mode ranges widened automatically, the exact
short-wave limit compared) or, where a mode is named, one :func:`critical_value`; a tube that
never wrinkles in the searched range is a row with a NaN value and its reason, not an error.
The tubes of an example are solved by ``mapper`` (a process pool's ``map`` runs them in
parallel). ``quick`` computes one or two tubes per example, for tests.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import Any

from ..basestate.layered import layered_threshold, pressure_response
from ..model.layers import Layer, Tube
from .gallery_base import FULL, QUICK, GalleryFigure, Job, draw_onsets, result, run_groups
from .style import COLORS, new_figure

# -- 1. mucosal folding ----------------------------------------------------------------------


def bilayer(h: float = 0.1, mu: float = 10.0, *, outer: float = 2.0, **loads) -> Tube:
    """A growing inner layer (1 .. 1 + h, shear modulus ratio ``mu``) bonded inside an
    ungrown neo-Hookean substrate (1 + h .. ``outer``); ``loads`` as in :class:`Tube`
    (default: lambda_z = 1)."""
    return Tube((Layer(1.0 + h, shear_modulus=mu), Layer(outer)), **loads)


def mucosal_folding(*, quick: bool = False, mapper: Callable = map) -> GalleryFigure:
    """Mucosal folding: a thin stiff inner layer (h = 0.1, mu_1/mu_2 = 10) growing in a thick
    soft tube (R = 1 .. 1.1 .. 2): critical hoop growth and mode against the inner layer's
    thickness, the modulus ratio (down to a soft inner layer) and the voltage; hoop,
    cross-section and isotropic growth at fixed stretch and with free ends."""
    opts = QUICK if quick else FULL
    hoop, free = "growth[1].theta", {"axial_force": 0.0}
    thick = (0.1,) if quick else (0.05, 0.1, 0.2, 0.3)
    moduli = (10.0,) if quick else (0.1, 1.0, 10.0, 100.0, 1000.0)
    volts = () if quick else (0.0, 0.4)
    kinds = (
        (("hoop", hoop),)
        if quick
        else (("hoop", hoop), ("cross-section", "growth[1].r+theta"), ("isotropic", "growth[1]"))
    )
    ends: tuple[tuple[str, dict[str, Any]], ...] = (("fixed stretch", {}), ("free ends", free))
    groups = {  # the slowest first
        "kinds": [
            Job(bilayer(**loads), control, f"{what}, {label}", "h", 0.1)
            for what, control in kinds
            for label, loads in ([ends[0]] if quick else ends)
        ],
        "h": [Job(bilayer(h), hoop, "hoop: thickness", "h", h) for h in thick],
        "mu": [Job(bilayer(mu=mu), hoop, "hoop: modulus", "mu1/mu2", mu) for mu in moduli],
        **{
            label: [
                Job(bilayer(voltage=v, **loads), hoop, f"hoop: voltage, {label}", "Vbar", v)
                for v in volts
            ]
            for label, loads in ends
        },
    }
    res = run_groups(groups, opts, mapper)
    by_h, by_mu = res["h"], res["mu"]
    by_v = {label: res[label] for label, _ in ends}
    by_kind = {tuple(o.case.split(", ")): o for o in res["kinds"]}
    onsets = by_h + by_mu + [o for v in by_v.values() for o in v] + list(by_kind.values())

    fig, axes = new_figure(7.0, 5.2, 2, 2)
    (a, b), (c, d) = axes
    draw_onsets(a, by_h, color=COLORS[0], label="hoop growth")
    a.set(
        xlabel=r"inner thickness $h$ ($R_o = 2$, $\mu_1/\mu_2 = 10$)",
        ylabel=r"critical $g_\theta$ of layer 1",
    )
    draw_onsets(b, by_mu, color=COLORS[1], label="hoop growth")
    b.set(
        xscale="log",
        xlabel=r"modulus ratio $\mu_1/\mu_2$ ($h = 0.1$)",
        ylabel=r"critical $g_\theta$",
    )
    for (label, rows), color in zip(by_v.items(), COLORS[2:4], strict=True):
        draw_onsets(c, rows, color=color, label=label)
    c.set(
        xlabel=r"voltage $\bar V$ ($h = 0.1$, $\mu_1/\mu_2 = 10$)", ylabel=r"critical $g_\theta$"
    )
    c.legend(fontsize=7)
    _bars(d, by_kind)
    for ax, tag in zip(axes.flat, "abcd", strict=True):
        ax.set_title(f"({tag}) labels: critical mode (m, n)", loc="left", fontsize=7)

    base = by_h[thick.index(0.1)]
    headline = {"hoop_growth": base.value, "m_cr": base.mode[0], "n_cr": base.mode[1]}
    points = (
        [("hoop", base)]
        + [
            (f"{what}-{label.replace(' ', '_')}", o)
            for (what, label), o in by_kind.items()
            if what != "hoop"
        ]
        + [(f"hoop-mu{o.x:g}", o) for o in by_mu if o.x < 1.0]
    )
    points = [
        (n, o.critical)
        for n, o in points
        if o.critical is not None and o.critical.kind == "bifurcation"
    ]
    return result("mucosal_folding", "Mucosal folding", onsets, fig, headline, points)


def _bars(ax, by_kind: dict) -> None:
    """Critical growth of each kind of growth at fixed stretch and with free ends, labelled
    with the mode; 'none' where no mode bifurcates for g < 6."""
    kinds = list(dict.fromkeys(what for what, _ in by_kind))
    for j, (label, color) in enumerate((("fixed stretch", COLORS[2]), ("free ends", COLORS[3]))):
        for i, what in enumerate(kinds):
            o = by_kind.get((what, label))
            if o is None:
                continue
            x = i + 0.4 * (j - 0.5)
            value = o.value if o.critical is not None else 1.0
            ax.bar(x, value - 1.0, 0.38, bottom=1.0, color=color, label=label if i == 0 else None)
            m, n = o.mode
            text = "none" if o.critical is None else (f"({m}, {n})" if m >= 0 else "∞")
            ax.annotate(
                text,
                (x, max(value, 1.0)),
                xytext=(0, 2),
                textcoords="offset points",
                ha="center",
                fontsize=6.5,
            )
    ax.set_xticks(range(len(kinds)), [f"{k} growth" for k in kinds], fontsize=7)
    ax.set(ylabel="critical growth of layer 1", ylim=(1.0, None))
    ax.legend(fontsize=7)


# -- 2. hoop versus axial growth of one thick layer --------------------------------------------


def one_layer_growth(*, quick: bool = False, mapper: Callable = map) -> GalleryFigure:
    """Circumferential-only versus axial-only growth of one thick neo-Hookean layer
    (R = 1 .. R_o): critical g_theta and g_z against R_o, at lambda_z = 1 and with free ends."""
    opts = QUICK if quick else FULL
    radii = (2.0,) if quick else (1.4, 2.0, 3.0)
    ends: tuple[tuple[str, dict[str, Any]], ...] = (
        ("fixed stretch", {"stretch": 1.0}),
        ("free ends", {"axial_force": 0.0}),
    )
    groups = {
        (comp, label): [
            Job(Tube((Layer(r),), **loads), f"growth[1].{comp}", f"g_{comp}, {label}", "R_o", r)
            for r in radii
        ]
        for comp in ("theta", "z")
        for label, loads in (ends[:1] if quick else ends)
    }
    rows = run_groups(groups, opts, mapper)
    fig, axes = new_figure(7.0, 2.8, 1, 2)
    for ax, comp in zip(axes[0], ("theta", "z"), strict=True):
        for label, color in (("fixed stretch", COLORS[0]), ("free ends", COLORS[2])):
            if (comp, label) in rows:
                draw_onsets(ax, rows[comp, label], color=color, label=label)
        ax.set(
            xlabel=r"outer radius $R_o$",
            ylabel=rf"critical $g_{{\{comp}}}$" if comp == "theta" else r"critical $g_z$",
        )
        ax.set_title(f"({'ab'[comp == 'z']}) growth along {comp} only", loc="left", fontsize=8)
        ax.legend(fontsize=7)
    onsets = [o for v in rows.values() for o in v]
    at2 = {k: v[radii.index(2.0)] for k, v in rows.items()}
    headline = {f"g_{c}_{lab.split()[0]}_Ro2": o.value for (c, lab), o in at2.items()}
    points = [
        (f"g_{c}-{lab.replace(' ', '_')}", o.critical)
        for (c, lab), o in at2.items()
        if o.critical is not None and o.critical.kind == "bifurcation"
    ]
    return result(
        "one_layer_growth",
        "Hoop versus axial growth of one thick layer",
        onsets,
        fig,
        headline,
        points,
    )


# -- 3. a pressurised dielectric tube -----------------------------------------------------------


def pressurised_dielectric(*, quick: bool = False, mapper: Callable = map) -> GalleryFigure:
    """A pressurised dielectric tube (R = 1 .. 1.4, lambda_z = 1): critical voltage against the
    inner pressure P_i; and under axial-force control (free or closed ends, no voltage) the
    bulging limit: the limit point of the inflation branch, approached by the axisymmetric
    (0, 1) mode of ever longer tubes."""
    opts = QUICK if quick else FULL
    pressures = (0.1,) if quick else (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)
    lengths = (20.0,) if quick else (2.0, 5.0, 10.0, 20.0, 40.0)
    ends = {"open ends": False, "closed ends": True}
    free = {
        label: Tube((Layer(1.4),), axial_force=0.0, closed_ends=c) for label, c in ends.items()
    }
    long_waves = ["open ends"] if quick else list(ends)
    groups = {
        "P": [
            Job(Tube((Layer(1.4),), inner_pressure=p), "voltage", "voltage vs pressure", "P_i", p)
            for p in pressures
        ],
        **{
            label: [
                Job(
                    dataclasses.replace(tube, length=length),
                    "pressure",
                    f"(0, 1) mode, {label}",
                    "L",
                    length,
                    (0, 1),
                )
                for length in lengths
            ]
            for label, tube in free.items()
            if label in long_waves
        },
    }
    res = run_groups(groups, opts, mapper)
    by_p, bulges = res["P"], {label: res[label] for label in long_waves}
    limits = {label: layered_threshold(tube, "pressure") for label, tube in free.items()}
    extra = [
        (
            f"limit point, {label}",
            "L",
            math.inf,
            "pressure",
            thr.value,
            -1,
            -1,
            "",
            "threshold",
            f"{thr.kind} at lambda_i = {thr.lambda_i!r}",
        )
        for label, thr in limits.items()
    ]

    fig, axes = new_figure(7.5, 2.7, 1, 3)
    a, b, c = axes[0]
    draw_onsets(a, by_p, color=COLORS[1], label=r"$\lambda_z = 1$")
    a.margins(y=0.12)
    a.set(xlabel=r"inner pressure $P_i/\mu$", ylabel=r"critical voltage $\bar V$")
    a.set_title("(a) voltage at onset; labels: critical mode (m, n)", loc="left", fontsize=7)
    colors = dict(zip(ends, COLORS[2:], strict=False))
    for label, thr in limits.items():
        resp = pressure_response(free[label], points=9 if quick else 41)
        b.plot(resp["lambda_i"], resp["inner_pressure"], "-", color=colors[label], label=label)
        if thr.kind == "limit point":
            b.plot([thr.lambda_i], [thr.value], "o", color=colors[label], ms=4)
            c.axhline(
                thr.value, color=colors[label], lw=0.8, ls="--", label=f"limit point, {label}"
            )
        else:
            b.axhline(thr.value, color=colors[label], lw=0.6, ls="--")
    b.set(xlabel=r"inner stretch $\lambda_i$", ylabel=r"inner pressure $P_i/\mu$")
    b.set_title("(b) inflation at zero axial force", loc="left", fontsize=7)
    b.legend(fontsize=6.5)
    for label, rows in bulges.items():
        ok = [o for o in rows if o.critical is not None]
        none = [o for o in rows if o.critical is None]
        c.plot(
            [1 / o.x**2 for o in ok],
            [o.value for o in ok],
            "o-",
            color=colors[label],
            ms=3.5,
            label=f"(0, 1) mode, {label}",
        )
        c.plot(
            [1 / o.x**2 for o in none],
            [0.03] * len(none),
            "x",
            color=colors[label],
            transform=c.get_xaxis_transform(),
            label=f"(0, 1) mode, {label}: none" if none else None,
        )
    c.set(xlabel=r"$1/L^2$", ylabel=r"critical $P_i/\mu$", xlim=(0, None))
    c.set_title("(c) (0, 1) mode of long tubes", loc="left", fontsize=7)
    c.legend(fontsize=6.5)
    onsets = by_p + [o for v in bulges.values() for o in v]
    headline = {"voltage_P0.1": by_p[pressures.index(0.1)].value}
    headline |= {
        f"limit_{k.split()[0]}": thr.value
        for k, thr in limits.items()
        if thr.kind == "limit point"
    }
    headline |= {f"bulge_L{lengths[-1]:g}_{k.split()[0]}": v[-1].value for k, v in bulges.items()}
    points = [
        (f"voltage-P{o.x:g}", o.critical)
        for o in by_p
        if o.critical is not None and o.critical.kind == "bifurcation"
    ][-1:]
    points += [
        (f"bulge-{k.split()[0]}_L{v[-1].x:g}", v[-1].critical)
        for k, v in bulges.items()
        if v[-1].critical is not None
    ]
    return result(
        "pressurised_dielectric",
        "A pressurised dielectric tube",
        onsets,
        fig,
        headline,
        points,
        extra,
    )
