"""Critical values of one mode: exact limits, identities and the root finder's precision."""

import dataclasses
import math

import pytest
from scipy.optimize import brentq

from electrogrowth import NoBifurcationFound, ParameterError, Tube, crease_onset, scan_modes
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value, stable_sign
from electrogrowth.incremental.targets import impedance_targets


def _f(params, m, n):
    return stable_sign(m, n, params) * impedance_targets(solve_base_state(params), [(m, n)])[0]


def test_euler_column_limit():
    """V = 0, g = 1, slender thin tube, mode (1, 1): 1 - lambda_z -> pi^2 (Ro^2 + 1)/(4 l^2)."""
    ro, errors = 1.1, []
    for L in (20.0, 40.0):
        lz = critical_value(Tube.uniform(ro, L), 1, 1, "stretch").value
        euler = math.pi**2 * (ro**2 + 1) / (4 * (lz * L) ** 2)
        errors.append(abs((1 - lz) / euler - 1))
    assert errors[1] < 0.02
    assert 3.0 < errors[0] / errors[1] < 5.0  # the O(1/L^2) approach to Euler


def test_surface_instability_limit():
    """Thick tube, short waves: lambda_z -> 0.443746, lambda_z^{3/2} root of x^3+x^2+3x-1."""
    x = brentq(lambda x: x**3 + x**2 + 3 * x - 1, 0, 1)
    lam = x ** (2 / 3)
    assert abs(lam - 0.443746) < 1e-6
    gaps = [critical_value(Tube.uniform(3.0, 1.0), 0, n, "stretch").value - lam for n in (20, 40)]
    assert 0 < gaps[1] < 2e-4
    assert 1.8 < gaps[0] / gaps[1] < 2.2  # O(1/n) approach from the stable side


def test_critical_growth_is_a_sign_change_to_many_digits():
    p = Tube.uniform(1.4, 1.0, stretch=1.0, voltage=0.4)
    c = critical_value(p, 3, 7, "growth")
    assert c.kind == "bifurcation" and c.error_estimate < 1e-8
    g = c.value
    assert _f(p.at("growth", g * (1 - 1e-10)), 3, 7) > 0
    assert _f(p.at("growth", g * (1 + 1e-10)), 3, 7) < 0


def test_growth_is_a_rescaling_of_the_reference_tube():
    """(g, lambda_z, Vbar) is the ungrown tube at (lambda_z/g, Vbar/g): same critical point."""
    p = Tube.uniform(1.4, 1.0, stretch=1.1, voltage=0.4)
    m, n = 4, 9
    g = critical_value(p, m, n, "growth").value
    ungrown = Tube.uniform(1.4, 1.0, growth=1.0, voltage=0.4 / g)

    def f(lz):
        return _f(dataclasses.replace(ungrown, stretch=lz), m, n)

    lz = brentq(f, 1.1 / g * (1 - 1e-6), 1.1 / g * (1 + 1e-6), xtol=1e-15, rtol=1e-15)
    assert abs(lz - 1.1 / g) < 1e-10


def test_growth_identity_for_critical_voltage():
    p = Tube.uniform(1.6, 1.2, growth=1.15, stretch=1.2)
    v = critical_value(p, 2, 1, "voltage").value
    v0 = critical_value(Tube.uniform(1.6, 1.2, stretch=1.2 / 1.15), 2, 1, "voltage").value
    assert abs(v - 1.15 * v0) < 1e-9 * v


def test_extension_and_compression_sides():
    p = Tube.uniform(1.4, 1.0, voltage=0.6)
    lo = critical_value(p, 0, 1, "stretch", side="compression")
    hi = critical_value(p, 0, 1, "stretch", side="extension")
    assert lo.value < 1.0 < hi.value
    for c in (lo, hi):
        assert abs(_f(c.params, 0, 1)) < 1e-9


def test_bad_mode_and_unknown_control():
    p = Tube.uniform()
    with pytest.raises(ParameterError, match="mode"):
        critical_value(p, -1, 1, "growth")
    with pytest.raises(ParameterError, match="'temperature' is unknown"):
        critical_value(p, 0, 1, "temperature")
    with pytest.raises(ParameterError, match="side"):
        critical_value(p, 0, 1, "stretch", side="sideways")


@pytest.mark.parametrize(
    "call",
    [
        lambda t: critical_value(t, 1, 1, "growth", side="compression"),
        lambda t: scan_modes(t, "voltage", side="compression"),
        lambda t: crease_onset(t, "growth", side="extension"),
    ],
    ids=["critical_value", "scan_modes", "crease_onset"],
)
def test_a_side_for_growth_or_voltage_is_refused(call):
    # it was ignored (growth (1, 1) 1.3168 for a "compression"); the command line refuses
    # --side for these controls (probe 7a, D4)
    with pytest.raises(ParameterError, match="applies only to stretch, pressure or force"):
        call(Tube.uniform(1.4))


def test_already_unstable_start_is_an_error():
    p = Tube.uniform(1.4, 1.0, stretch=0.5)  # far beyond compressive buckling
    with pytest.raises(ParameterError, match="already unstable"):
        critical_value(p, 0, 1, "growth")


def test_no_bifurcation_in_range():
    p = Tube.uniform(1.4, 1.0, growth=1.0)
    with pytest.raises(NoBifurcationFound):  # axial extension of an unloaded tube is stable
        critical_value(p, 0, 1, "stretch", side="extension")


def test_a_bracket_without_a_sign_change_says_the_value_is_the_marchs():
    """A bracket that holds the root is solved in (no note); one that does not is marched
    past, and the value outside it says why (probe round 14a: no note)."""
    tube = Tube.uniform(1.4, 1.0, voltage=0.4)
    inside = critical_value(tube, 0, 1, "growth", bracket=(1.2, 1.3))
    assert 1.2 < inside.value < 1.3 and inside.message == ""
    past = critical_value(tube, 0, 1, "growth", bracket=(1.0, 1.1))
    assert past.value == pytest.approx(inside.value, rel=1e-10)
    assert past.message.startswith("no sign change on the bracket (1.0, 1.1)")
