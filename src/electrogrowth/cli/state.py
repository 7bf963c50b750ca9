"""``electrogrowth state``: the axisymmetric base state of a grown, stretched, charged tube."""

from __future__ import annotations

import argparse
import json

from ..basestate.tube import solve_base_state
from .options import add_tube_options, tube_from_args


def configure_state(parser: argparse.ArgumentParser) -> None:
    add_tube_options(parser)
    parser.add_argument(
        "--json", action="store_true", help="print one JSON object instead of text"
    )


def run_state(args) -> int:
    params = tube_from_args(args)
    rec = solve_base_state(params).as_dict()
    if args.json:
        print(json.dumps(rec))
        return 0
    thr = rec["voltage_threshold"]
    lines = [
        f"base state: {rec['material']}, Rbar_o = {params.outer_radius:g}, g = {params.growth:g},"
        f" lambda_z = {params.stretch:g}, Vbar = {params.voltage:g}",
        f"  lambda_i = r_i / R_i         {rec['lambda_i']:.12g}",
        f"  lambda_o = r_o / R_o         {rec['lambda_o']:.12g}",
        f"  r_i, r_o                     {rec['r_i']:.12g}, {rec['r_o']:.12g}",
        f"  charge c (D_r = c / r)       {rec['charge']:.12g}",
        f"  Vbar threshold               {'none (unbounded)' if thr is None else f'{thr:.12g}'}"
        f" ({rec['threshold_kind']})",
        f"  axial force N / (mu R_i^2)   {rec['axial_force']:.12g}",
    ]
    for key, name in (
        ("sigma_rr", "sigma_rr"),
        ("sigma_tt", "sigma_theta"),
        ("sigma_zz", "sigma_zz"),
    ):
        lines.append(
            f"  {name + ' / mu (min, max)':<29}{rec[key + '_min']:.6g}, {rec[key + '_max']:.6g}"
        )
    print("\n".join(lines))
    return 0
