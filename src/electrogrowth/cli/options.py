"""Command-line options shared by the subcommands: numbers, the tube and its material."""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import ParameterError
from ..model import energy_words
from ..model.controls import KINDS, SIDED, SIDES, TUBE_CONTROLS
from ..model.layers import Tube
from ..model.materials import BUILTIN, material_by_name
from .energy import energy_from_args
from .units import add_unit_options, number_or_quantity

if TYPE_CHECKING:
    from ..bifurcation.options import ScanOptions
    from ..incremental.modes import Family

# The mode, scan and method options import bifurcation.options and incremental.modes inside
# their functions (an exception to docs/architecture.md's rule, for start-up speed): `state`
# and the tube options every command shares do not need them. Neither imports the compiled
# kernels (numba, ~0.35 s of CPU per process), so a command's options are configured and a
# bad argument named before any solver loads.


def finite_number(text: str) -> float:
    """A finite real number (ranges are checked by Tube.uniform, which names the value)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
    return value


def path_arg(text: str) -> Path:
    """A path; an empty one is refused (it would silently mean the current directory)."""
    if not text.strip():
        raise argparse.ArgumentTypeError(
            f"{text!r} is an empty path; give a file or directory ('.' for this one)"
        )
    return Path(text)


def bounded_int(lowest: int, highest: int, why: str = ""):
    """An argument type: a whole number in [lowest, highest], else a one-line error naming
    the value, the range and ``why`` the range ends there (never an overflow or a hang)."""

    def parse(text: str) -> int:
        try:
            value = int(text) if len(text) <= 20 else None
        except ValueError:
            value = None
        if value is None or not lowest <= value <= highest:
            shown = text if len(text) <= 20 else text[:17] + "..."
            reason = f" ({why})" if why else ""
            raise argparse.ArgumentTypeError(
                f"{shown!r} is not a whole number from {lowest} to {highest}{reason}"
            )
        return value

    parse.__name__ = "whole number"  # argparse names the type in its messages
    return parse


#: What --koiter costs, as measured (CPU seconds, 2 shared cores at load ~4.5, 2026-12-08:
#: the paper's tube Rbar_o 1.4, Vbar 0.4 +2.5 s for --mode 0 1 and +7.1 s for its scan;
#: README's examples/mucosa.toml --mode 12 0 +11.6 s; a fresh install compiles ~10 s more
#: once). The help of critical and design and critical's note say the same.
KOITER_COST = "adds ~3-7 s on the paper's tube, ~12 s on a layered tube; ~10 s more the first time"


#: Why the largest m and n of a scan's ranges and of one --mode are
#: incremental.modes.MODE_MAX (what the kernel resolves, with a decade to spare); shorter
#: waves tend to the exact short-wave (half-space) limit, which every scan computes.
SHORT_WAVES = (
    "the shortest waves the kernel resolves; shorter ones tend to the exact short-wave"
    " limit, which every scan computes"
)


# -- the tube --------------------------------------------------------------------------------


def add_tube_options(
    parser: argparse.ArgumentParser,
    *,
    outer_radius: float | None = None,
    require_outer_radius: bool = True,
) -> None:
    """The tube, its loading and its material, shared by every subcommand.

    ``outer_radius``: a default for --outer-radius; without one the option is required
    unless ``require_outer_radius`` is False (a tube file may give the radii instead).
    """
    tube = parser.add_argument_group("tube and loading (units mu = eps = R_i = 1)")
    tube.add_argument(
        "--outer-radius",
        type=number_or_quantity,
        required=outer_radius is None and require_outer_radius,
        default=outer_radius,
        metavar="RBAR_O",
        help="Rbar_o = R_o / R_i > 1, undeformed outer over inner radius, or R_o as a length"
        " (2.8mm, with --inner-radius)"
        + ("" if outer_radius is None else f" (default {outer_radius:g})"),
    )
    tube.add_argument(
        "--growth",
        type=finite_number,
        default=1.0,
        metavar="G",
        help="isotropic growth factor g > 0, F_g = g I (default 1: no growth)",
    )
    tube.add_argument(
        "--stretch",
        type=finite_number,
        default=1.0,
        metavar="LAMBDA_Z",
        help="total axial stretch lambda_z = l / L > 0, growth included (default 1)",
    )
    tube.add_argument(
        "--voltage",
        type=number_or_quantity,
        default=0.0,
        metavar="VBAR",
        help="Vbar = V / (R_o - R_i) sqrt(eps / mu) >= 0, the radial voltage, or V with its"
        " unit (3kV, with the physical units below); must stay below the threshold"
        " (default 0)",
    )
    tube.add_argument(
        "--length",
        type=number_or_quantity,
        default=1.0,
        metavar="L",
        help="L / R_i > 0, undeformed length, or a length (10mm, with --inner-radius); does"
        " not change the base state (default 1)",
    )
    mat = parser.add_argument_group(
        "material (ideal dielectric, Omega = W + I5 / 2, or any energy with --energy)"
    )
    choice = mat.add_mutually_exclusive_group()
    choice.add_argument(
        "--material",
        choices=sorted(BUILTIN),
        default="neo-hookean",
        help="elastic energy W (default neo-hookean)",
    )
    choice.add_argument(
        "--energy",
        metavar="OMEGA",
        help="the energy Omega(I1, I2, I4, I5, I6) per unit virtual volume, units mu = eps = 1,"
        ' instead of --material, e.g. "(I1 - 3)/2 + 0.1*(I2 - 3) + I5/2": I1 = tr C, I2,'
        f" I4 = D~.D~, I5 = D~.C D~, I6 = D~.C^2 D~ (paper eq. 8); {energy_words.words()};"
        " stresses, field and moduli follow from it",
    )
    mat.add_argument(
        "--jm",
        type=finite_number,
        metavar="JM",
        help="Gent stiffening parameter J_m >= 0.001 (only with --material gent; default 97.2)",
    )
    mat.add_argument(
        "--alpha",
        type=finite_number,
        metavar="ALPHA",
        help="Mooney-Rivlin weight 0 < alpha <= 1 of I1 (only with"
        " --material mooney-rivlin; default 0.5)",
    )
    add_unit_options(parser)


def tube_from_args(args) -> Tube:
    """The paper's tube (``Tube.uniform``) from the options of :func:`add_tube_options`."""
    return Tube.uniform(
        outer_radius=args.outer_radius,
        length=args.length,
        growth=args.growth,
        stretch=args.stretch,
        voltage=args.voltage,
        material=_material(args),
    )


