"""``electrogrowth critical``: the critical growth factor, axial stretch or voltage.

The solvers (numba's kernels, scipy) are imported by the functions that call them, once the
input is checked: a bad argument is named without loading them.
"""

from __future__ import annotations

import argparse
import contextlib
import json

from ..errors import ConvergenceError, ParameterError
from ..incremental.accuracy import CERTIFIED, CERTIFY_RTOL, check_rtol
from ..outcomes import Kind, Status
from .critical_text import print_text, value_name
from .options import (
    KOITER_COST,
    MODE_COVERAGE,
    add_control_options,
    add_method_option,
    add_mode_option,
    add_mode_range_options,
    check_side_option,
    mode_from_args,
    scan_options_from_args,
)
from .progress import LATE_NOTICE, add_quiet_option, bar, stage
from .report import NAMED, edge_warning, physical_record, warn
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
        f" stderr, and exit status {INACCURATE_EXIT}; likewise a value --certify refuses and a"
        " crease that comes first by a criterion not established for the energy",
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
        f" faces, or the axial force prescribed without them; {KOITER_COST})",
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
        # collocation takes tens of seconds: say so at once; the kernel's march mostly
        # milliseconds, but minutes for a mode that never bifurcates on a long path (a
        # stiffening tube's voltage to 1e3 scales): shown from 2 s on
        delay = 0.0 if args.method == "collocation" else LATE_NOTICE
        with stage(args, f"solving mode ({m}, {n}) by {args.method}", tick=True, delay=delay):
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
        verdict = crit.verdict  # the mode's own: no other mode was looked at
        record = verdict_record(crit.as_dict(), verdict, crit, first_on_top=False)
        runners = []
    else:
        if args.method != "impedance":
            raise ParameterError(
                "a mode scan uses --method impedance; give --mode M N for"
                " collocation (or use --certify)"
            )
        # a thin layer's scan searches its folds up to its caps (m ~ 64 R / h): tens of seconds
        with stage(args, "scanning the modes (m, n) for the first bifurcation", tick=True):
            result = scan_modes(
                params,
                solve_for,
                side=args.side,
                options=scan_options_from_args(args),
                rtol=args.rtol,
            )
        crit, record, verdict = result.critical, result.as_dict(), result.verdict
        runners = record["runners_up"]
        warn(edge_warning(result))
    if args.koiter:
        record.update(_amplitude_equation(args, params, solve_for, verdict))
    elif record.get("wrinkle") is not None:  # say how to learn it, rather than nothing
        record["branch_note"] = (
            f"not asked: add --koiter for super- or subcritical ({KOITER_COST})"
        )
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
        record["physical"].update(_koiter_physical(record, args.scales))
    if args.json:
        print(json.dumps(record))
    else:
        print_text(record, runners, getattr(args, "scales", None))
    if record.get("certified") is False:  # --certify refused it (the text says why)
        return 0 if args.accept_inaccurate else INACCURATE_EXIT
    if record["status"] == Status.INACCURATE and crit.status != Status.INACCURATE:
        # a crease first whose criterion is not established for the energy (verdict.py)
        warn(
            f"{record['solve_for']} = {record['value']:.3g} is not certified:"
            f" {record['crease_criterion']}"
        )
        return 0 if args.accept_inaccurate else INACCURATE_EXIT
    return _inaccurate_exit(crit, args, params)


def _amplitude_equation(args, params, solve_for, verdict) -> dict:
    """The verdict's ``branch``, ``koiter`` and ``meaning`` from the amplitude equation, or
    ``branch_note``: why it is not computed."""
    from ..bifurcation.koiter import with_branch  # scipy's dense algebra: only when asked

    with stage(args, "solving the amplitude equation at onset", tick=True):
        verdict, note = with_branch(verdict, params, solve_for, args.side)
    if note is not None:
        return {"branch_note": note}
    return {
        "branch": verdict.branch,
        "koiter": verdict.koiter,
        "koiter_error": verdict.koiter_error,
        "koiter_resonance": verdict.koiter_resonance,
        "meaning": verdict.meaning,
    }


def _koiter_physical(record: dict, scales) -> dict:
    """The Koiter coefficient c_2 in the unit of its control ({} where that has none, or
    none was computed): on the branch the control is c_cr + c_2 eps^2, eps = peak u_r / R_i a
    ratio, so c_2 is a pressure, a force or a voltage like the control itself (probe round
    12a: -10.96 was printed for -1096 kPa)."""
    from ..model.controls import parse_control

    c2 = record.get("koiter")
    key = NAMED.get(parse_control(record["solve_for"]).kind)
    if c2 is None or key is None:
        return {}
    converted = physical_record({key: c2}, scales, {key: record.get("koiter_error")})
    return {"koiter": converted[key]} if key in converted else {}


def _inaccurate_exit(crit, args, tube) -> int:
    """0, or INACCURATE_EXIT with a warning for a value not certified to --rtol (unless
    --accept-inaccurate)."""
    if crit.status != Status.INACCURATE:
        return 0
    from ..bifurcation.critical import is_certified

    if is_certified(crit, args.rtol, tube):
        # accurate, but not the tube's critical value for certain (a scan at its mode cap)
        why = "; ".join(filter(None, (crit.message, crit.remedy)))
        warn(f"{crit.solve_for} = {crit.value:.6g} is not certified: {why}")
    else:
        warn(
            f"{crit.solve_for} = {crit.value:.6g} is not certified to rtol = {args.rtol:g}:"
            f" its error estimate {crit.error_estimate:.1e} remained above {CERTIFIED:g} rtol"
            " |value| at rtol / 100 (only the digits it supports are printed)"
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
            self.bar.update(done - self.bar.n)  # the modes of the last batch

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
