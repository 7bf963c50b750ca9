"""``electrogrowth curve``: the critical value along a parameter, mode switches located.

Registered in :data:`cli.COMMANDS` as ("...", configure_curve, run_curve). Writes
``curve_<solve_for>_vs_<along>.csv`` and ``.png`` into ``--out`` and prints a summary
(``--json``: one JSON object). Progress bars (the points, then the switches being
located) go to stderr when it is a terminal. Points whose critical value is not certified
to the accuracy asked (status "inaccurate" in the CSV and JSON) get one warning line on
stderr; the exit status stays 0 (unlike ``critical``): the curve is written, each such row
marked. A curve whose every point failed is written too, and exits 2 with one line naming
the first failure (as a sweep does).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from ..atomic import write_figure
from ..bifurcation.curves import MAX_POINTS, check_curve, critical_curve
from ..digits import decimal_grid
from ..errors import ParameterError
from ..figures.plots import plot_curve
from ..figures.style import wrapped_title
from ..interrupts import Interrupted
from ..model.layers import KEYS_TEXT
from ..outcomes import Status
from ..summary import tube_text
from . import resume
from .options import (
    add_control_options,
    add_mode_range_options,
    check_side_option,
    path_arg,
    scan_options_from_args,
)
from .progress import add_quiet_option, enabled
from .report import (
    NAMED,
    face_text,
    grid_or_located,
    named_physical,
    physical_line,
    supported,
    warn,
)
from .tube_input import add_any_tube_options, control_of
from .units import check_held_voltage, key_value

#: How each parameter is described in the options' help (the paper's terms).
MEANING = {
    "growth": "the isotropic growth factor g (F_g = g I)",
    "stretch": "the total axial stretch lambda_z = l / L, growth included",
    "voltage": "the radial voltage Vbar = V / (R_o - R_i) sqrt(eps / mu)",
    "outer_radius": "the undeformed outer radius Rbar_o = R_o / R_i",
    "length": "the undeformed length L / R_i",
}


def configure_curve(parser: argparse.ArgumentParser) -> None:
    what = parser.add_argument_group("what to compute")
    add_control_options(what)
    what.add_argument(
        "--along",
        required=True,
        metavar="NAME",
        help="the abscissa: "
        + "; ".join(f"{k} = {v}" for k, v in MEANING.items())
        + ". For a layered --tube: any control (growth[K], growth[K].theta, stretch, voltage,"
        f" pressure, force) or key of the tube ({KEYS_TEXT})",
    )
    what.add_argument(
        "--from",
        dest="start",
        required=True,
        metavar="X0",
        help="first value of the --along parameter (with the tube's physical scales below,"
        " a length, voltage, pressure or force may carry its unit: 2.6mm)",
    )
    what.add_argument(
        "--to",
        dest="stop",
        required=True,
        metavar="X1",
        help="last value of the --along parameter",
    )
    what.add_argument(
        "--points",
        type=int,
        default=30,
        metavar="N",
        help="grid points from X0 to X1 (>= 2, default 30); switches of the"
        " critical mode (m, n) between them are located exactly",
    )
    add_any_tube_options(parser, outer_radius=1.4)  # --along and --solve-for values ignored
    modes = parser.add_argument_group("modes u ~ cos(m theta) cos(n pi z / l)")
    add_mode_range_options(modes)
    parser.add_argument(
        "--out",
        type=path_arg,
        default=Path("out"),
        metavar="DIR",
        help="directory for the CSV and PNG (default ./out)",
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object instead of text (no progress bar)",
    )
    add_quiet_option(parser)


def run_curve(args) -> int:
    params, solve_for = control_of(args)
    check_curve(solve_for, args.along, params)
    scales = getattr(args, "scales", None)  # --from 2.6mm: a value with the tube's scales
    args.start, args.stop = (key_value(f, args.along, v, scales) for f, v in
                             (("--from", args.start), ("--to", args.stop)))  # fmt: skip
    check_held_voltage(args, [args.along], len(params.layers))
    params = params.at(args.along, args.start)
    if not 2 <= args.points <= MAX_POINTS:
        raise ParameterError(
            f"--points = {args.points} is out of range; need 2 to {MAX_POINTS} (a curve"
            " point is a mode scan, ~1 s)"
        )
    options = scan_options_from_args(args)
    check_side_option(args)
    if args.start == args.stop:
        raise ParameterError(f"--from = --to = {args.start:g}; need two different values")
    values = np.array(decimal_grid(args.start, args.stop, args.points))  # 0.1, not 0.09999...
    stem = f"curve_{solve_for}_vs_{args.along}".replace("[", "").replace("]", "")
    what = (args.along, solve_for, args.side, params)
    earlier, records = resume.resumable(
        args.out, stem, what, args.points, args, values=values.tolist(), options=options
    )
    try:
        curve = critical_curve(  # bars over the points, then the switches being located
            params,
            solve_for,
            args.along,
            values,
            side=args.side,
            options=options,
            progress=not args.json and enabled(args),
            resume=earlier,
        )
    except Interrupted as stop:  # keep the finished points
        raise _kept(stop, args.out / f"{stem}.partial.csv", args.points, records) from None
    csv = curve.to_csv(args.out / f"{stem}.csv")
    resume.discard(args.out, stem)  # what an interrupted run kept
    ax = plot_curve(curve)
    wrapped_title(ax, tube_text(curve.params, SYMBOLS, skip=(curve.along, curve.solve_for)), 8)
    png = write_figure(ax.figure, args.out / f"{stem}.png")
    warn(_inaccurate_text(curve))
    physical = _physical(curve, getattr(args, "scales", None))
    if args.json:
        extra = {"physical": physical} if physical else {}
        extra["resumed_points"] = 0 if earlier is None else len(earlier.grid)
        print(json.dumps({**curve.as_dict(), **extra, "csv": str(csv), "png": str(png)}))
    else:
        print("\n".join(summary(curve) + physical_line(physical) + [str(csv), str(png)]))
    return _all_failed(curve)


def _physical(curve, scales) -> dict:
    """The curve's fixed loads and sizes and the range of its critical value in physical
    units, when they are given: the help promises them (probe 10b D4: --inner-pressure
    5kPa came back as P_i = 0.05 alone)."""
    if scales is None:
        return {}
    skip = {NAMED.get(curve.along), NAMED.get(curve.solve_for)}
    fixed = {
        k: v
        for k, v in curve.params.record().items()
        if isinstance(v, (int, float)) and NAMED.get(k) not in skip
    }
    out = named_physical(fixed, scales, variables=(curve.along,))
    ok = np.isfinite(curve.value)
    if ok.any():
        for end, value in (("min", curve.value[ok].min()), ("max", curve.value[ok].max())):
            solved = named_physical({curve.solve_for: float(value)}, scales, (curve.along,))
            for entry in solved.values():  # none: the control has no unit (growth)
                out[f"{curve.solve_for}_cr_{end}"] = entry
    return out


def _failed(curve) -> list[int]:
    """The rows of ``curve`` whose point failed."""
    return [i for i, k in enumerate(curve.kind) if k in (Status.FAILED, Status.ERROR)]


def _all_failed(curve) -> int:
    """0, or 2 with one line naming the first failure when every point failed (as a sweep
    does): a written curve of failures is no result."""
    failed = _failed(curve)
    if not failed or len(failed) < len(curve.kind):
        return 0
    first = " ".join(str(curve.status[failed[0]]).split())
    print(
        f"electrogrowth: error: every point of the curve failed ({len(failed)}); the first:"
        f" {first}",
        file=sys.stderr,
    )
    return 2


def _inaccurate_text(curve) -> str:
    """The warning for rows not certified to the accuracy asked ("" if there are none)."""
    count = int(curve.inaccurate.sum())
    if not count:
        return ""
    return (
        f"{count} of {len(curve.x)} points are inaccurate: their critical value's error"
        ' estimate exceeds the accuracy asked even after refinement (status "inaccurate"'
        " in the table)"
    )


def _kept(stop: Interrupted, path: Path, total: int, records=None) -> Interrupted:
    """The interrupt, saying where the points finished before it were written (a CSV named
    .partial.csv: the grid points only, no switch located; with ``records``, (path, run),
    also the points whole for the same command run again, cli/resume.py)."""
    done = stop.partial
    if done is None or not len(done.x):
        return Interrupted(stop.signum, f"{stop}; no point was finished")
    done.to_csv(path)
    again = resume.keep(records, done)
    return Interrupted(
        stop.signum,
        f"{stop}; {len(done.x)} of {total} points written to {path} (switches not located){again}",
    )


#: the symbols of the CLI's text (ASCII)
SYMBOLS = {
    "outer_radius": "Rbar_o",
    "length": "L",
    "growth": "g",
    "stretch": "lambda_z",
    "voltage": "Vbar",
    "layer_outer_radii": "R_k",
    "axial_force": "N",
    "inner_pressure": "P_i",
    "outer_pressure": "P_o",
}


def summary(curve) -> list[str]:
    """Text lines: the fixed parameters, the range of the critical value, each branch
    (mode and extent) and each switch."""
    side = f" ({curve.side})" if curve.side else ""
    lines = [
        f"critical {curve.solve_for}{side} along {curve.along}: "
        + tube_text(curve.params, SYMBOLS, skip=(curve.along, curve.solve_for))
    ]
    ok = np.isfinite(curve.value)
    if ok.any():
        lines.append(
            f"  {curve.solve_for}_cr from {curve.value[ok].min():.10g} to "
            f"{curve.value[ok].max():.10g}"
        )
    located = (*curve.switches, *curve.ends)
    for _, rows in curve.branches():
        lo, hi = (grid_or_located(curve.x[i], located) for i in (rows[0], rows[-1]))
        lines.append(f"  {curve.along} {lo} .. {hi}: {_branch_text(curve, rows[0])}")
    for s in curve.switches:  # with the digits their error estimates support
        jump = abs(s.value_after - s.value) > 1e-9 * max(1.0, abs(s.value))
        value = (
            f"jumps from {supported(s.value, s.value_error)} to"
            f" {supported(s.value_after, s.value_error)}"
            if jump
            else f"= {supported(s.value, s.value_error)}"
        )
        lines.append(
            f"  switch at {curve.along} = {supported(s.x, s.x_error)}, {curve.solve_for}_cr"
            f" {value}: {_mode(s.mode_before)} -> {_mode(s.mode_after)}"
        )
    for e in curve.ends:
        lines.append(_end_line(curve, e))
    lines.append(crease_line(curve))
    for i in _failed(curve):
        lines.append(f"  failed at {curve.along} = {curve.x[i]:.10g}: {curve.status[i]}")
    return lines


def _end_line(curve, e) -> str:
    """One line: the branch that ends at ``e``, where, and what comes after it."""
    rows = np.flatnonzero((curve.x == e.x) & (curve.kind == "end"))
    limit = [i for i in rows if curve.surface[i]]  # the short-wave limit's row at the end
    after = None
    if e.mode_after[0] < 0:
        after = (
            f"the short-wave limit at {face_text(curve.surface_face[limit[-1]])} from"
            f" {supported(e.value_after, e.value_error)}"
            if limit
            else "the threshold (axisymmetric state lost)"
        )
    branch = f"branch {_mode(e.mode_before)}"
    if e.mode_before[0] < 0 and e.mode_after[0] < 0 and limit:  # limit <-> threshold
        limit_first = bool(curve.surface[rows[0]])
        if limit_first:
            branch = f"the short-wave limit at {face_text(curve.surface_face[limit[0]])}"
            after = "the threshold (axisymmetric state lost)"
        else:
            branch = "the threshold (axisymmetric state lost)"
    return (
        f"  {branch} ends at {curve.along} = {supported(e.x, e.x_error)},"
        f" {curve.solve_for}_cr = {supported(e.value, e.value_error)}; then "
        + (after or f"{_mode(e.mode_after)} from {supported(e.value_after, e.value_error)}")
    )


def _branch_text(curve, row: int) -> str:
    """What is critical on the branch of ``row``: a mode, the exact short-wave limit (at its
    face, as `critical` says it) or the threshold."""
    if curve.m[row] >= 0:
        return f"mode (m, n) = ({curve.m[row]}, {curve.n[row]})"
    if curve.surface[row]:
        face = curve.surface_face[row]
        at = f", at {face_text(face)}" if face else ""  # a record from before the face was kept
        return f"short-wave (surface) instability, the exact limit m, n -> infinity{at}"
    return "threshold (axisymmetric state lost)"


def crease_line(curve) -> str:
    """One line: where along the curve a free face creases before the wrinkle (the crease
    criterion at every point, bifurcation/curve_crease.py), or that it nowhere does; the
    field criterion's early bound, never ranked, is said apart, before or after the
    critical value along the control's direction (as `critical` words it)."""
    c = curve.crease
    first = np.flatnonzero(c.first)
    if not first.size:
        return "  crease: no point creases before it wrinkles" + "".join(
            f"; {clause}" for clause in _later_creases(curve)
        )
    xs = curve.x[first]
    faces = ", ".join(sorted({f"{c.face[i]} face ({c.trigger[i]})" for i in first}))
    return (
        f"  crease first at {len(set(xs.tolist()))} of {len(set(curve.x.tolist()))} points,"
        f" {curve.along} {_range(xs)}: the {faces} creases at {curve.solve_for} ="
        f" {_range(c.value[first])} before the wrinkle (the pattern there is a crease)"
    )


