"""A scan's runners-up are solved at the scan's rtol and carry an error estimate (probe 9a,
D2).

They were the march's roots, solved with the kernel at max(rtol, 1e-9) (Accuracy.runners_up)
and printed to 10 digits with no estimate: a film's ring under force control 1.3e-6 off
(relative), a film's growth 2.3e-9, a tube's growth up to 4e-11. Each is now solved at rtol
near its march root (bifurcation/runners.py); the values are checked against single-mode
solves at rtol 1e-13, an independent march and Brent per mode.
"""

import dataclasses

import pytest

from electrogrowth import (
    Layer,
    ScanOptions,
    Tube,
    critical_value,
    gent,
    mooney_rivlin,
    scan_modes,
)
from electrogrowth.bifurcation import runners
from electrogrowth.bifurcation.critical import CriticalPoint
from electrogrowth.bifurcation.march import ModeValue
from electrogrowth.bifurcation.scan_record import ScanResult
from electrogrowth.cli.app import main
from electrogrowth.outcomes import NO_MODE, Kind

P = Tube.uniform(1.4, 1.0, voltage=0.4)
FILM = Tube(
    (Layer(2.0, shear_modulus=1e-4), Layer(2.001, shear_modulus=1.0)), length=2.0, axial_force=0.0
)


def _true(tube, r, solve_for, side=None):
    return critical_value(tube, r.m, r.n, solve_for, family=r.family, side=side, rtol=1e-13)


def test_runners_up_are_solved_at_the_scan_rtol():
    """(3, 1) and (4, 1) were 3.2e-11 and 4.2e-11 off, 2e-11 relative."""
    s = scan_modes(P, "growth", options=ScanOptions((0, 4), (1, 2)))
    assert len(s.runners_up) == 4
    for r in s.runners_up:
        true = _true(P, r, "growth")
        assert r.value == pytest.approx(true.value, rel=1e-11), (r.m, r.n)
        assert abs(r.value - true.value) <= max(r.error_estimate, 1e-13)
        assert 0 < r.error_estimate < 1e-10


def test_at_a_loose_rtol_the_estimates_cover_the_errors():
    """At rtol 1e-8 the march's roots are already at rtol (max(rtol, 1e-9)): they stand, and
    their estimates (1e-8) cover their errors (1e-10)."""
    s = scan_modes(P, "growth", options=ScanOptions((0, 4), (1, 2)), rtol=1e-8)
    for r in s.runners_up:
        assert abs(r.value - _true(P, r, "growth").value) <= r.error_estimate < 1e-7


def test_the_json_record_of_a_runner_up_has_its_estimate(capsys):
    argv = ["critical", "--outer-radius", "1.4", "--length", "1.0", "--voltage", "0.4"]
    assert main(argv + ["--solve-for", "growth", "--m-max", "2", "--n-max", "1", "--json"]) == 0
    import json

    rec = json.loads(capsys.readouterr().out)
    assert rec["runners_up"] and all(r["error_estimate"] < 1e-10 for r in rec["runners_up"])


def test_a_runner_up_before_the_critical_mode_at_rtol_becomes_it(monkeypatch):
    """Solved at rtol a runner-up may come before the critical mode (a film's rings lie
    2.7e-10 apart, the march's roots 2.3e-9 from the fine ones): it is then the critical
    mode, and the critical one a runner-up with its estimate. Injected: (1, 1)'s fine
    value put before (0, 1)'s."""
    s = scan_modes(P, "growth", options=ScanOptions((0, 2), (1, 1), extend=False))
    c = s.critical
    assert (c.m, c.n) == (0, 1)
    early = ModeValue(1, 1, c.value - 1e-9, "wrinkle", 1e-12)

    def fake(at, side, rtol, mv):
        return early if (mv.m, mv.n) == (1, 1) else dataclasses.replace(mv, error_estimate=1e-12)

    monkeypatch.setattr(runners, "finished_runner", fake)
    monkeypatch.setattr(
        runners, "finished", lambda *a: dataclasses.replace(c, m=1, value=a[-1].value)
    )
    marched = dataclasses.replace(
        s, runners_up=tuple(dataclasses.replace(r, error_estimate=None) for r in s.runners_up)
    )
    got = runners.with_finished_runners(P, "growth", None, 1e-12, marched)
    assert (got.critical.m, got.critical.value) == (1, early.value)
    first = got.runners_up[0]
    assert (first.m, first.n, first.value, first.error_estimate) == (
        0,
        1,
        c.value,
        c.error_estimate,
    )


