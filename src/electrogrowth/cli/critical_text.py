"""The text report of ``electrogrowth critical`` (and the tube line ``pattern`` shares): the
critical value with the digits its error estimate supports, the runners-up, the crease and
threshold that compete with it, and the verdict.
"""

from __future__ import annotations

import math

from ..model.controls import KINDS, parse_control
from ..outcomes import Kind
from .report import face_text, physical_line, supported, voltage_text


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


def tube_line(rec: dict, scales=None) -> str:
    """The tube of a JSON record in one line (one layer, or the layers and loads); the value
    solved for with the digits its error estimate supports, the voltage next to Vbar."""
    if "layers" not in rec:
        volts = voltage_text(rec["voltage"], rec["outer_radius"], scales, _error(rec, "voltage"))
        return (
            f"  tube: Rbar_o = {rec['outer_radius']:g}, L = {rec['length']:g},"
            f" g = {_given(rec, 'growth')}, lambda_z = {_given(rec, 'stretch')},"
            f" {volts}, {rec['material']}"
        )
    layers = "; ".join(
        f"R <= {ly['outer_radius']:g} {ly['material']} mu {ly['shear_modulus']:g}"
        f" g {_growth_text(ly['growth'], rec)}"
        for ly in rec["layers"]
    )
    axial = (
        f"lambda_z = {_load(rec, 'stretch')}"
        if rec["stretch"] is not None
        else f"axial force {_load(rec, 'axial_force')}"
    )
    return (
        f"  tube: {len(rec['layers'])} layer(s) [{layers}], L = {rec['length']:g}, {axial},"
        f" Vbar = {_load(rec, 'voltage')}, P_i = {_load(rec, 'inner_pressure')},"
        f" P_o = {_load(rec, 'outer_pressure')}"
    )


def _load(rec: dict, key: str) -> str:
    """A layered tube's stretch, force, voltage or pressure: the one solved for (the
    control's tube field, model/controls.py KINDS) with the digits its error estimate
    supports, as the headline prints it; a given load to 12 digits. Only where the tube is
    at the value solved for: a crease's record carries the wrinkle's tube, and its own
    estimate is not that value's (a force solved at rtol 1e-8, estimate 1.1e-7, was
    printed -6.27486723204e-05 for -6.27486168431e-05: probe 9a, D4)."""
    value = rec[key]
    field = KINDS[parse_control(rec["solve_for"]).kind].field
    if field == key and value == rec["value"]:
        return supported(value, rec["error_estimate"])
    return f"{value:.12g}"


def _growth_text(growth, rec: dict) -> str:
    """A layer's growth triple, the component solved for with the digits its estimate
    supports (graded growth as recorded)."""
    if not isinstance(growth, list):
        return str(growth)
    solved = rec["solve_for"].startswith("growth") and rec["kind"] == Kind.BIFURCATION
    return (
        "["
        + ", ".join(
            supported(g, rec["error_estimate"]) if solved and g == rec["value"] else f"{g:.12g}"
            for g in growth
        )
        + "]"
    )


