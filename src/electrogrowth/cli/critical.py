"""``electrogrowth critical``: the critical growth factor, axial stretch or voltage."""

from __future__ import annotations

import argparse
import json
import math

from ..bifurcation.critical import critical_value
from ..bifurcation.scan import scan_modes
from ..errors import ConvergenceError, ParameterError
from ..incremental.accuracy import check_rtol
from ..outcomes import Kind
from .options import (
    add_control_options,
    add_method_option,
    add_mode_range_options,
    add_tube_options,
    check_side_option,
    scan_options_from_args,
    tube_from_args,
)

CERTIFY_RTOL = 1e-8  # the two methods must agree this well for a certified value


def configure_critical(parser: argparse.ArgumentParser) -> None:
    add_control_options(parser)
    add_tube_options(parser)
    modes = parser.add_argument_group("wrinkling modes u ~ cos(m theta) cos(k z),"
                                      " k = n pi / (lambda_z L)")
    modes.add_argument("--mode", nargs=2, type=int, metavar=("M", "N"),
                       help="one mode: circumferential wavenumber m >= 0 and axial"
                            " half-wavenumber n >= 1; without it all modes 0 <= m <= M_MAX,"
                            " 1 <= n <= N_MAX are scanned and the first to bifurcate is"
                            " reported")
    add_mode_range_options(modes, top=True)
    num = parser.add_argument_group("numerics")
    add_method_option(num, "impedance = compiled surface-impedance Riccati integration"
                           " (default); collocation = independent Chebyshev collocation")
    num.add_argument("--certify", action="store_true",
                     help="also solve with the other method and require agreement to"
                          f" {CERTIFY_RTOL:g} (relative)")
    num.add_argument("--rtol", type=float, default=1e-12,
                     help="local integration tolerance (default 1e-12)")
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object (solve_for, value, m, n, kind,"
                             " error_estimate, ...) instead of text")


def run_critical(args) -> int:
    params = tube_from_args(args)
    check_side_option(args)
    check_rtol(args.rtol, "--rtol")
    if args.mode is not None:
        crit = critical_value(params, *args.mode, args.solve_for, side=args.side,
                              method=args.method, rtol=args.rtol)
        record, runners = crit.as_dict(), []
    else:
        if args.method != "impedance":
            raise ParameterError("a mode scan uses --method impedance; give --mode M N for"
                                 " collocation (or use --certify)")
        result = scan_modes(params, args.solve_for, side=args.side,
                            options=scan_options_from_args(args), rtol=args.rtol)
        crit, record = result.critical, result.as_dict()
        runners = record["runners_up"]
    if args.certify and crit.kind == Kind.BIFURCATION:
        record.update(_certify(params, crit, args))
    if args.json:
        print(json.dumps(record))
        return 0
    _print_text(record, runners)
    return 0


def _certify(params, crit, args) -> dict:
    other = "collocation" if crit.method == "impedance" else "impedance"
    w = max(1e-6 * abs(crit.value), 10 * crit.error_estimate)
    check = critical_value(params, crit.m, crit.n, crit.solve_for, side=crit.side,
                           method=other, bracket=(crit.value - w, crit.value + w))
    diff = abs(check.value - crit.value) / abs(crit.value)
    if diff > CERTIFY_RTOL:
        raise ConvergenceError(f"not certified: {crit.method} gives {crit.value:.12g},"
                               f" {other} gives {check.value:.12g} (relative difference"
                               f" {diff:.2e} > {CERTIFY_RTOL:g})")
    return {"certified": True, "certified_by": other, "certified_value": check.value,
            "certification_difference": diff}


def _print_text(rec: dict, runners: list) -> None:
    name = {"growth": "g_cr", "stretch": "lambda_z,cr", "voltage": "Vbar_cr"}[rec["solve_for"]]
    if rec["kind"] == Kind.THRESHOLD:
        head = (f"{name} = {rec['value']:.12g}: the axisymmetric state is lost (voltage"
                " threshold) before any wrinkling mode")
    elif rec["kind"] == Kind.SURFACE:
        along = ("theta" if rec["psi"] == 0 else "z" if abs(rec["psi"] - math.pi / 2) < 1e-12
                 else f"the direction psi = {rec['psi']:.6g} rad from theta to z")
        head = (f"{name} = {rec['value']:.12g}  (error estimate {rec['error_estimate']:.1e},"
                f" half-space)   short-wave (surface) instability, m, n -> infinity, at the"
                f" {rec['face']} face, wrinkles along {along}")
    else:
        head = (f"{name} = {rec['value']:.12g}  (error estimate {rec['error_estimate']:.1e},"
                f" {rec['method']})   mode (m, n) = ({rec['m']}, {rec['n']})")
    lines = [head, f"  tube: Rbar_o = {rec['outer_radius']:g}, L = {rec['length']:g},"
                   f" g = {rec['growth']:.12g}, lambda_z = {rec['stretch']:.12g},"
                   f" Vbar = {rec['voltage']:.12g}, {rec['material']}"]
    if rec.get("certified"):
        lines.append(f"  certified by {rec['certified_by']}: {rec['certified_value']:.12g}"
                     f" (relative difference {rec['certification_difference']:.1e})")
    if rec.get("short_wave_limit") is not None and rec["kind"] != Kind.SURFACE:
        lines.append(f"  short-wave (surface) limit m, n -> infinity: {name} ="
                     f" {rec['short_wave_limit']:.12g} (after this mode)")
    for r in runners:
        lines.append(f"  next: (m, n) = ({r['m']}, {r['n']})   {name} = {r['value']:.10g}")
    print("\n".join(lines))
