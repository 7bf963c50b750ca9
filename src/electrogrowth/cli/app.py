"""The ``electrogrowth`` command line (also ``python -m electrogrowth``).

Each subcommand is a pair of functions in :data:`COMMANDS`: ``configure(parser)`` adds its
options, ``run(args) -> int`` does the work. :func:`main` parses, dispatches and turns every
failure into one line ``electrogrowth: error: <message>`` on stderr with exit status 2
(1 for an unexpected internal error); no traceback reaches the user. To add a subcommand,
write the two functions and add an entry to :data:`COMMANDS`; to add a figure, add an entry
to :data:`FIGURES`.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Callable

from .. import __version__
from ..figures import base_state as figures_base
from ..figures import critical as figures_modes
from .options import UsageError, _Parser, add_tube_options, tube_from_args
from .critical import configure_critical, run_critical
from .curve import configure_curve, run_curve
from .demo import configure_demo, run_demo
from .pattern import HELP as PATTERN_HELP
from .pattern import configure_pattern, run_pattern
from .reproduce import configure_reproduce, run_reproduce
from .sweep import configure_plot, configure_sweep, run_plot, run_sweep
from ..errors import ElectrogrowthError
from ..basestate.tube import solve_base_state

PROG = "electrogrowth"

#: Paper figure number -> function(*, quick: bool) returning a figures_base.FigureResult;
#: the first line of its docstring is the help text.
FIGURES: dict[int, Callable[..., figures_base.FigureResult]] = {
    4: figures_base.figure4,
    5: figures_base.figure5,
    **figures_modes.FIGURES,
}


def configure_state(parser: argparse.ArgumentParser) -> None:
    add_tube_options(parser)
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object instead of text")


def state_record(state) -> dict:
    """The JSON record of a base state (inf -> null): geometry, charge, threshold, axial force
    and the extremes of the three principal Cauchy stresses over 401 points of the wall."""
    p = state.params
    prof = state.profiles(401)
    finite = lambda x: float(x) if math.isfinite(x) else None  # noqa: E731
    record = {
        "material": p.material.name, "outer_radius": p.outer_radius, "growth": p.growth,
        "stretch": p.stretch, "voltage": p.voltage, "length": p.length,
        "lambda_i": state.lambda_i, "lambda_o": state.lambda_o, "r_i": state.r_i,
        "r_o": state.r_o, "charge": state.charge,
        "voltage_threshold": finite(state.voltage_threshold),
        "threshold_kind": state.threshold_kind, "axial_force": state.axial_force,
    }
    for key in ("sigma_rr", "sigma_tt", "sigma_zz"):
        record[f"{key}_min"] = float(prof[key].min())
        record[f"{key}_max"] = float(prof[key].max())
    return record


def run_state(args) -> int:
    params = tube_from_args(args)
    rec = state_record(solve_base_state(params))
    if args.json:
        print(json.dumps(rec))
        return 0
    thr = rec["voltage_threshold"]
    lines = [
        f"base state: {rec['material']}, Rbar_o = {params.outer_radius:g}, g = {params.growth:g},"
        f" lambda_z = {params.stretch:g}, Vbar = {params.voltage:g}",
        f"  lambda_i = r_i / R_i         {rec['lambda_i']:.12g}",
        f"  lambda_o = r_o / R_o         {rec['lambda_o']:.12g}",
        f"  r_i, r_o                     {rec['r_i']:.12g}, {rec['r_o']:.12g}",
        f"  charge c (D_r = c / r)       {rec['charge']:.12g}",
        f"  Vbar threshold               {'none (unbounded)' if thr is None else f'{thr:.12g}'}"
        f" ({rec['threshold_kind']})",
        f"  axial force N / (mu R_i^2)   {rec['axial_force']:.12g}",
    ]
    for key, name in (("sigma_rr", "sigma_rr"), ("sigma_tt", "sigma_theta"),
                      ("sigma_zz", "sigma_zz")):
        lines.append(f"  {name + ' / mu (min, max)':<29}{rec[key + '_min']:.6g},"
                     f" {rec[key + '_max']:.6g}")
    print("\n".join(lines))
    return 0


# -- figure ----------------------------------------------------------------------------------

def configure_figure(parser: argparse.ArgumentParser) -> None:
    titles = ((n, (FIGURES[n].__doc__ or "").strip().split("\n")[0].rstrip("."))
              for n in sorted(FIGURES))
    parser.add_argument("number", type=int, choices=sorted(FIGURES),
                        help="paper figure: " + "; ".join(f"{n}: {t}" for n, t in titles))
    parser.add_argument("--out", type=Path, default=Path("out"), metavar="DIR",
                        help="directory for fig<N>.png and fig<N>.csv (default ./out)")
    parser.add_argument("--quick", action="store_true",
                        help="low resolution (previews and tests)")


def run_figure(args) -> int:
    result = FIGURES[args.number](quick=args.quick)
    for path in result.save(args.out):
        print(path)
    return 0


#: Subcommand name -> (one-line help, configure(parser), run(args) -> exit status).
COMMANDS: dict[str, tuple[str, Callable, Callable]] = {
    "state": ("solve the axisymmetric base state of a grown, stretched, charged tube",
              configure_state, run_state),
    "figure": ("reproduce a figure of the paper (PNG + CSV)", configure_figure, run_figure),
    "critical": ("critical growth factor, axial stretch or voltage for the onset of"
                 " wrinkling, for one mode or scanned over modes", configure_critical,
                 run_critical),
    "demo": ("the paper's headline tube (Rbar_o = 1.4, L = 1, lambda_z = 1, Vbar = 0.4):"
             " base state, critical growth and mode, curve and 3D pattern",
             configure_demo, run_demo),
    "pattern": (PATTERN_HELP, configure_pattern, run_pattern),
    "curve": ("critical value along a parameter, with the mode switches located",
              configure_curve, run_curve),
    "reproduce": ("the paper's Figures 4-10, the 3D patterns of Figs 9B/10B and an index page",
                  configure_reproduce, run_reproduce),
    "sweep": ("critical points over a grid of tubes, in parallel, into a resumable Zarr store",
              configure_sweep, run_sweep),
    "plot": ("phase diagram (PNG + SVG) of a sweep store", configure_plot, run_plot),
}


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog=PROG, description="Growth, voltage and wrinkling of soft"
                     " electro-elastic tubes (units mu = eps = R_i = 1).")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, (help_text, configure, run) in COMMANDS.items():
        cmd = sub.add_parser(name, help=help_text, description=help_text)
        configure(cmd)
        cmd.set_defaults(run=run)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status (0 ok, 2 bad input, 1 internal error)."""
    try:
        try:
            args = build_parser().parse_args(argv)
        except SystemExit as done:  # --help, --version
            return done.code if isinstance(done.code, int) else 0
        return args.run(args)
    except (UsageError, ElectrogrowthError) as exc:
        print(f"{PROG}: error: {' '.join(str(exc).split())}", file=sys.stderr)
        return 2
    except Exception as exc:  # a bug: still one line, never a traceback
        print(f"{PROG}: internal error: {type(exc).__name__}: {' '.join(str(exc).split())}",
              file=sys.stderr)
        return 1