@pytest.mark.slow
def test_a_film_ring_runner_up_under_force_to_the_scan_rtol():
    """The force-controlled film of probe 9a (ratio 1e4, h = 1e-3, L = 2): (2, 44) was
    -6.27609172004e-05 for -6.27608330496e-05 (1.3e-6 relative), the others 1.4e-6."""
    s = scan_modes(FILM, "force", side="compression", options=ScanOptions((0, 12), (1, 30)))
    for r in s.runners_up:
        true = _true(FILM, r, "force", "compression").value
        assert r.value == pytest.approx(true, rel=1e-8), (r.m, r.n)
        assert abs(r.value - true) <= max(r.error_estimate, 1e-16)


#: three layers (probe 11a, Q1): a stiff film, a Mooney-Rivlin layer and a Gent (jm 15) skin
#: whose kinematic lock under stretch is lambda_z = 4.185954093606898 (lambda^2 + 2 / lambda
#: - 3 = 15), reached before any mode bifurcates
LAYERS3 = (
    Layer(1.03, shear_modulus=50.0),
    Layer(1.4, material=mooney_rivlin(0.8)),
    Layer(2.2, shear_modulus=5.0, material=gent(15.0)),
)
TUBE3 = Tube(LAYERS3, length=3.0, stretch=1.0, voltage=0.2)
LOCK3 = 4.185954093606898


def _lost_at_lock(runners_up) -> ScanResult:
    """A stretch scan of TUBE3 as the march left it: the loss at the lock, and runners-up."""
    crit = CriticalPoint(
        "stretch", LOCK3, *NO_MODE, Kind.THRESHOLD, 0.0, "impedance", "extension",
        TUBE3.at("stretch", LOCK3),
    )  # fmt: skip
    return ScanResult(crit, tuple(runners_up), (0, 10), (0, 3))


def test_runners_up_before_a_loss_must_be_roots_at_rtol():
    """The stretch scan of TUBE3 listed (4, 1) at 4.185951531 and (10, 2) at 4.185952006,
    2.6e-6 and 2.1e-6 BEFORE its threshold, the lock (estimates 4.3e-5: no root at rtol was
    found near the march's, which then stood). Their fine targets (rtol 1e-12) keep their
    sign up to the lock (a single solve of each returns the lock); next to it every target
    saturates (~1e259) and the march's looser ones (1e-9) flip sign there. They are not
    bifurcations, and are no longer listed."""
    marched = _lost_at_lock(
        [ModeValue(4, 1, 4.185951531, "wrinkle"), ModeValue(10, 2, 4.185952006, "wrinkle")]
    )
    got = runners.with_finished_runners(TUBE3, "stretch", "extension", 1e-12, marched)
    assert got.critical == marched.critical
    assert got.runners_up == ()


def test_a_root_at_rtol_before_a_loss_is_the_critical_mode(monkeypatch):
    """A runner-up whose root at rtol comes before the loss of the state bifurcates first: it
    is the critical mode (a threshold result after it was wrong). Injected: (4, 1) confirmed
    1e-6 before the lock, (10, 2) not."""
    early = ModeValue(4, 1, LOCK3 - 1e-6, "wrinkle", 1e-12)

    def fine(at, side, rtol, mv):
        return early if (mv.m, mv.n) == (4, 1) else None

    monkeypatch.setattr(runners, "fine_runner", fine)
    point = dataclasses.replace(_lost_at_lock([]).critical, kind=Kind.BIFURCATION, m=4, n=1)
    monkeypatch.setattr(
        runners, "finished", lambda *a: dataclasses.replace(point, value=a[-1].value)
    )
    marched = _lost_at_lock(
        [ModeValue(4, 1, 4.185951531, "wrinkle"), ModeValue(10, 2, 4.185952006, "wrinkle")]
    )
    got = runners.with_finished_runners(TUBE3, "stretch", "extension", 1e-12, marched)
    assert (got.critical.kind, got.critical.m, got.critical.value) == (
        Kind.BIFURCATION,
        4,
        early.value,
    )
    assert got.runners_up == ()


@pytest.mark.slow
def test_a_scan_lost_at_a_lock_lists_no_mode_before_it():
    """The whole scan (~3 min): a threshold labelled with mode (8, 2) (the march's root of
    (8, 2), which a solve at rtol does not confirm) and (4, 1), (10, 2) before it; now the
    lock, no mode, no runner-up."""
    s = scan_modes(TUBE3, "stretch", side="extension")
    c = s.critical
    assert (c.kind, c.value, (c.m, c.n)) == (Kind.THRESHOLD, LOCK3, NO_MODE)
    assert all(r.value > c.value for r in s.runners_up)
