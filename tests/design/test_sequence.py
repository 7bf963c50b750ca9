"""Design along one variable (src/electrogrowth/design/): the mode sequence's switches
against bisection of full scans and against collocation, the switch condition, the
sensitivities against finite differences of full critical-value solves, the margin against
direct solves, the target sets, and the command line."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, gent
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.scan import scan_modes
from electrogrowth.bifurcation.scan_grid import scan_grid, stable_signs
from electrogrowth.cli.app import main
from electrogrowth.design import mode_sequence, prescribe
from electrogrowth.design.sensitivity import key_value, sensitivities
from electrogrowth.design.targets import check_target
from electrogrowth.errors import ParameterError
from electrogrowth.incremental.targets import impedance_targets

SMALL = ScanOptions((0, 2), (1, 2))
TUBE = Tube.uniform()  # uncharged, ungrown, L = 1: axial compression
VARY = ("outer_radius", 1.2, 1.3)


@pytest.fixture(scope="module")
def sequence():
    return mode_sequence(TUBE, "stretch", VARY, side="compression", points=2, options=SMALL)


def _first(x: float) -> tuple[int, int]:
    c = scan_modes(TUBE.at("outer_radius", x), "stretch", side="compression", options=SMALL)
    return c.critical.m, c.critical.n


def test_switch_equals_bisection_of_full_scans(sequence):
    (s,) = sequence.switches
    assert (s.mode_before, s.mode_after) == ((1, 1), (0, 1))
    lo, hi = VARY[1:]
    assert _first(lo) == (1, 1) and _first(hi) == (0, 1)
    while hi - lo > 2e-9:  # the scans themselves, not the two-mode condition
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _first(mid) == (1, 1) else (lo, mid)
    assert abs(s.x - 0.5 * (lo + hi)) < 1e-8
    iv = sequence.intervals
    assert [i.mode for i in iv] == [(1, 1), (0, 1)]
    assert iv[0].hi == iv[1].lo == s.x and iv[0].lo_edge and iv[1].hi_edge


def test_at_a_switch_both_modes_are_critical_and_no_other_is_earlier(sequence):
    (s,) = sequence.switches
    at = TUBE.at("outer_radius", s.x)
    a = critical_value(at, 1, 1, "stretch", side="compression").value
    b = critical_value(at, 0, 1, "stretch", side="compression").value
    assert abs(a - b) < 1e-8 and abs(a - s.value) < 1e-8
    scan = scan_modes(at, "stretch", side="compression", options=SMALL)
    assert (scan.critical.m, scan.critical.n) in ((1, 1), (0, 1))
    assert abs(scan.critical.value - s.value) < 1e-8
    # every scanned mode on its stable side just before the common value (compression:
    # lambda_z falls from 1, so just before is just above)
    grid = scan_grid(SMALL.m_range, SMALL.n_range, False, (True, True))
    signs = stable_signs(SMALL.m_range, SMALL.n_range, False, (True, True))
    f = impedance_targets(solve_base_state(at.at("stretch", s.value + 1e-7)), grid)
    assert np.all(signs * f > 0)


def test_switch_agrees_with_collocation_at_the_switch(sequence):
    """The independent route: the collocation target of each mode changes sign across the
    common value, within 1e-9 of it (the full collocation solves are the slow twin)."""
    from electrogrowth.incremental.targets import collocation_targets

    (s,) = sequence.switches
    at = TUBE.at("outer_radius", s.x)
    for mode in ((1, 1), (0, 1)):
        below, above = (
            collocation_targets(solve_base_state(at.at("stretch", s.value + d)), [mode])[0]
            for d in (-1e-9, 1e-9)
        )
        assert below * above < 0, mode


def test_the_switch_error_estimate_covers_its_error(sequence):
    """The tie of the two modes' values solved at rtol 1e-13 (their own Brent, not the
    locator's) is within the switch's x_error of it; the estimate, from the values' own
    (1e-11) over the slope of their difference, is not vacuous either."""
    from scipy.optimize import brentq

    (s,) = sequence.switches

    def d(x):
        at = TUBE.at("outer_radius", x)
        a, b = (critical_value(at, *mode, "stretch", side="compression", rtol=1e-13).value
                for mode in ((1, 1), (0, 1)))  # fmt: skip
        return a - b

    tie = brentq(d, *VARY[1:], xtol=1e-15, rtol=1e-15)
    assert abs(s.x - tie) <= s.x_error < 1e-9
    at = TUBE.at("outer_radius", tie)
    value = critical_value(at, 1, 1, "stretch", side="compression", rtol=1e-13).value
    assert abs(s.value - value) <= s.value_error < 1e-9


@pytest.mark.slow
def test_switch_agrees_with_collocation_solves(sequence):
    (s,) = sequence.switches
    at = TUBE.at("outer_radius", s.x)
    for mode in ((1, 1), (0, 1)):
        c = critical_value(at, *mode, "stretch", side="compression", method="collocation")
        assert abs(c.value - s.value) < 1e-8, mode


def _fd(tube, mode, solve_for, key, h=1e-4):
    """Richardson-extrapolated central difference of full critical_value solves."""
    p = key_value(tube, key)
    h *= max(1.0, abs(p))

    def v(q):
        return critical_value(tube.at(key, q), *mode, solve_for).value

    return (8 * (v(p + h / 2) - v(p - h / 2)) - (v(p + h) - v(p - h))) / (6 * h)


def test_sensitivities_equal_finite_differences_one_layer():
    tube = Tube.uniform(outer_radius=1.25, voltage=0.2, stretch=0.9)
    c = critical_value(tube, 1, 1, "growth")
    sens = sensitivities(tube, (1, 1), "growth", c.value)
    assert set(sens) == {"outer_radius", "length", "stretch", "voltage"}
    for key in ("outer_radius", "voltage", "length"):
        ref = _fd(tube, (1, 1), "growth", key)
        assert abs(sens[key] - ref) < 1e-6 * abs(ref), key


def test_sensitivities_equal_finite_differences_bilayer():
    tube = Tube(
        [Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0, material=gent(97.2))],
        length=3.0,
        voltage=0.3,
    )
    c = critical_value(tube, 12, 1, "growth[1].theta")
    keys = ("layers[1].shear_modulus", "voltage", "layers[2].thickness")
    sens = sensitivities(tube, (12, 1), "growth[1].theta", c.value, keys=keys)
    for key in keys:
        ref = _fd(tube, (12, 1), "growth[1].theta", key)
        assert abs(sens[key] - ref) < 1e-6 * abs(ref), key


def test_design_widest_margin_in_the_region(sequence):
    d = prescribe(TUBE, "stretch", (1, 1), VARY, sequence=sequence, options=SMALL)
    assert d.status == "found" and d.mode == (1, 1)
    assert [(iv.lo, iv.hi) for iv in d.region] == [(1.2, sequence.switches[0].x)]

    def margin(x):  # M = s (v_next - v) / |v|, s = -1 in compression, by direct solves
        at = TUBE.at("outer_radius", x)
        v = critical_value(at, 1, 1, "stretch", side="compression").value
        others = [critical_value(at, *m, "stretch", side="compression").value
                  for m in ((0, 1), (2, 1))]  # fmt: skip
        return min(-(w - v) / abs(v) for w in others)

    assert abs(d.margin - margin(d.x)) < 1e-8
    assert d.margin > 0
    for x in (1.2, 1.205, 1.23, 1.25, d.x - 1e-4, d.x + 1e-4):
        assert margin(x) <= d.margin + 1e-9, x
    assert abs(d.to_boundary - (sequence.switches[0].x - d.x)) < 1e-12
    # the margin's sensitivity from the two modes' sensitivities; (0, 1) and (2, 1) tie at
    # the design (6e-10 apart): M has a kink, and dM/dL against the next mode alone
    # (-0.0565) held only raising L (lowering it M follows (0, 1), +0.0345; probe 8b, D5)
    at, v = TUBE.at("outer_radius", d.x), d.value
    slopes = []
    for mode in ((0, 1), (2, 1)):
        w = critical_value(at, *mode, "stretch", side="compression").value
        dw = sensitivities(at, mode, "stretch", w, keys=("length",))["length"]
        slopes.append(-(v * dw - w * d.sensitivity["length"]) / v**2)
    assert d.margin_sensitivity["length"] is None and d.next_mode in ((0, 1), (2, 1))
    assert d.margin_sides["length"] == pytest.approx((max(slopes), min(slopes)), rel=1e-9)


def test_design_never_first_names_the_closest_design(sequence):
    d = prescribe(TUBE, "stretch", (0, 2), VARY, sequence=sequence, options=SMALL)
    assert d.status == "not_first" and d.region == () and d.margin < 0
    at = TUBE.at("outer_radius", d.x)
    scan = scan_modes(at, "stretch", side="compression", options=SMALL)
    assert d.next_mode == (scan.critical.m, scan.critical.n)
    v = critical_value(at, 0, 2, "stretch", side="compression").value
    assert d.margin == pytest.approx(-(scan.critical.value - v) / abs(v), abs=1e-8)


def test_target_sets():
    axi = check_target("axisymmetric")
    assert (0, 3) in axi and (1, 1) not in axi
    assert (4, 0) in check_target("prismatic") and (4, 1) not in check_target("prismatic")
    assert (1, 2) in check_target([(0, 1), (1, 2)])
    assert (2, 1) in check_target(lambda m, n: m == 2)
    # beyond the largest mode, as the command line refuses it (probe round 6b: (2001, 0) was
    # accepted and reported not reached when that was 2000)
    for bad in ("helical", (1, -1), [], 3, (10**6 + 1, 0), [(0, 1), (0, 10**6 + 1)]):
        with pytest.raises(ParameterError):
            check_target(bad)


@pytest.mark.parametrize("target", [(1, 0), (0, 0), [(0, 1), (1, 0)]])
def test_a_target_that_is_no_mode_is_refused(target):
    # probe 7b D4: (1, 0), a rigid translation, and (0, 0) were accepted and reported
    # not_reached with "widen --m-max / --n-max"
    with pytest.raises(ParameterError, match=r"target mode \(m, n\) = \((1|0), 0\).*m >= 2"):
        prescribe(TUBE, "stretch", target, VARY, side="compression", options=SMALL, points=2)


def test_a_triple_is_no_list_of_modes():
    with pytest.raises(ParameterError, match=r"target = \(0, 1, 2\) is invalid; give \(m, n\)"):
        check_target((0, 1, 2))


@pytest.mark.parametrize("mode", [("1", "0"), ("0", "0")])
def test_cli_design_target_that_is_no_mode_exits_2(capsys, mode):
    args = ["design", "--solve-for", "stretch", "--side", "compression", "--target", *mode]
    args += ["--vary", "outer_radius", "1.2", "1.3", "--points", "2", "--m-max", "2"]
    assert main([*args, "--n-max", "2"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and f"({mode[0]}, 0)" in err and "m >= 2" in err


def test_cli_design_json(capsys, tmp_path):
    args = ["design", "--solve-for", "stretch", "--side", "compression", "--target", "0", "1"]
    args += ["--vary", "outer_radius", "1.2", "1.3", "--points", "2", "--m-max", "2"]
    args += ["--n-max", "2", "--json", "--out", str(tmp_path)]
    assert main(args) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["target"] == "(0, 1)" and out["best"]["mode"] == [0, 1]
    assert out["region"][0]["lo"] == pytest.approx(1.2563609916543, abs=1e-10)
    (s,) = out["switches"]
    assert s["mode_before"] == [1, 1] and s["mode_after"] == [0, 1]
    assert set(out["sensitivity"]["value"]) == {"outer_radius", "length", "growth", "voltage"}
    assert math.isfinite(out["best"]["margin"]) and out["best"]["margin"] > 0
    assert sorted(p.rsplit(".", 1)[1] for p in out["files"]) == ["csv", "png"]


@pytest.mark.parametrize(
    "extra, words",
    [
        (["--vary", "length", "1", "2", "--vary", "voltage", "0", "1"], "once or twice"),
        (["--target-set", "prismatic"], "--target and --target-set prismatic are both given"),
    ],
)
def test_cli_design_bad_input(capsys, extra, words):
    args = ["design", "--solve-for", "stretch", "--target", "0", "1"]
    args += ["--vary", "outer_radius", "1.2", "1.3", *extra]
    assert main(args) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("electrogrowth: error:") and words in err and "\n" not in err


def test_cli_design_bad_range(capsys):
    args = ["design", "--solve-for", "stretch", "--target", "0", "1"]
    assert main([*args, "--vary", "outer_radius", "1.3", "1.2"]) == 2
    assert main([*args, "--vary", "outer_radius", "0.5", "1.2"]) == 2
    assert main([*args, "--vary", "layers[2].thickness", "0.1", "0.2"]) == 2  # one layer
    assert main([*args, "--vary", "outer_radius", "nan", "1.2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 4 and all(e.startswith("electrogrowth: error:") for e in err)
    assert "vary key 'layers[2].thickness' is not a key of this tube" in err[2]


def test_public_names_are_the_functions():
    """prescribe and mode_sequence are exported from the top (lazily) as the functions."""
    import electrogrowth

    assert electrogrowth.prescribe is prescribe and electrogrowth.mode_sequence is mode_sequence


def test_sequence_records(sequence):
    record = json.loads(json.dumps(sequence.as_dict()))
    assert [iv["mode"] for iv in record["intervals"]] == [[1, 1], [0, 1]]
    assert record["switches"][0]["x"] == sequence.switches[0].x
    assert record["switches"][0]["x_error"] == sequence.switches[0].x_error
    pytest.importorskip("xarray")
    ds = sequence.to_xarray()
    assert ds["switch_x"].values.tolist() == [sequence.switches[0].x]
    assert ds["switch_x_error"].values.tolist() == [sequence.switches[0].x_error]
    assert ds["mode"].values.tolist() == [[1, 1], [0, 1]]
    assert ds["hi"].values[0] == ds["lo"].values[1] == sequence.switches[0].x


def test_design_for_a_set_joins_its_intervals(sequence):
    d = prescribe(TUBE, "stretch", [(1, 1), (0, 1)], VARY, sequence=sequence, options=SMALL)
    assert d.status == "found" and len(d.region) == 2
    assert d.to_boundary is None  # the set is first over the whole range
    assert d.next_mode not in ((1, 1), (0, 1)) and d.margin > 0
    at = TUBE.at("outer_radius", d.x)
    v = critical_value(at, *d.mode, "stretch", side="compression").value
    w = critical_value(at, *d.next_mode, "stretch", side="compression").value
    assert d.margin == pytest.approx(-(w - v) / abs(v), abs=1e-9)
    axi = prescribe(TUBE, "stretch", "axisymmetric", VARY, sequence=sequence, options=SMALL)
    assert [iv.mode for iv in axi.region] == [(0, 1)] and axi.mode == (0, 1)


def test_a_wider_map_every_switch_agrees_with_collocation():
    """Rbar_o from 1.1 to 1.5 in compression: every located switch is a common root of the
    two modes' collocation targets (sign changes within 1e-9 of the common value)."""
    from electrogrowth.incremental.targets import collocation_targets

    seq = mode_sequence(
        TUBE, "stretch", ("outer_radius", 1.1, 1.5), side="compression", points=9,
        options=ScanOptions((0, 4), (1, 3)),
    )  # fmt: skip
    chain = [(s.mode_before, s.mode_after) for s in seq.switches]
    assert chain == [((3, 1), (2, 1)), ((2, 1), (1, 1)), ((1, 1), (0, 1))]
    for s in seq.switches:
        at = TUBE.at("outer_radius", s.x)
        for mode in (s.mode_before, s.mode_after):
            below, above = (
                collocation_targets(solve_base_state(at.at("stretch", s.value + d)), [mode])[0]
                for d in (-1e-9, 1e-9)
            )
            assert below * above < 0, (s, mode)


