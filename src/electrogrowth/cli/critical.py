"""``electrogrowth critical``: the critical growth factor, axial stretch or voltage."""

from __future__ import annotations

import argparse
import json
import math

from ..bifurcation.critical import critical_value
from ..bifurcation.scan import scan_modes
from ..errors import ConvergenceError, ParameterError
from ..incremental.accuracy import check_rtol
from ..model.controls import parse_control
from ..outcomes import Kind
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
from .tube_input import add_any_tube_options, control_of

CERTIFY_RTOL = 1e-8  # the two methods must agree this well for a certified value


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
    parser.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object (solve_for, value, m, n, family, kind,"
        " error_estimate, ...) instead of text",
    )


def run_critical(args) -> int:
    params, solve_for = control_of(args)
    check_side_option(args)
    check_rtol(args.rtol, "--rtol")
    mode = mode_from_args(args)
    if mode is not None:
        m, n, family = mode
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
        record, runners = crit.as_dict(), []
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
    check = critical_value(
        params,
        crit.m,
        crit.n,
        crit.solve_for,
        family=crit.family,
        side=crit.side,
        method=other,
        bracket=(crit.value - w, crit.value + w),
    )
    diff = abs(check.value - crit.value) / abs(crit.value)
    if diff > CERTIFY_RTOL:
        raise ConvergenceError(
            f"not certified: {crit.method} gives {crit.value:.12g},"
            f" {other} gives {check.value:.12g} (relative difference"
            f" {diff:.2e} > {CERTIFY_RTOL:g})"
        )
    return {
        "certified": True,
        "certified_by": other,
        "certified_value": check.value,
        "certification_difference": diff,
    }


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


def tube_line(rec: dict) -> str:
    """The tube of a JSON record in one line (one layer, or the layers and loads)."""
    if "layers" not in rec:
        return (
            f"  tube: Rbar_o = {rec['outer_radius']:g}, L = {rec['length']:g},"
            f" g = {rec['growth']:.12g}, lambda_z = {rec['stretch']:.12g},"
            f" Vbar = {rec['voltage']:.12g}, {rec['material']}"
        )
    layers = "; ".join(
        f"R <= {ly['outer_radius']:g} {ly['material']} mu {ly['shear_modulus']:g} g {ly['growth']}"
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


def _print_text(rec: dict, runners: list) -> None:
    name = value_name(rec["solve_for"])
    if rec["kind"] == Kind.THRESHOLD:
        head = (
            f"{name} = {rec['value']:.12g}: the axisymmetric state is lost (voltage"
            " threshold) before any wrinkling mode"
        )
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
            f"{name} = {rec['value']:.12g}  (error estimate {rec['error_estimate']:.1e},"
            f" half-space)   short-wave (surface) instability, m, n -> infinity, at the"
            f" {where}, wrinkles along {along}"
        )
    else:
        head = (
            f"{name} = {rec['value']:.12g}  (error estimate {rec['error_estimate']:.1e},"
            f" {rec['method']})   mode (m, n) = ({rec['m']}, {rec['n']})"
            f"{_family_note(rec.get('family'))}"
        )
    lines = [head, tube_line(rec)]
    if rec.get("certified"):
        lines.append(
            f"  certified by {rec['certified_by']}: {rec['certified_value']:.12g}"
            f" (relative difference {rec['certification_difference']:.1e})"
        )
    if rec.get("short_wave_limit") is not None and rec["kind"] != Kind.SURFACE:
        lines.append(
            f"  short-wave (surface) limit m, n -> infinity: {name} ="
            f" {rec['short_wave_limit']:.12g} (after this mode)"
        )
    for r in runners:
        lines.append(
            f"  next: (m, n) = ({r['m']}, {r['n']}){_family_note(r.get('family'))}"
            f"   {name} = {r['value']:.10g}"
        )
    print("\n".join(lines))


def _family_note(family: str | None) -> str:
    """How a mode's family is named after (m, n) in text: nothing for a wrinkle."""
    return {
        "prismatic": ", prismatic (n = 0: plane strain)",
        "torsional": ", torsional (u_theta only)",
    }.get(family or "", "")
