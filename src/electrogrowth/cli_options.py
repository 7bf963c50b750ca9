"""Command-line options shared by the subcommands: numbers, the tube and its material."""

from __future__ import annotations

import argparse
import math

from .errors import ParameterError
from .materials import BUILTIN, material_by_name
from .params import TubeParameters


class UsageError(Exception):
    """A bad command line (raised by the parser instead of printing usage and exiting)."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(message)


def _number(text: str) -> float:
    """A finite real number (ranges are checked by TubeParameters, which names the value)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
    return value


# -- the tube --------------------------------------------------------------------------------

def add_tube_options(parser: argparse.ArgumentParser) -> None:
    """The tube, its loading and its material, shared by every subcommand."""
    tube = parser.add_argument_group("tube and loading (units mu = eps = R_i = 1)")
    tube.add_argument("--outer-radius", type=_number, required=True, metavar="RBAR_O",
                      help="Rbar_o = R_o / R_i > 1, undeformed outer over inner radius")
    tube.add_argument("--growth", type=_number, default=1.0, metavar="G",
                      help="isotropic growth factor g > 0, F_g = g I (default 1: no growth)")
    tube.add_argument("--stretch", type=_number, default=1.0, metavar="LAMBDA_Z",
                      help="total axial stretch lambda_z = l / L > 0, growth included"
                           " (default 1)")
    tube.add_argument("--voltage", type=_number, default=0.0, metavar="VBAR",
                      help="Vbar = V / (R_o - R_i) sqrt(eps / mu) >= 0, the radial voltage;"
                           " must stay below the threshold (default 0)")
    tube.add_argument("--length", type=_number, default=1.0, metavar="L",
                      help="L / R_i > 0, undeformed length; does not change the base state"
                           " (default 1)")
    mat = parser.add_argument_group("material (ideal dielectric, Omega = W + I5 / 2)")
    mat.add_argument("--material", choices=sorted(BUILTIN), default="neo-hookean",
                     help="elastic energy W (default neo-hookean)")
    mat.add_argument("--jm", type=_number, metavar="JM",
                     help="Gent stiffening parameter J_m > 0 (only with --material gent;"
                          " default 97.2)")
    mat.add_argument("--alpha", type=_number, metavar="ALPHA",
                     help="Mooney-Rivlin weight 0 < alpha <= 1 of I1 (only with"
                          " --material mooney-rivlin; default 0.5)")


def tube_from_args(args) -> TubeParameters:
    """TubeParameters from the options of :func:`add_tube_options`."""
    return TubeParameters(outer_radius=args.outer_radius, length=args.length,
                          growth=args.growth, stretch=args.stretch, voltage=args.voltage,
                          material=_material(args))


def _material(args):
    options = {}
    for flag, name, owner in (("--jm", "jm", "gent"), ("--alpha", "alpha", "mooney-rivlin")):
        value = getattr(args, name)
        if value is not None:
            if args.material != owner:
                raise ParameterError(f"{flag} = {value:g} applies only to --material {owner},"
                                     f" not {args.material}")
            options[name] = value
    return material_by_name(args.material, **options)
