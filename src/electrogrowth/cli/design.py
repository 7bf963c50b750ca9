"""``electrogrowth design``: which value of one design variable (or pair of values of two)
gives the target pattern, with the widest margin against the next pattern, and how
sensitive that is.

Registered in :data:`cli.COMMANDS` as ("...", configure_design, run_design). Prints the
region, the switches (boundaries), the best design and the sensitivities (``--json``: one
JSON object); writes ``design_<target>_vs_<key>.csv`` (the first mode along the variable,
switches located) and ``.png`` (the competing modes, the region shaded) into ``--out``; for
two variables ``design_<target>_<x>_<y>.csv`` (the traced boundaries' points), ``.png``
(the map: regions labelled (m, n), boundaries, the target's region, the design; beside it
the design's wrinkled tube in 3D) and ``.nc``
(the map as netCDF, needs xarray).
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
from pathlib import Path

import numpy as np

from ..atomic import replaced, replaced_name, write_figure
from ..errors import ParameterError, UsageError
from ..interrupts import Interrupted
from ..model.layers import KEYS_TEXT
from ..pool import check_workers, usable_cores
from . import resume
from .options import (
    KOITER_COST,
    SHORT_WAVES,
    add_control_options,
    add_mode_range_options,
    bounded_int,
    check_side_option,
    path_arg,
    scan_options_from_args,
)
from .progress import add_quiet_option
from .report import grid_or_located, named_physical, physical_line, supported
from .tube_input import add_any_tube_options, control_of
from .units import QuantityText, check_held_voltage, key_value, number_or_quantity

PLOT_POINTS = 25  # critical values of each competing mode drawn at this many designs
MAP_NODES = 101  # grid points along each variable of a map, at most


def configure_design(parser: argparse.ArgumentParser) -> None:
    from ..incremental.modes import MODE_MAX  # the package's mode range

    what = parser.add_argument_group("what to design")
    add_control_options(what)
    what.add_argument(
        "--target",
        nargs=2,
        action="append",
        type=bounded_int(0, MODE_MAX, SHORT_WAVES),
        metavar=("M", "N"),
        help="the pattern wanted: mode (m, n) = (M, N), each from 0 to"
        f" {MODE_MAX} (repeat for a set of modes)",
    )
    what.add_argument(
        "--target-set",
        choices=("axisymmetric", "prismatic"),
        help="the pattern wanted as a set: axisymmetric (m = 0) or prismatic (n = 0)",
    )
    what.add_argument(
        "--vary",
        nargs=3,
        action="append",
        required=True,
        metavar=("KEY", "LO", "HI"),
        help="the design variable and its range: outer_radius, length, growth, stretch or"
        f" voltage; for a layered --tube any control or key ({KEYS_TEXT}); give it twice"
        " for a map over two variables. With the tube's physical scales below, a length,"
        " voltage, pressure or force may carry its unit (2.6mm 4mm)",
    )
    what.add_argument(
        "--points",
        type=bounded_int(2, 2001),
        default=None,
        metavar="N",
        help="grid points from LO to HI scanned before the switches between them are"
        " located (default 9); with two variables, grid points along each (default 5, at"
        " most 101), from which the boundaries are traced",
    )
    add_any_tube_options(parser, outer_radius=1.4)
    modes = parser.add_argument_group("modes u ~ cos(m theta) cos(n pi z / l)")
    add_mode_range_options(modes)
    parser.add_argument(
        "--out",
        type=path_arg,
        default=None,
        metavar="DIR",
        help="directory for the CSV of the mode sequence and the PNG (none by default)",
    )
    where = parser.add_argument_group(
        "where a map is computed (two variables: the grid's scans, the boundaries traced from"
        " different seeds, the certificates)"
    ).add_mutually_exclusive_group()
    where.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="local worker processes (default: the usable cores; 1 computes in this"
        " process); the map is the same for any N",
    )
    where.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="send them to an existing dask.distributed cluster, e.g. tcp://host:8786",
    )
    parser.add_argument(
        "--koiter",
        action="store_true",
        help="also solve the amplitude equation of the chosen design's wrinkle: super- or"
        " subcritical (as critical --koiter: every wrinkle (m, n) of tubes of any energy"
        f" in a growth, stretch, pressure or voltage control; {KOITER_COST})",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    add_quiet_option(parser)


def _vary(args) -> list[tuple[str, float, float]]:
    if len(args.vary) > 2:
        raise ParameterError("give --vary once or twice (one or two design variables)")
    out = []
    for key, lo, hi in args.vary:  # a value may carry a unit (2.6mm) with the tube's scales
        scales = getattr(args, "scales", None)
        lo, hi = (key_value("--vary", key, v, scales) for v in (lo, hi))
        if not lo < hi:
            raise ParameterError(f"--vary {key} {lo:g} {hi:g}: need LO < HI")
        out.append((key, lo, hi))
    if len(out) == 2 and out[0][0] == out[1][0]:
        raise ParameterError(f"--vary {out[0][0]} is given twice; choose two variables")
    return out


def _has_unit(text: str) -> bool:
    """Whether a bound of --vary (checked by _vary) carries a unit."""
    return isinstance(number_or_quantity(text), QuantityText)


def _target(args):
    if args.target is not None and args.target_set is not None:
        raise ParameterError(
            f"--target and --target-set {args.target_set} are both given; give one of them"
            " (--target M N, repeatable, for listed modes)"
        )
    if args.target is None and args.target_set is None:
        raise ParameterError("give the pattern wanted: --target M N (repeatable) or --target-set")
    if args.target_set is not None:
        return args.target_set
    modes = [tuple(t) for t in args.target]
    return modes[0] if len(modes) == 1 else modes


def run_design(args) -> int:
    from ..design import mode_sequence, prescribe  # the numeric stack, after the checks
    from ..design.sequence import check_vary, shared_variable
    from ..design.targets import check_target

    varies, target = _vary(args), _target(args)
    check_side_option(args)
    tube, solve_for = control_of(args)
    for vary in varies:
        check_vary(vary, tube, solve_for)  # the key and its range, before any work
    volts = [lo for key, lo, _ in args.vary if key == "voltage" and _has_unit(lo)]
    check_held_voltage(args, [v[0] for v in varies], len(tube.layers), (volts or [None])[0])
    if len(varies) == 2 and (same := shared_variable(tube, varies[0][0], varies[1][0])):
        raise ParameterError(
            f"--vary {varies[0][0]} and --vary {varies[1][0]} both set {same} of this tube;"
            " choose two variables"
        )
    if len(varies) == 2:
        if args.points is not None and args.points > MAP_NODES:
            raise ParameterError(
                f"--points {args.points} is too many for a map; at most {MAP_NODES} a variable"
            )
        if args.workers is not None:
            check_workers(args.workers)
        return _run_map(args, tube, solve_for, varies, target)
    if args.workers is not None or args.scheduler is not None:
        raise UsageError(
            "--workers and --scheduler run a map's tasks: give --vary twice (one variable"
            " is one sequence of scans, computed here)"
        )
    vary = varies[0]
    tube = tube.at(vary[0], vary[1])
    options = scan_options_from_args(args)
    points = 9 if args.points is None else args.points
    stem = _stem(check_target(target).name, vary[0])
    earlier, records = None, None  # without --out nothing is kept
    if args.out is not None:
        what = (vary[0], solve_for, args.side, tube)
        earlier, records = resume.resumable(
            args.out, stem, what, points, args, vary=vary, points=points, options=options
        )
    try:
        sequence = mode_sequence(
            tube, solve_for, vary, side=args.side, options=options, points=points,
            resume=earlier,
        )  # fmt: skip
    except Interrupted as stop:  # keep the finished scans
        raise _kept(stop, args.out, stem, points, records) from None
    if _every_point_failed(sequence):
        return 2
    try:
        result = prescribe(
            tube, solve_for, target, vary, options=options, sequence=sequence, koiter=args.koiter
        )
    except Interrupted as stop:  # the sequence is whole: keep it
        raise _kept(Interrupted(stop.signum, str(stop), sequence.curve), args.out, stem) from None
    record = result.as_dict()
    seq = sequence
    _add_physical(record, args, result, {seq.solve_for: result.value, seq.key: result.x})
    if args.out is not None:
        record["files"] = [str(p) for p in _write(result, args.out)]
        record["resumed_points"] = 0 if earlier is None else len(earlier.grid)
        resume.discard(args.out, stem)  # what an interrupted run kept
    if args.json:
        print(json.dumps(record))
        return 0
    lines = summary(result, record.get("physical"))
    print("\n".join(lines + record.get("files", [])))
    return 0


def _add_physical(record: dict, args, result, values: dict) -> None:
    """The design's ``values`` (the control solved for first, then the design variables)
    in physical units (key "physical": those that have a unit) when they are given: the
    help promises them (probe 10b D4: P_o in kPa gave pressure_cr in units mu only)."""
    scales = getattr(args, "scales", None)
    if scales is None or result.status == "not_reached":
        return
    finite = {k: v for k, v in values.items() if v is not None and math.isfinite(v)}
    record["physical"] = named_physical(finite, scales, variables=list(values)[1:])


def _every_point_failed(sequence) -> bool:
    """True, after one line on stderr naming the first failure, when every point of the
    sequence failed (as `curve` and a sweep do): its "failed" intervals hold no design, and
    "widen --m-max / --n-max" would not help (e.g. no mode bifurcates in the range at all)."""
    from ..outcomes import Status

    curve = sequence.curve
    failed = [i for i, k in enumerate(curve.kind) if k in (Status.FAILED, Status.ERROR)]
    if not failed or len(failed) < len(curve.kind):
        return False
    first = " ".join(str(curve.status[failed[0]]).split())
    print(
        f"electrogrowth: error: every point of the design's sequence failed ({len(failed)});"
        f" the first: {first}",
        file=sys.stderr,
    )
    return True


def _stem(target: str, key: str) -> str:
    """The name of a one-variable design's files: design_<target>_vs_<key>."""
    name = re.sub(r"[^A-Za-z0-9]+", "_", target).strip("_")
    return f"design_{name}_vs_{key}".replace("[", "").replace("]", "")


