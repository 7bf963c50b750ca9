"""Savings of a scan that must change nothing: a bracket whose ends were evaluated to check
its sign change is handed to Brent's method remembered, not evaluated again (a runner-up's
window, a critical value's bracket, the short-wave limit's coarse root). Each test runs the
route that evaluated the ends twice (Remembered replaced by the bare function) next to the
saving one and asks for the same numbers to the bit."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation import critical, runners, surface
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes


def _bare(f):
    """What the routes called before the saving: the function itself."""
    return f


def _counted(f):
    calls = []

    def g(x):
        calls.append(float(x))
        return f(x)

    return g, calls


def test_runner_window_asks_each_point_once(monkeypatch):
    """_root_near: the root of the first window with a sign change, each point asked once,
    the root of the bare function's Brent to the bit."""
    f = lambda x: np.tanh(x - 0.3021) + 1e-3 * (x - 0.3021) ** 2  # noqa: E731
    g, calls = _counted(f)
    root = runners._root_near(g, 0.3, 1e-4, (0.0, 1.0))
    assert len(calls) == len(set(calls))
    monkeypatch.setattr(runners, "Remembered", _bare)
    g_bare, bare_calls = _counted(f)
    assert runners._root_near(g_bare, 0.3, 1e-4, (0.0, 1.0)) == root
    assert len(bare_calls) == len(calls) + 2  # the window's two ends, paid twice before


def test_surface_coarse_root_asks_each_point_once(monkeypatch):
    f = lambda x: (x - 2.4562211) * (1.0 + 0.1 * x)  # noqa: E731
    g, calls = _counted(f)
    err = surface._second_resolution(g, 2.4562211287, (1.0, 8.0))
    assert len(calls) == len(set(calls))
    monkeypatch.setattr(surface, "Remembered", _bare)
    g_bare, bare_calls = _counted(f)
    assert surface._second_resolution(g_bare, 2.4562211287, (1.0, 8.0)) == err
    assert len(bare_calls) == len(calls) + 2


def test_bracketed_critical_value_asks_each_state_once(monkeypatch):
    """critical_value in a bracket (as a scan finishes its critical mode): the mode's fine
    det(M2) is solved once per state, and value and estimate are the bare route's to the
    bit (the fine target's calls, two fewer than before)."""
    tube = Tube.uniform(1.4, 1.0, voltage=0.4)
    bracket = (1.2661 * (1 - 1e-4), 1.2661 * (1 + 1e-4))
    root_mode, asked = critical.root_mode, []

    def counting(*args):
        g, calls = _counted(root_mode(*args))
        asked.append(calls)
        return g

    monkeypatch.setattr(critical, "root_mode", counting)
    point = critical_value(tube, 0, 1, "growth", bracket=bracket)
    fine = asked[0]  # the value's target; then the estimate's (second_resolution's own)
    assert point.value == pytest.approx(1.26611, rel=1e-5)
    assert len(fine) == len(set(fine))
    monkeypatch.setattr(critical, "Remembered", _bare)
    asked.clear()
    bare = critical_value(tube, 0, 1, "growth", bracket=bracket)
    assert (bare.value, bare.error_estimate) == (point.value, point.error_estimate)
    assert len(asked[0]) == len(fine) + 2


def _numbers(res):
    c = res.critical
    runners_up = [(r.m, r.n, r.family, r.value, r.error_estimate) for r in res.runners_up]
    return (
        (c.kind, c.m, c.n, c.value, c.error_estimate, c.face, c.psi),
        runners_up,
        (res.short_wave_limit, res.short_wave_error),
    )


@pytest.mark.parametrize(
    "tube, control, side",
    [
        (Tube.uniform(1.4, 1.0, voltage=0.4), "growth", None),  # Fig. 9: a finite mode
        (Tube.uniform(1.4, 1.0, voltage=0.4), "stretch", "extension"),  # a surface limit
    ],
)
def test_scan_numbers_are_the_bare_routes(monkeypatch, tube, control, side):
    """A small scan's critical point, runners-up, limit and every error estimate: the same
    bits with the remembered brackets as with the ends evaluated twice."""
    options = ScanOptions((0, 4), (1, 4))
    saved = _numbers(scan_modes(tube, control, side=side, options=options))
    for module in (critical, runners, surface):
        monkeypatch.setattr(module, "Remembered", _bare)
    bare = _numbers(scan_modes(tube, control, side=side, options=options))
    assert saved == bare
