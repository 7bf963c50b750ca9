"""The widest-margin design next to a cliff: an end of the valid range where the target's
onset does not fall to the control's start.

An ungrown tube of Rbar_o = 1.4 under a voltage, growing: (0, 1) wrinkles at g = 1.104 up
to the critical voltage of the ungrown tube (0.7234620248), and beyond it the tube is
unstable at g = 1 at once. The room-below rule M_0 = (v_T - v_0) / (v_N - v_T) assumed
v_T falls to v_0 at the end; here it stays ~5, never limited the design, and the design
sat at Vbar = 0.723462009, 2e-8 (relative) below the voltage that wrinkles the ungrown
tube (probe 8b, D4). The room below is now also measured by the design variable itself,
M_end = (x_e - x) / x_e (design/margins.py), checked here against direct solves."""

import numpy as np

from electrogrowth import ScanOptions, Tube, critical_value, prescribe

TUBE = Tube.uniform(1.4, length=1.0)
OPTIONS = ScanOptions((0, 4), (1, 4))
MODES = ((1, 1), (2, 1), (0, 2))  # the competitors of (0, 1) that the scans find


def _by_solves(x, v_alone):
    """min(M, M_end) at Vbar = x from single-mode solves, M against the nearest mode."""
    at = TUBE.at("voltage", x)
    v_t = critical_value(at, 0, 1, "growth", rtol=1e-12).value
    v_n = min(critical_value(at, *m, "growth", rtol=1e-12).value for m in MODES)
    return min((v_n - v_t) / v_t, (v_alone - x) / v_alone)


def test_design_keeps_room_from_the_voltage_that_wrinkles_the_ungrown_tube():
    d = prescribe(TUBE, "growth", (0, 1), ("voltage", 0.3, 1.3), points=5, options=OPTIONS)
    v_alone = critical_value(TUBE, 0, 1, "voltage", rtol=1e-12).value  # 0.7234620248
    assert d.status == "found" and d.mode == (0, 1)
    room = (v_alone - d.x) / v_alone  # was 2.2e-8
    assert room > 1e-3, (d.x, d.margin, d.limited_by, room)
    assert d.limited_by == "no design"  # the two rooms balance at the design
    assert abs(d.margin - _by_solves(d.x, v_alone)) < 1e-9
    for x in np.linspace(0.3, v_alone, 9)[1:-1]:  # and it is the widest margin over the region
        assert _by_solves(x, v_alone) <= d.margin + 1e-9