def _material(args):
    if getattr(args, "energy", None) is not None:
        return energy_from_args(args)
    options = {}
    for flag, name, owner in (("--jm", "jm", "gent"), ("--alpha", "alpha", "mooney-rivlin")):
        value = getattr(args, name)
        if value is not None:
            if args.material != owner:
                raise ParameterError(
                    f"{flag} = {value:g} applies only to --material {owner}, not {args.material}"
                )
            options[name] = value
    return material_by_name(args.material, **options)


# -- what to solve for, and over which modes ------------------------------------------------


def add_control_options(parser: argparse.ArgumentParser) -> None:
    """--solve-for, --layer, --component and --side: the control parameter whose critical
    value is sought (model/controls.py)."""
    parser.add_argument(
        "--solve-for",
        required=True,
        choices=TUBE_CONTROLS,
        help="the control parameter to find: "
        + "; ".join(kind.help for kind in KINDS.values())
        + ". The value given for it below is ignored.",
    )
    parser.add_argument(
        "--layer",
        type=int,
        metavar="K",
        help="with --solve-for growth: the layer K of the --tube file that grows (1 ="
        " innermost; required for several layers)",
    )
    parser.add_argument(
        "--component",
        metavar="C",
        help="with --solve-for growth: the component(s) of the layer's growth tensor"
        " diag(g_r, g_theta, g_z) that are varied, r, theta or z, or several joined by +"
        " (r+theta: growth in the cross-section); the others keep their values"
        " (default: all three, isotropic growth)",
    )
    parser.add_argument(
        "--side",
        choices=SIDES,
        default=None,
        help="the direction of the control: for --solve-for stretch axial compression"
        " (lambda_z below its free value, default) or extension; for pressure inflation"
        " (extension, default) or collapse (compression); for force compression (default)"
        " or tension (extension)",
    )


def check_side_option(args) -> None:
    """--side belongs to --solve-for stretch, pressure and force only."""
    if args.side is not None and args.solve_for not in SIDED:
        raise ParameterError(
            f"--side {args.side} applies only to --solve-for {', '.join(SIDED[:-1])}"
            f" or {SIDED[-1]}"
        )