def _later_creases(curve) -> list[str]:
    """Clauses for the crease values found that do not come first: the field criterion's
    bound before or after the critical value along the control (its sign: compression
    lowers it), and a mechanical crease after it; rows without a critical value say
    neither."""
    c = curve.crease
    sense = -1.0 if curve.side == "compression" else 1.0
    found = np.isfinite(c.value) & np.isfinite(curve.value)
    before = found & (sense * c.value < sense * curve.value)  # a tie: the linear result first
    field = np.array([t == "field" for t in c.trigger], bool).reshape(found.shape)
    clauses = []
    for rows, when in ((field & before, "before"), (field & found & ~before, "after")):
        if rows.any():
            faces = sorted({c.face[i] for i in np.flatnonzero(rows)})
            whose = f"the {faces[0]} face's" if len(faces) == 1 else "the inner and outer faces'"
            clauses.append(
                f"{whose} field reaches the electro-creasing field of a bonded, unstretched"
                f" film (an early bound for a crease, not ranked) at {curve.solve_for} ="
                f" {_range(c.value[rows])}, {when} the critical value"
            )
    later = found & ~field & ~before
    if later.any():
        clauses.append(f"a face creases later, from {curve.solve_for} = {_range(c.value[later])}")
    return clauses


def _range(values) -> str:
    lo, hi = float(np.min(values)), float(np.max(values))
    return f"{lo:.4g}" if f"{lo:.4g}" == f"{hi:.4g}" else f"{lo:.4g} .. {hi:.4g}"


def _mode(mode) -> str:
    return "threshold" if mode[0] < 0 else f"({mode[0]}, {mode[1]})"
