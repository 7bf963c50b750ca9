"""certify(): a critical value checked by the other method, a scan's choice of mode checked
mode by mode (one-layer and layered tubes), and surface results that say what they certify.

A value claimed by collocation is certified by the impedance kernel (seconds); the fast
tests below use that direction, the collocation direction (tens of seconds a solve) is
exercised by the CLI tests and the slow ones here."""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

from electrogrowth import (
    ScanOptions,
    ScanResult,
    Tube,
    certify,
    critical_value,
    load_tube,
    scan_modes,
)
from electrogrowth.bifurcation import certify as certify_module
from electrogrowth.bifurcation.certify import CERTIFY_RTOL
from electrogrowth.cli.app import main
from electrogrowth.errors import ConvergenceError

P = Tube.uniform(1.4, 1.0, voltage=0.4)
BILAYER = Path(__file__).parents[2] / "examples" / "bilayer.toml"


def _as_collocation(crit):
    """``crit`` (an impedance root) as if collocation had found it: certify() then checks it
    by the impedance kernel, the fast direction."""
    return dataclasses.replace(crit, method="collocation")


def test_a_value_claimed_by_collocation_is_certified_by_impedance():
    crit = critical_value(P, 0, 1, "growth")
    cert = certify(P, _as_collocation(crit))
    assert cert.certified and cert.by == "impedance" and cert.modes_checked is None
    assert cert.difference < 1e-11 and abs(cert.value - crit.value) < 1e-11 * crit.value
    d = cert.as_dict()
    assert set(d) == {"certified", "certified_by", "certified_value", "certification_difference"}


def test_a_wrong_value_is_refused():
    crit = critical_value(P, 0, 1, "growth")
    wrong = dataclasses.replace(_as_collocation(crit), value=crit.value * (1 + 1e-7))
    with pytest.raises(ConvergenceError, match="not certified: collocation gives"):
        certify(P, wrong)


def test_a_wrong_choice_of_mode_is_refused_naming_the_mode_that_comes_first():
    """A scan result claiming mode (2, 1), which comes after (0, 1): certify names (0, 1)."""
    first = critical_value(P, 0, 1, "growth")
    later = critical_value(P, 2, 1, "growth")
    assert later.value > first.value
    fake = ScanResult(_as_collocation(later), (), (0, 2), (1, 1))
    opts = ScanOptions((0, 2), (1, 1), prismatic=False, torsional=False)
    with pytest.raises(ConvergenceError, match=r"mode \(0, 1\) is already unstable"):
        certify(P, fake.critical, scan=fake, options=opts)


def test_a_true_choice_counts_every_scanned_mode():
    opts = ScanOptions((0, 2), (1, 1), extend=False, surface=False, prismatic=False)
    opts = dataclasses.replace(opts, torsional=False)
    res = scan_modes(P, "growth", options=opts)
    cert = certify(P, _as_collocation(res.critical), scan=res, options=opts)
    assert cert.certified and cert.modes_checked == 3  # (0, 1), (1, 1), (2, 1)
    assert cert.as_dict()["certified_modes"] == 3


def test_a_layered_scan_certifies_its_choice_of_mode():
    """Bilayer (a stiff grown inner ply): every scanned mode checked against its sign on
    the unloaded tube, not against "positive" (docs/derivation-layered-modes.md L.3)."""
    tube = load_tube(BILAYER)
    opts = ScanOptions((0, 1), (1, 1), extend=False, surface=False, prismatic=False)
    opts = dataclasses.replace(opts, torsional=False)
    res = scan_modes(tube, "voltage", options=opts)
    cert = certify(tube, _as_collocation(res.critical), scan=res, options=opts)
    assert cert.certified and cert.modes_checked == 2  # (0, 1), (1, 1)


def test_a_layered_wrong_choice_is_refused_by_both_methods():
    """Claiming the bilayer's runner-up (1, 2): mode (1, 1) has changed sign by collocation
    and by impedance before it, a real crossing."""
    tube = load_tube(BILAYER)
    later = critical_value(tube, 1, 2, "voltage")
    fake = ScanResult(_as_collocation(later), (), (0, 1), (1, 2))
    opts = ScanOptions((0, 1), (1, 2), prismatic=False, torsional=False)
    with pytest.raises(ConvergenceError, match=r"collocation and impedance mode \(1, 1\)"):
        certify(tube, fake.critical, scan=fake, options=opts)


def test_a_layered_collocation_sign_change_alone_is_no_bifurcation(monkeypatch):
    """Where only the collocation determinant changes sign (L.3), the impedance kernel
    decides: mode (1, 1) keeps its unloaded impedance sign before the critical value, so
    a collocation sign flipped there (injected) does not refuse the choice."""
    tube = load_tube(BILAYER)
    opts = ScanOptions((0, 1), (1, 1), extend=False, surface=False, prismatic=False)
    opts = dataclasses.replace(opts, torsional=False)
    res = scan_modes(tube, "voltage", options=opts)
    real = certify_module.collocation_targets

    def flipped(state, modes, **kw):
        f = real(state, modes, **kw)
        return -f if modes[0, 0] == 1 and state.tube.voltage > 0 else f  # not the reference

    monkeypatch.setattr(certify_module, "collocation_targets", flipped)
    cert = certify(tube, _as_collocation(res.critical), scan=res, options=opts)
    assert cert.certified and cert.modes_checked == 2


