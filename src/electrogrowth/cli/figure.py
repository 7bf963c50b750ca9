"""``electrogrowth figure N``: one figure of the paper (PNG + CSV)."""

from __future__ import annotations

import argparse
from pathlib import Path

from ..figures import FIGURES


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
        type=Path,
        default=Path("out"),
        metavar="DIR",
        help="directory for fig<N>.png and fig<N>.csv (default ./out)",
    )
    parser.add_argument("--quick", action="store_true", help="low resolution (previews and tests)")


def run_figure(args) -> int:
    result = FIGURES[args.number](quick=args.quick)
    for path in result.save(args.out):
        print(path)
    return 0