def test_cli_design_target_takes_the_package_mode_range(capsys):
    """--target M N accepts every mode the scans reach (incremental.modes.MODE_MAX, the
    kernel's), and names that range when a number is beyond it."""
    from electrogrowth.cli.app import build_parser
    from electrogrowth.incremental.modes import MODE_MAX

    base = ["design", "--solve-for", "stretch", "--vary", "outer_radius", "1.2", "1.3"]
    top = MODE_MAX
    args = build_parser("design").parse_args([*base, "--target", str(top), "0"])
    assert args.target == [[top, 0]]
    for bad in ([str(top + 1), "0"], ["0", str(top + 1)], ["-1", "0"]):
        assert main([*base, "--target", *bad]) == 2
        err = capsys.readouterr().err.strip()
        assert err.startswith("electrogrowth: error:") and "\n" not in err
        assert f"is not a whole number from 0 to {top}" in err
        assert "short-wave limit" in err


def test_cli_design_whose_every_point_failed_exits_2_naming_the_failure(capsys, tmp_path):
    """Probe 8b D8: every grid point failed (no mode bifurcates in extension up to lambda_z =
    8, `critical` exits 2 with that line), yet `design` exited 0 with "no target mode among
    the scanned modes: widen --m-max / --n-max", a remedy that cannot help. Now exit 2 with
    one line naming the first failure, as `curve` does."""
    tube = tmp_path / "comp.toml"
    tube.write_text(
        "length = 1.0\nstretch = 1.0\n[[layers]]\nouter_radius = 1.1\nshear_modulus = 3.0\n"
        "[[layers]]\nouter_radius = 1.6\n"
    )
    args = ["design", "--tube", str(tube), "--solve-for", "stretch", "--side", "extension"]
    args += ["--target", "1", "1", "--vary", "length", "0.6", "3", "--points", "3"]
    assert main([*args, "--m-max", "4", "--n-max", "3", "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "widen" not in err
    assert "every point of the design's sequence failed (3)" in err
    assert "no mode bifurcates for stretch between 1 and 8" in err
