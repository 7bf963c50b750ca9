"""``electrogrowth state``: the axisymmetric base state of a grown, stretched, charged tube.

A one-layer tube from the shared options (today's solver), or a layered tube from ``--tube FILE``
(model/tube_file.py) or from the shared options plus a pressure or an axial force
(basestate/layered.py). Next to ``--tube``, an option given on the command line overrides the
file's value of the same name; the single-layer options (--outer-radius, --growth, --material
and its parameters) apply then only to a one-layer file.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import re

from ..basestate.tube import solve_base_state
from ..errors import BaseStateError, ParameterError, UsageError
from ..model.layers import Tube
from ..model.materials import material_by_name
from ..model.tube_file import line_of, load_tube
from .energy import energy_from_args
from .options import add_tube_options, finite_number, tube_from_args
from .report import physical_line, physical_record, voltage_text

#: shared options whose defaults are applied here, so that a given one can override a file
_SHARED = ("outer_radius", "growth", "stretch", "voltage", "length", "material")
#: the loads only a layered tube has (option dest = Tube field)
_LOADS = ("inner_pressure", "outer_pressure", "axial_force")


def configure_state(parser: argparse.ArgumentParser) -> None:
    add_tube_options(parser, require_outer_radius=False)  # or the radii of a --tube file
    defaults = {dest: parser.get_default(dest) for dest in _SHARED}
    parser.set_defaults(**{dest: None for dest in _SHARED}, shared_defaults=defaults)
    tube = parser.add_argument_group(
        "layered tube and loads (docs/derivation-layered.md; a one-layer tube without --tube)"
    )
    tube.add_argument(
        "--tube",
        metavar="FILE",
        help="a tube file (TOML: layers, growth, loads; see examples/bilayer.toml) in place of"
        " --outer-radius, --growth and --material; other options override its values",
    )
    tube.add_argument(
        "--inner-pressure",
        type=finite_number,
        metavar="P_I",
        help="follower pressure P_i on the inner face, units mu (> 0 inflates; default 0)",
    )
    tube.add_argument(
        "--outer-pressure",
        type=finite_number,
        metavar="P_O",
        help="follower pressure P_o on the outer face, units mu (> 0 squeezes; default 0)",
    )
    tube.add_argument(
        "--axial-force",
        type=finite_number,
        metavar="F",
        help="axial force on the ends (units mu R_i^2; free ends: 0) instead of --stretch:"
        " lambda_z is then solved for",
    )
    tube.add_argument(
        "--closed-ends",
        action="store_true",
        default=None,
        help="capped ends: the pressures load them as well (with --axial-force)",
    )
    parser.add_argument(
        "--json", action="store_true", help="print one JSON object instead of text"
    )


def _given(args) -> dict:
    return {dest: getattr(args, dest) for dest in _SHARED if getattr(args, dest) is not None}


def _layered_options(args) -> bool:
    return any(getattr(args, d) is not None for d in _LOADS) or args.closed_ends is not None


def tube_of(args):
    """TubeParameters (one layer, no pressure or force: today's solver) or a layered Tube."""
    given = _given(args)
    if "stretch" in given and args.axial_force is not None:
        raise ParameterError(
            f"--stretch {given['stretch']:g} and --axial-force {args.axial_force:g} are both"
            " given; prescribe one of them"
        )
    if args.tube is None:
        if "outer_radius" not in given:
            raise UsageError("the following arguments are required: --outer-radius (or --tube)")
        for dest, value in args.shared_defaults.items():
            setattr(args, dest, given.get(dest, value))
        params = tube_from_args(args)
        if not _layered_options(args):
            return params
        tube = Tube.from_parameters(params)
    else:
        tube = load_tube(args.tube)
        layer_opts = {k: given[k] for k in ("outer_radius", "growth", "material") if k in given}
        if args.energy is not None:
            layer_opts["energy"] = args.energy
        layer_opts.update(
            {k: getattr(args, k) for k in ("jm", "alpha") if getattr(args, k) is not None}
        )
        if layer_opts:
            tube = _override_layer(tube, args, layer_opts)
        for dest in ("voltage", "length"):
            if dest in given:
                tube = dataclasses.replace(tube, **{dest: given[dest]})
        if "stretch" in given:
            tube = dataclasses.replace(tube, stretch=given["stretch"], axial_force=None)
    for dest in _LOADS:
        value = getattr(args, dest)
        if value is not None:
            extra = {"stretch": None} if dest == "axial_force" else {}
            tube = dataclasses.replace(tube, **{dest: value}, **extra)
    if args.closed_ends:
        tube = dataclasses.replace(tube, closed_ends=True)
    return tube


def _override_layer(tube: Tube, args, opts: dict) -> Tube:
    """The one layer of a one-layer file with --outer-radius, --growth, --material (+ --jm,
    --alpha) applied."""
    flags = ", ".join("--" + k.replace("_", "-") for k in opts)
    if len(tube.layers) != 1:
        raise ParameterError(
            f"{flags} applies to a one-layer tube; {args.tube} has {len(tube.layers)} layers:"
            " edit its [[layers]] instead"
        )
    fields = {k: opts[k] for k in ("outer_radius", "growth") if k in opts}
    if "energy" in opts:
        fields["material"] = energy_from_args(args)
    elif {"material", "jm", "alpha"} & set(opts):
        name = opts.get("material", "neo-hookean")
        params = {}
        for flag, key, owner in (("--jm", "jm", "gent"), ("--alpha", "alpha", "mooney-rivlin")):
            if key in opts:
                if name != owner:
                    raise ParameterError(
                        f"{flag} = {opts[key]:g} applies only to --material {owner}, not {name}"
                    )
                params[key] = opts[key]
        fields["material"] = material_by_name(name, **params)
    return dataclasses.replace(tube, layers=(dataclasses.replace(tube.layers[0], **fields),))


def run_state(args) -> int:
    tube = tube_of(args)
    if not isinstance(tube, Tube):
        rec = _with_physical(solve_base_state(tube).as_dict(), args)
        return _print_one_layer(tube, rec, args.json)
    try:
        rec = _with_physical(solve_base_state(tube).as_dict(), args)
    except BaseStateError as exc:
        raise _located(exc, args) from None
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


def _located(exc: BaseStateError, args) -> BaseStateError:
    """A threshold error with the file and line of the load it names, when it is the file's."""
    key = "voltage" if "Vbar" in str(exc) else "inner_pressure" if "P_i" in str(exc) else None
    if args.tube is None or key is None or getattr(args, key) is not None:
        return exc
    with open(args.tube, encoding="utf-8") as fh:
        line = line_of(fh.read(), (key,))
    where = ":".join(str(p) for p in (args.tube, line) if p is not None)
    return BaseStateError(f"{where}: {key}: {exc}")


def _print_one_layer(params, rec: dict, as_json: bool) -> int:
    if as_json:
        print(json.dumps(rec))
        return 0
    thr = rec["voltage_threshold"]
    lines = [
        f"base state: {rec['material']}, Rbar_o = {params.outer_radius:g}, g = {params.growth:g},"
        f" lambda_z = {params.stretch:g}, {voltage_text(params.voltage, params.outer_radius)}",
        f"  lambda_i = r_i / R_i         {rec['lambda_i']:.12g}",
        f"  lambda_o = r_o / R_o         {rec['lambda_o']:.12g}",
        f"  r_i, r_o                     {rec['r_i']:.12g}, {rec['r_o']:.12g}",
        f"  charge c (D_r = c / r)       {rec['charge']:.12g}",
        f"  Vbar threshold               {'none (unbounded)' if thr is None else f'{thr:.12g}'}"
        f" ({rec['threshold_kind']})",
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
    print("\n".join(lines))
