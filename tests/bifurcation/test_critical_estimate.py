"""A critical value whose error estimate exceeds the accuracy asked is refined or flagged,
never returned silently (issue 21, bug 2), and the error estimate never probes outside the
control's domain (bug 3).

The faults are injected into the targets at chosen tolerances, as the kernel's missed
orientation produced them (a spurious sign window at some tolerances only): what is checked
is the rule, with the true root computed without the fault.
"""

import dataclasses
import json
import math
from pathlib import Path

import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation import critical, error_estimate
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.cli.app import main
from electrogrowth.model.layers import Layer
from electrogrowth.model.materials import mooney_rivlin
from electrogrowth.outcomes import Status

PARAMS = Tube.uniform(outer_radius=1.4, length=1.0, voltage=0.4)
MODE = (3, 1)
TRUE = critical_value(PARAMS, *MODE, "growth")
#: growth windows where the faulty targets of a tolerance have the wrong sign (the march's
#: signs are at 1e-8, the default fine and coarse targets at 1e-12 and 1e-10)
MARCH, FINE, TIGHT = {1e-8: (1.04, 1.3)}, {1e-12: (1.05, 1.3)}, {1e-14: (1.06, 1.3)}


def faulty_targets(windows):
    real = critical.targets_for

    def targets_for(method, rtol):
        f = real(method, rtol)
        lo, hi = next(
            (w for r, w in windows.items() if rtol == pytest.approx(r, rel=1e-6, abs=0)), (0, 0)
        )

        def wrong(state, modes):
            out = f(state, modes)
            return -out if lo < state.tube.growth < hi else out

        return wrong

    return targets_for


@pytest.fixture
def faults(monkeypatch):
    """faults(windows): the targets of critical_value with the sign faults of ``windows``
    (the second resolution of rtol is the target at 100 rtol, as for the impedance kernel)."""

    def inject(windows):
        faulty = faulty_targets(windows)
        monkeypatch.setattr(critical, "targets_for", faulty)
        monkeypatch.setattr(critical, "coarse_targets_for", lambda m, r: faulty(m, 100.0 * r))

    return inject


def test_true_root_is_outside_the_fault_windows():
    assert TRUE.status == Status.OK and TRUE.value > 1.3 + 0.1


def test_a_wrong_root_is_refined_at_a_tighter_rtol(faults):
    """The march's signs and the fine target see a spurious sign change, the coarse one does
    not: the estimate (the distance to the coarse root) is large, so the value is solved
    again at 1e-14, which finds the true root (whose coarse root, at 1e-12, agrees)."""
    faults(MARCH | FINE)
    cp = critical_value(PARAMS, *MODE, "growth")
    assert cp.status == Status.OK
    assert cp.value == pytest.approx(TRUE.value, rel=1e-11)


def test_a_value_that_stays_wrong_is_flagged(faults):
    """Every tolerance but the coarse one sees a spurious root, each elsewhere: the refined
    value is spurious too, and returned with status INACCURATE and an estimate beyond the
    accuracy asked."""
    faults(MARCH | FINE | TIGHT)
    cp = critical_value(PARAMS, *MODE, "growth")
    assert cp.value == pytest.approx(1.06, abs=1e-9)
    assert cp.status == Status.INACCURATE
    assert cp.error_estimate == pytest.approx(0.01, abs=1e-9)
    assert cp.as_dict()["status"] == "inaccurate"


# -- the command line: only the supported digits, a warning, exit 3 unless accepted -----------

ARGV = ["critical", "--solve-for", "growth", "--outer-radius", "1.4", "--length", "1.0"]
ARGV += ["--voltage", "0.4", "--mode", "3", "1"]


@pytest.fixture
def inaccurate(monkeypatch):
    # the command imports its solver from this module when it runs (cli/critical.py)
    import electrogrowth.bifurcation.critical as solver

    def fake(*args, **kwargs):
        return dataclasses.replace(TRUE, error_estimate=3e-4, status=Status.INACCURATE)

    monkeypatch.setattr(solver, "critical_value", fake)