def _kept(
    stop: Interrupted, out: Path | None, stem: str, total: int = 0, records=None
) -> Interrupted:
    """The interrupt, saying what was kept: the scans finished before it (``total`` the
    grid's points; a CSV named .partial.csv, no switch located, and with ``records``,
    (path, run), the points whole for the same command run again, cli/resume.py), or the
    whole mode sequence (total 0: its CSV, no design chosen); nothing without --out."""
    done = stop.partial
    if done is None or not len(done.x):
        return Interrupted(stop.signum, f"{stop}; no point was finished")
    if out is None:
        return Interrupted(stop.signum, f"{stop}; give --out DIR to keep the finished points")
    if not total:
        path = done.to_csv(out / f"{stem}.csv")
        return Interrupted(
            stop.signum, f"{stop}; the mode sequence written to {path} (no design chosen)"
        )
    path = done.to_csv(out / f"{stem}.partial.csv")
    again = resume.keep(records, done)
    return Interrupted(
        stop.signum,
        f"{stop}; {len(done.x)} of {total} points written to {path} (switches not located){again}",
    )


def _write(result, out: Path) -> list[Path]:
    from ..design.sequence import mode_values
    from ..figures.design import plot_design, plotted_modes

    seq = result.sequence
    stem = _stem(result.target, seq.key)
    csv = seq.curve.to_csv(out / f"{stem}.csv")
    xs = np.linspace(seq.lo, seq.hi, PLOT_POINTS)
    values = mode_values(
        seq.curve.params, seq.solve_for, seq.key, plotted_modes(result), xs, side=seq.side
    )
    ax = plot_design(result, values, xs)
    png = write_figure(ax.figure, out / f"{stem}.png")
    return [csv, png]


