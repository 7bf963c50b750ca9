"""``electrogrowth critical``: the verdict in the JSON record and the text, bad input."""

import json

import pytest

from electrogrowth.bifurcation.crease import CREASE_RATIO
from electrogrowth.cli.app import main

COMPRESSED = [
    "critical",
    "--outer-radius",
    "1.8",
    "--length",
    "1.0",
    "--solve-for",
    "stretch",
    "--side",
    "compression",
    "--m-max",
    "2",
    "--n-max",
    "2",
]
CREASE = CREASE_RATIO ** (-2 / 3)  # the homogeneous tube's axial crease (closed form)


def _json(capsys, argv):
    assert main(argv + ["--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_json_kind_is_crease_with_the_wrinkle_as_runner_up(capsys):
    rec = _json(capsys, COMPRESSED)
    assert rec["kind"] == rec["verdict"] == "crease" and rec["face"] in ("inner", "outer")
    assert rec["value"] == pytest.approx(CREASE, rel=1e-12) == rec["verdict_value"]
    w = rec["wrinkle"]
    assert w["kind"] == "bifurcation" and (w["m"], w["n"]) == (0, 1) and w["value"] < CREASE
    for key in ("crease", "surface", "threshold", "meaning", "branch", "koiter"):
        assert key in rec
    assert rec["branch"] is None and rec["koiter"] is None


def test_json_of_one_mode_has_the_verdict_and_the_threshold(capsys):
    argv = ["critical", "--outer-radius", "1.4", "--solve-for", "voltage", "--mode", "0", "1"]
    rec = _json(capsys, argv)
    assert rec["kind"] == "bifurcation" and (rec["m"], rec["n"]) == (0, 1)
    assert rec["threshold"]["kind"] == "threshold" and rec["threshold"]["value"] > rec["value"]
    assert rec["crease"]["trigger"] == "field" and rec["crease"]["face"] == "inner"


def test_one_mode_asked_for_stays_on_top_with_the_verdict_beside(capsys):
    rec = _json(capsys, COMPRESSED[:-4] + ["--mode", "0", "1"])
    assert rec["kind"] == "bifurcation" and (rec["m"], rec["n"]) == (0, 1)
    assert rec["value"] < CREASE and rec["verdict"] == "crease"
    assert rec["verdict_value"] == pytest.approx(CREASE, rel=1e-12)
    assert (
        rec["crease"]["value"] == rec["verdict_value"] and rec["wrinkle"]["value"] == rec["value"]
    )
    assert main(COMPRESSED[:-4] + ["--mode", "0", "1"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("lambda_z,cr = 0.51124807") and "  crease: " in out
    assert "verdict: the" in out and "creases" in out


def test_text_names_the_crease_the_wrinkle_and_the_verdict(capsys):
    assert main(COMPRESSED) == 0
    out = capsys.readouterr().out
    assert out.startswith("lambda_z,cr = 0.558")  # the digits the criterion supports
    assert "crease at the" in out and "wrinkle (linear analysis): (m, n) = (0, 1)" in out
    assert "verdict: the" in out and "creases" in out


@pytest.mark.parametrize(
    "extra",
    [["--side", "sideways"], ["--mode", "0", "x"], ["--rtol", "-1"]],
)
def test_bad_input_is_one_line_and_exit_2(capsys, extra):
    assert main(COMPRESSED[:-4] + extra) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("electrogrowth: error:")


def test_a_crease_the_criterion_cannot_establish_prints_no_digits_it_lacks(capsys):
    """A Gent tube with no Biot ratio (J_m 3): its crease onset's estimate is infinite (null
    in the record, crease.energy_shift); the text prints three digits and says why, where
    it used to end in an internal error formatting the null estimate."""
    argv = ["critical", "--outer-radius", "2", "--solve-for", "stretch", "--side"]
    argv += ["compression", "--material", "gent", "--jm", "3", "--mode", "0", "1"]
    assert main(argv) == 0
    out, err = capsys.readouterr()
    (line,) = [x for x in out.splitlines() if x.strip().startswith("crease:")]
    assert f"= {CREASE:.3g}  (neo-Hookean criterion, not established" in line, line
    assert "may not crease" in out and "internal error" not in err
    rec = _json(capsys, argv)
    assert rec["crease"]["error_estimate"] is None


def test_a_crease_first_that_the_criterion_cannot_establish_is_not_ok(capsys):
    """A scan whose first event is such a crease (a thick Gent J_m 3 tube compressed): the
    record's status is inaccurate, the command warns and exits 3 unless the user accepts
    it (probe round 13c: status ok with a null estimate); the neo-Hookean tube's crease,
    whose criterion holds to its stated estimate, stays ok."""
    argv = ["critical", "--outer-radius", "3", "--length", "1", "--solve-for", "stretch"]
    argv += ["--m-max", "3", "--n-max", "3"]
    gent = argv + ["--material", "gent", "--jm", "3"]
    assert main([*gent, "--json"]) == 3
    out, err = capsys.readouterr()
    rec = json.loads(out)
    assert (rec["kind"], rec["status"], rec["error_estimate"]) == ("crease", "inaccurate", None)
    assert "not certified" in err and "not that energy's own onset" in err
    assert main(gent) == 3 and main([*gent, "--accept-inaccurate"]) == 0
    capsys.readouterr()
    rec = _json(capsys, argv)
    assert (rec["kind"], rec["status"]) == ("crease", "ok") and rec["error_estimate"] > 0
    assert main(argv) == 0


def test_a_surface_result_names_its_best_finite_mode_once(capsys):
    """The best finite mode of a surface result heads its runners-up in the record; the
    text shows it on the wrinkle line and lists the next ones after it, not it again. It is
    the first of the scanned modes only (shorter waves tend to the surface value, none is
    first among all), and the line says so with the ranges of the record."""
    argv = ["critical", "--outer-radius", "2", "--length", "1", "--solve-for", "voltage"]
    rec = _json(capsys, argv)
    assert rec["kind"] == "surface"
    w = rec["wrinkle"]
    assert {k: rec["runners_up"][0][k] for k in ("m", "n", "value")} == {
        k: w[k] for k in ("m", "n", "value")
    }
    assert main(argv) == 0
    lines = capsys.readouterr().out.splitlines()
    best = f"(m, n) = ({w['m']}, {w['n']})"
    (wline,) = [line for line in lines if line.startswith("  wrinkle (linear analysis): ")]
    assert wline.startswith("  wrinkle (linear analysis): " + best)
    (m0, m1), (n0, n1) = rec["m_range"], rec["n_range"]
    assert wline.endswith(f"(the first of the scanned m = {m0}..{m1}, n = {n0}..{n1})")
    nxt = [line for line in lines if line.startswith("  next: ")]
    assert len(nxt) == len(rec["runners_up"]) - 1 and not any(best in line for line in nxt)


FILM_8000 = """length = 170.0
[[layers]]
outer_radius = 1.0026
shear_modulus = 8000.0
[[layers]]
outer_radius = 2.7
"""


def test_the_verdict_line_and_json_meaning_keep_the_onset_s_digits(tmp_path, capsys):
    """Probe 12b, D2: the verdict line and the JSON ``meaning`` read "at growth[1] = 1", the
    start of the march, for a film's onset 1.00027786548 (estimate 5e-12): the verdict
    printed 4 digits. Now the digits the estimate supports, as the headline."""
    film = tmp_path / "film.toml"
    film.write_text(FILM_8000)
    argv = ["critical", "--tube", str(film), "--solve-for", "growth", "--layer", "1"]
    argv += ["--mode", "1", "1"]
    rec = _json(capsys, argv)
    assert "(1, 1) wrinkles smoothly at growth[1] = 1.00027786548 (" in rec["meaning"]
    assert main(argv) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if "verdict:" in x)
    assert "(1, 1) wrinkles smoothly at growth[1] = 1.00027786548 (" in line, line
