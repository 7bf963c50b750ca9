"""The growth-voltage map of an electro-active tube: which pattern the voltage selects.

At a voltage Vbar the tube stays axisymmetric while its growth g is below the first
critical growth g_cr(Vbar) = min over (m, n) of g_mn(Vbar), g_mn the first critical value
of the growth for the mode (m, n) alone; growing past it the tube wrinkles in the mode that
attains the minimum. In the (Vbar, g) plane the onset curve g = g_cr(Vbar) therefore
separates the unwrinkled state below from regions above it, one for each mode, bounded
by vertical lines at the switch voltages V_s where two modes are equally critical,
g_A(V_s) = g_B(V_s) (the mode sequence along the voltage, design/sequence.py: Brent's
method on the two-mode condition, to 1e-13 in Vbar). Each region's stretch of the onset
curve is drawn from the sequence's rows (its grid voltages and switches) and ``fill``
more single-mode solves of its mode. docs/design.md, "The growth-voltage map".
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..bifurcation.critical import critical_value
from ..bifurcation.scan import ScanOptions
from ..errors import ParameterError
from ..outcomes import Kind, json_number
from .sequence import ModeSequence, SequenceSwitch, _label, check_vary, mode_sequence

VOLTAGE = "voltage"
MAX_FILL = 50


@dataclasses.dataclass(frozen=True)
class VoltageRegion:
    """Vbar in [lo, hi] selects ``mode`` (kind "bifurcation"; or "surface", "threshold",
    "failed": mode (-1, -1)); ``voltage`` and ``growth`` sample the onset curve
    g_cr(Vbar) over [lo, hi] (its ends included)."""

    lo: float
    hi: float
    mode: tuple[int, int]
    kind: str
    voltage: tuple[float, ...]
    growth: tuple[float, ...]

    def as_dict(self) -> dict:
        finite = self.kind == Kind.BIFURCATION
        return {
            "lo": self.lo,
            "hi": self.hi,
            "mode": list(self.mode) if finite else None,
            "kind": str(self.kind),
            "voltage": list(self.voltage),
            "growth": [json_number(v) for v in self.growth],
        }


@dataclasses.dataclass(frozen=True)
class GrowthVoltageMap:
    """Result of :func:`growth_voltage_map`: the regions in increasing Vbar, the switches
    between them (``x`` the switch voltage, ``value`` the common critical growth) and the
    mode sequence behind them."""

    growth: str
    lo: float
    hi: float
    regions: tuple[VoltageRegion, ...]
    switches: tuple[SequenceSwitch, ...]
    sequence: ModeSequence

    def region_at(self, voltage: float) -> VoltageRegion | None:
        """The (first) region holding ``voltage``, or None outside [lo, hi]."""
        return next((r for r in self.regions if r.lo <= voltage <= r.hi), None)

    def as_dict(self) -> dict:
        return {
            "growth": self.growth,
            "voltage": [self.lo, self.hi],
            "regions": [r.as_dict() for r in self.regions],
            "switches": [s.as_dict() for s in self.switches],
        }

    def to_xarray(self):
        """The sequence's dataset (:meth:`ModeSequence.to_xarray`) with the onset curve's
        samples on dimension ``onset`` (voltage, critical growth, region index)."""
        ds = self.sequence.to_xarray()
        rows = [(v, g, k) for k, r in enumerate(self.regions) for v, g in zip(r.voltage, r.growth)]
        v, g, k = (np.array(c) for c in zip(*rows, strict=True)) if rows else ([], [], [])
        growth = {"long_name": f"critical {self.growth}"}
        ds["onset_voltage"] = ("onset", np.asarray(v, float), {"long_name": "voltage Vbar"})
        ds["onset_growth"] = ("onset", np.asarray(g, float), growth)
        ds["onset_region"] = ("onset", np.asarray(k, int), {"long_name": "index of its interval"})
        return ds


def check_growth(growth) -> str:
    if not isinstance(growth, str) or growth.split("[")[0].split(".")[0] != "growth":
        raise ParameterError(
            f"growth = {growth!r} is not a growth control; give growth, growth.theta,"
            " growth[K] or growth[K].theta (K a layer)"
        )
    return growth


def growth_voltage_map(
    tube,
    growth: str,
    voltage: tuple[float, float],
    *,
    options: ScanOptions = ScanOptions(),
    points: int = 9,
    fill: int = 4,
    progress=None,
) -> GrowthVoltageMap:
    """The first pattern's critical growth over a voltage range, regions labelled (m, n).

    Parameters
    ----------
    tube : Tube
        The electro-active tube; its voltage is overridden.
    growth : str
        The growth control whose critical value decides the first pattern (``growth``,
        ``growth.theta``, ``growth[1].theta``, ...).
    voltage : (lo, hi)
        The range of Vbar = V sqrt(eps/mu) / (R_o - R_i).
    options : ScanOptions
        The modes each scan examines.
    points : int
        Grid voltages scanned before the switches between them are located (2 to 2001):
        a region narrower than their spacing can be missed.
    fill : int
        Extra single-mode solves inside each region, for the drawn onset curve (0 to 50).

    Returns
    -------
    GrowthVoltageMap

    Raises
    ------
    ParameterError
        A control that is not a growth, a bad range, ``points`` or ``fill``.
    """
    check_growth(growth)
    if not isinstance(voltage, (tuple, list)) or len(voltage) != 2:
        raise ParameterError(f"voltage = {voltage!r} is invalid; give (lo, hi) of Vbar")
    _, lo, hi = check_vary((VOLTAGE, *voltage), tube, growth)
    if isinstance(fill, bool) or not isinstance(fill, int) or not 0 <= fill <= MAX_FILL:
        raise ParameterError(f"fill = {fill!r} is out of range; valid range: 0 to {MAX_FILL}")
    seq = mode_sequence(
        tube, growth, (VOLTAGE, lo, hi), options=options, points=points, progress=progress
    )
    regions = tuple(_region(tube, growth, seq, iv, fill) for iv in seq.intervals)
    return GrowthVoltageMap(growth, lo, hi, regions, seq.switches, seq)


def _region(tube, growth, seq: ModeSequence, iv, fill: int) -> VoltageRegion:
    """The interval ``iv`` with its stretch of the onset curve: the curve's rows of its
    pattern in [lo, hi], and ``fill`` single-mode solves of its mode between them."""
    curve = seq.curve
    rows = {
        float(curve.x[i]): float(curve.value[i])
        for i in range(len(curve.x))
        if iv.lo <= curve.x[i] <= iv.hi and _label(curve, i) == (iv.mode, iv.kind, iv.failure)
    }
    if iv.kind == Kind.BIFURCATION and iv.hi > iv.lo:
        for v in np.linspace(iv.lo, iv.hi, fill + 2)[1:-1]:
            c = critical_value(tube.at(VOLTAGE, float(v)), *iv.mode, growth)
            rows.setdefault(float(v), c.value if c.kind == Kind.BIFURCATION else math.nan)
    xs = sorted(rows)
    return VoltageRegion(iv.lo, iv.hi, iv.mode, iv.kind, tuple(xs), tuple(rows[x] for x in xs))
