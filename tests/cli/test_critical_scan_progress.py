"""A scan by `electrogrowth critical` (no --mode) says on a terminal that it is running.

Found by probing: a film-lined tube (a Gent film 0.00375 thick, 645 times as stiff as its
Gent substrate to Rbar_o = 3.44, L = 11.4, growing isotropically) takes 27 s to scan to its
rings (0, 168), and the command printed nothing on stderr all that time, under a terminal
too, while `pattern` names the same scan as a stage ("solving the critical mode (a scan of
the modes) ...") and the README promises that long commands report their progress. Thin
films take 30-60 s. The test uses a quick scan; what it checks is the report, not the time.
"""

import sys

from electrogrowth.cli.app import main

ARGV = [
    "critical", "--solve-for", "growth", "--outer-radius", "1.4", "--length", "1",
    "--voltage", "0.4", "--m-max", "3", "--n-max", "2",
]  # fmt: skip


def test_a_scan_names_its_stage_on_a_terminal(capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    assert main(ARGV) == 0
    out, err = capsys.readouterr()
    assert "mode (m, n) = (0, 1)" in out
    assert "electrogrowth:" in err and "scan" in err  # the stage is named while it runs
    assert main([*ARGV, "--quiet"]) == 0
    assert capsys.readouterr().err == ""
