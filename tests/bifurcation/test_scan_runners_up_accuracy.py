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

from electrogrowth import Layer, ScanOptions, Tube, critical_value, scan_modes
from electrogrowth.bifurcation import runners
from electrogrowth.bifurcation.march import ModeValue
from electrogrowth.cli.app import main

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
