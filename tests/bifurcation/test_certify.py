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
    Layer,
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


def test_a_wrong_choice_of_mode_is_remedied_by_solving_the_first_mode_alone():
    """probe 9a, D5: the refusal of a scan's choice carried ConvergenceError's remedy, "pass a
    looser rtol (e.g. rtol=1e-10), or certify ... with method='collocation'", given at
    rtol 1e-6: neither helps, the scan's mode is the wrong one. The remedy names the mode
    that comes first and how to solve it, in both forms."""
    later = critical_value(P, 2, 1, "growth")
    fake = ScanResult(_as_collocation(later), (), (0, 2), (1, 1))
    opts = ScanOptions((0, 2), (1, 1), prismatic=False, torsional=False)
    with pytest.raises(ConvergenceError) as exc:
        certify(P, fake.critical, scan=fake, options=opts, rtol=1e-6)
    remedy = exc.value.remedy
    assert "looser" not in remedy.python and "loosen" not in remedy.cli
    assert "--mode 0 1 " in remedy.cli and "(2, 1)" in remedy.cli
    assert "critical_value(tube, 0, 1, 'growth')" in remedy.python


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
    # check round 29: two values agreeing to the bit certify to the precision achieved at
    # rtol 1e-14 (5e-14), not to a difference of 0
    assert cert.difference >= 5e-14 * cert.value / res.critical.value
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


def test_the_choice_reads_the_unloaded_tube_at_a_few_modes_per_family_block(monkeypatch):
    """Probe 8a, D5: ``certify`` of a film's scan (m to 2000, n to 240: 482 000 modes) ran
    past 13 minutes, because the kernel read every scanned mode four times, twice on the
    unloaded tube, whose signs are one per family block (certify.unloaded_signs). Now the
    unloaded tube is read at a few modes of each block and only the state mode by mode."""
    opts = ScanOptions((0, 40), (1, 10), extend=False, surface=False)
    res = scan_modes(P, "growth", options=opts)
    real, rows = certify_module.impedance_targets, {"reference": 0, "state": 0}

    def counted(state, modes, **kw):
        rows["reference" if state.tube.voltage == 0 else "state"] += len(modes)
        return real(state, modes, **kw)

    monkeypatch.setattr(certify_module, "impedance_targets", counted)
    cert = certify(P, _as_collocation(res.critical), scan=res, options=opts)
    assert cert.certified and cert.modes_checked == 41 * 10 + 39 + 10
    assert rows["state"] >= 2 * cert.modes_checked  # every mode, at 1e-9 and 1e-7
    assert rows["reference"] <= 100  # four blocks of <= 22 samples, not 2 x 459 modes


@pytest.mark.parametrize("name", ["uniform", "bilayer"])
def test_the_unloaded_sign_of_a_family_block_is_the_sign_of_each_of_its_modes(name):
    """The one sign per block that certify.unloaded_signs reads is every mode's own sign at
    1e-12 on the unloaded tube (here +1), for every family, one layer and two."""
    from electrogrowth import solve_base_state
    from electrogrowth.bifurcation.scan_grid import scan_grid
    from electrogrowth.incremental.targets import impedance_targets

    tube = P if name == "uniform" else load_tube(BILAYER)
    reference = solve_base_state(tube.reference())
    modes = scan_grid((0, 30), (1, 20), False, (True, True))
    tight = np.sign(impedance_targets(reference, modes, rtol=certify_module.SIGN_RTOL))
    np.testing.assert_array_equal(certify_module.unloaded_signs(reference, modes), tight)


def test_a_block_whose_sampled_unloaded_signs_disagree_is_read_mode_by_mode(monkeypatch):
    """Where the samples of a block disagree (injected: the kernel misreads the modes of the
    largest m on the unloaded tube) no block sign is assumed: every mode is read, and the
    misread modes keep their misread sign (a suspect for collocation, not a silent +1)."""
    from electrogrowth import solve_base_state

    real = certify_module.impedance_targets

    def misread(state, modes, **kw):
        f = real(state, modes, **kw)
        return np.where(modes[:, 0] == 12, -f, f)

    monkeypatch.setattr(certify_module, "impedance_targets", misread)
    reference = solve_base_state(P.reference())
    modes = np.array([[m, n, 0] for m in range(1, 13) for n in (1, 2)], dtype=float)
    signs = certify_module.unloaded_signs(reference, modes)
    np.testing.assert_array_equal(signs, np.where(modes[:, 0] == 12, -1.0, 1.0))


