"""``electrogrowth pattern``: the wrinkling mode at onset, through the wall and in 3D.

Finds the critical point (one mode with ``--mode M N``, else the first mode to bifurcate
over a scan), computes its mode shape (shapes/mode_shape.py) and writes, on request, a 3D
picture of the wrinkled tube, a plot and a CSV of the mode shape (``--out DIR``) and a VTK mesh of
the wall (``--vtk FILE``). Each stage (a few seconds) is named on stderr when it is a
terminal and ``--quiet`` is not given (cli/progress.py); stdout is left to the results.
To register: ``COMMANDS["pattern"] = (HELP, configure_pattern, run_pattern)`` in cli/app.py.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
from pathlib import Path

import numpy as np

from ..atomic import replaced, write_figure
from ..bifurcation.critical import critical_value
from ..bifurcation.scan import scan_modes
from ..errors import MissingDependencyError, ParameterError
from ..figures.plots import plot_mode_shape, render_pattern
from ..incremental.targets import Family
from ..outcomes import Status
from ..shapes.mode_shape import mode_shape
from ..shapes.wall import export_vtk
from .critical_text import tube_line, value_name
from .options import (
    MODE_COVERAGE,
    add_control_options,
    add_method_option,
    add_mode_option,
    add_mode_range_options,
    check_side_option,
    finite_number,
    mode_from_args,
    path_arg,
    scan_options_from_args,
)
from .progress import add_quiet_option, stage
from .report import edge_warning, physical_line, physical_record, supported, warn
from .tube_input import add_any_tube_options, control_of

HELP = "mode shape of the wrinkles at onset: 3D picture, plot and CSV, VTK mesh of the wall"

#: Radii at which the shape is sampled, at most (10^4: ~15 s; more only costs time).
MAX_RADII = 10_000


def configure_pattern(parser: argparse.ArgumentParser) -> None:
    add_control_options(parser)
    add_any_tube_options(parser)
    modes = parser.add_argument_group(
        "wrinkling mode u_r = U_r(r) cos(m theta) cos(k z), k = n pi / (lambda_z L)",
        MODE_COVERAGE + " Without --mode the scan's critical mode"
        " is drawn (a surface instability has no finite mode"
        " shape).",
    )
    add_mode_option(modes)
    add_mode_range_options(modes)
    shape = parser.add_argument_group("mode shape and output")
    add_method_option(
        shape,
        "impedance = the paper's Riccati equation for the surface impedance,"
        " then dU/dr = (G1 + G2 z) U / r inwards from the outer face (default;"
        " where the impedance has a pole inside the wall, the independent"
        " collocation method is used instead and the output says so);"
        " collocation = the null vector of the independent Chebyshev"
        " collocation method",
    )
    shape.add_argument(
        "--points",
        type=int,
        default=101,
        help="radii through the wall at which the mode shape is sampled (default 101)",
    )
    shape.add_argument(
        "--amplitude",
        type=finite_number,
        default=0.1,
        metavar="A",
        help="largest incremental displacement drawn, in units of R_i (the"
        " mode has max |U| = 1; default 0.1)",
    )
    shape.add_argument(
        "--out",
        type=path_arg,
        metavar="DIR",
        help="write pattern-m<M>-n<N>.png (3D wrinkled tube, coloured by u_r),"
        " mode-shape-m<M>-n<N>.png (U_r, U_theta, U_z, Phi against r) and"
        " mode-shape-m<M>-n<N>.csv into DIR (a torsional mode: the names"
        " end in -torsional and no 3D picture is drawn)",
    )
    shape.add_argument(
        "--vtk",
        type=path_arg,
        metavar="FILE",
        help="write the wall as a hexahedral VTK mesh (.vtu or .vtk) with"
        " point data displacement, radial_displacement, potential and"
        " r_reference (open in ParaView, Warp By Vector); needs meshio"
        " (pip install 'electrogrowth[vtk]')",
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object (critical point, mode, route, files) instead of text",
    )
    add_quiet_option(parser)


def run_pattern(args) -> int:
    params, solve_for = control_of(args)
    check_side_option(args)
    if not (math.isfinite(args.amplitude) and args.amplitude >= 0):
        raise ParameterError(f"--amplitude = {args.amplitude:g} is out of range; need A >= 0")
    if not 2 <= args.points <= MAX_RADII:
        raise ParameterError(
            f"--points = {args.points} is out of range; need 2 to {MAX_RADII} radii"
        )
    if args.vtk is not None and args.vtk.suffix not in (".vtu", ".vtk"):
        raise ParameterError(f"--vtk {args.vtk} must end in .vtu (XML) or .vtk (legacy)")
    if args.vtk is not None and importlib.util.find_spec("meshio") is None:
        raise MissingDependencyError(
            "--vtk needs the optional package meshio; install it"
            " with pip install 'electrogrowth[vtk]'"
        )
    mode = mode_from_args(args)
    if mode is not None and mode[2] == Family.TORSIONAL:
        _check_torsional_outputs(args)
    if mode is not None:
        m, n, family = mode
        with stage(args, f"solving mode ({m}, {n})"):
            crit = critical_value(params, m, n, solve_for, family=family, side=args.side)
    else:
        options = scan_options_from_args(args)
        with stage(args, "solving the critical mode (a scan of the modes)"):
            scan = scan_modes(params, solve_for, side=args.side, options=options)
        crit = scan.critical
        warn(edge_warning(scan))
        warn(crit.message if crit.status == Status.INACCURATE else "")  # the cap, an estimate
        if crit.family == Family.TORSIONAL:
            _check_torsional_outputs(args)
    with stage(args, f"mode shape of ({crit.m}, {crit.n}) through the wall"):
        shape = mode_shape(crit, method=args.method, points=args.points)
    files = []
    if args.out is not None:
        with stage(args, f"3D pattern and mode-shape plot into {args.out}"):
            files += write_outputs(shape, args.out, amplitude=args.amplitude)
    if args.vtk is not None:
        with stage(args, f"VTK mesh of the wall into {args.vtk}"):
            files.append(export_vtk(shape, args.vtk, amplitude=args.amplitude))
    record = crit.as_dict()
    record.update(
        k=shape.k,
        route=shape.route,
        note=shape.note,
        boundary_residual=shape.boundary_residual,
        amplitude=args.amplitude,
        max_abs={
            name: float(np.abs(getattr(shape, name)).max())
            for name in ("U_r", "U_th", "U_z", "Phi")
        },
        files=[str(f) for f in files],
    )
    if getattr(args, "scales", None) is not None:
        record["physical"] = physical_record(record, args.scales)
    if args.json:
        print(json.dumps(record))
        return 0
    _print_text(record)
    return 0


def _check_torsional_outputs(args) -> None:
    """--vtk draws the paper's ansatz, in which a torsional mode vanishes: refuse it."""
    if args.vtk is not None:
        raise ParameterError(
            "--vtk is not available for a torsional mode: the wall mesh"
            " draws the paper's ansatz (u_theta ~ sin(m theta), zero at"
            " m = 0); use --out for its mode shape plot and CSV"
        )