def summary(result, physical: dict | None = None) -> list[str]:
    """Text lines: the sequence, the region, the best design (``physical``: its values in
    physical units, under it), the largest sensitivities."""
    seq = result.sequence
    side = f" ({seq.side})" if seq.side else ""
    lines = [f"target {result.target}: critical {seq.solve_for}{side} along {seq.key}"]
    creases = dict(zip(result.region, result._crease_rows()))
    for iv in seq.intervals:
        what = _pattern(iv) + (f": {_reason(iv)}" if iv.reason else "")
        lo, hi = (grid_or_located(x, seq.switches) for x in (iv.lo, iv.hi))
        lines.append(f"  {seq.key} {lo} .. {hi}: {what}{_creased(creases.get(iv))}")
    for s in seq.switches:
        lines.append(_change_line(seq, s))
    if result.status == "not_reached":
        lines.append(f"  not reached: {result.note}")
        return lines
    best = BEST.get(result.status, "never first; closest design")
    lines.append(
        f"  {best}: {seq.key} = {result.x:.10g}, mode {result.mode} at {seq.solve_for}_cr ="
        f" {result.value:.10g}, margin {result.margin:.4g} to {_limit(result)}"
    )
    lines += physical_line(physical or {})
    lines += _tied_only_lines(result)
    lines += [f"  note: {result.note}"] if result.note else []
    lines += _verdict_lines(result.verdict)
    if result.to_boundary is not None:
        lines.append(f"  distance to the region's boundary: {result.to_boundary:.6g}")
    lines += _tie_lines(result)
    for p, d in sorted(result.sensitivity.items(), key=lambda kv: -abs(kv[1])):
        lines.append(f"  d{seq.solve_for}_cr/d{p} = {d:.6g}{_margin_slope(result, p)}")
    return lines


