"""``electrogrowth critical``: the critical growth factor, axial stretch or voltage.

The solvers (numba's kernels, scipy) are imported by the functions that call them, once the
input is checked: a bad argument is named without loading them.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math

from ..errors import ConvergenceError, ParameterError
from ..incremental.accuracy import CERTIFIED, CERTIFY_RTOL, check_rtol
from ..model.controls import parse_control
from ..outcomes import Kind, Status
from .options import (
    MODE_COVERAGE,
    add_control_options,
    add_method_option,
    add_mode_option,
    add_mode_range_options,
    check_side_option,
    mode_from_args,
    scan_options_from_args,
)
from .progress import add_quiet_option, bar, stage
from .report import edge_warning, physical_line, physical_record, supported, voltage_text, warn
from .tube_input import add_any_tube_options, control_of

INACCURATE_EXIT = 3  # the exit status of a value not certified to --rtol


def configure_critical(parser: argparse.ArgumentParser) -> None:
    add_control_options(parser)
    add_any_tube_options(parser)
    modes = parser.add_argument_group(
        "wrinkling modes u ~ cos(m theta) cos(k z), k = n pi / (lambda_z L)", MODE_COVERAGE
    )
    add_mode_option(modes)
    add_mode_range_options(modes, top=True)
    num = parser.add_argument_group("numerics")
    add_method_option(
        num,
        "impedance = compiled surface-impedance Riccati integration"
        " (default); collocation = independent Chebyshev collocation",
    )
    num.add_argument(
        "--certify",
        action="store_true",
        help="also solve with the other method and require agreement to"
        f" {CERTIFY_RTOL:g} (relative)",
    )
    num.add_argument(
        "--rtol", type=float, default=1e-12, help="local integration tolerance (default 1e-12)"
    )
    num.add_argument(
        "--accept-inaccurate",
        action="store_true",
        help="exit 0 even when the critical value is not certified to --rtol (its error"
        f" estimate exceeds {CERTIFIED:g} rtol |value| after a solve at rtol / 100); without"
        " it such a value is printed with the digits its estimate supports, a warning on"
        f" stderr, and exit status {INACCURATE_EXIT}; likewise a value --certify refuses",
    )
    parser.add_argument(
        "--koiter",
        action="store_true",
        help="also solve the amplitude equation of the wrinkle at onset: supercritical"
        " (folds grow gradually) or subcritical (a jump to large folds), with the Koiter"
        " coefficient c_2 of control = c_cr + c_2 eps^2, eps the mode's peak radial"
        " displacement over R_i (every wrinkle (m, n), m >= 2 or n >= 1, of layered"
        " tubes of any energy, graded growth included, for a growth, the stretch, the"
        " pressure or the voltage; ideal dielectrics under a voltage; pressures on the"
        " faces, or the axial force prescribed without them; one to five seconds)",
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object (solve_for, value, m, n, family, kind,"
        " error_estimate, ...; verdict is what comes first of a wrinkle, a crease of a free"
        " face and the loss of the axisymmetric state, and a scan's kind and value are"
        " its; each kind under wrinkle, crease, surface, threshold; meaning in words)"
        " instead of text",
    )
    add_quiet_option(parser)


def run_critical(args) -> int:
    params, solve_for = control_of(args)
    check_side_option(args)
    check_rtol(args.rtol, "--rtol")
    mode = mode_from_args(args)
    from ..bifurcation.critical import critical_value
    from ..bifurcation.scan import scan_modes
    from ..bifurcation.verdict import record as verdict_record

    if mode is not None:
        m, n, family = mode
        slow = args.method == "collocation"  # tens of seconds: say what is going on
        with stage(args if slow else None, f"solving mode ({m}, {n}) by collocation", tick=True):
            crit = critical_value(
                params,
                m,
                n,
                solve_for,
                family=family,
                side=args.side,
                method=args.method,
                rtol=args.rtol,
            )
        record = verdict_record(crit.as_dict(), crit.verdict, crit, first_on_top=False)
        runners = []
    else:
        if args.method != "impedance":
            raise ParameterError(
                "a mode scan uses --method impedance; give --mode M N for"
                " collocation (or use --certify)"
            )
        result = scan_modes(
            params,
            solve_for,
            side=args.side,
            options=scan_options_from_args(args),
            rtol=args.rtol,
        )
        crit, record = result.critical, result.as_dict()
        runners = record["runners_up"]
        warn(edge_warning(result))
    if args.koiter:
        record.update(_amplitude_equation(args, params, solve_for, crit))
    elif record.get("wrinkle") is not None:  # say how to learn it, rather than nothing
        record["branch_note"] = "not asked: add --koiter for super- or subcritical (1-5 s)"
    if args.certify and crit.kind in (Kind.BIFURCATION, Kind.SURFACE):
        # a scan: certify the choice of the mode as well
        try:
            record.update(_certify(params, crit, args, result if mode is None else None))
        except ConvergenceError as exc:  # the value is printed, said uncertified: exit 3
            why = " ".join(str(exc).split())
            if not why.startswith("not certified: "):
                raise
            record.update(certified=False, certification=why.removeprefix("not certified: "))
            warn(f"{why}; the value is printed as found")
    if getattr(args, "scales", None) is not None:
        errors = {record.get("solve_for"): record.get("error_estimate")}
        record["physical"] = physical_record(record, args.scales, errors)
    if args.json:
        print(json.dumps(record))
    else:
        _print_text(record, runners, getattr(args, "scales", None))
    if record.get("certified") is False:  # --certify refused it (the text says why)
        return 0 if args.accept_inaccurate else INACCURATE_EXIT
    return _inaccurate_exit(crit, args)


def _amplitude_equation(args, params, solve_for, crit) -> dict:
    """The verdict's ``branch``, ``koiter`` and ``meaning`` from the amplitude equation, or
    ``branch_note``: why it is not computed."""
    from ..bifurcation.koiter import with_branch  # scipy's dense algebra: only when asked

    with stage(args, "solving the amplitude equation at onset", tick=True):
        verdict, note = with_branch(crit.verdict, params, solve_for, args.side)
    if note is not None:
        return {"branch_note": note}
    return {
        "branch": verdict.branch,
        "koiter": verdict.koiter,
        "koiter_error": verdict.koiter_error,
        "meaning": verdict.meaning,
    }


def _inaccurate_exit(crit, args) -> int:
    """0, or INACCURATE_EXIT with a warning for a value not certified to --rtol (unless
    --accept-inaccurate)."""
    if crit.status != Status.INACCURATE:
        return 0
    warn(
        f"{crit.solve_for} = {crit.value:.6g} is not certified to rtol = {args.rtol:g}: its"
        f" error estimate {crit.error_estimate:.1e} remained above {CERTIFIED:g} rtol |value|"
        " at rtol / 100 (only the digits it supports are printed)"
    )
    return 0 if args.accept_inaccurate else INACCURATE_EXIT


def _certify(params, crit, args, result=None) -> dict:
    """The certificate of ``crit`` (and of the scan ``result``'s choice of mode)."""
    from ..bifurcation.certify import certify

    if crit.kind == Kind.SURFACE:
        with stage(args, "certifying the half-space value and the best finite mode", tick=True):
            return certify(params, crit, scan=result).as_dict()
    other = "collocation" if crit.method == "impedance" else "impedance"
    name = value_name(crit.solve_for)
    options = None if result is None else scan_options_from_args(args)
    progress = _Progress(args)
    progress.stage.enter_context(
        stage(args, f"certifying {name} of mode ({crit.m}, {crit.n}) by {other}", tick=True)
    )
    with progress.stage:
        cert = certify(params, crit, scan=result, options=options, progress=progress)
    progress.close()
    return cert.as_dict()


class _Progress:
    """A progress bar over the scanned modes, opened on the first mode checked (once the
    stage of the other method's solve, a line of its own, is over)."""

    def __init__(self, args):
        self.args, self.bar = args, None
        self.stage = contextlib.ExitStack()

    def __call__(self, done: int, total: int) -> None:
        if self.bar is None:
            self.stage.close()
            self.bar = bar(
                self.args, total, "certifying: every scanned mode stable before it", "mode"
            )
        if self.bar is not None:
            self.bar.update(1)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def value_name(solve_for: str) -> str:
    """How a critical value is named in text: g_cr, lambda_z,cr, Vbar_cr, P_i,cr, F_cr;
    g_theta[2],cr for a component of layer 2's growth."""
    c = parse_control(solve_for)
    if c.kind != "growth":
        return {"stretch": "lambda_z,cr", "voltage": "Vbar_cr", "pressure": "P_i,cr"}.get(
            c.kind, "F_cr"
        )
    if c.components is None and c.layer is None:
        return "g_cr"
    comp = "" if c.components is None else "_" + "".join(c.components)
    return f"g{comp}{'' if c.layer is None else f'[{c.layer}]'},cr"


def tube_line(rec: dict, scales=None) -> str:
    """The tube of a JSON record in one line (one layer, or the layers and loads); the value
    solved for with the digits its error estimate supports, the voltage next to Vbar."""
    if "layers" not in rec:
        volts = voltage_text(rec["voltage"], rec["outer_radius"], scales, _error(rec, "voltage"))
        return (
            f"  tube: Rbar_o = {rec['outer_radius']:g}, L = {rec['length']:g},"
            f" g = {_given(rec, 'growth')}, lambda_z = {_given(rec, 'stretch')},"
            f" {volts}, {rec['material']}"
        )
    layers = "; ".join(
        f"R <= {ly['outer_radius']:g} {ly['material']} mu {ly['shear_modulus']:g}"
        f" g {_growth_text(ly['growth'], rec)}"
        for ly in rec["layers"]
    )
    axial = (
        f"lambda_z = {rec['stretch']:.12g}"
        if rec["stretch"] is not None
        else f"axial force {rec['axial_force']:.12g}"
    )
    return (
        f"  tube: {len(rec['layers'])} layer(s) [{layers}], L = {rec['length']:g}, {axial},"
        f" Vbar = {rec['voltage']:.12g}, P_i = {rec['inner_pressure']:.12g},"
        f" P_o = {rec['outer_pressure']:.12g}"
    )


def _growth_text(growth, rec: dict) -> str:
    """A layer's growth triple, the component solved for with the digits its estimate
    supports (graded growth as recorded)."""
    if not isinstance(growth, list):
        return str(growth)
    solved = rec["solve_for"].startswith("growth") and rec["kind"] == Kind.BIFURCATION
    return (
        "["
        + ", ".join(
            supported(g, rec["error_estimate"]) if solved and g == rec["value"] else f"{g:.12g}"
            for g in growth
        )
        + "]"
    )


def _print_text(rec: dict, runners: list, scales=None) -> None:
    from ..bifurcation.verdict import crease_where

    name = value_name(rec["solve_for"])
    value = supported(rec["value"], rec["error_estimate"])  # the digits the estimate supports
    if rec["kind"] == Kind.CREASE:
        head = (
            f"{name} = {_crease_value(rec['value'], rec['error_estimate'])}"
            f"   crease at {crease_where(rec['face'], rec['crease'].get('detail'))},"
            f" {_TRIGGER.get(rec['crease']['trigger'], '')}"
        )
    elif rec["kind"] == Kind.THRESHOLD:
        head = f"{name} = {value}: the axisymmetric state is lost before any wrinkling mode"
    elif rec["kind"] == Kind.SURFACE:
        along = (
            "theta"
            if rec["psi"] == 0
            else "z"
            if abs(rec["psi"] - math.pi / 2) < 1e-12
            else f"the direction psi = {rec['psi']:.6g} rad from theta to z"
        )
        where = rec["face"] if rec["face"].startswith("interface") else f"{rec['face']} face"
        head = (
            f"{name} = {value}  (error estimate {rec['error_estimate']:.1e},"
            f" half-space)   short-wave (surface) instability, m, n -> infinity, at the"
            f" {where}, wrinkles along {along}"
        )
    else:
        head = (
            f"{name} = {value}  (error estimate {rec['error_estimate']:.1e},"
            f" {rec['method']})   mode (m, n) = ({rec['m']}, {rec['n']})"
            f"{_family_note(rec.get('family'))}"
        )
    lines = [head, tube_line(rec, scales)]
    lines += physical_line(rec.get("physical", {}))
    w = rec.get("wrinkle")
    if w is not None and rec["kind"] != Kind.BIFURCATION:
        lines.append(
            f"  wrinkle (linear analysis): (m, n) = ({w['m']}, {w['n']})"
            f"{_family_note(w.get('family'))}   {name} = {w['value']:.10g}"
        )
    if "certification" in rec:  # a surface result: what was certified and how, or why not
        lines.append(
            f"  {'certified' if rec['certified'] else 'NOT certified'}: {rec['certification']}"
        )
    elif rec.get("certified"):
        lines.append(
            f"  certified by {rec['certified_by']}: {rec['certified_value']:.12g}"
            f" (relative difference {rec['certification_difference']:.1e})"
            + (
                f"; all {rec['certified_modes']} scanned modes stable before it"
                if "certified_modes" in rec
                else ""
            )
        )
    if rec.get("short_wave_limit") is not None and rec["kind"] != Kind.SURFACE:
        lines.append(
            f"  short-wave (surface) limit m, n -> infinity: {name} ="
            f" {rec['short_wave_limit']:.12g} (after this mode)"
        )
    shown = None if w is None or rec["kind"] == Kind.BIFURCATION else w
    for r in runners:
        if shown is not None and all(r[k] == shown[k] for k in ("m", "n", "family", "value")):
            continue  # a surface result's best finite mode heads its runners-up: shown above
        lines.append(
            f"  next: (m, n) = ({r['m']}, {r['n']}){_family_note(r.get('family'))}"
            f"   {name} = {r['value']:.10g}"
        )
    lines += _rival_lines(rec, name)
    print("\n".join(lines))


_TRIGGER = {
    "prismatic": "fold lines along the axis (hoop compression)",
    "axial": "rings (axial compression)",
    "field": "by the field criterion of a bonded, unstretched film (an early bound, not ranked)",
}


def _crease_value(value: float, estimate: float | None) -> str:
    """A crease onset with the digits its criterion supports; an estimate that is not finite
    (null in the record: an energy with no Biot ratio, crease.energy_shift) supports none
    of the criterion's digits."""
    if estimate is None:
        return f"{value:.3g}  (neo-Hookean criterion, not established for this energy)"
    return f"{supported(value, estimate)}  (accuracy of the crease criterion {estimate:.1e})"


def _rival_lines(rec: dict, name: str) -> list[str]:
    """The runner-up crease and threshold, and the verdict in words."""
    from ..bifurcation.verdict import crease_where

    lines = []
    c, t = rec.get("crease"), rec.get("threshold")
    if c is not None and rec["kind"] != Kind.CREASE:
        lines.append(
            f"  crease: {crease_where(c['face'], c.get('detail'))},"
            f" {_TRIGGER.get(c['trigger'], '')}   {name} ="
            f" {_crease_value(c['value'], c['error_estimate'])}"
        )
    if t is not None and rec["kind"] != Kind.THRESHOLD:
        lines.append(f"  axisymmetric state lost ({t['detail']}): {name} = {t['value']:.10g}")
    if rec.get("koiter") is not None:
        lines.append(
            f"  amplitude equation: {rec['branch']}, Koiter coefficient c_2 ="
            f" {rec['koiter']:.6g} (on the branch the control is its critical value"
            " + c_2 eps^2, eps = peak u_r / R_i)"
        )
    elif rec.get("branch_note"):
        lines.append(f"  amplitude equation not computed: {rec['branch_note']}")
    if rec.get("meaning"):
        lines.append(f"  verdict: {rec['meaning']}")
    return lines


def _error(rec: dict, key: str) -> float | None:
    """The error estimate of ``key`` if it is the value solved for (else an input: None)."""
    return rec["error_estimate"] if rec["solve_for"] == key else None


def _given(rec: dict, key: str) -> str:
    return supported(rec[key], _error(rec, key))


def _family_note(family: str | None) -> str:
    """How a mode's family is named after (m, n) in text: nothing for a wrinkle."""
    return {
        "prismatic": ", prismatic (n = 0: plane strain)",
        "torsional": ", torsional (u_theta only)",
    }.get(family or "", "")
