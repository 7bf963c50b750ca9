"""How the commands print results a person can trust at a glance.

* :func:`supported` (from digits.py, shared with the verdict's text) prints a value with as
  many digits as its error estimate supports: the last digit shown is the decade of the
  estimate (1.266 for 1.26611 +- 3.8e-3), never more than 12 significant digits, never
  fewer than 3;
* :func:`voltage_text` puts the voltage next to Vbar: V = Vbar (Rbar_o - 1) in units
  R_i sqrt(mu / eps), or in kV when the physical units are known (cli/units.py);
* :func:`physical_record` and :func:`physical_line` report a result in physical units;
* :func:`edge_warning` says when the critical mode of a scan sits on the edge of the
  scanned range (a larger range might hold a lower mode).
"""

from __future__ import annotations

import dataclasses
import sys
import textwrap

from ..digits import digits, supported
from ..errors import BaseStateError, ParameterError


def voltage_text(vbar: float, outer_radius: float, scales=None, error: float | None = None) -> str:
    """ "Vbar = 0.4 (V = 0.16 R_i sqrt(mu/eps))", or with the physical scales "(V = 3.2 kV)".

    >>> voltage_text(0.4, 1.4)
    'Vbar = 0.4 (V = Vbar (Rbar_o - 1) = 0.16 R_i sqrt(mu/eps))'
    """
    head = f"Vbar = {supported(vbar, error)}"
    if scales is not None and scales.has(
        "inner_radius", "outer_radius", "shear_modulus", "permittivity"
    ):
        return f"{head} (V = {scales.voltage(vbar):.{digits(vbar, error)}g~P})"
    if vbar == 0:
        return head
    rel = None if error is None else error * (outer_radius - 1.0)
    return (
        f"{head} (V = Vbar (Rbar_o - 1) = {supported(vbar * (outer_radius - 1.0), rel)}"
        " R_i sqrt(mu/eps))"
    )


#: record key -> (kind, unit) of the values a result may carry in physical units
_PHYSICAL = {
    "voltage": ("voltage", "kV"),
    "voltage_threshold": ("voltage", "kV"),
    "outer_radius": ("length", "mm"),
    "length": ("length", "mm"),
    "r_i": ("length", "mm"),
    "r_o": ("length", "mm"),
    "axial_force": ("force", "N"),
    "inner_pressure": ("stress", "kPa"),
    "outer_pressure": ("stress", "kPa"),
    **{f"sigma_{c}_{e}": ("stress", "kPa") for c in ("rr", "tt", "zz") for e in ("min", "max")},
}


def physical_record(record: dict, scales, errors: dict | None = None) -> dict:
    """The values of a JSON record that have a physical unit: key -> [value, unit]. A
    voltage needs the four scales, a length R_i, a stress mu, a force mu and R_i; others are
    left out, and so is the tube's length unless the user gave one. Each value keeps the
    significant digits of its non-dimensional value: those its absolute error estimate in
    ``errors`` (key -> error) supports, else 14 (a converted input such as 3 kV comes back as
    3, not 3.0000000000000004)."""
    if scales is None:
        return {}
    out = {}
    for key, (kind, unit) in _PHYSICAL.items():
        value = record.get(key)
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            continue
        if key == "length" and not scales.given_length:
            continue
        try:
            q = getattr(scales, kind)(value, unit)
        except ParameterError:  # that scale is not given
            continue
        error = (errors or {}).get(key)
        n = digits(value, error) if error else 14
        out[key] = [float(f"{float(q.magnitude):.{n}g}"), unit]
    return out


#: a control or key of a solve, curve or design -> its key in a physical record (_PHYSICAL)
NAMED = {
    "pressure": "inner_pressure",
    "force": "axial_force",
    "voltage": "voltage",
    "inner_pressure": "inner_pressure",
    "outer_pressure": "outer_pressure",
    "axial_force": "axial_force",
    "outer_radius": "outer_radius",
    "length": "length",
}


def named_physical(values: dict, scales, variables=()) -> dict:
    """:func:`physical_record` of ``values`` keyed by a control or key (``pressure``,
    ``outer_pressure``, ...): those with a physical unit. A voltage is converted with the
    tube's own R_o (Vbar = V / (R_o - R_i) sqrt(eps / mu)): left out when one of the
    result's ``variables`` moves the outer radius, as at another R_o it is another V."""
    moves = any(moves_radius(key) for key in variables)
    rec = {
        NAMED[name]: value
        for name, value in values.items()
        if name in NAMED and not (moves and NAMED[name] == "voltage")
    }
    return physical_record(rec, scales)


def moves_radius(key: str) -> bool:
    """Whether setting the key ``key`` (Tube.at) moves the tube's outer radius."""
    from ..model.keys import layer_key

    lk = layer_key(key)
    return key == "outer_radius" or (lk is not None and lk[1] in ("outer_radius", "thickness"))


