"""``electrogrowth demo``: the paper's headline tube, from base state to wrinkling pattern.

Rbar_o = 1.4, L = 1, lambda_z = 1, Vbar = 0.4 (paper Sec. 4.4): the residual stress of the
charged tube, the critical growth factor and mode with the runners-up, the critical growth
factor along the axial stretch, and the 3D wrinkled tube. Everything lands in --out.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from ..atomic import write_figure, write_text
from ..basestate.tube import solve_base_state
from ..bifurcation.curves import critical_curve
from ..bifurcation.scan import scan_modes
from ..figures.plots import plot_curve, render_pattern
from ..figures.style import COLORS, new_figure
from ..model.layers import Tube
from ..shapes.mode_shape import mode_shape
from .options import path_arg
from .progress import add_quiet_option, enabled, stage

HEADLINE = Tube.uniform(outer_radius=1.4, length=1.0, growth=1.0, stretch=1.0, voltage=0.4)


def configure_demo(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--out",
        type=path_arg,
        default=Path("out"),
        metavar="DIR",
        help="directory for the PNG, CSV and JSON results (default ./out)",
    )
    parser.add_argument("--quick", action="store_true", help="fewer curve points (for tests)")
    add_quiet_option(parser)


def run_demo(args) -> int:
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    p = HEADLINE
    state = solve_base_state(p)
    rec = state.as_dict()
    write_text(out / "state.json", json.dumps(rec, indent=1))
    _stress_profile(state, out)
    with stage(args, "scanning the wrinkling modes for the critical growth"):
        scan = scan_modes(p, "growth")
    crit = scan.critical
    write_text(out / "critical.json", json.dumps(scan.as_dict(), indent=1))
    lines = [
        f"Tube Rbar_o = {p.outer_radius:g}, L = {p.length:g}, lambda_z = {p.stretch:g},"
        f" Vbar = {p.voltage:g} ({p.material.name}); units mu = eps = R_i = 1",
        f"  base state: lambda_i = {state.lambda_i:.10f}, lambda_o = {state.lambda_o:.10f},"
        f" voltage threshold {state.voltage_threshold:.6f} ({state.threshold_kind})",
        f"  residual hoop stress from {rec['sigma_tt_min']:.4f} to {rec['sigma_tt_max']:.4f},"
        f" axial force {state.axial_force:.6f}",
        f"  wrinkles at g_cr = {crit.value:.10f} in mode (m, n) = ({crit.m}, {crit.n})"
        f"  (error estimate {crit.error_estimate:.0e})",
        "  next modes: " + ", ".join(f"({r.m}, {r.n}) at {r.value:.6f}" for r in scan.runners_up),
    ]
    written = [
        out / "state.json",
        out / "stress_profile.csv",
        out / "stress_profile.png",
        out / "critical.json",
    ]
    written += _extras(p, crit, out, args)
    lines.append("  wrote " + ", ".join(str(w) for w in written))
    print("\n".join(lines))
    return 0


def _stress_profile(state, out: Path) -> None:
    prof = state.profiles(201)
    cols = ("r", "sigma_rr", "sigma_tt", "sigma_zz", "p", "D_r", "E_r")
    np.savetxt(
        out / "stress_profile.csv",
        np.column_stack([prof[c] for c in cols]),
        delimiter=",",
        header=",".join(cols),
        comments="",
        fmt="%.15g",
    )
    fig, axes = new_figure(4.0, 3.0, 1, 1)
    ax = axes[0, 0]
    for key, label, color in zip(
        ("sigma_rr", "sigma_tt", "sigma_zz"),
        (r"$\sigma_{rr}$", r"$\sigma_{\theta\theta}$", r"$\sigma_{zz}$"),
        COLORS,
    ):
        ax.plot(prof["r"], prof[key], color=color, label=label)
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel(r"current radius $r / R_i$ (–)")
    ax.set_ylabel(r"Cauchy stress / $\mu$ (–)")
    ax.set_title(
        rf"$\bar R_o$ = {state.tube.outer_radius:g}, $\bar V$ ="
        rf" {state.tube.voltage:g}, $\lambda_z$ = {state.tube.stretch:g}",
        fontsize=9,
    )
    ax.legend()
    write_figure(fig, out / "stress_profile.png")


def _extras(params, crit, out: Path, args) -> list[Path]:
    """The g_cr curve along the axial stretch and the 3D pattern of the critical mode."""
    xs = np.linspace(0.95, 1.25, 4 if args.quick else 13)
    curve = critical_curve(params, "growth", "stretch", xs, progress=enabled(args))
    curve.to_csv(out / "gcr_curve.csv")
    write_figure(plot_curve(curve).figure, out / "gcr_curve.png")
    with stage(args, "drawing the wrinkled tube in 3D"):
        render_pattern(mode_shape(crit), path=out / "pattern.png")
    return [out / "gcr_curve.csv", out / "gcr_curve.png", out / "pattern.png"]