def _pattern(iv) -> str:
    """An interval's pattern in words: "mode (m, n)", "threshold", "surface" or "failed"."""
    return f"mode {iv.mode}" if iv.kind == "bifurcation" else str(iv.kind)


def _reason(iv) -> str:
    """A failed interval's failure, its first clause (without "start from a stable
    state")."""
    return iv.reason.split("; ")[0]


def _change_line(seq, s) -> str:
    """A switch or end of the sequence, its two sides in words ((-1, -1) was the threshold,
    the short-wave limit and a failure alike); next to a failed interval, its failure: the
    value at the end of a range where no mode bifurcates before the control's cap is that
    cap (probe 14d: "(-1, -1) -> (-1, -1), growth_cr = 6" said neither)."""
    before, after = seq.sides(s)
    value = s.value if math.isfinite(s.value) else s.value_after  # NaN: from no mode
    line = (
        f"  {s.kind} at {seq.key} = {supported(s.x, s.x_error)}: {_pattern(before)} ->"
        f" {_pattern(after)}, {seq.solve_for}_cr = {supported(value, s.value_error)}"
    )
    failed = [(side, iv) for side, iv in (("before", before), ("after", after)) if iv.reason]
    return line + "".join(f"; {side} it: {_reason(iv)}" for side, iv in failed)


def _tied_only_lines(result) -> list[str]:
    """One line where a target that is first nowhere ties with the next mode at the closest
    design (an interval of no width: its margin is ~0, of either sign by rounding)."""
    from ..design.prescribe import no_width

    point = any(
        no_width(iv, result.sequence) and iv.lo == result.x and iv.mode == result.mode
        for iv in result.sequence.intervals
    )
    if result.status != "not_first" or not point:
        return []
    return [
        f"  {result.mode} only ties with {result.next_mode} at this design (a switch): it is"
        " first on no interval of the range"
    ]


def _tie_lines(result) -> list[str]:
    """One line where competitors tie at the design (a kink of the margin)."""
    if not result.tied_with:
        return []
    lead = RIVALS.get(result.limited_by, result.next_mode)
    names = ", ".join(str(RIVALS.get(t, t)) for t in (lead, *result.tied_with))
    return [
        f"  {names} tie at this design: the margin has a kink there, its derivatives are"
        " one-sided (lowering / raising the parameter)"
    ]


def _margin_slope(result, p: str) -> str:
    """The text ", d(margin)/dp = ..." for one parameter: the two one-sided derivatives at a
    kink, "" where none was formed; a slope within its own error of 0 is 0 within it (the
    rounding of an exact 0 printed as "2.3e-12 lowering it, -8.7e-12 raising it (a kink)",
    check round 29)."""
    error = getattr(result, "margin_error", {}).get(p)
    dm = result.margin_sensitivity.get(p)
    if dm is not None:
        return f", d(margin)/d{p} = {_slope(dm, error)}"
    down, up = result.margin_sides.get(p, (None, None))
    if down is None or up is None:
        return ""
    return (
        f", d(margin)/d{p} = {_slope(down, error)} lowering it, {_slope(up, error)} raising it"
        " (a kink)"
    )


