"""Command-line options shared by the subcommands: numbers, the tube and its material."""

from __future__ import annotations

import argparse
import math

from ..bifurcation.scan import ScanOptions
from ..errors import ParameterError, UsageError
from ..incremental.targets import METHODS
from ..model.materials import BUILTIN, material_by_name
from ..model.params import CONTROLS, SIDES, TubeParameters


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

def add_tube_options(parser: argparse.ArgumentParser, *,
                     outer_radius: float | None = None) -> None:
    """The tube, its loading and its material, shared by every subcommand.

    ``outer_radius``: a default for --outer-radius (None: the option is required).
    """
    tube = parser.add_argument_group("tube and loading (units mu = eps = R_i = 1)")
    tube.add_argument("--outer-radius", type=_number, required=outer_radius is None,
                      default=outer_radius, metavar="RBAR_O",
                      help="Rbar_o = R_o / R_i > 1, undeformed outer over inner radius"
                           + ("" if outer_radius is None else f" (default {outer_radius:g})"))
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


# -- what to solve for, and over which modes ------------------------------------------------

def add_control_options(parser: argparse.ArgumentParser) -> None:
    """--solve-for and --side: the control parameter whose critical value is sought."""
    parser.add_argument("--solve-for", required=True, choices=CONTROLS,
                        help="the control parameter to find: growth = g_cr, the smallest"
                             " g > 1 at which the tube wrinkles; stretch = lambda_z,cr on"
                             " --side; voltage = Vbar_cr, the smallest Vbar (or the threshold"
                             " where the axisymmetric state is lost, if that comes first)."
                             " The value given for it below is ignored.")
    parser.add_argument("--side", choices=SIDES, default=None,
                        help="for --solve-for stretch: axial compression (lambda_z < g,"
                             " default) or extension (lambda_z > g)")


def check_side_option(args) -> None:
    """--side belongs to --solve-for stretch only."""
    if args.side is not None and args.solve_for != "stretch":
        raise ParameterError(f"--side {args.side} applies only to --solve-for stretch")


def add_mode_range_options(group, *, top: bool = False) -> None:
    """--m-max and --n-max (and --top): the ScanOptions of a scan, defaults from it."""
    default = ScanOptions()
    group.add_argument("--m-max", type=int, default=default.m_range[1], metavar="M_MAX",
                       help="largest circumferential wavenumber m of the scan, from 0"
                            f" (default {default.m_range[1]}; widened automatically when the"
                            " critical mode sits on the edge, and probed beyond for short"
                            " waves)")
    group.add_argument("--n-max", type=int, default=default.n_range[1], metavar="N_MAX",
                       help="largest axial half-wavenumber n of the scan, from 1 (default"
                            f" {default.n_range[1]}; widened likewise)")
    if top:
        group.add_argument("--top", type=int, default=default.top,
                           help=f"number of modes to report in a scan (default {default.top})")


def scan_options_from_args(args) -> ScanOptions:
    """The ScanOptions of --m-max, --n-max (and --top, where the command has it)."""
    top = getattr(args, "top", ScanOptions().top)
    return ScanOptions(m_range=(0, args.m_max), n_range=(1, args.n_max), top=top)


def add_method_option(group, help_text: str) -> None:
    """--method: how the incremental problem is solved (incremental.targets.Method)."""
    group.add_argument("--method", choices=METHODS, default=METHODS[0], help=help_text)
