"""``electrogrowth sweep`` (a grid of critical points into a Zarr store) and ``electrogrowth
plot`` (its phase diagram). xarray, zarr and dask (the ``sweep`` extra) are imported only
when one of them runs, so the other commands work without them."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..atomic import write_figure
from ..errors import ElectrogrowthError, UsageError
from ..interrupts import Interrupted, interrupt_of
from ..model.toml_input import read_text
from ..pool import check_workers
from ..sweep.file import load_config
from ..sweep.run import compute_sweep
from .options import path_arg
from .progress import enabled

EXTRA = "pip install 'electrogrowth[sweep]'"


def _need_sweep_extra() -> None:
    missing = []
    for module in ("xarray", "zarr"):
        try:
            __import__(module)
        except ImportError:
            missing.append(module)
    if missing:
        raise ElectrogrowthError(f"this command needs {' and '.join(missing)}: {EXTRA}")


# -- sweep -----------------------------------------------------------------------------------


def configure_sweep(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "file",
        type=path_arg,
        metavar="SWEEP.toml",
        help="the sweep: material (or a layered [tube] file, whose controls and keys such as"
        " layers[1].thickness it may fix and vary), fixed parameters, grids, what to solve for,"
        " mode ranges and rtol (see docs/sweeps.md and"
        " examples/sweep.toml); checked in full before any work",
    )
    parser.add_argument(
        "--out",
        type=path_arg,
        metavar="STORE.zarr",
        help="the Zarr store of the results (default: the file's name with"
        " .zarr, in the current directory). If it holds the same sweep,"
        " only the unfinished chunks are computed (resume)",
    )
    where = parser.add_mutually_exclusive_group()
    where.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="local worker processes (default: the usable cores; 1 computes in this process)",
    )
    where.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run on an existing dask.distributed cluster, e.g."
        " tcp://host:8786 (started with `dask scheduler` and `dask worker"
        " tcp://host:8786 --nthreads 1`); results are written here",
    )
    parser.add_argument(
        "--check",
        action="store_true",
        help="only validate the file (and an existing store) and print the plan; compute nothing",
    )
    parser.add_argument(
        "--quiet", action="store_true", help="no progress bar (shown only on a terminal)"
    )


def run_sweep(args) -> int:
    config = load_config(args.file)
    if args.workers is not None:
        check_workers(args.workers)
    _need_sweep_extra()
    out = args.out if args.out is not None else Path(args.file.stem + ".zarr")
    if args.check:
        return _print_plan(config, out)
    try:
        summary = compute_sweep(
            config,
            out,
            workers=args.workers,
            scheduler=args.scheduler,
            progress=enabled(args),  # a terminal, and no --quiet
            source_text=read_text(args.file, "sweep file"),  # as the config read it
        )
    except KeyboardInterrupt as exc:  # main prints the one line and exits 130 / 143
        stop = interrupt_of(exc)
        raise Interrupted(
            stop.signum,
            f"{stop}; the finished chunks are saved in {out}: run the same command again"
            " to resume",
        ) from None
    print(summary.text())
    failed = summary.counts.get("failed", 0) + summary.counts.get("error", 0)
    if failed and failed == sum(v for k, v in summary.counts.items() if k != "pending"):
        from ..sweep.store import open_results  # the sweep extra

        ds = open_results(out)
        first = next(
            str(m)
            for s, m in zip(ds["status"].values.flat, ds["message"].values.flat)
            if s != "ok"
        )
        print(
            f"electrogrowth: error: every computed point of the sweep failed ({failed});"
            f" the first: {' '.join(first.split())}",
            file=sys.stderr,
        )
        return 2
    return 0


def _print_plan(config, out: Path) -> int:
    from ..sweep.store import block_shape, check_same_sweep, grid_blocks  # the sweep extra

    state = "new store"
    if out.exists():
        check_same_sweep(out, config)
        state = "existing store of the same sweep: resumes"
    blocks = grid_blocks(config.shape, block_shape(config.shape, config.chunk))
    grid = " x ".join(f"{name} ({len(v)}: {v[0]:g} .. {v[-1]:g})" for name, v in config.grid)
    print(
        f"{config.size} points: {grid}; critical {config.solve_for}"
        f"{' (' + config.side + ')' if config.side else ''},"
        f" modes m {list(config.scan.m_range)}, n {list(config.scan.n_range)},"
        f" rtol {config.rtol:g}"
        f"{', with the amplitude equation (koiter)' if config.koiter else ''};"
        f" {len(blocks)} chunks of up to"
        f" {config.chunk} points; {out}: {state}"
    )
    return 0


# -- plot ------------------------------------------------------------------------------------


def configure_plot(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "store",
        type=path_arg,
        metavar="RESULTS.zarr",
        help="a store written by `electrogrowth sweep` (may be unfinished)",
    )
    parser.add_argument(
        "--x", metavar="PARAM", help="swept parameter on the horizontal axis (default the first)"
    )
    parser.add_argument(
        "--y", metavar="PARAM", help="swept parameter on the vertical axis (default the second)"
    )
    parser.add_argument(
        "--at",
        action="append",
        default=[],
        metavar="PARAM=VALUE",
        help="value of a further swept parameter (the nearest grid value;"
        " default its first value); repeatable",
    )
    parser.add_argument(
        "--out",
        type=path_arg,
        default=Path("out"),
        metavar="DIR",
        help="directory for <store>_<x>_<y>.png and .svg (default ./out)",
    )


def run_plot(args) -> int:
    _need_sweep_extra()
    from ..figures.phase_diagram import phase_diagram  # start-up speed: matplotlib, `plot` only
    from ..sweep.store import open_results  # the sweep extra (xarray, zarr)

    ds = open_results(args.store)
    dims = [d for d in ds["critical_value"].dims]
    x = args.x or dims[0]
    y = args.y or next((d for d in dims if d != x), None)
    fig = phase_diagram(ds, x, y, at=_parse_at(args.at))
    args.out.mkdir(parents=True, exist_ok=True)
    stem = f"{args.store.name.removesuffix('.zarr')}_{x}_{y}"
    for path in (args.out / f"{stem}.png", args.out / f"{stem}.svg"):
        write_figure(fig, path, dpi=150)
        print(path)
    return 0


def _parse_at(items: list[str]) -> dict:
    at = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep:
            raise UsageError(f"--at {item!r}: expected PARAM=VALUE, e.g. --at length=2")
        try:
            at[name.strip()] = float(value)
        except ValueError:
            raise UsageError(
                f"--at {item!r}: the value {value.strip()!r} is not a number"
                " (non-dimensional, as the store's grid), e.g. --at length=2"
            ) from None
    return at