def _slope(d: float, error: float | None) -> str:
    """A margin slope: 0 within its error where it is no larger (+ 0.0: an exact zero prints
    as 0, not -0, probe 14e)."""
    if error is not None and abs(d) <= error:
        return f"0 (within its error {error:.1e})"
    return f"{d + 0.0:.6g}"


#: how the text names the design of each status
BEST = {"found": "best design", "crease_first": "creases first everywhere; nearest design"}


def _creased(crease: dict | None) -> str:
    """What an interval of the region says of the crease ("" for none or not computed)."""
    if not crease or crease.get("crease_first") in (None, "none"):
        return ""
    first, rows = crease["crease_first_points"]
    return f" (a face creases first at {first} of its {rows} points)"


#: how the text names the competitors that are no mode (limited_by, tied_with)
RIVALS = {"crease": "the crease", "surface": "the short-wave limit"}


def _lead(result) -> str:
    """What sets a design's margin, with its value: a mode, the crease or the limit."""
    if result.limited_by == "crease":
        return f"the crease ({result.crease_value:.10g})"
    if result.limited_by == "surface":
        return f"the short-wave limit ({result.surface_value:.10g})"
    return f"{_name(result.next_mode)} ({result.next_value:.10g})"


def _limit(result) -> str:
    """What sets a one-variable design's margin, with its value."""
    if result.limited_by == "no design":  # the room below the target over the room above
        return f"the end of the valid range (next {result.next_mode} at {result.next_value:.10g})"
    if result.limited_by == "range end":  # no competitor before it: a lower bound
        return "the end of the control's range (no competitor comes before it)"
    return _lead(result)


def _verdict_lines(verdict: dict) -> list[str]:
    """The chosen design's verdict in one line, and one more where its pattern may not be
    observed (design/onset.py observable)."""
    from ..design.onset import observable

    if not verdict:
        return []
    lines = [f"  verdict at the design: {verdict['meaning']}"]
    if verdict.get("branch_note") and verdict["branch_note"] != "not asked (--koiter)":
        lines.append(f"  branch not computed: {verdict['branch_note']}")
    warning = observable(verdict)
    return lines + ([f"  {warning}"] if warning else [])


def _run_map(args, tube, solve_for, varies, target) -> int:
    from ..design.mode_map import mode_map
    from ..design.prescribe_map import prescribe_map
    from .progress import enabled

    def say(text: str) -> None:
        print(f"design: {text}", file=sys.stderr, flush=True)

    options = scan_options_from_args(args)
    tube = tube.at(varies[0][0], varies[0][1]).at(varies[1][0], varies[1][1])
    mmap = mode_map(
        tube, solve_for, tuple(varies), side=args.side, options=options,
        points=5 if args.points is None else args.points,
        workers=usable_cores() if args.workers is None else args.workers,
        scheduler=args.scheduler,
        progress=say if not args.json and enabled(args) else None,
    )  # fmt: skip
    result = prescribe_map(tube, target, mmap, options=options, koiter=args.koiter)
    record = result.as_dict()
    (kx, ky), v = mmap.keys, mmap.solve_for
    _add_physical(record, args, result, {v: result.value, kx: result.x, ky: result.y})
    if args.out is not None:
        record["files"] = [str(p) for p in _write_map(result, args.out, tube)]
    if args.json:
        print(json.dumps(record))
        return 0
    lines = map_summary(result, record.get("physical"))
    print("\n".join(lines + record.get("files", [])))
    return 0


