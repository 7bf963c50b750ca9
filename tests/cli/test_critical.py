"""``electrogrowth critical``: JSON contract, agreement with the API, bad input."""

import json

import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.cli.app import main

BASE = ["critical", "--outer-radius", "1.4", "--length", "1.0"]


def _json(capsys, argv):
    assert main(argv + ["--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_single_mode_json_equals_api(capsys):
    rec = _json(capsys, BASE + ["--solve-for", "growth", "--voltage", "0.4", "--mode", "3", "1"])
    want = critical_value(Tube.uniform(1.4, 1.0, voltage=0.4), 3, 1, "growth")
    assert {"solve_for", "value", "m", "n", "error_estimate", "kind"} <= rec.keys()
    assert rec["kind"] == "bifurcation" and (rec["m"], rec["n"]) == (3, 1)
    assert rec["value"] == pytest.approx(want.value, rel=1e-12)
    assert rec["error_estimate"] < 1e-9


def test_scan_reports_critical_mode_and_runners_up(capsys):
    rec = _json(capsys, BASE + ["--solve-for", "voltage", "--m-max", "4", "--n-max", "4"])
    values = [rec["value"]] + [r["value"] for r in rec["runners_up"]]
    assert values == sorted(values) and len(values) == 5
    direct = critical_value(Tube.uniform(1.4, 1.0), rec["m"], rec["n"], "voltage")
    assert rec["value"] == pytest.approx(direct.value, rel=1e-11)
    for r in rec["runners_up"][:2]:  # each runner-up is a genuine critical value of its mode
        c = critical_value(Tube.uniform(1.4, 1.0), r["m"], r["n"], "voltage")
        assert r["value"] == pytest.approx(c.value, rel=1e-8)


def test_certify_agrees_with_collocation(capsys):
    rec = _json(
        capsys,
        BASE + ["--solve-for", "stretch", "--voltage", "0.2", "--mode", "2", "1", "--certify"],
    )
    assert rec["certified"] and rec["certification_difference"] < 1e-9


def test_text_output_names_mode(capsys):
    assert main(BASE + ["--solve-for", "growth", "--voltage", "0.4", "--mode", "0", "1"]) == 0
    out = capsys.readouterr().out
    assert "g_cr = 1.2661115622" in out and "(m, n) = (0, 1)" in out


@pytest.mark.parametrize(
    "extra, needle",
    [
        (["--solve-for", "growth", "--mode", "-1", "1"], "mode"),
        (["--solve-for", "growth", "--mode", "0", "0"], "mode"),
        (["--solve-for", "heat"], "solve-for"),
        (["--solve-for", "growth", "--side", "extension"], "--side"),
        (["--solve-for", "growth", "--voltage", "nan"], "nan"),
        (["--solve-for", "growth", "--voltage", "-0.1"], "Vbar"),
        (["--solve-for", "growth", "--rtol", "1"], "rtol"),
        (["--solve-for", "stretch", "--mode", "0", "1", "--voltage", "5"], "threshold"),
        (["--solve-for", "growth", "--method", "collocation"], "collocation"),
    ],
)
def test_bad_input_is_one_line_exit_2(capsys, extra, needle):
    assert main(BASE + extra) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and needle in err and "Traceback" not in err


FILM_TOML = """length = 10.0
axial_force = 0.0
[[layers]]
outer_radius = 2.0
shear_modulus = 1e-4
[[layers]]
outer_radius = 2.001
shear_modulus = 1.0
"""


def test_layered_tube_line_prints_the_force_to_its_estimate(monkeypatch, capsys, tmp_path):
    """probe 9a, D4: the "tube:" line of a layered tube printed the force solved for to 12
    digits whatever its estimate (cli/critical_text.py:tube_line trimmed only a layer's
    growth): at rtol 1e-8 the headline said -6.27e-05 (estimate 1.1e-7) and the tube line
    -6.27486723204e-05, whose 6th digit is wrong (-6.27486168431e-05). The solve is faked
    with that point; the given loads keep their 12 digits."""
    import electrogrowth.bifurcation.critical as solver
    from electrogrowth.bifurcation.critical import CriticalPoint
    from electrogrowth.outcomes import Kind

    value = -6.27486723204e-05

    def fake(params, m, n, solve_for, **kwargs):
        at = params.at(solve_for, value)
        return CriticalPoint(
            solve_for, value, m, n, Kind.BIFURCATION, 1.1e-7, "impedance", "compression", at
        )

    monkeypatch.setattr(solver, "critical_value", fake)
    film = tmp_path / "film.toml"
    film.write_text(FILM_TOML)
    argv = ["critical", "--tube", str(film), "--solve-for", "force", "--side", "compression"]
    assert main(argv + ["--mode", "0", "220", "--rtol", "1e-8"]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("  tube:"))
    assert "axial force -6.27e-05," in line, line
    assert "P_i = 0, P_o = 0" in line


def test_a_runner_up_is_printed_with_the_digits_its_estimate_supports(monkeypatch, capsys):
    """probe 9a, D2: the runners-up were printed to 10 digits with no estimate (a film's
    force ring 1.3e-6 off, relative). A runner-up's estimate, here made 1e-7, now sets its
    digits, as the headline's does."""
    import dataclasses

    import electrogrowth.bifurcation.scan as scan

    real = scan.scan_modes

    def coarse(*args, **kwargs):
        res = real(*args, **kwargs)
        runners = tuple(dataclasses.replace(r, error_estimate=1e-7) for r in res.runners_up)
        return dataclasses.replace(res, runners_up=runners)

    monkeypatch.setattr(scan, "scan_modes", coarse)
    argv = BASE + ["--solve-for", "growth", "--voltage", "0.4", "--m-max", "1", "--n-max", "1"]
    assert main(argv) == 0
    nxt = [x for x in capsys.readouterr().out.splitlines() if x.startswith("  next:")]
    assert nxt[0] == "  next: (m, n) = (1, 1)   g_cr = 1.2817091", nxt


def test_a_runner_up_at_the_mode_cap_says_a_shorter_wave_may_come_first(monkeypatch, capsys):
    """probe 12b (doubt): a long film's scan to --n-max 2000 listed the rings (0, 2000) and
    (0, 1999) next with no word that their optimum lies beyond the cap (n ~ 2056), so modes
    the scan cannot reach come before them. A runner-up at the cap now says so in its line
    and its JSON ``note``; one below the cap, and the critical mode, are unchanged."""
    import dataclasses

    import electrogrowth.bifurcation.scan as scan
    from electrogrowth.bifurcation.march import ModeValue

    real = scan.scan_modes

    def capped(*args, **kwargs):
        res = real(*args, **kwargs)
        top = res.critical.value + 1e-3
        rings = (ModeValue(0, 2000, top, error_estimate=1e-12), ModeValue(0, 1999, top + 1e-6))
        return dataclasses.replace(res, runners_up=rings)

    monkeypatch.setattr(scan, "scan_modes", capped)
    argv = BASE + ["--solve-for", "growth", "--voltage", "0.4", "--m-max", "1", "--n-max", "1"]
    assert main(argv) == 0
    nxt = [x for x in capsys.readouterr().out.splitlines() if x.startswith("  next:")]
    assert nxt[0].endswith(
        "(at the largest n = 2000 its scan searched: a mode beyond it may come first)"
    ), nxt
    assert nxt[1].startswith("  next: (m, n) = (0, 1999)") and "searched" not in nxt[1]
    assert main(argv + ["--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["runners_up"][0]["note"].startswith("at the largest n = 2000 its scan")
    assert rec["runners_up"][1]["note"] is None and rec["status"] == "ok"
