"""``electrogrowth state``: the axisymmetric base state of a grown, stretched, charged tube.

A one-layer tube from the shared options (today's solver), or a layered tube from ``--tube FILE``
or from the shared options plus a pressure or an axial force (cli/tube_input.py).
"""

from __future__ import annotations

import argparse
import json
import re

from ..basestate.tube import solve_base_state
from ..errors import ConvergenceError, Remedy
from ..model.layers import Tube
from .report import physical_line, physical_record, voltage_text
from .tube_input import add_any_tube_options, tube_of


def configure_state(parser: argparse.ArgumentParser) -> None:
    add_any_tube_options(parser)  # the radii may come from a --tube file instead
    parser.add_argument(
        "--json", action="store_true", help="print one JSON object instead of text"
    )


#: `state` has neither --rtol nor --method (ConvergenceError's own remedy names both): the
#: looser tolerance it can be given is the Python API's
STATE_REMEDY = Remedy(
    "`state` solves to rtol = 1e-12; Python's solve_base_state(tube, rtol=1e-10) takes a"
    " looser tolerance",
    python="pass a looser rtol (e.g. rtol=1e-10)",
)


def run_state(args) -> int:
    tube = tube_of(args)
    try:
        state = solve_base_state(tube)
    except ConvergenceError as exc:
        if exc.remedy is ConvergenceError.remedy:  # not a particular one (e.g. OVERFLOW)
            exc.remedy = STATE_REMEDY
        raise
    rec = _with_physical(state.as_dict(), args)
    if tube.is_uniform:  # the paper's tube: its five numbers, as the paper prints them
        return _print_one_layer(tube, rec, args.json)
    if args.json:
        print(json.dumps(rec))
        return 0
    _print_layered(tube, rec)
    return 0


def _with_physical(rec: dict, args) -> dict:
    """The record with its values in physical units (key "physical") when they are given."""
    if getattr(args, "scales", None) is not None:
        rec["physical"] = physical_record(rec, args.scales)
    return rec


def _print_one_layer(params, rec: dict, as_json: bool) -> int:
    if as_json:
        print(json.dumps(rec))
        return 0
    lines = [
        f"base state: {rec['material']}, Rbar_o = {params.outer_radius:g}, g = {params.growth:g},"
        f" lambda_z = {params.stretch:g}, {voltage_text(params.voltage, params.outer_radius)}",
        f"  lambda_i = r_i / R_i         {rec['lambda_i']:.12g}",
        f"  lambda_o = r_o / R_o         {rec['lambda_o']:.12g}",
        f"  r_i, r_o                     {rec['r_i']:.12g}, {rec['r_o']:.12g}",
        f"  charge c (D_r = c / r)       {rec['charge']:.12g}",
        f"  Vbar threshold               {_threshold_text(rec)}",
        f"  axial force N / (mu R_i^2)   {rec['axial_force']:.12g}",
    ]
    _stress_lines(lines, rec)
    lines += physical_line(rec.get("physical", {}))
    print("\n".join(lines))
    return 0


def _stress_lines(lines: list, rec: dict) -> None:
    for key, name in (
        ("sigma_rr", "sigma_rr"),
        ("sigma_tt", "sigma_theta"),
        ("sigma_zz", "sigma_zz"),
    ):
        lines.append(
            f"  {name + ' / mu (min, max)':<29}{rec[key + '_min']:.6g}, {rec[key + '_max']:.6g}"
        )


def _growth_text(growth) -> str:
    if isinstance(growth, list):
        return f"g = {growth[0]:g}" if len(set(growth)) == 1 else "g = " + str(growth)
    if isinstance(growth, dict):
        return f"g from {growth['inner']} to {growth['outer']}"
    return "g graded " + re.sub(r"\s+", " ", str(growth))


def _threshold_text(rec: dict) -> str:
    thr, kind, lam = rec["voltage_threshold"], rec["threshold_kind"], rec["threshold_lambda_i"]
    if kind == "closing":
        return "0 (closing: this energy's field closes the bore; no charged state is followed)"
    if kind == "unresolved":
        return (
            "0 (unresolved: the wall's traction is flat to rounding at the uncharged state;"
            " which way a charge moves it is not resolved, no charged state is followed)"
        )
    if kind == "locking":
        return f"none before the locking stretch lambda_i = {lam:.12g} (locking)"
    if thr is None:
        return f"none (unbounded) ({kind})"
    return f"{thr:.12g} ({kind}" + (f" at lambda_i = {lam:.12g})" if lam is not None else ")")


def _print_layered(tube: Tube, rec: dict) -> None:
    control = (
        f"lambda_z = {tube.stretch:g}"
        if tube.control == "stretch"
        else f"axial force {tube.axial_force:g}{' (closed ends)' if tube.closed_ends else ''}"
    )
    lines = [
        f"base state of a {len(tube.layers)}-layer tube: {control}, Vbar = {tube.voltage:g},"
        f" P_i = {tube.inner_pressure:g}, P_o = {tube.outer_pressure:g}"
    ]
    a = 1.0
    for k, layer in enumerate(rec["layers"], 1):
        lines.append(
            f"  layer {k}: R = {a:g} .. {layer['outer_radius']:g}, {layer['material']},"
            f" mu_k = {layer['shear_modulus']:g}, eps_k = {layer['permittivity']:g},"
            f" {_growth_text(layer['growth'])}"
        )
        a = layer["outer_radius"]
    lines += [
        f"  lambda_i = r_i / R_i         {rec['lambda_i']:.12g}",
        f"  lambda_o = r_o / R_o         {rec['lambda_o']:.12g}",
        f"  r_i, r_o                     {rec['r_i']:.12g}, {rec['r_o']:.12g}",
        "  interface radii r            "
        + (", ".join(f"{r:.12g}" for r in rec["interface_radii"]) or "(one layer)"),
        f"  axial stretch lambda_z       {rec['stretch']:.12g}"
        + (" (solved)" if tube.control == "force" else ""),
        f"  charge c (D_r = c / r)       {rec['charge']:.12g}",
        f"  Vbar threshold               {_threshold_text(rec)}",
        f"  axial force N / (mu R_i^2)   {rec['axial_force']:.12g}",
        f"  end force (N less caps)      {rec['end_force']:.12g}",
    ]
    _stress_lines(lines, rec)
    lines += physical_line(rec.get("physical", {}))  # as for one layer (probe 8b D7)
    print("\n".join(lines))