def test_cli_exits_3_with_a_warning_for_an_inaccurate_value(inaccurate, capsys):
    assert main(ARGV) == 3
    out, err = capsys.readouterr()
    head = out.splitlines()[0]
    assert head.startswith(f"g_cr = {TRUE.value:.5g} ") and f"{TRUE.value:.7g}" not in head
    assert err.startswith("electrogrowth: warning: growth") and "not certified" in err
    assert len(err.splitlines()) == 1


def test_cli_accept_inaccurate_exits_0(inaccurate, capsys):
    assert main(ARGV + ["--accept-inaccurate", "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["status"] == "inaccurate" and "not certified" in err


def test_cli_help_documents_the_flag(capsys):
    assert main(["critical", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "--accept-inaccurate" in text and "exit status 3" in text


# -- bug 3: the estimate's windows stay inside the march's path ---------------------------------


def test_second_resolution_never_leaves_the_path():
    """A coarse target without a root near the value: the windows widen to +-4.2 but are
    clipped to the path (growth from 1): no probe below 1, and the estimate says the looser
    root is at least the widest window away (an uncertified value, not a ParameterError)."""
    seen = []

    def g(x):
        seen.append(x)
        return 1.0

    est = error_estimate.second_resolution(g, 1.1, (1.0, 6.0))
    assert min(seen) >= 1.0 and max(seen) <= 6.0
    assert est == pytest.approx(1.1e-6 * 4**11, rel=1e-12)


def test_second_resolution_finds_the_coarse_root_inside_the_path():
    est = error_estimate.second_resolution(lambda x: x - 1.3, 1.2999, (1.0, 6.0))
    assert est == pytest.approx(1e-4, rel=1e-9)


def test_soft_substrate_scan_is_not_killed_by_an_estimate():
    """The issue's scan: a hoop-growing layer on a substrate of modulus 0.01 ended after
    45-60 s with "ParameterError: growth[1] = -0.16 is out of range"."""
    from electrogrowth.bifurcation.scan import ScanOptions, scan_modes

    tube = Tube((Layer(1.1), Layer(2.0, shear_modulus=0.01)))
    res = scan_modes(tube, "growth[1].theta", options=ScanOptions(top=2))
    assert res.critical.value > 1.0
    assert res.critical.status in (Status.OK, Status.INACCURATE)


def test_cli_layered_tube_line_shows_only_supported_digits(monkeypatch, capsys):
    """The solved growth also appears in the tube's line (it printed all 17 digits)."""
    # the command imports its solver from this module when it runs (cli/critical.py)
    import electrogrowth.bifurcation.critical as solver
    from electrogrowth.bifurcation.critical import CriticalPoint
    from electrogrowth.outcomes import Kind

    value = 2.0404425746823858

    def fake(params, m, n, solve_for, **kwargs):
        at = params.at(solve_for, value)
        return CriticalPoint(
            solve_for, value, m, n, Kind.BIFURCATION, 3e-4, "impedance", None, at,
            status=Status.INACCURATE,
        )  # fmt: skip

    monkeypatch.setattr(solver, "critical_value", fake)
    bilayer = str(Path(__file__).resolve().parents[2] / "examples" / "bilayer.toml")
    argv = ["critical", "--tube", bilayer, "--solve-for", "growth"]
    assert main(argv + ["--layer", "1", "--component", "theta", "--mode", "12", "1"]) == 3
    out = capsys.readouterr().out
    assert "2.040442" not in out and "g [1, 2.0404, 1]" in out


# -- the estimate by the secant (docs/derivation.md section 6) --------------------------------


def _curved(root, calls):
    """A signed target positive before ``root`` (growth rises from 1), curved, with an exact
    difference root - x near the root (Sterbenz)."""

    def g(x):
        calls.append(x)
        return (root - x) * (1.0 + 5.0 * (x - 1.0) ** 2)

    return g


@pytest.mark.parametrize("offset", [-4e-11, -1e-12, 3e-13, 2e-12, 5e-11])
def test_secant_estimate_is_the_distance_to_the_root(offset):
    """Past the root (interpolated, 2 evaluations) and before it (extrapolated and checked,
    3 evaluations), on both senses of the path; then two reads of the rounding noise."""
    for root, path in ((1.3, (1.0, 6.0)), (0.7, (1.0, 0.5))):
        calls = []
        sense = 1.0 if path[1] > path[0] else -1.0
        value = root + sense * offset
        g = _curved(root, calls) if sense > 0 else (lambda x, f=_curved(root, calls): -f(x))
        est = error_estimate.second_resolution(g, value, path)
        assert est == pytest.approx(abs(value - root), rel=1e-4)
        assert len(calls) == (2 if offset > 0 else 3) + len(error_estimate.NOISE_OFFSETS)


def test_a_root_within_the_noise_is_bracketed_at_the_noise_read():
    """The coarse root 1e-15 beyond the value, the target's noise (+1e-14 just past the
    value) above the line's fall at twice that distance: the bracket is taken at the
    rounding floor's read, 1e-12 beyond (an evaluation it makes anyway), not at 2 d, where
    the noise hid the sign change and the windows' search cost six evaluations more (a
    thick tube's (400, 0) in voltage)."""
    calls = []
    value, root = 0.25, 0.25 + 1e-15

    def g(x):
        calls.append(x)
        return (root - x) + (1e-14 if value < x < value + 1e-13 else 0.0)

    est = error_estimate.second_resolution(g, value, (0.0, 6.0))
    assert est == pytest.approx(1e-15, rel=0.3)
    assert len(set(calls)) == 2 + len(error_estimate.NOISE_OFFSETS)


def test_secant_estimate_falls_back_without_a_sign_change():
    """A target that only touches zero near the value (no root within the secant's step):
    the windows' Brent decides, as before."""
    calls = []

    def g(x):
        calls.append(x)
        return (x - 1.3) ** 2 + 1e-20

    assert error_estimate.secant_estimate(g, 1.3 + 1e-9, (1.0, 6.0)) is None
    est = error_estimate.second_resolution(g, 1.3 + 1e-9, (1.0, 6.0))
    assert est == pytest.approx(1e-6 * (1.3 + 1e-9) * 4**11, rel=1e-12)  # the widest window


CASES = [
    (PARAMS, 0, 1, "growth", None),
    (PARAMS, 3, 1, "growth", None),
    (PARAMS, 2, 3, "stretch", "compression"),
    (Tube.uniform(outer_radius=1.4, length=1.0, growth=1.1), 0, 1, "voltage", None),
    (Tube((Layer(1.2, growth=1.1), Layer(1.4, growth=1.1)), length=1.0), 0, 1, "voltage", None),
]


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c[3]} {c[1:3]}")
def test_secant_estimate_equals_the_windows_and_bounds_the_error(case, monkeypatch):
    """The same value; the secant's estimate equals the windows' Brent one to the latter's
    resolution (its root to 2e-15 max(1, |value|)); both bound the true error against a
    reference at rtol 1e-14."""
    tube, m, n, control, side = case
    new = critical_value(tube, m, n, control, side=side)
    reference = critical_value(tube, m, n, control, side=side, rtol=1e-14)
    monkeypatch.setattr(error_estimate, "secant_estimate", lambda *args: None)
    old = critical_value(tube, m, n, control, side=side)
    assert new.value == old.value
    resolution = 4e-15 * max(1.0, abs(new.value))
    assert abs(new.error_estimate - old.error_estimate) <= 1e-3 * old.error_estimate + resolution
    assert new.error_estimate >= abs(new.value - reference.value)


def test_collocation_estimate_bounds_its_noise_floor():
    """At rtol 1e-8 collocation's fine and coarse targets are the same 40-node determinant,
    flat at rounding level over ~1e-10 around its root: the windows' Brent put the coarse root
    9e-14 from the value (two roots of one function), below the true error (2e-13, against
    the impedance root at rtol 1e-14); the secant reads the target's value there against its
    slope, and its estimate bounds the error."""
    got = critical_value(PARAMS, 0, 1, "growth", method="collocation", rtol=1e-8)
    reference = critical_value(PARAMS, 0, 1, "growth", rtol=1e-14)
    assert got.error_estimate >= abs(got.value - reference.value)


def test_secant_estimate_checks_its_straight_line():
    """A target that turns from one plateau to the other within 1e-9 of its root, as a thin
    stiff film's does: the secant alone would put the root h / 2 = 6.5e-7 away; the check
    at the secant's root sends it to Brent's windows, which find the true distance."""
    root, value = 1.3, 1.3 + 2e-12

    def g(x):
        return -5e-4 * math.tanh((x - root) / 1e-9)

    assert error_estimate.secant_estimate(g, value, (1.0, 6.0)) is None
    est = error_estimate.second_resolution(g, value, (1.0, 6.0))
    assert est == pytest.approx(2e-12, rel=1e-2)


def test_secant_estimate_keeps_a_straight_line_far_from_the_value():
    """A straight target whose root lies 0.3 h back: the check at the secant's root passes
    and the secant's distance stands (3 evaluations)."""
    calls = []
    h = 1e-6 * 1.3

    def g(x):
        calls.append(x)
        return 1.3 - 0.3 * h - x

    est = error_estimate.second_resolution(g, 1.3, (1.0, 6.0))
    assert est == pytest.approx(0.3 * h, rel=1e-6)
    assert len(calls) == 3 + len(error_estimate.NOISE_OFFSETS)


def test_a_stiff_thin_films_value_is_certified_and_its_estimate_bounds_its_error():
    """A film 1e-3 thick and 10^4 times as stiff as its substrate, mode (40, 0): its target
    is a step at the 1e-8 scale, which made the secant report 5.2e-7 and every such value
    uncertified. Now the estimate bounds the distance to the value at rtol 1e-14 and is
    certified."""
    film = Tube((Layer(1.001, shear_modulus=1e4), Layer(3.0)), length=2.0, stretch=1.0)
    ref = critical_value(film, 40, 0, "growth[1].theta", rtol=1e-14)
    point = critical_value(film, 40, 0, "growth[1].theta")
    assert point.status == "ok"
    assert abs(point.value - ref.value) <= point.error_estimate <= 1e-10


def test_cli_a_refused_certificate_prints_the_value_and_exits_3(monkeypatch, capsys):
    """--certify refusing a value is not bad input (exit 2): the value is printed with the
    reason it is not certified, a warning, and exit status 3 (0 with --accept-inaccurate)."""
    import electrogrowth.bifurcation.certify as certifier
    from electrogrowth.errors import ConvergenceError

    def refuse(*args, **kwargs):
        raise ConvergenceError("not certified: impedance gives 1.2, collocation gives 1.3")

    monkeypatch.setattr(certifier, "certify", refuse)
    assert main(ARGV + ["--certify"]) == 3
    out, err = capsys.readouterr()
    assert out.startswith("g_cr = ") and "NOT certified: impedance gives 1.2" in out
    assert err.startswith("electrogrowth: warning: not certified") and err.count("\n") == 1
    assert main(ARGV + ["--certify", "--accept-inaccurate", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["certified"] is False and rec["certification"].startswith("impedance gives")


def test_collocation_floor_is_the_rounding_noise_over_the_slope():
    """A straight target g = 1e-3 (1.3 - x) with noise of amplitude 1e-12 (made up: a
    deterministic hash of x): the floor is at least the noise over the slope (1e-9) and at
    most a few times it; without noise it is the secant's distance."""

    def noisy(x):
        return 1e-3 * (1.3 - x) + 1e-12 * math.sin(1e15 * x)

    est = error_estimate.collocation_floor(noisy, 1.3, (1.0, 6.0))
    assert 1e-10 <= est <= 4e-9
    clean = error_estimate.collocation_floor(lambda x: 1e-3 * (1.3 - x), 1.3 + 2e-11, (1.0, 6.0))
    assert clean == pytest.approx(2e-11, rel=1e-3)


def test_the_second_resolution_is_at_least_its_rounding_noise_over_the_slope():
    """A straight coarse target 1e-5 (1.3 - x) with noise of amplitude 1e-16 (a deterministic
    hash of x - 1.3) that vanishes at the value 1.3: the secant alone says 0, while the root
    is known only to the noise over the slope, read 1.3e-12 on either side."""

    def noise(x):
        return 1e-16 * math.sin(1e15 * (x - 1.3))

    est = error_estimate.second_resolution(lambda x: 1e-5 * (1.3 - x) + noise(x), 1.3, (1.0, 6.0))
    read = max(abs(noise(1.3 + t)) for t in (-1.3e-12, 1.3e-12)) / 1e-5
    assert read > 1e-12
    assert est == pytest.approx(read, rel=1e-3)


@pytest.mark.parametrize(
    "layers",
    [
        (Layer(1.5),),
        (
            Layer(1.3, shear_modulus=3.0),
            Layer(1.5, shear_modulus=0.3, material=mooney_rivlin(0.5)),
        ),
    ],
    ids=["one layer", "bilayer"],
)
def test_a_small_critical_force_is_within_its_estimates(layers):
    """Euler buckling (1, 1) of a tube 200 long under force control (probe round 6a): the
    target is ~1e-15 over the window with rounding noise ~5e-16 on a slope of ~7e-6, so the
    critical force (-2.4e-3, -3.6e-3) is known to ~5e-11 whatever rtol. Solved at four rtol,
    any two values lie within the sum of their estimates (they did not: values 6.0e-11 apart
    with estimates of 9.5e-12 and 3.1e-11; one layer 3.0e-11 against 2.1e-11).

    ~1e-8 of the value is all any rtol gives, so rtol 1e-13 and 1e-14 (certified to
    CERTIFIED rtol = 1e-9 and 1e-10 of the value) are INACCURATE: they were "ok" while the
    rule was absolute below 1 (max(1, |value|))."""
    tube = Tube(layers, length=200.0, axial_force=0.0)
    pts = [critical_value(tube, 1, 1, "force", rtol=r) for r in (1e-11, 1e-12, 1e-13, 1e-14)]
    assert [p.status for p in pts] == [Status.OK] * 2 + [Status.INACCURATE] * 2
    assert all(p.error_estimate > 1e-9 * abs(p.value) for p in pts[2:])
    for a in pts:
        for b in pts:
            assert abs(a.value - b.value) <= a.error_estimate + b.error_estimate


def test_an_estimate_is_at_least_the_accuracy_asked():
    """Found by probing (round 9a, D3): an inner film [1, 1.001] (mu 1) on a substrate to 2
    (mu 1e-4), hoop growth, mode (67, 0), gave 1.0320894981908515 with an estimate of
    3.4e-14, status OK; its value at rtol 1e-14 is 1.0320894981896265 (the shooting twin's
    root: 1.0320894981896187), an error of 1.2e-12, 36x the estimate. The second resolution
    (rtol 1e-10) landed on the same root to 2e-16: both carried the same error. Now an
    estimate is at least ACHIEVED rtol |value| (error_estimate.achieved_floor)."""
    film = Tube((Layer(1.001, shear_modulus=1.0), Layer(2.0, shear_modulus=1e-4)), length=2.0)
    point = critical_value(film, 67, 0, "growth[1].theta")
    ref = critical_value(film, 67, 0, "growth[1].theta", rtol=1e-14)
    assert point.status == Status.OK
    assert abs(point.value - ref.value) <= point.error_estimate


def test_the_floor_is_relative_to_the_value():
    """A small value (a critical force of a soft tube, 6e-5) gets a relative floor, not
    rtol max(1, |value|), which would say 1e-12 of a value known to 2e-14."""
    assert error_estimate.achieved_floor(-6.27e-5, 1e-12) == pytest.approx(3.135e-16)
    assert error_estimate.achieved_floor(1.032, 1e-12) == pytest.approx(5.16e-12)


def test_cli_the_other_methods_failure_is_a_refusal_with_exit_3(monkeypatch, capsys):
    """probe 12b, D8: collocation's "no sign change" (layered collocation solves only in a
    bracket) escaped --certify as an error: exit 2, nothing on stdout, and the remedy
    "certify the point with --method collocation", the method that failed. Now the value is
    printed, refused, with exit 3."""
    import electrogrowth.bifurcation.certify as certifier
    from electrogrowth.bifurcation.critical import NoSignChange

    def no_sign_change(*args, bracket, **kwargs):
        raise NoSignChange(f"collocation has no sign change on {bracket}")

    monkeypatch.setattr(certifier, "critical_value", no_sign_change)
    assert main(ARGV + ["--certify"]) == 3
    out, err = capsys.readouterr()
    assert out.startswith("g_cr = ") and "collocation cannot resolve this mode" in out
    assert err.startswith("electrogrowth: warning: not certified") and err.count("\n") == 1
