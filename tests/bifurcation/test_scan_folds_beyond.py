"""A scan must not report the exact short-wave limit as the first instability while a
finite mode within the supported range comes much earlier.

A neo-Hookean film [1, 1.0003] with shear modulus 3 on a neo-Hookean substrate to
Rbar_o = 1.5 (modulus 1), L = 2, hoop growth of the film. The film folds at a finite
wavelength near m ~ 1 / (h (3 / 3)^(1/3)) = 3300, beyond the cap m = 2000, so the supported
modes fall towards the cap: (1998, 0) 1.30679977, (1999, 0) 1.30673526, (2000, 0)
1.30667084 (impedance, single modes). The short-wave limit of the film's free face is
g_theta = 1.84731269, far later.

Found by probing: ``scan_modes`` returned kind "surface" at 1.84731269 (the inner face)
with m_range (0, 12): the modes scanned mode by mode (the best, (1, 120) at 2.4499, a
probe of short axial waves) all come after the limit, and the scan takes the limit for
the infimum without searching m beyond 64, although a thin film's folds lie below the
limit at a finite wavelength (the runs with the fold inside the range, m = 640 ... 1567,
search and find it). Expected: (2000, 0) at the cap, about 1.30667, with the limit a
runner-up. Now, where the limit comes before the scanned modes, the folds beyond the scan
(geometric samples of m up to 2000) are read at the limit's state, and searched if one is
unstable there. About 7 s.

Found by probing (2026-12-05): the result at the cap had status OK in Python, although
the true first fold (near m = 3300) comes before it; only the CLI warned. Then its status
was INACCURATE with a message saying why, and the CLI exited 3 with one warning: the tests
with every tube's caps at 2000 (``caps_of_2000``) keep that for a layer thinner than its
caps. Now each tube's caps are chosen by its thinnest layer (options.mode_caps: 213397
here), and the scan finds the fold (3018, 0) at 1.27921022715, status ok.
"""

import numpy as np
import pytest

from electrogrowth import Layer, Tube, critical_value, scan_modes
from electrogrowth.bifurcation.options import M_CAP, N_CAP, mode_caps
from electrogrowth.cli.app import main
from electrogrowth.cli.report import edge_warning

FILM = Tube((Layer(1.0003, shear_modulus=3.0), Layer(1.5)), length=2.0, stretch=1.0)


@pytest.fixture
def caps_of_2000(monkeypatch):
    """Every tube's caps at 2000, as before each tube had its own (options.mode_caps)."""
    import electrogrowth.bifurcation.beyond as beyond
    import electrogrowth.bifurcation.scan as scan

    monkeypatch.setattr(scan, "mode_caps", lambda tube: (M_CAP, N_CAP))
    monkeypatch.setattr(beyond, "mode_caps", lambda tube: (M_CAP, N_CAP))


def test_the_film_is_scanned_to_its_fold_past_2000():
    """The film's own caps (213397, 135812) take the search past 2000 to the least of the
    prismatic row, (3018, 0), near the flat film's 1 / (h (3 / 3)^(1/3)) = 3333 (the tube's
    curvature and pre-strain move it); its neighbours by single modes lie on a parabola
    whose least integer it is, and (2000, 0) comes 0.027 later."""
    scan = scan_modes(FILM, "growth[1].theta")
    c = scan.critical
    assert scan.caps == mode_caps(FILM) == (213397, 135812)
    assert (c.kind, c.m, c.n, c.status) == ("bifurcation", 3018, 0, "ok")
    assert c.value == pytest.approx(1.2792102271465, rel=1e-11)
    ms = np.arange(3015, 3022)
    vs = np.array([critical_value(FILM, int(m), 0, "growth[1].theta").value for m in ms])
    assert ms[np.argmin(vs)] == 3018 and vs.min() == pytest.approx(c.value, rel=1e-12)
    assert critical_value(FILM, 2000, 0, "growth[1].theta").value > c.value + 0.02


def test_scan_prefers_the_capped_fold_to_a_later_short_wave_limit(caps_of_2000):
    cap = critical_value(FILM, 2000, 0, "growth[1].theta")
    scan = scan_modes(FILM, "growth[1].theta")
    assert scan.critical.value <= cap.value + 1e-9
    assert (scan.critical.kind, scan.critical.m, scan.critical.n) == ("bifurcation", 2000, 0)
    assert scan.critical.status == "inaccurate"  # the fold lies beyond the cap: said
    assert "(2000, 0) sits at the largest m = 2000 the scan searched" in scan.critical.message
    assert "1.84731" in scan.critical.message  # the limit, later
    assert edge_warning(scan) == ""  # the status says it, not a second warning


def test_the_cli_exits_3_at_the_cap_with_one_warning(tmp_path, capsys, caps_of_2000):
    tube = tmp_path / "film.toml"
    tube.write_text(
        "length = 2.0\nstretch = 1.0\n[[layers]]\nouter_radius = 1.0003\n"
        "shear_modulus = 3.0\n[[layers]]\nouter_radius = 1.5\n"
    )
    args = [
        "critical",
        "--tube",
        str(tube),
        "--solve-for",
        "growth",
        "--layer",
        "1",
        "--component",
        "theta",
    ]
    assert main(args + ["--quiet"]) == 3
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "not certified: the critical mode (2000, 0)" in err[0]
    assert main(args + ["--quiet", "--accept-inaccurate", "--json"]) == 0
