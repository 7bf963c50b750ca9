"""``electrogrowth postbuckle``: the post-buckled cross-section of a prismatic mode (m, 0), or
meridian of an axisymmetric mode (0, n), by finite elements, from the package's onset (the
``fe`` extra)."""

from __future__ import annotations

import argparse
import csv
import json
import sys
from pathlib import Path

from ..atomic import replaced, replaced_name, write_figure
from ..errors import ElectrogrowthError, MissingDependencyError, ParameterError, Remedy
from ..interrupts import Interrupted
from ..outcomes import Kind
from .options import add_control_options, bounded_int, check_side_option, finite_number
from .progress import add_quiet_option, enabled
from .report import named_physical, physical_line
from .tube_input import add_any_tube_options, control_of

INSTALL = "pip install 'electrogrowth[fe]'"


def configure_postbuckle(parser: argparse.ArgumentParser) -> None:
    add_control_options(parser)
    add_any_tube_options(parser)
    mode = parser.add_argument_group("mode and branch")
    mode.add_argument(
        "--mode",
        nargs="+",
        type=bounded_int(0, 200),
        metavar="M",
        help="the mode: M (or M 0) the prismatic mode (m, 0), m >= 2, on the cross-section;"
        " 0 N the axisymmetric mode (0, n), n >= 1, on the meridian (default: the critical"
        " prismatic mode of a scan)",
    )
    mode.add_argument(
        "--amplitude",
        type=finite_number,
        default=0.05,
        metavar="A",
        help="follow the branch up to this fold amplitude, units R_i: the inner (or, where"
        " the mode is larger, the outer) face's cos(m theta) (axisymmetric: cos(k z))"
        " radial displacement (default 0.05)",
    )
    mode.add_argument(
        "--points",
        type=bounded_int(1, 1000),
        default=10,
        metavar="N",
        help="amplitude steps, equal, up to --amplitude: the branch is the onset and one"
        " point per step, N + 1 rows (default 10)",
    )
    mode.add_argument(
        "--imperfection",
        type=finite_number,
        default=0.0,
        metavar="XI",
        help="a load imperfection in the shape of the critical mode, units mu (default 0: the"
        " perfect bifurcated branch)",
    )
    mode.add_argument(
        "--periods",
        type=bounded_int(1, 100),
        default=1,
        metavar="K",
        help="compute on K half wavelengths of the mode (the sector K pi/m; the window K L/n),"
        " K a divisor of m (of n): K = 2 holds the subharmonic m/2, so period doubling can"
        " appear (default 1: the mode's own family alone)",
    )
    num = parser.add_argument_group("mesh")
    num.add_argument(
        "--density",
        type=finite_number,
        default=20.0,
        help="elements per unit reference length across the wall, at least 2 per layer"
        " (default 20)",
    )
    num.add_argument(
        "--hoop",
        type=bounded_int(1, 1000),
        metavar="N",
        help="prismatic modes: elements along each pi/m of the sector (default from"
        " --density, at least 4)",
    )
    num.add_argument(
        "--axial",
        type=bounded_int(1, 1000),
        metavar="N",
        help="axisymmetric modes: elements along each L/n of the window, half an axial"
        " wavelength (default from --density, at least 4)",
    )
    parser.add_argument("--json", action="store_true", help="print the result as JSON")
    parser.add_argument(
        "--out",
        metavar="DIR",
        help="write branch.csv, branch.png, folding.png and the deformed ring (axisymmetric:"
        " longitudinal section) of each branch point as shape-K.vtu (VTK, needs meshio: the"
        " vtk extra) into DIR",
    )
    add_quiet_option(parser)