def print_text(rec: dict, runners: list, scales=None) -> None:
    from ..bifurcation.verdict import crease_where

    name = value_name(rec["solve_for"])
    value = supported(rec["value"], rec["error_estimate"])  # the digits the estimate supports
    if rec["kind"] == Kind.CREASE:
        head = (
            f"{name} = {_crease_value(rec['value'], rec['error_estimate'])}"
            f"   crease at {crease_where(rec['face'], rec['crease'].get('detail'))},"
            f" {_TRIGGER.get(rec['crease']['trigger'], '')}"
        )
    elif rec["kind"] == Kind.THRESHOLD:
        head = f"{name} = {value}: the axisymmetric state is lost before any wrinkling mode"
    elif rec["kind"] == Kind.SURFACE:
        along = (
            "theta"
            if rec["psi"] == 0
            else "z"
            if abs(rec["psi"] - math.pi / 2) < 1e-12
            else f"the direction psi = {rec['psi']:.6g} rad from theta to z"
        )
        head = (
            f"{name} = {value}  (error estimate {rec['error_estimate']:.1e},"
            f" half-space)   short-wave (surface) instability, m, n -> infinity, at"
            f" {face_text(rec['face'])}, wrinkles along {along}"
        )
    else:
        head = (
            f"{name} = {value}  (error estimate {rec['error_estimate']:.1e},"
            f" {rec['method']})   mode (m, n) = ({rec['m']}, {rec['n']})"
            f"{_family_note(rec.get('family'))}"
        )
    lines = [head, tube_line(rec, scales)]
    lines += physical_line(rec.get("physical", {}))
    w = rec.get("wrinkle")
    if w is not None and rec["kind"] != Kind.BIFURCATION:
        lines.append(
            f"  wrinkle (linear analysis): (m, n) = ({w['m']}, {w['n']})"
            f"{_family_note(w.get('family'))}   {name} ="
            f" {supported(w['value'], w.get('error_estimate'))}{_scanned(rec)}"
        )
    if "certification" in rec:  # a surface result: what was certified and how, or why not
        lines.append(
            f"  {'certified' if rec['certified'] else 'NOT certified'}: {rec['certification']}"
        )
    elif rec.get("certified"):
        lines.append(
            f"  certified by {rec['certified_by']}: {rec['certified_value']:.12g}"
            f" (relative difference {rec['certification_difference']:.1e})"
            + (
                f"; all {rec['certified_modes']} scanned modes stable before it"
                if "certified_modes" in rec
                else ""
            )
        )
    if rec.get("short_wave_limit") is not None and rec["kind"] != Kind.SURFACE:
        lines.append(
            f"  short-wave (surface) limit m, n -> infinity: {name} ="
            f" {rec['short_wave_limit']:.12g} (after this mode)"
        )
    shown = None if w is None or rec["kind"] == Kind.BIFURCATION else w
    for r in runners:
        if shown is not None and all(r[k] == shown[k] for k in ("m", "n", "family", "value")):
            continue  # a surface result's best finite mode heads its runners-up: shown above
        # the digits its estimate supports (a scan's runners-up carry one: runners.py)
        lines.append(
            f"  next: (m, n) = ({r['m']}, {r['n']}){_family_note(r.get('family'))}"
            f"   {name} = {supported(r['value'], r.get('error_estimate'))}"
            + (f"  ({r['note']})" if r.get("note") else "")
        )
    lines += _rival_lines(rec, name)
    print("\n".join(lines))


def _scanned(rec: dict) -> str:
    """Where a surface result's finite mode is first: only among the scanned modes (shorter
    waves than those tend to the surface value, no finite mode is first among all)."""
    if not rec.get("surface_instability") or "m_range" not in rec:
        return ""
    (m0, m1), (n0, n1) = rec["m_range"], rec["n_range"]
    return f"  (the first of the scanned m = {m0}..{m1}, n = {n0}..{n1})"


_TRIGGER = {
    "prismatic": "fold lines along the axis (hoop compression)",
    "axial": "rings (axial compression)",
    "field": "by the field criterion of a bonded, unstretched film (an early bound, not ranked)",
}


def _crease_value(value: float, estimate: float | None) -> str:
    """A crease onset with the digits its criterion supports; an estimate that is not finite
    (null in the record: an energy with no Biot ratio, crease.energy_shift) supports none
    of the criterion's digits."""
    if estimate is None:
        return f"{value:.3g}  (neo-Hookean criterion, not established for this energy)"
    return f"{supported(value, estimate)}  (accuracy of the crease criterion {estimate:.1e})"


def _rival_lines(rec: dict, name: str) -> list[str]:
    """The runner-up crease and threshold, and the verdict in words."""
    from ..bifurcation.verdict import crease_where

    lines = []
    c, t = rec.get("crease"), rec.get("threshold")
    if c is not None and rec["kind"] != Kind.CREASE:
        lines.append(
            f"  crease: {crease_where(c['face'], c.get('detail'))},"
            f" {_TRIGGER.get(c['trigger'], '')}   {name} ="
            f" {_crease_value(c['value'], c['error_estimate'])}"
        )
    if t is not None and rec["kind"] != Kind.THRESHOLD:
        lines.append(f"  axisymmetric state lost ({t['detail']}): {name} = {t['value']:.10g}")
    if rec.get("koiter") is not None:
        lines.append(
            f"  amplitude equation: {rec['branch']}, Koiter coefficient c_2 ="
            f" {rec['koiter']:.6g} (on the branch the control is its critical value"
            " + c_2 eps^2, eps = peak u_r / R_i)"
        )
    elif rec.get("branch_note"):
        lines.append(f"  amplitude equation not computed: {rec['branch_note']}")
    if rec.get("meaning"):
        lines.append(f"  verdict: {rec['meaning']}")
    return lines


def _error(rec: dict, key: str) -> float | None:
    """The error estimate of ``key`` if it is the value solved for (else an input: None)."""
    return rec["error_estimate"] if rec["solve_for"] == key else None


def _given(rec: dict, key: str) -> str:
    return supported(rec[key], _error(rec, key))


def _family_note(family: str | None) -> str:
    """How a mode's family is named after (m, n) in text: nothing for a wrinkle."""
    return {
        "prismatic": ", prismatic (n = 0: plane strain)",
        "torsional": ", torsional (u_theta only)",
    }.get(family or "", "")
