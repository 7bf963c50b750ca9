"""The ``electrogrowth`` command line (also ``python -m electrogrowth``).

Each subcommand is a pair of functions in :data:`COMMANDS`: ``configure(parser)`` adds its
options, ``run(args) -> int`` does the work. :func:`main` parses, dispatches and turns every
failure into one line ``electrogrowth: error: <message>`` on stderr with exit status 2
(1 for an unexpected internal error); no traceback reaches the user. To add a subcommand,
write the two functions (a module of this package) and add an entry to :data:`COMMANDS`;
figures are registered in ``electrogrowth.figures.FIGURES``.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable
from importlib.metadata import version

from ..errors import ElectrogrowthError
from .critical import configure_critical, run_critical
from .curve import configure_curve, run_curve
from .demo import configure_demo, run_demo
from .figure import configure_figure, run_figure
from .options import _Parser
from .pattern import HELP as PATTERN_HELP
from .pattern import configure_pattern, run_pattern
from .reproduce import configure_reproduce, run_reproduce
from .state import configure_state, run_state
from .sweep import configure_plot, configure_sweep, run_plot, run_sweep

PROG = "electrogrowth"

#: Subcommand name -> (one-line help, configure(parser), run(args) -> exit status).
COMMANDS: dict[str, tuple[str, Callable, Callable]] = {
    "state": (
        "solve the axisymmetric base state of a grown, stretched, charged tube",
        configure_state,
        run_state,
    ),
    "figure": ("reproduce a figure of the paper (PNG + CSV)", configure_figure, run_figure),
    "critical": (
        "critical growth factor, axial stretch or voltage for the onset of"
        " wrinkling, for one mode or scanned over modes",
        configure_critical,
        run_critical,
    ),
    "demo": (
        "the paper's headline tube (Rbar_o = 1.4, L = 1, lambda_z = 1, Vbar = 0.4):"
        " base state, critical growth and mode, curve and 3D pattern",
        configure_demo,
        run_demo,
    ),
    "pattern": (PATTERN_HELP, configure_pattern, run_pattern),
    "curve": (
        "critical value along a parameter, with the mode switches located",
        configure_curve,
        run_curve,
    ),
    "reproduce": (
        "the paper's Figures 4-10, the 3D patterns of Figs 9B/10B and an index page",
        configure_reproduce,
        run_reproduce,
    ),
    "sweep": (
        "critical points over a grid of tubes, in parallel, into a resumable Zarr store",
        configure_sweep,
        run_sweep,
    ),
    "plot": ("phase diagram (PNG + SVG) of a sweep store", configure_plot, run_plot),
}


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog=PROG,
        description="Growth, voltage and wrinkling of soft"
        " electro-elastic tubes (units mu = eps = R_i = 1).",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {version(PROG)}")
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
    except ElectrogrowthError as exc:  # bad input, or a failure with a remedy
        text = " ".join(str(exc).split())
        remedy = f" ({exc.remedy})" if exc.remedy else ""
        print(f"{PROG}: error: {text}{remedy}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # the reader went away (e.g. `| head`): end quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no flush error
        return 0
    except Exception as exc:  # a bug: still one line, never a traceback
        print(
            f"{PROG}: internal error: {type(exc).__name__}: {' '.join(str(exc).split())}",
            file=sys.stderr,
        )
        return 1
