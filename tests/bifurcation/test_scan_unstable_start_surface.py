"""A scan whose tube is past a face's short-wave instability at the control's start is
already unstable (check round 20, D1).

Three layers (Gent / an I5 coupling text / an I4 text) held at Vbar = 0.79, the growth of
layer 3 as the control: the ungrown tube is past its inner face's short-wave limit (the
voltage scan's surface at Vbar = 0.75502), (0, 40) bifurcates at Vbar = 0.7619176717 (the
package's single mode; an independent shooting and collocation of the whole tube, 2e-13
apart), and (0, 24)-(0, 60) are all unstable at g = 1, restabilised as layer 3 grows. The
scan read only its own modes at the start (n <= 5) and weighed the limit only against its
critical value, where the face is stable again: (2, 1) at g = 1.38034, status ok.
"""

import pytest

from electrogrowth import Layer, Material, ScanOptions, Tube, critical_value, gent, scan_modes
from electrogrowth.errors import UnstableAtStart

COUPLED = Material("coup", "(I1-3)/2 + I5/2*(1 + 0.1*(I1-3))")
STIFFENED = Material("i4", "(I1-3)/2 + 0.4*I5 + 0.1*I4")
TUBE = Tube(
    [
        Layer(1.15, material=gent(20.0), shear_modulus=0.5, permittivity=1.0),
        Layer(1.5, material=COUPLED, shear_modulus=2.0, permittivity=0.7),
        Layer(1.8, material=STIFFENED, shear_modulus=1.0, permittivity=1.3),
    ],
    length=4.0,
    stretch=1.0,
    voltage=0.79,
)
OPTIONS = ScanOptions((0, 8), (1, 5), torsional=False)


def test_a_scan_past_the_inner_faces_limit_at_its_start_is_unstable_at_start():
    with pytest.raises(UnstableAtStart, match="inner face is past its short-wave"):
        scan_modes(TUBE, "growth[3]", options=OPTIONS)  # was (2, 1) at 1.38034, ok
    with pytest.raises(UnstableAtStart, match=r"mode \(0, 40\)"):  # as its single mode says
        critical_value(TUBE, 0, 40, "growth[3]")


def test_below_the_limit_the_scan_stands():
    c = scan_modes(TUBE.at("voltage", 0.75), "growth[3]", options=OPTIONS).critical
    assert (c.kind, c.m, c.n, c.status) == ("bifurcation", 2, 1, "ok")


def test_a_followed_curve_point_checks_the_start_too():
    """A curve's points between full scans are followed from the last scan's modes; a
    followed point checked the modes just before its value only, so Vbar = 0.76 (past the
    inner face's limit at g = 1, 0.7550174324) was (2, 1), status ok."""
    from electrogrowth import critical_curve

    curve = critical_curve(TUBE, "growth[3]", "voltage", [0.70, 0.72, 0.74, 0.76, 0.78],
                           options=OPTIONS)  # fmt: skip
    assert [int(m) for m in curve.m[:3]] == [2, 2, 2]
    assert list(curve.kind[:3]) == ["bifurcation"] * 3
    assert list(curve.kind[3:]) == ["failed", "failed"]
    assert all("inner face is past its short-wave" in s for s in curve.status[3:])


@pytest.mark.slow  # 40 s: the end's bisection, some 40 scans
def test_a_sequence_ends_at_the_inner_faces_limit():
    """check round 20's S6: the end of the valid range was 0.8065 (the grid point 0.7667
    followed as (2, 1)); it is the ungrown tube's inner-face limit in Vbar, 0.7550174324477
    (its own short-wave limit; (0, 40) follows at 0.7619176717, independent)."""
    from electrogrowth.bifurcation.surface import short_wave_limit
    from electrogrowth.design import mode_sequence

    ungrown = TUBE.at("voltage", 0.0)
    seq = mode_sequence(ungrown, "growth[3]", ("voltage", 0.5, 0.8), points=4, options=OPTIONS)
    (end,) = [s for s in seq.switches if s.kind == "end"]
    limit = short_wave_limit(ungrown, "voltage")
    assert limit.face == "inner" and end.x == pytest.approx(limit.value, abs=1e-12)
    assert end.x < 0.7619176717  # the independent (0, 40) onset of the ungrown tube
    assert [iv.failure for iv in seq.intervals][-1] == "UnstableAtStart"