def physical_line(physical: dict) -> list[str]:
    """One text line of a :func:`physical_record` (none when it is empty)."""
    if not physical:
        return []
    # no-break spaces inside "name = value unit": a line break falls between the entries
    parts = [f"{key}\xa0=\xa0{value:.6g}\xa0{unit}" for key, (value, unit) in physical.items()]
    text = "in physical units: " + ", ".join(parts)
    lines = textwrap.wrap(text, 95, initial_indent="  ", subsequent_indent="    ")
    return [line.replace("\xa0", " ") for line in lines]


def edge_warning(result) -> str:
    """A one-line warning when the critical mode of a scan (a ScanResult) sits on the upper
    edge of the final m or n range, else "" (the scan widens a range and searches m up to
    the tube's cap; a mode on the edge may still hide a lower one beyond). At the tube's
    cap the scan's status says it (INACCURATE, bifurcation/scan.py); at the largest mode
    the kernel resolves (MODE_MAX) raising --m-max / --n-max cannot help, and the warning
    says so."""
    from ..incremental.modes import MODE_MAX  # start-up speed: `state` loads no kernel

    c = result.critical
    if c.kind != "bifurcation":
        return ""
    edges, capped = [], []
    for name, value, top, cap in (
        ("m", c.m, result.m_range[1], result.caps[0]),
        ("n", c.n, result.n_range[1], result.caps[1]),
    ):
        if value >= cap and c.status == "inaccurate":  # said by the status's own message
            continue
        if value == top:
            (capped if value >= MODE_MAX else edges).append(
                f"{name} = {value} is the largest {name} scanned"
            )
    if not edges and not capped:
        return ""
    where = " and ".join(edges + capped)
    head = f"the critical mode (m, n) = ({c.m}, {c.n}) sits on the edge of the scanned range"
    head += f" ({where})"
    if edges:
        return f"{head}; raise --m-max / --n-max to make sure no mode beyond it comes first"
    return (
        f"{head}, the largest supported; shorter waves tend to the exact short-wave limit,"
        " which the scan compares with and reports when it comes first"
    )


def warn(message: str) -> None:
    """Print ``message`` as one warning line on stderr (nothing when it is empty)."""
    if message:
        print(f"electrogrowth: warning: {message}", file=sys.stderr)


#: warnings about how the input was read, printed once the command has run
#: (:func:`flush_notes`): bad input found later still gets its one line alone
_NOTES: list[str] = []


def note_after(message: str) -> None:
    """Queue ``message`` for :func:`flush_notes`."""
    _NOTES.append(message)


def flush_notes(keep: bool = True) -> None:
    """Print the queued notes as warnings (``keep`` False: drop them), and forget them."""
    notes = list(_NOTES) if keep else []
    _NOTES.clear()
    for message in notes:
        warn(message)


def grid_or_located(x: float, located) -> str:
    """A branch's or an interval's end ``x``: a point of the grid as given (10 digits), a
    located switch or end (``located``: objects with x and x_error) with the digits its
    estimate supports, as its own line prints it."""
    at = [s for s in located if s.x == x]
    return supported(x, at[0].x_error) if at else f"{x:.10g}"


def face_text(face: str) -> str:
    """Where a short-wave (surface) instability is, in words: "the outer face", "the inner
    face" or an interface by its name ("interface-1")."""
    return face if face.startswith("interface") else f"the {face} face"


#: a load's symbol, in a refusal quoted in physical units
_LOAD_SYMBOL = {"voltage": "V", "inner_pressure": "P_i"}


def beyond_in_units(exc: BaseStateError, scales) -> BaseStateError:
    """A load at or beyond its threshold (``exc.beyond``) refused in the units the user gave
    too, as results are printed (:func:`physical_record`): "...; in kV: V = 100 kV, its
    threshold V = 39.4005 kV". A voltage is converted with the refused tube's own R_o. Any
    other error, or no such scales, as it is."""
    b = getattr(exc, "beyond", None)
    if b is None or scales is None:
        return exc
    at = scales  # a voltage's scale: the refused tube's own wall (R_i known)
    if scales.has("inner_radius"):
        at = dataclasses.replace(scales, outer_radius=scales.inner_radius * b.outer_radius)
    pair = [physical_record({b.load: v}, at).get(b.load) for v in (b.value, b.threshold)]
    if None in pair:
        return exc
    (value, unit), (threshold, _) = pair
    name = _LOAD_SYMBOL[b.load]
    out = BaseStateError(
        f"{exc}; in {unit}: {name} = {value:.6g} {unit}, its threshold {name} ="
        f" {threshold:.6g} {unit}",
        beyond=b,
    )
    out.remedy = exc.remedy
    return out
