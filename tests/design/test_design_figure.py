"""The figure of a two-variable design (figures/design.py): the map and, beside it, the
chosen design's wrinkled tube in 3D, drawn from a mode shape solved again at the design."""

from __future__ import annotations

import io

import numpy as np
import pytest
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d import Axes3D

from electrogrowth import ScanOptions, Tube
from electrogrowth.design import mode_map, prescribe_map
from electrogrowth.figures.design import design_shape, plot_map_pattern

TUBE = Tube.uniform()  # uncharged, ungrown, compressed axially (as tests/design/test_mode_map)
NEAR = ScanOptions((0, 1), (1, 1), extend=False)
VARY = (("outer_radius", 1.2, 1.3), ("length", 0.95, 1.05))


@pytest.fixture(scope="module")
def design():
    mmap = mode_map(TUBE, "stretch", VARY, side="compression", points=2, options=NEAR, certify=1)
    return prescribe_map(TUBE, (0, 1), mmap, options=NEAR)


def test_design_shape_is_the_target_mode_at_the_design(design):
    shape = design_shape(design, TUBE)
    assert design.status == "found" and (shape.m, shape.n) == design.mode == (0, 1)
    at = shape.params  # the tube at the critical point: the design's (R_o, L) and its value
    assert at.outer_radius == design.x and at.length == design.y
    assert at.stretch == pytest.approx(design.value, abs=1e-8)  # solved again, from scratch
    assert shape.boundary_residual < 1e-6  # an eigenmode there: the faces free of traction


def test_map_and_pattern_side_by_side(design):
    fig = plot_map_pattern(design, TUBE)
    assert isinstance(fig, Figure)
    panels = [ax for ax in fig.axes if ax.get_label() != "<colorbar>"]
    flat = [ax for ax in panels if not isinstance(ax, Axes3D)]
    wall = [ax for ax in panels if isinstance(ax, Axes3D)]
    assert len(flat) == 1 and len(wall) == 1
    assert wall[0].collections, "the 3D wall is drawn"
    assert "(0, 1)" in wall[0].get_title()
    (x0, x1), (y0, y1) = design.map.box
    assert flat[0].get_xlim() == (x0, x1) and flat[0].get_ylim() == (y0, y1)
    fig.savefig(io.BytesIO(), format="png")  # drawing is where a mathtext label would fail


def test_no_design_says_so(design):
    import dataclasses
    import math

    none = dataclasses.replace(design, mode=None, x=math.nan, y=math.nan)
    assert design_shape(none, TUBE) is None
    fig = plot_map_pattern(none, TUBE)
    texts = [t.get_text() for ax in fig.axes for t in ax.texts]
    assert "no design to draw" in texts


def test_stored_map_and_design_read_back_as_written(design):
    """A map and its design written as JSON and read back (design/map_record.py
    ModeMap.from_dict, design/prescribe_map.py stored_design) are the same records: the
    gallery draws a map traced once and stored, without tracing it again."""
    import json

    from electrogrowth.design.map_record import ModeMap
    from electrogrowth.design.prescribe_map import stored_design

    text = json.dumps({"map": design.map.as_dict(), "design": design.as_dict()})
    back = json.loads(text)
    mmap = ModeMap.from_dict(back["map"])
    assert mmap.as_dict() == design.map.as_dict()
    again = stored_design(back["design"], mmap, (0, 1))
    assert again.as_dict() == design.as_dict()
    assert again.region and all((0, 1) in (b.left, b.right) for b in again.region)
    xs, ys = np.linspace(1.2, 1.3, 7), np.linspace(0.95, 1.05, 7)
    assert (mmap.raster(xs, ys) == design.map.raster(xs, ys)).all()


@pytest.mark.parametrize(
    "broken",
    [{}, {"vary": [["outer_radius", 1.2]]}, {"vary": "x"}],
)
def test_a_malformed_stored_map_is_a_value_error(broken):
    from electrogrowth.design.map_record import ModeMap

    with pytest.raises(ValueError, match="not a stored mode map"):
        ModeMap.from_dict(broken)
