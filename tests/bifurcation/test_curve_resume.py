"""An interrupted curve resumed: its finished grid points taken back (``resume=``) give the
curve an uninterrupted run gives, computing only the rest; the points' records (the file
the command line keeps them in) read back exactly and refuse anything else."""

import json
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from electrogrowth import Tube
from electrogrowth.bifurcation import curves
from electrogrowth.bifurcation.curve_record import CurvePoint, point_of, point_record
from electrogrowth.bifurcation.scan import ScanOptions
from electrogrowth.errors import ParameterError
from electrogrowth.interrupts import Interrupted
from electrogrowth.outcomes import Status
from tests.interrupting import interrupt_scan_at

TUBE = Tube.uniform(1.4)
GRID = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]
OPTIONS = ScanOptions((0, 4), (1, 3))


def _curve(monkeypatch=None, stop_at=None, **kwargs):
    """The curve of growth along the voltage; with ``stop_at``, interrupted at that scan."""
    if stop_at is not None:
        interrupt_scan_at(monkeypatch, stop_at)
    return curves.critical_curve(TUBE, "growth", "voltage", GRID, options=OPTIONS, **kwargs)


@pytest.mark.parametrize("follow", [True, False])
def test_a_resumed_curve_is_the_uninterrupted_one(monkeypatch, follow):
    whole = _curve(follow=follow)
    with pytest.raises(Interrupted) as stop:
        _curve(monkeypatch, stop_at=2 if follow else 4, follow=follow)
    monkeypatch.undo()
    partial = stop.value.partial
    done = len(partial.grid)
    assert 0 < done < len(GRID) and partial.x.tolist() == GRID[:done]
    computed = []
    resumed = _curve(resume=partial, follow=follow, progress=computed.append)
    assert len(computed) == len(GRID) - done  # only the rest was computed
    assert resumed.x.tolist() == whole.x.tolist()
    assert resumed.m.tolist() == whole.m.tolist() and resumed.n.tolist() == whole.n.tolist()
    assert resumed.value == pytest.approx(whole.value, rel=1e-12)
    assert resumed.switches == whole.switches


def test_every_grid_point_carries_its_error_estimate():
    """Followed points too (check round 16c: NaN where the point was followed, not
    scanned): the estimate of the critical value solved there."""
    grid = _curve().grid
    assert len(grid) == len(GRID)
    for pt in grid:
        assert 0 <= pt.error_estimate <= 1e-10 * abs(pt.value), pt


def test_a_curve_of_another_tube_is_not_resumed():
    partial = curves.grid_curve("voltage", "growth", None, Tube.uniform(1.5), [])
    with pytest.raises(ParameterError, match="resume is a curve of another tube"):
        _curve(resume=partial)


def test_only_the_leading_points_at_the_grid_s_values_are_taken():
    point = CurvePoint(0.05, 1.3, (0, 1), "bifurcation")
    partial = curves.grid_curve("voltage", "growth", None, TUBE, [point])
    computed = []
    _curve(resume=partial, progress=computed.append)
    assert len(computed) == len(GRID)  # x = 0.05 is no point of this grid


numbers = st.floats(allow_nan=True, allow_infinity=False, width=64)
modes = st.tuples(st.integers(-1, 2000), st.integers(-1, 2000))
points = st.builds(
    CurvePoint,
    numbers,
    numbers,
    modes,
    st.sampled_from(["", "bifurcation", "threshold", "surface"]),
    st.sampled_from(list(Status)),
    st.lists(st.tuples(st.integers(0, 99), st.integers(0, 99), numbers), max_size=4).map(tuple),
    st.booleans(),
    numbers,
    numbers,
    *[
        st.text(
            st.characters(exclude_categories=["C", "Z"], include_characters=" \n\t"), max_size=20
        )
    ]
    * 4,
)


@given(points)
def test_a_point_s_record_reads_back_exactly(pt):
    back = point_of(json.loads(json.dumps(point_record(pt))))
    assert point_record(back) == point_record(pt)
    assert back.traceback == pt.traceback


@pytest.mark.parametrize(
    "change",
    [
        {"x": "1.0"},
        {"value": True},
        {"mode": [1]},
        {"mode": [1.5, 2]},
        {"kind": "crease"},
        {"status": "fine"},
        {"surface": 1},
        {"runners_up": [[1, 2]]},
        {"runners_up": [[1, 2, "3"]]},
        {"runners_up": 5},
        {"message": 3},
        {"message": "\x1b[2J"},
        {"extra": 1},
        {"unstable_row": [2, 1]},
        {"unstable_row": [2, 1, -1]},
        {"unstable_row": "2, 1, 0"},
    ],
)
def test_a_record_that_is_no_point_is_refused(change):
    record = point_record(CurvePoint(0.1, 1.2, (2, 1), "bifurcation", runners_up=((3, 1, 1.3),)))
    with pytest.raises(ValueError):
        point_of({**record, **change})


def test_a_failed_points_unstable_mode_reads_back_and_old_records_still_read():
    """The mode an UnstableAtStart scan found unstable locates the end of a design's valid
    range (bifurcation/start_edge.py): a resumed curve keeps it. Records written before it
    existed have no such field and read as ()."""
    pt = CurvePoint(0.7, math.nan, (-1, -1), "", "failed", failure="UnstableAtStart",
                    unstable_row=(2, 1, 0))  # fmt: skip
    record = json.loads(json.dumps(point_record(pt)))
    assert point_of(record).unstable_row == (2, 1, 0)
    del record["unstable_row"]
    assert point_of(record).unstable_row == ()
