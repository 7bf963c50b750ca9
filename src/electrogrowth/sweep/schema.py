"""What a sweep's store holds: every variable of a grid point with its type, its value
before the point is computed and its description (the attributes users read in the store),
and the names and symbols of the swept parameters. store.py writes and reads them.
"""

from __future__ import annotations

import math

# the axes' names and symbols, shared with a design map's store
from ..labelled import axis_label as label  # noqa: F401
from ..labelled import parameter

#: name -> (dtype, value before the point is computed, description)
POINT_VARIABLES = {
    "critical_value": (
        "f8",
        math.nan,
        "critical value of the solved-for parameter: at the"
        " bifurcation, or where the axisymmetric state is lost",
    ),
    "m": ("i4", -1, "circumferential wavenumber of the critical mode (-1: none)"),
    "n": (
        "i4",
        -1,
        "axial half-wavenumber of the critical mode, k = n pi / (lambda_z L) (-1: none)",
    ),
    "kind": (
        object,
        "",
        "bifurcation | threshold (the axisymmetric state is lost first) |"
        " surface (the short-wave limit m, n -> inf at a face comes first)"
        " | none (no instability in the range)",
    ),
    "error_estimate": ("f8", math.nan, "|value - value at 100 times looser accuracy|"),
    "surface_instability": (
        "?",
        False,
        "the critical point is the short-wave (surface) limit m, n -> infinity at a face",
    ),
    "status": (
        object,
        "pending",
        "ok | inaccurate (error estimate above the accuracy asked, see message) |"
        " failed (see message) | error (a bug) | pending",
    ),
    "message": (
        object,
        "",
        "why the point failed or is inaccurate, or why no instability was found",
    ),
    "remedy": (object, "", "what to try where the point failed"),
    "seconds": ("f8", math.nan, "wall time of the point's mode scan"),
    "verdict": (
        object,
        "",
        "what comes first: bifurcation (a smooth wrinkle) | crease (a free face, or an"
        " interface bonded to a much softer layer, creases) |"
        " surface | threshold | none",
    ),
    "verdict_value": ("f8", math.nan, "the value of the solved-for parameter where it comes"),
    "verdict_face": (object, "", "the face of a crease or surface instability that comes first"),
    "wrinkle_value": ("f8", math.nan, "the first wrinkle of the linear analysis (NaN: none)"),
    "crease_value": (
        "f8",
        math.nan,
        "where a face (free, or an interface bonded to a much softer layer) reaches the crease"
        " onset (neo-Hookean criterion; NaN: not reached)",
    ),
    "crease_face": (
        object,
        "",
        "inner | outer | interface-K (between layers K and K + 1): the face that creases first",
    ),
    "crease_trigger": (
        object,
        "",
        "prismatic (hoop compression) | axial (axial compression) | field (electric field)",
    ),
    "crease_error": ("f8", math.nan, "the crease value's spread over the criterion's accuracy"),
    "threshold_value": ("f8", math.nan, "where the axisymmetric state is lost (NaN: not found)"),
    "meaning": (object, "", "the verdict in one line"),
    "branch": (
        object,
        "",
        "supercritical | subcritical: the wrinkle's branch by its amplitude equation"
        " ([solve] koiter = true) | '' (not computed: see branch_note)",
    ),
    "koiter": (
        "f8",
        math.nan,
        "the Koiter coefficient c_2 of control = c_cr + c_2 eps^2, eps = peak u_r / R_i"
        " (NaN: not computed)",
    ),
    "koiter_error": ("f8", math.nan, "the Koiter coefficient's change from a coarser mesh"),
    "koiter_resonance_value": (
        "f8",
        math.nan,
        "where a second harmonic of the wrinkle bifurcates next to onset (within 5 % of it),"
        " or the wrinkle itself restabilises (within 10 % past it): the coefficient, which"
        " has a pole there, holds only much closer to onset than that (NaN: none, or not"
        " computed)",
    ),
    "koiter_resonance_m": ("i4", -1, "m of that harmonic, or of the wrinkle (-1: none)"),
    "koiter_resonance_n": ("i4", -1, "n of that harmonic, or of the wrinkle (-1: none)"),
    "branch_note": (
        object,
        "",
        "why branch is empty: a case the amplitude equation does not cover, or"
        " 'amplitude equation failed: ...' ('' where computed or not asked)",
    ),
}
RUNNER_VARIABLES = {
    "runner_up_value": ("f8", math.nan, "critical value of the next modes, in order"),
    "runner_up_m": ("i4", -1, "m of the next modes"),
    "runner_up_n": ("i4", -1, "n of the next modes"),
}
#: the variables that hold a value of the solved-for control (or its error, or the Koiter
#: coefficient c_2 of control = c_cr + c_2 eps^2, eps a pure number): in its units
CONTROL_VALUED = frozenset(
    {
        "critical_value",
        "error_estimate",
        "verdict_value",
        "wrinkle_value",
        "crease_value",
        "crease_error",
        "threshold_value",
        "koiter",
        "koiter_error",
        "koiter_resonance_value",
        "runner_up_value",
    }
)


def units(name: str, solve_for: str) -> str:
    """The units of a store's variable: the control's (labelled.parameter: "1" for g,
    lambda_z and Vbar, "mu" for a pressure, ...), seconds, or "1" (a pure number, a
    wavenumber, text), as a curve's and a scan's ``to_xarray`` give them."""
    if name in CONTROL_VALUED:
        return parameter(solve_for)[0]
    return "s" if name == "seconds" else "1"


MARK = (
    "run",
    "i2",
    0,
    "completion mark: number of the run that computed the point (0: not yet computed)",
)
