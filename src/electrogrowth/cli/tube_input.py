"""The tube of a command: one homogeneous layer from the shared options (the paper's tube),
or a layered tube from ``--tube FILE`` (model/tube_file.py) and the loads a layered tube has
(pressures, an axial force; basestate/layered.py).

Next to ``--tube``, an option given on the command line overrides the file's value of the
same name; the single-layer options (--outer-radius, --growth, --material and its
parameters) apply then only to a one-layer file. Shared by ``state``, ``critical``,
``curve`` and ``pattern``.
"""

from __future__ import annotations

import argparse
import dataclasses

from ..errors import BaseStateError, ParameterError, UsageError
from ..model.layers import Tube
from ..model.materials import material_by_name
from ..model.toml_input import read_text
from ..model.tube_file import line_of, load_tube
from .energy import energy_from_args
from .options import add_tube_options, tube_from_args
from .units import number_or_quantity

#: shared options whose defaults are applied here, so that a given one can override a file
_SHARED = ("outer_radius", "growth", "stretch", "voltage", "length", "material")
#: the loads only a layered tube has (option dest = Tube field)
_LOADS = ("inner_pressure", "outer_pressure", "axial_force")


def add_any_tube_options(parser: argparse.ArgumentParser, *, outer_radius=None) -> None:
    """The one-layer options (:func:`options.add_tube_options`) and the layered ones:
    ``--tube FILE``, ``--inner-pressure``, ``--outer-pressure``, ``--axial-force``,
    ``--closed-ends``. ``outer_radius``: a default Rbar_o for the one-layer tube."""
    add_tube_options(parser, require_outer_radius=False)
    defaults = {dest: parser.get_default(dest) for dest in _SHARED}
    if outer_radius is not None:
        defaults["outer_radius"] = outer_radius
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
        type=number_or_quantity,
        metavar="P_I",
        help="follower pressure P_i on the inner face, units mu (> 0 inflates; default 0), or"
        " a pressure with its unit (5kPa, with --shear-modulus)",
    )
    tube.add_argument(
        "--outer-pressure",
        type=number_or_quantity,
        metavar="P_O",
        help="follower pressure P_o on the outer face, units mu (> 0 squeezes; default 0), or"
        " a pressure with its unit (5kPa, with --shear-modulus)",
    )
    tube.add_argument(
        "--axial-force",
        type=number_or_quantity,
        metavar="F",
        help="axial force on the ends (units mu R_i^2; free ends: 0), or a force with its unit"
        " (0.1N, with --shear-modulus and --inner-radius), instead of --stretch: lambda_z is"
        " then solved for",
    )
    tube.add_argument(
        "--closed-ends",
        action="store_true",
        default=None,
        help="capped ends: the pressures load them as well (with --axial-force)",
    )


def _given(args) -> dict:
    return {dest: getattr(args, dest) for dest in _SHARED if getattr(args, dest) is not None}


def tube_of(args) -> Tube:
    """The tube of the options: the paper's tube (``Tube.uniform``) from --outer-radius,
    --growth, ..., or a --tube file, with the loads given (pressures, force) applied."""
    given = _given(args)
    if "stretch" in given and args.axial_force is not None:
        raise ParameterError(
            f"--stretch {given['stretch']:g} and --axial-force {args.axial_force:g} are both"
            " given; prescribe one of them"
        )
    if args.tube is None:
        if given.get("outer_radius", args.shared_defaults["outer_radius"]) is None:
            raise UsageError("the following arguments are required: --outer-radius (or --tube)")
        for dest, value in args.shared_defaults.items():
            setattr(args, dest, given.get(dest, value))
        tube = tube_from_args(args)
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


def control_of(args) -> tuple[Tube, str]:
    """(the tube, the canonical control name) of a command with --solve-for, --layer,
    --component."""
    params = tube_of(args)
    name = args.solve_for
    if args.layer is not None or args.component is not None:
        if name != "growth":
            raise ParameterError(
                f"--layer / --component apply to --solve-for growth, not {args.solve_for}"
            )
        name = str(params.check_control(f"growth[{1 if args.layer is None else args.layer}]"))
        if args.component is not None:
            name += "." + args.component
    name = str(params.check_control(name))
    if args.solve_for == "growth" and args.component is None:
        _note_isotropic(params, args.layer or 1, name)
    return params, name


def _note_isotropic(params: Tube, k: int, control: str) -> None:
    """A warning, once the command has run, where ``control`` (growth or growth[k]: all
    three components, g I) replaces an anisotropic constant growth of the file's layer k:
    the file's hoop growth (1, 1.2, 1) was dropped without a word by a README command
    (check round 29)."""
    from .report import note_after

    layer = params.layers[k - 1]
    if layer.graded or len(set(layer.growth)) == 1:
        return
    g = ", ".join(f"{v:g}" for v in layer.growth)
    note_after(
        f"{control} varies layer {k}'s growth isotropically (g_r = g_theta = g_z = g),"
        f" replacing its ({g}); --component r, theta or z varies one of them alone"
    )


#: the loads a threshold message names as its cause: tube field -> how the message starts
#: (uniform.py's and layered.py's voltage messages, thresholds.py's pressure one)
_THRESHOLD_LOADS = {"voltage": "Vbar = ", "inner_pressure": "inner pressure P_i = "}


def located(exc: BaseStateError, args) -> BaseStateError:
    """A load beyond its threshold, prefixed ``FILE:LINE: key:`` when that load is the tube
    file's (not a command-line override, nor a value a command marched to); any other
    error as it is. One path for every command and for one layer or several."""
    path = getattr(args, "tube", None)
    if path is None:
        return exc
    tube = load_tube(path)
    for key, start in _THRESHOLD_LOADS.items():
        if (
            str(exc).startswith(f"{start}{getattr(tube, key):.12g} ")
            and getattr(args, key) is None
        ):
            line = line_of(read_text(path, "tube file"), (key,))
            where = ":".join(str(p) for p in (path, line) if p is not None)
            out = BaseStateError(f"{where}: {key}: {exc}")
            out.remedy = exc.remedy  # the load's own remedy (a pressure's is not a voltage's)
            return out
    return exc