def run_postbuckle(args) -> int:
    try:
        import skfem  # noqa: F401
    except ImportError:
        missing = MissingDependencyError("postbuckle needs the finite-element extra, scikit-fem")
        missing.remedy = Remedy(INSTALL)
        raise missing from None
    from ..postbuckle import postbuckle

    check_side_option(args)
    tube, control = control_of(args)
    if args.mode is not None:
        m, n = _mode_of(args.mode)
    scan = _scan(tube, control, args, need=args.mode is None)
    if args.mode is None:
        m, n = _critical_prismatic(scan), 0
    note = _not_first(scan, (m, n), control)
    if note:
        _say(f"note: {note}")
    say = _say if enabled(args) else None
    try:
        result = postbuckle(
            tube,
            (m, n),
            control,
            amplitude=args.amplitude,
            points=args.points,
            density=args.density,
            hoop=args.hoop,
            axial=args.axial,
            imperfection=args.imperfection,
            periods=args.periods,
            side=args.side,
            progress=say,
        )
    except Interrupted as stop:  # keep the finished branch points
        done = stop.partial
        if done is None or args.out is None:
            raise
        _write(done, Path(args.out), _columns(done, control, getattr(args, "scales", None)))
        raise Interrupted(
            stop.signum,
            f"{stop}; {len(done.amplitude)} finished branch points written to {args.out}",
        ) from None
    scales = getattr(args, "scales", None)
    if args.out:
        _write(result, Path(args.out), _columns(result, control, scales))
    if result.ended:
        print(f"electrogrowth: warning: {result.ended}", file=sys.stderr)
    if result.stability_note:
        print(f"electrogrowth: warning: {result.stability_note}", file=sys.stderr)
    physical = _physical(result, control, scales)
    if args.json:
        branch = dict(_columns(result, control, scales))
        extra = {"physical": {**physical, "branch": branch}} if physical or branch else {}
        print(json.dumps({**result.as_dict(), "not_first": note or None, **extra}, indent=2))
    else:
        print(
            f"mode ({m}, {n}), {control}: linear onset {result.onset_linear:.8g}, FE onset"
            f" {result.onset_fe:.8g} (relative difference"
            f" {(result.onset_fe - result.onset_linear) / abs(result.onset_linear):.2e}),"
            f" mesh {result.mesh.elements} elements, {result.unknowns} unknowns"
        )
        if physical:
            print("\n".join(physical_line(physical)))
        print(
            f"initial curvature d({control})/d(a^2) = {result.curvature:.6g} (it changed by"
            f" {result.curvature_error:.2g} from amplitudes ten times larger)"
        )
        columns = _columns(result, control, getattr(args, "scales", None))
        names = "".join(f"  {name}" for name, _ in columns)
        print(f"amplitude  control  energy  lowest_eigenvalue  lowest_mode{names}")
        rows = zip(
            result.amplitude, result.control, result.energy, result.eigenvalue, result.lowest_mode
        )
        for k, (a, c, e, v, kind) in enumerate(rows):
            more = "".join(f"  {values[k]:.10g}" for _, values in columns)
            print(f"{a:.6g}  {c:.10g}  {e:.10g}  {v:.4g}  {kind}{more}")
        for s in result.secondary:
            how = "located" if s.located else "interpolated"
            print(
                f"secondary ({s.kind}): the lowest eigenvalue changes sign at amplitude"
                f" {s.amplitude:.6g}, {control} = {s.control:.10g} ({how})"
            )
    return 0


def _physical(result, control: str, scales) -> dict:
    """The two onsets in physical units, when they are given and the control has a unit:
    the help promises them (probe 10b D4: --outer-pressure 2kPa, the onset in units mu
    only)."""
    if scales is None:
        return {}
    out = {}
    for name, value in (("onset_linear", result.onset_linear), ("onset_fe", result.onset_fe)):
        for entry in named_physical({control: value}, scales).values():  # none: no unit
            out[name] = entry
    return out


def _columns(result, control: str, scales) -> list[tuple[str, list[float]]]:
    """The branch in the physical units given, as (name with its unit, values): the
    amplitude in mm (with --inner-radius), the control in its unit (kPa, kV, N; a growth
    or stretch has none), the energy per unit length in N = J/m (with --shear-modulus and
    --inner-radius). None without physical units."""
    if scales is None:
        return []
    out = []
    if scales.has("inner_radius"):
        out.append(("amplitude_mm", [float(scales.length(a).magnitude) for a in result.amplitude]))
    entries = [named_physical({control: float(c)}, scales) for c in result.control]
    if entries and entries[0]:
        unit = next(iter(entries[0].values()))[1]
        out.append((f"{control}_{unit}", [next(iter(e.values()))[0] for e in entries]))
    if scales.has("inner_radius", "shear_modulus"):
        r_i, mu = scales.inner_radius, scales.shear_modulus  # energy in units mu R_i^2
        out.append(("energy_J_per_m", [float(e) * mu * r_i * r_i for e in result.energy]))
    return out


def _say(text: str) -> None:
    print(f"electrogrowth: {text}", file=sys.stderr, flush=True)


