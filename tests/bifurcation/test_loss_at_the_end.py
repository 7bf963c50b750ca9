"""A march that loses no state on its way and stops at its path's end or at a film: the loss
of the axisymmetric state there is a result (kind THRESHOLD), as for the voltage, not "no mode
bifurcates" (bifurcation/state_loss.py loss_at_end).

Found by probe 7a (D2): the mode march and the short-wave march turned only the voltage's
threshold into a result. A pressure's path ends at its limit point (docs/patterns.md: where
the tube is lost), and a tube pulled at a fixed inner pressure thins to a film as its
inflation threshold falls to that pressure (an asymptote: lambda_i -> inf).
"""

import pytest

from electrogrowth import (
    BaseStateError,
    Layer,
    ScanOptions,
    Tube,
    critical_value,
    scan_modes,
    solve_base_state,
    threshold,
)
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.outcomes import Kind


def closed_bilayer() -> Tube:
    """Force-free, closed ends: inflated, it snaps through at P_i = 0.268134034372."""
    return Tube(
        [Layer(1.1, shear_modulus=2.0), Layer(1.3)],
        length=30.0,
        axial_force=0.0,
        closed_ends=True,
    )


def pulled_at_a_pressure() -> Tube:
    """Pulled at P_i = 0.15: states exist up to F = 13.2545 (lambda_i 1700 just short)."""
    return Tube([Layer(1.56)], length=4.0, axial_force=0.0, inner_pressure=0.15)


def test_the_limit_point_ends_the_pressure_march():
    tube = closed_bilayer()
    thr = threshold(tube, "pressure")
    assert thr.kind == "limit point" and thr.value == pytest.approx(0.268134034372, abs=1e-11)
    solve_base_state(tube.at("pressure", 0.26813))  # just short: a state
    with pytest.raises(BaseStateError, match="beyond the limit point|beyond the pressure"):
        solve_base_state(tube.at("pressure", 0.26814))
    c = critical_value(tube, 0, 1, "pressure")
    assert c.kind == Kind.THRESHOLD and c.value == pytest.approx(thr.value, abs=1e-12)
    surface = short_wave_limit(tube, "pressure")
    assert surface.kind == Kind.THRESHOLD and surface.value == pytest.approx(thr.value, abs=1e-12)


def test_a_scan_reports_the_limit_point():
    tube = closed_bilayer()
    scan = scan_modes(tube, "pressure", options=ScanOptions((0, 2), (1, 4)))
    assert scan.critical.kind == Kind.THRESHOLD
    assert scan.critical.value == pytest.approx(threshold(tube, "pressure").value, abs=1e-12)


@pytest.mark.slow  # 30-60 s (the approach past the film): make test-slow runs it
def test_the_force_march_ends_where_the_inflation_threshold_falls_to_the_pressure():
    tube = pulled_at_a_pressure()
    c = critical_value(tube, 5, 0, "force", side="extension")  # (5, 0) never bifurcates
    assert c.kind == Kind.THRESHOLD and c.value == pytest.approx(13.2545325786, abs=1e-9)
    # the independent reading: the inflation threshold of the tube pulled by c.value is its
    # pressure (the margin's slope is 0.011 a unit of F: 1e-13 here is 1e-11 in F)
    at = tube.at("force", c.value)
    assert threshold(at, "pressure").value == pytest.approx(0.15, abs=1e-12)
    solve_base_state(tube.at("force", c.value - 1e-7))
    with pytest.raises(BaseStateError, match="pressure threshold"):
        solve_base_state(tube.at("force", c.value + 1e-7))
    surface = short_wave_limit(tube, "force", side="extension")
    assert surface.kind == Kind.THRESHOLD and surface.value == pytest.approx(c.value, abs=1e-9)
    # marched on past the film toward the asymptote until the states stop resolving (a shear
    # modulus ~1e-8 of its own, lambda_i ~ 3.8e3, 2.1e-8 short): the estimate covers that gap
    assert 1e-9 < surface.error_estimate < 1e-7 and "not excluded" in surface.message


def test_a_mode_before_the_loss_still_wins():
    # (0, 1) bifurcates at F = 13.2130553272, before the loss at 13.2545325786
    tube = pulled_at_a_pressure()
    c = critical_value(tube, 0, 1, "force", side="extension")
    assert c.kind == Kind.BIFURCATION and c.value == pytest.approx(13.2130553272, abs=1e-8)
