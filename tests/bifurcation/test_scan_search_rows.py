"""The rows a scan searches beyond its ranges stay in their family's domain.

Found by the fast suite on a new machine (2026-12-05): the film on a Gent substrate of
tests/bifurcation/test_voltage_to_lock.py, critical in the prismatic mode (4, 0), had a ring
beyond its n range past its root at the last runner-up's value (beyond.py), and the search
along n took the critical mode's row with it: the prismatic family at m = 4, searched over
n, asked for (4, 1325) prismatic and ended the scan in "ParameterError: mode (m, n) =
(4, 1325) is not prismatic" (a rounding away from passing on the machine before). A
prismatic row is searched along m only (n = 0), a torsional row along n only (m = 0).
"""

from __future__ import annotations

import dataclasses

import pytest

from electrogrowth import ScanOptions, Tube, critical_value
from electrogrowth.bifurcation import scan
from electrogrowth.bifurcation.options import M_CAP, N_CAP
from electrogrowth.bifurcation.scan_record import ScanResult
from electrogrowth.errors import NoBifurcationFound
from electrogrowth.incremental.targets import Family

TUBE = Tube.uniform(1.4, 1.0, voltage=0.4)


@pytest.fixture(scope="module")
def onset():
    return critical_value(TUBE, 0, 1, "growth")


@pytest.mark.parametrize(
    "mode, family, axis, cap",
    [((4, 0), Family.PRISMATIC, "n", N_CAP), ((0, 3), Family.TORSIONAL, "m", M_CAP)],
)
def test_a_family_row_is_searched_only_along_its_own_axis(
    monkeypatch, onset, mode, family, axis, cap
):
    searched = []

    def search(params, solve_for, side, rows, edge, top, rtol, keep, **more):
        searched.extend(rows)
        raise NoBifurcationFound("none beyond")

    monkeypatch.setattr(scan, f"search_{axis}", search)
    crit = dataclasses.replace(onset, m=mode[0], n=mode[1], family=family)
    result = ScanResult(crit, (), (0, 12), (1, 30))
    rows = scan._search_rows(result, ScanOptions(), axis, ())
    edge = 12 if axis == "m" else 30
    out, at_top = scan._searched(
        TUBE, "growth", None, result, ScanOptions(), 1e-12, cap, axis, rows, edge
    )
    assert searched and all(code != family.code for _, code in searched)
    assert out.critical is crit and not at_top  # nothing beyond: the scan stands