def _write_map(result, out: Path, tube) -> list[Path]:
    from ..figures.design import plot_map_pattern

    mmap = result.map
    out.mkdir(parents=True, exist_ok=True)
    name = re.sub(r"[^A-Za-z0-9]+", "_", result.target).strip("_")
    stem = f"design_{name}_{mmap.keys[0]}_{mmap.keys[1]}"
    stem = re.sub(r"[^A-Za-z0-9_.]+", "_", stem)
    csv = out / f"{stem}.csv"
    with replaced(csv) as fh:
        lines = [f"boundary,{mmap.keys[0]},{mmap.keys[1]},critical_{mmap.solve_for},left,right"]
        for k, b in enumerate(mmap.boundaries):
            sides = f"{_text(b.left)},{_text(b.right)}"
            # float(): NumPy 2's repr of its scalars is "np.float64(...)", not a number
            lines += [
                f"{k},{float(x)!r},{float(y)!r},{float(v)!r},{sides}"
                for x, y, v in zip(b.x, b.y, b.value)
            ]
        fh.write("\n".join(lines) + "\n")
    png = write_figure(plot_map_pattern(result, tube), out / f"{stem}.png")  # and the design in 3D
    files = [csv, png]
    try:
        ds = mmap.to_xarray()
    except ImportError:
        return files
    nc = out / f"{stem}.nc"
    try:
        with replaced_name(nc) as name:
            ds.to_netcdf(name)
    except (ImportError, ValueError):
        return files  # no netCDF engine installed
    return files + [nc]


def _text(label) -> str:
    return f"({label[0]} {label[1]})" if isinstance(label, tuple) else str(label)


def _name(label) -> str:
    return f"({label[0]}, {label[1]})" if isinstance(label, tuple) else str(label)


def _uncertified(boundary) -> str:
    """Why a boundary is not certified: its first failed point, what the scan found there
    and how far ahead, with the remedy."""
    c = next(c for c in boundary.certificates if not c.ok)
    where = f"at ({c.x:.8g}, {c.y:.8g})"
    if boundary.left != c.first != boundary.right and math.isfinite(c.ahead):
        missed = f"{_name(c.first)} comes first {where}"
        why = f"{missed}, {-c.ahead:.3g} ahead (a pattern the map missed)"
    else:
        why = f"the two critical values differ by {c.gap:.3g} {where}"
    return f"NOT certified: {why}; raise --points"


def map_summary(result, physical: dict | None = None) -> list[str]:
    """Text lines of a two-variable design: the boundaries, triple points, the design
    (``physical``: its values in physical units, under it)."""
    mmap = result.map
    kx, ky = mmap.keys
    side = f" ({mmap.side})" if mmap.side else ""
    lines = [f"target {result.target}: critical {mmap.solve_for}{side} over {kx} and {ky}"]
    for b in mmap.boundaries:
        ok = "certified" if b.certified else _uncertified(b)
        lines.append(
            f"  boundary {_name(b.left)} | {_name(b.right)}: {len(b.x)} points from"
            f" ({b.x[0]:.8g}, {b.y[0]:.8g}) to ({b.x[-1]:.8g}, {b.y[-1]:.8g}), ends"
            f" {b.ends[0]}/{b.ends[1]}, {ok}"
        )
    for t in mmap.triple_points:
        modes = ", ".join(_name(p) for p in t.patterns)
        lines.append(
            f"  triple point {modes} at ({t.x:.10g}, {t.y:.10g}), {mmap.solve_for}_cr ="
            f" {t.value:.10g}"
        )
    if result.status == "not_reached":
        lines.append(f"  not reached: {result.note}")
        return lines
    rc = result.region_crease
    if rc and rc["crease_first"] != "none":
        first, points = rc["crease_first_points"]
        lines.append(
            f"  a face creases before the target at {first} of the {points} raster points"
            " in its region"
        )
    best = BEST.get(result.status, "never first; closest design")
    lines.append(
        f"  {best}: {kx} = {result.x:.10g}, {ky} = {result.y:.10g}, mode {result.mode} at"
        f" {mmap.solve_for}_cr = {result.value:.10g}, margin {result.margin:.4g} to"
        f" {_lead(result)}"
    )
    lines += physical_line(physical or {})
    lines += [f"  note: {result.note}"] if result.note else []
    lines += _verdict_lines(result.verdict)
    for k, d in result.to_boundary.items():
        if d is not None:
            lines.append(f"  distance to the region's boundary along {k}: {d:.6g}")
    lines += _tie_lines(result)
    for p, d in sorted(result.sensitivity.items(), key=lambda kv: -abs(kv[1])):
        lines.append(f"  d{mmap.solve_for}_cr/d{p} = {d:.6g}{_margin_slope(result, p)}")
    return lines