#: The mode families and what a scan covers, in the paper's terms (--help of every command
#: that finds a critical mode).
MODE_COVERAGE = (
    "Mode families: 'wrinkle' = the paper's ansatz u_r = U_r(r) cos(m theta) cos(k z),"
    " u_theta ~ sin(m theta) cos(k z), u_z ~ cos(m theta) sin(k z), k = n pi / (lambda_z L),"
    " m >= 0, n >= 1 (m = 0: axisymmetric); 'prismatic' = n = 0 (k = 0), m >= 2:"
    " plane-strain wrinkles with u_z = 0, admissible with sliding ends (the long-tube limit"
    " of n = 1); 'torsional' = m = 0: u_theta = U(r) cos(k z) alone, n >= 1. A scan examines"
    " by default all three: wrinkles 0 <= m <= M_MAX, 1 <= n <= N_MAX, prismatic"
    " 2 <= m <= M_MAX and torsional 1 <= n <= N_MAX (ranges widened and probed beyond for"
    " short waves); the short-wave (surface) limit m, n -> infinity is not scanned but"
    " computed exactly from the half-space problem at each face, and reported when it comes"
    " first."
)


def add_mode_range_options(group, *, top: bool = False) -> None:
    """--m-max and --n-max (and --top): the ScanOptions of a scan, defaults from it."""
    # start-up speed (see top)
    from ..bifurcation.options import EVERY_M, M_CAP, TOP_MAX, ScanOptions
    from ..incremental.modes import MODE_MAX

    default = ScanOptions()
    group.add_argument(
        "--m-max",
        type=bounded_int(0, MODE_MAX, SHORT_WAVES),
        default=default.m_range[1],
        metavar="M_MAX",
        help="largest circumferential wavenumber m of the scan, from 0"
        f" (default {default.m_range[1]}; widened automatically when the"
        " critical mode sits on the edge, and probed beyond for short"
        f" waves; every m is scanned up to {EVERY_M}, larger m up to {M_CAP} (more for a"
        " thin layer: its folds' m) are searched coarse-to-fine for the best m). The"
        " scan covers the"
        " wrinkles (m, n), n >= 1, the"
        " prismatic modes (m, 0), m >= 2, and the torsional modes (0, n);"
        " the short-wave limit m, n -> infinity comes exactly from the"
        " half-space problem",
    )
    group.add_argument(
        "--n-max",
        type=bounded_int(1, MODE_MAX, SHORT_WAVES),
        default=default.n_range[1],
        metavar="N_MAX",
        help="largest axial half-wavenumber n of the scan, from 1 (default"
        f" {default.n_range[1]}; widened likewise); the prismatic modes"
        " n = 0 are scanned too",
    )
    if top:
        group.add_argument(
            "--top",
            type=bounded_int(1, TOP_MAX),
            default=default.top,
            help=f"number of modes to report in a scan (default {default.top})",
        )


def add_mode_option(group) -> None:
    """--mode M N and --family: one mode instead of a scan."""
    from ..incremental.modes import FAMILIES, MODE_MAX  # start-up speed (see top)

    group.add_argument(
        "--mode",
        nargs=2,
        type=bounded_int(0, MODE_MAX, SHORT_WAVES),
        metavar=("M", "N"),
        help="one mode instead of a scan: circumferential wavenumber m >= 0"
        " (lobes around) and axial half-wavenumber n >= 0 (half-waves"
        " along the tube); n = 0 is a prismatic mode (m >= 2; (0, 0) is"
        " the breathing mode, the base state's own limit point, and"
        " (1, 0) a rigid translation); (0, n) is axisymmetric unless"
        " --family torsional",
    )
    group.add_argument(
        "--family",
        choices=FAMILIES,
        default=None,
        help="the family of --mode (default: prismatic for n = 0, else"
        " wrinkle): wrinkle = the paper's ansatz, prismatic = n = 0"
        " plane strain, torsional = m = 0, u_theta = U(r) cos(k z)",
    )


def mode_from_args(args) -> tuple[int, int, Family] | None:
    """(m, n, family) of --mode and --family, checked; None for a scan."""
    if args.mode is None:
        if args.family is not None:
            raise ParameterError(
                f"--family {args.family} needs --mode M N (a scan covers every family)"
            )
        return None
    from ..incremental.modes import check_mode  # start-up speed (see top)

    m, n = args.mode
    return m, n, check_mode(m, n, args.family)


def scan_options_from_args(args) -> ScanOptions:
    """The ScanOptions of --m-max, --n-max (and --top, where the command has it)."""
    from ..bifurcation.options import ScanOptions  # start-up speed (see top)

    top = getattr(args, "top", ScanOptions().top)
    return ScanOptions(m_range=(0, args.m_max), n_range=(1, args.n_max), top=top)


def add_method_option(group, help_text: str) -> None:
    """--method: how the incremental problem is solved (incremental.modes.Method)."""
    from ..incremental.modes import METHODS  # start-up speed (see top)

    group.add_argument("--method", choices=METHODS, default=METHODS[0], help=help_text)
