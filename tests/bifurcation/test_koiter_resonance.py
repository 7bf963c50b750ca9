"""A second harmonic of the mode bifurcating next to its onset (bifurcation/
koiter_resonance.py): the Koiter coefficient has a pole there and the amplitude equation
says so (probe round 8b, a doubt: no note was given).

A uniform tube Rbar_o 1.2 compressed axially, mode (1, 1): its c_2 is the elastica's
geometric shortening -pi^2 / (4 lambda_c L^2) for slender tubes (ratio 0.973 at L = 30) but
12.5 times it at L = 8, where the harmonic (2, 2) bifurcates 0.07 % of the scale from the
onset (and before it): A(c_c) is nearly singular on the correction's harmonics.
"""

import math

import pytest

from electrogrowth import Tube, critical_value
from electrogrowth.bifurcation.koiter import koiter_coefficient, with_branch
from electrogrowth.bifurcation.koiter_resonance import (
    WINDOW,
    harmonics,
    nearest_resonance,
    window_size,
)
from electrogrowth.bifurcation.scan import scan_modes


def _elastica(k) -> float:
    L = 2 * math.pi / (2 * k.wavenumber)  # K = n pi / L with n = 1
    return -(math.pi**2) / (4 * k.critical_value * L**2)


def test_the_harmonics_of_each_family():
    assert harmonics(3, 0) == [(6, 0)]
    assert harmonics(0, 2) == [(0, 4)]
    assert harmonics(1, 1) == [(2, 2), (2, 0), (0, 2)]


def test_the_window_is_relative_to_the_onset_unless_it_is_next_to_zero():
    """Probe round 10a: relative to the scale alone, a film's collapse pressure (1/12 of its
    scale) flagged harmonics 70 % away from onset."""
    assert window_size(0.92, 1.0) == 0.92
    assert window_size(-0.08, 1.0) == 0.08
    assert window_size(1e-5, 1.0) == 1.0  # a load next to zero: its scale


def test_a_harmonic_next_to_onset_is_named_with_its_own_critical_value():
    tube = Tube.uniform(1.2, length=8.0)
    k = koiter_coefficient(tube, (1, 1), "stretch", side="compression")
    assert abs(k.coefficient / _elastica(k)) > 10  # the pole's doing
    r = k.resonance
    assert (r.m, r.n, r.before) == (2, 2, True)
    # the harmonic's root is its critical value (its first root, reached before onset)
    c22 = critical_value(tube, 2, 2, "stretch", side="compression").value
    assert r.value == pytest.approx(c22, rel=1e-8)
    gap = abs(c22 - k.critical_value) / abs(k.critical_value)  # relative to the onset
    assert r.gap == pytest.approx(gap, rel=1e-6)
    assert r.gap < 1e-3


def test_a_slender_tube_has_no_harmonic_next_to_onset():
    k = koiter_coefficient(Tube.uniform(1.2, length=30.0), (1, 1), "stretch", side="compression")
    assert k.resonance is None
    assert k.coefficient / _elastica(k) == pytest.approx(0.973, abs=5e-3)


def test_a_harmonic_after_onset_within_the_window():
    """L = 10: (2, 2) bifurcates 3 % of the scale after (1, 1)'s onset, inside the window;
    c_2 is still 0.17 times the elastica's."""
    tube = Tube.uniform(1.2, length=10.0)
    onset = critical_value(tube, 1, 1, "stretch", side="compression").value
    c22 = critical_value(tube, 2, 2, "stretch", side="compression").value
    assert 0.02 < onset - c22 < WINDOW * window_size(onset, 1.0)  # compression: after onset
    r = nearest_resonance(tube, (1, 1), "stretch", "compression", onset)
    assert (r.m, r.n, r.before) == (2, 2, False)
    assert r.value == pytest.approx(c22, rel=1e-8)


def test_the_verdict_says_so():
    """L = 8.5: the scan's first mode is (1, 1), its harmonic (2, 2) 0.74 % after it; the
    verdict's meaning and record carry the note."""
    tube = Tube.uniform(1.2, length=8.5)
    verdict = scan_modes(tube, "stretch", side="compression").verdict
    assert (verdict.wrinkle.m, verdict.wrinkle.n) == (1, 1)
    out, note = with_branch(verdict, tube, "stretch", "compression")
    assert note is None
    assert "second harmonic (2, 2) bifurcates at stretch = 0.922418, 0.8 % from" in out.meaning
    rec = out.as_dict()["koiter_resonance"]
    assert (rec["m"], rec["n"], rec["before"]) == (2, 2, False)


def test_a_mode_that_restabilises_next_to_onset_says_so():
    """Probe round 12a (doubt 2): a Gent tube (J_m 1.32), (0, 1) in compression, is unstable
    only for 0.5701 < lambda_z < 0.6054: its c_2 (-1.59, against -0.27 neo-Hookean) is a true
    derivative, but the one-mode expansion's range ends where the mode restabilises, and the
    verdict said only "the folds grow gradually". The restabilisation is a root of the
    mode's own target: collocation, an independent method, changes sign across it too."""
    from electrogrowth.basestate.tube import solve_base_state
    from electrogrowth.incremental.targets import CollocationTarget
    from electrogrowth.model.materials import gent

    tube = Tube.uniform(1.5, length=3, material=gent(1.32))
    k = koiter_coefficient(tube, (0, 1), "stretch", side="compression")
    r = k.resonance
    assert r is not None and r.own and (r.m, r.n) == (0, 1) and not r.before
    assert r.value < k.critical_value and r.gap == pytest.approx(0.0583, abs=1e-3)
    colloc = CollocationTarget(1e-10)
    signs = [
        colloc(solve_base_state(tube.at("stretch", r.value + d)), [[0, 1]])[0]
        for d in (-1e-6, 1e-6)
    ]
    assert signs[0] * signs[1] < 0
    verdict, _ = with_branch(critical_value(tube, 0, 1, "stretch", side="compression").verdict,
                             tube, "stretch", "compression")  # fmt: skip
    assert "the mode restabilises at stretch = 0.570119, 5.8 % past onset" in verdict.meaning
    plain = koiter_coefficient(Tube.uniform(1.5, length=3), (0, 1), "stretch", side="compression")
    assert plain.resonance is None  # neo-Hookean: the mode stays unstable past the window
