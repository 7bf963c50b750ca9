"""``electrogrowth figure N``: one figure of the paper (PNG + CSV)."""

from __future__ import annotations

import argparse
from pathlib import Path

from ..figures import FIGURES
from .options import path_arg
from .progress import add_quiet_option, progress_options, stage


def configure_figure(parser: argparse.ArgumentParser) -> None:
    titles = (
        (n, (FIGURES[n].__doc__ or "").strip().split("\n")[0].rstrip(".")) for n in sorted(FIGURES)
    )
    parser.add_argument(
        "number",
        type=int,
        choices=sorted(FIGURES),
        help="paper figure: " + "; ".join(f"{n}: {t}" for n, t in titles),
    )
    parser.add_argument(
        "--out",
        type=path_arg,
        default=Path("out"),
        metavar="DIR",
        help="directory for fig<N>.png and fig<N>.csv (default ./out)",
    )
    parser.add_argument("--quick", action="store_true", help="low resolution (previews and tests)")
    add_quiet_option(parser)


def run_figure(args) -> int:
    fn = FIGURES[args.number]
    with stage(args, f"computing figure {args.number}"):  # its curves show their own bars
        result = fn(quick=args.quick, **progress_options(fn, args))
    for path in result.save(args.out):
        print(path)
    return 0