def test_a_film_scan_claiming_a_later_fold_is_refused():
    """A film's fold (231, 0) (mu 100, h 0.004 on R 3, hoop growth): a scan result claiming
    its neighbour (233, 0) is refused, a fold before it named (the kernel's and collocation's
    signs have both changed), with the block signs of the unloaded tube read at samples."""
    film = Tube([Layer(3.0), Layer(3.004, shear_modulus=100.0)], length=2.0)
    later = critical_value(film, 233, 0, "growth[2].theta")
    fake = ScanResult(later, (), (229, 233), (1, 1))
    opts = ScanOptions((229, 233), (1, 1), torsional=False)
    with pytest.raises(ConvergenceError, match=r"mode \(2(29|3[012]), [01]\) is already unstable"):
        certify(film, fake.critical, scan=fake, options=opts)


def test_a_value_less_accurate_than_the_certificate_is_the_one_blamed():
    """probe 12b, D4: a value solved at rtol 1e-4 (its estimate 5.2e-4) disagreed with
    collocation by 6.6e-7 and the refusal said collocation "cannot judge impedance here",
    while collocation agreed with the value at rtol 1e-12 to 2.2e-10. A value whose own
    estimate exceeds CERTIFY_RTOL |value| is named as the one not accurate enough, with
    --rtol as the remedy (made up here: the impedance kernel judges, the fast direction)."""
    crit = critical_value(P, 0, 1, "growth")
    loose = dataclasses.replace(
        _as_collocation(crit), value=crit.value * (1 + 1e-6), error_estimate=1e-5 * crit.value
    )
    with pytest.raises(ConvergenceError) as exc:
        certify(P, loose)
    why = str(exc.value)
    assert "not accurate enough to be certified to 1e-08" in why and "--rtol" in why
    assert "cannot judge" not in why


def test_no_root_of_the_other_method_near_the_value_is_a_refusal(monkeypatch):
    """probe 12b, D8: layered collocation's "no sign change on (...)" passed through certify
    as a ConvergenceError that is not a refusal: the CLI exited 2 with nothing printed. It
    is "not certified: collocation cannot resolve this mode near the value", after the
    brackets widened to OTHER_BRACKETS (each tried once)."""
    from electrogrowth.bifurcation.critical import NoSignChange

    crit = critical_value(P, 0, 1, "growth")
    brackets = []

    def no_sign_change(*args, bracket, **kwargs):
        brackets.append(bracket)
        raise NoSignChange(f"collocation has no sign change on {bracket}")

    monkeypatch.setattr(certify_module, "critical_value", no_sign_change)
    with pytest.raises(ConvergenceError, match="^not certified: collocation cannot resolve"):
        certify(P, crit)
    widths = [(b - a) / 2 / crit.value for a, b in brackets]
    assert len(widths) == 3 and widths[1:] == pytest.approx(certify_module.OTHER_BRACKETS)


@pytest.mark.slow
def test_a_film_pressure_next_to_its_fold_is_refused_not_failed():
    """probe 12b, D8, the real case: a film 1e4 times as stiff, 1e-5 below its fold at
    P_i = 0: P_i,cr = -1.68626e-5 (estimate 2e-14). Collocation's root lies 4.8e-8 of it
    away (its own estimate 9e-8), outside the first bracket (1.7e-11): "not certified",
    naming collocation as unresolved, not "no sign change" (CLI exit 2, nothing printed)."""
    t = Tube(
        [Layer(1.001, shear_modulus=1e4, growth=(1, 1.026916558161777, 1)), Layer(3.0)],
        length=2.0,
    )
    c = critical_value(t, 69, 0, "pressure", side="compression")
    with pytest.raises(ConvergenceError, match="^not certified: ") as exc:
        certify(t, c)
    assert "collocation did not resolve this mode" in str(exc.value)