def _mode_of(values: list[int]) -> tuple[int, int]:
    """(m, n) of --mode M or --mode M N, ParameterError unless a model covers it."""
    m, n = (values[0], 0) if len(values) == 1 else (values[0], values[1])
    if len(values) > 2 or not ((m >= 2 and n == 0) or (m == 0 and n >= 1)):
        shown = " ".join(str(v) for v in values)
        raise ParameterError(
            f"--mode {shown} is out of range; valid: M or M 0 with M >= 2 (the cross-section),"
            " 0 N with N >= 1 (the meridian)"
        )
    return m, n


def _scan(tube, control, args, need: bool):
    """The tube's mode scan (~1-2 s beside the branch's minutes): which mode comes first.
    Where a mode was given (``need`` False) a scan that fails leaves None: the branch of the
    asked mode stands without the comparison."""
    from ..bifurcation.scan import scan_modes

    if enabled(args):
        _say("scanning the modes: which comes first")
    try:
        return scan_modes(tube, control, side=args.side)
    except ElectrogrowthError as exc:
        if need:
            raise
        _say(f"note: no scan, so whether this mode comes first is not known: {exc}")
        return None


def _critical_prismatic(scan) -> int:
    """m of the first prismatic mode (m, 0), m >= 2, among the scan's critical mode and its
    runners-up."""
    for point in (scan.critical, *scan.runners_up):
        m, n = getattr(point, "m", None), getattr(point, "n", None)
        if n == 0 and isinstance(m, int) and m >= 2:
            return m
    c = scan.critical
    raise ParameterError(
        f"the scan's critical mode is ({c.m}, {c.n}) and no prismatic mode (m, 0) is among"
        " its runners-up; give --mode M (the cross-section, (m, 0)) or --mode 0 N (the"
        " meridian, (0, n))"
    )


def _not_first(scan, mode: tuple[int, int], control: str) -> str:
    """Why the branch of ``mode`` is not the tube's own (another mode, the short-wave limit
    or the loss of the state comes first), or "": the cross-section and the meridian hold
    one family each, and the first mode among them need not be the tube's first."""
    if scan is None:
        return ""
    c = scan.critical
    if c.kind == Kind.BIFURCATION and (c.m, c.n) == mode:
        return ""
    first = {
        Kind.BIFURCATION: f"({c.m}, {c.n}) bifurcates first",
        Kind.SURFACE: "the short-wave (surface) limit comes first",
        Kind.THRESHOLD: "the axisymmetric state is lost first",
    }.get(c.kind, f"{c.kind} comes first")
    return (
        f"mode {mode} is not the tube's first: {first}, at {control} = {c.value:.10g};"
        " the branch below is that of the mode asked for"
    )


def _write(result, out: Path, columns=()) -> None:
    """branch.csv (with ``columns``: the branch in physical units), the two PNGs and one VTK
    file of the section per branch point."""
    from ..figures.postbuckle import plot_branch, plot_folding
    from ..postbuckle.shape import whole

    out.mkdir(parents=True, exist_ok=True)
    with replaced(out / "branch.csv", newline="") as f:
        w = csv.writer(f)
        w.writerow(
            ["amplitude", result.solve_for, "energy", "lowest_eigenvalue", "lowest_mode"]
            + ["subharmonic_fraction"]
            + [name for name, _ in columns]
        )
        numbers = zip(result.amplitude, result.control, result.energy, result.eigenvalue)
        for k, (row, kind, sub) in enumerate(zip(numbers, result.lowest_mode, result.subharmonic)):
            more = [repr(float(values[k])) for _, values in columns]
            w.writerow([repr(float(v)) for v in row] + [kind or "", repr(float(sub))] + more)
    write_figure(plot_branch(result), out / "branch.png", dpi=150)
    write_figure(plot_folding(result), out / "folding.png", dpi=150)
    try:
        import meshio
    except ImportError:
        print(
            "electrogrowth: no VTK files: meshio is missing (pip install 'electrogrowth[vtk]')",
            file=sys.stderr,
        )
        return
    import numpy as np

    section = result.section
    for k, x in enumerate(result.states):
        section.set_tube(result.tube.at(result.solve_for, result.control[k]))
        pts, cells, layer = whole(section, x)
        zero = np.zeros(pts.shape[1])
        # the ring in the plane z = 0; the longitudinal section in the plane y = 0
        points = np.vstack([pts, zero] if result.n == 0 else [pts[0], zero, pts[1]]).T
        with replaced_name(out / f"shape-{k}.vtu") as name:
            mesh = meshio.Mesh(points, [("quad", cells)], cell_data={"layer": [layer + 1]})
            meshio.write(name, mesh)