def test_a_surface_result_says_what_it_certified():
    """The thick compressed tube of test_scan: the inner face's half-space value first."""
    p = Tube.uniform(2.5, 3.0, stretch=0.8)
    res = scan_modes(p, "voltage", options=ScanOptions((0, 2), (1, 6)))
    assert res.critical.kind == "surface"
    cert = certify(p, res.critical)  # no scan: the half-space value alone
    assert cert.certified and cert.by == "halfspace" and cert.difference <= CERTIFY_RTOL
    assert "half-space value recomputed" in cert.message
    assert cert.as_dict()["certification"] == cert.message


@pytest.mark.slow
def test_a_surface_scan_certifies_its_best_finite_mode_too():
    p = Tube.uniform(2.5, 3.0, stretch=0.8)
    res = scan_modes(p, "voltage", options=ScanOptions((0, 2), (1, 6)))
    cert = certify(p, res.critical, scan=res)
    best = res.runners_up[0]
    assert f"({best.m}, {best.n})" in cert.message
    assert ("certified by collocation" in cert.message) == cert.certified


def test_the_library_certificate_equals_the_cli_one_layer(capsys):
    """The CLI prints the library's certificate (a one-layer scan, collocation checking)."""
    argv = ["critical", "--outer-radius", "1.4", "--length", "1.0", "--voltage", "0.4"]
    argv += ["--solve-for", "growth", "--m-max", "2", "--n-max", "1", "--certify", "--json"]
    assert main(argv + ["--quiet"]) == 0
    rec = json.loads(capsys.readouterr().out)
    opts = ScanOptions((0, 2), (1, 1))
    res = scan_modes(P, "growth", options=opts)
    cert = certify(P, res.critical, scan=res, options=opts).as_dict()
    for key in ("certified", "certified_by", "certified_value", "certified_modes"):
        assert rec[key] == cert[key], key
    assert rec["certified_modes"] > 0


@pytest.mark.slow
def test_the_cli_certifies_a_layered_scan(capsys):
    argv = ["critical", "--tube", str(BILAYER), "--solve-for", "voltage"]
    argv += ["--m-max", "3", "--n-max", "2", "--certify", "--json", "--quiet"]
    assert main(argv) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["certified"] and rec["certified_modes"] > 0 and rec["certified_by"] == "collocation"


def test_the_cli_prints_what_a_surface_result_certified(capsys):
    argv = ["critical", "--outer-radius", "2.5", "--length", "3.0", "--stretch", "0.8"]
    argv += ["--solve-for", "voltage", "--m-max", "2", "--n-max", "6", "--certify", "--quiet"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "  certified: half-space value recomputed at rtol 1e-14" in out
    assert "the first scanned finite mode (0, 24)" in out and "certified by collocation" in out


def test_a_judge_that_missed_its_own_accuracy_says_so(monkeypatch):
    """A disagreement where the second method returned INACCURATE names that method as the
    one that could not resolve the mode, instead of only refusing the first."""
    from electrogrowth.bifurcation import certify as certify_module
    from electrogrowth.outcomes import Status

    crit = critical_value(P, 0, 1, "growth")
    real = certify_module.critical_value

    def unresolved(*args, **kwargs):
        c = real(*args, **kwargs)
        return dataclasses.replace(
            c, value=c.value * (1 + 1e-6), error_estimate=3e-6, status=Status.INACCURATE
        )

    monkeypatch.setattr(certify_module, "critical_value", unresolved)
    with pytest.raises(ConvergenceError, match="collocation did not resolve this mode"):
        certify(P, crit)


def test_the_kernel_signs_of_the_choice_are_its_tight_signs_next_to_a_root():
    """The choice reads every scanned mode's sign at 1e-9 and 1e-7, and at 1e-12 where those
    do not agree: next to the root of (3, 1) (from 1e-3 to 1e-11 before and after it) the
    signs are those at 1e-12, and they change at the root."""
    from electrogrowth import solve_base_state
    from electrogrowth.incremental.targets import impedance_targets

    crit = critical_value(P, 3, 1, "growth")
    rows = np.array([[3, 1], [2, 1], [0, 1], [5, 0]], dtype=float)
    for d in (-1e-3, -1e-7, -1e-9, -1e-11, 1e-11, 1e-9, 1e-7, 1e-3):
        state = solve_base_state(P.at("growth", crit.value + d))
        signs = certify_module.kernel_signs(state, rows)
        tight = np.sign(impedance_targets(state, rows, rtol=certify_module.SIGN_RTOL))
        np.testing.assert_array_equal(signs, tight)
        assert signs[0] == (1.0 if d < 0 else -1.0)  # stable before the root, not after