def write_outputs(shape, directory: Path, *, amplitude: float) -> list[Path]:
    """The 3D picture, the mode-shape plot and its CSV in ``directory`` (created).

    A torsional mode has no 3D picture (shapes/wall.py draws the paper's ansatz, in which
    u_theta ~ sin(m theta) vanishes at m = 0), and its names end in -torsional.
    """
    directory.mkdir(parents=True, exist_ok=True)
    torsional = shape.family == Family.TORSIONAL
    stem = f"m{shape.m}-n{shape.n}" + ("-torsional" if torsional else "")
    pattern = directory / f"pattern-{stem}.png"
    plot, csv = directory / f"mode-shape-{stem}.png", directory / f"mode-shape-{stem}.csv"
    if not torsional:
        render_pattern(shape, amplitude=amplitude, path=pattern)
    write_figure(plot_mode_shape(shape), plot)
    columns, table = shape.table()
    with replaced(csv) as fh:
        np.savetxt(fh, table, delimiter=",", header=",".join(columns), comments="", fmt="%.15g")
    return ([] if torsional else [pattern]) + [plot, csv]


def _print_text(rec: dict) -> None:
    name = value_name(rec["solve_for"])
    big = rec["max_abs"]
    lines = [
        f"{name} = {supported(rec['value'], rec['error_estimate'])}   mode (m, n) ="
        f" ({rec['m']}, {rec['n']}),"
        f" {rec['family']}, k = {rec['k']:.6g}",
        tube_line(rec),
        f"  mode shape by the {rec['route']} method (boundary residual"
        f" {rec['boundary_residual']:.1e}): max |U_r|, |U_theta|, |U_z| = {big['U_r']:.4g},"
        f" {big['U_th']:.4g}, {big['U_z']:.4g}; max |Phi| = {big['Phi']:.4g}",
    ]
    lines += physical_line(rec.get("physical", {}))
    if rec["note"]:
        lines.append(f"  note: {rec['note']}")
    lines += [f"  wrote {f}" for f in rec["files"]]
    print("\n".join(lines))
