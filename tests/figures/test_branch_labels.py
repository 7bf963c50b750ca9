"""A branch's label in a curve's plot (figures/plots.py) stays inside its axes."""

import math

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.curve_record import Curve
from electrogrowth.figures.plots import plot_curve


def _surface_curve(values):
    """A curve of the exact short-wave limit at the outer face along outer_radius."""
    rows = len(values)
    return Curve(
        "outer_radius", "stretch", "extension", np.linspace(1.2, 2.0, rows),
        np.array(values, float), np.full(rows, -1), np.full(rows, -1),
        np.array(["surface"] * rows), ("ok",) * rows, (), Tube.uniform(1.2, voltage=0.4),
        np.ones(rows, bool), np.array(values, float), surface_face=("outer",) * rows,
    )  # fmt: skip


@pytest.mark.parametrize("sign", [1, -1])
def test_the_label_at_an_extreme_of_the_curve_is_inside_the_axes(sign):
    """Check round 29 (cosmetic): Fig. 7 (extension, Vbar = 0.4) drew "m, n → ∞" 10
    points below its curve's middle, which is the curve's lowest point: on the x-axis line.
    At a minimum it goes above the line, at a maximum below, inside the axes either way."""
    x = np.linspace(-1, 1, 17)
    curve = _surface_curve(2.455 + sign * 0.012 * x**2)  # Fig. 7's range, extreme at the middle
    ax = plot_curve(curve)
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(ax.figure).get_renderer()
    ax.figure.draw(renderer)  # the constrained layout placed, as when saved
    (label,) = [t for t in ax.texts if t.get_text() == "m, n → ∞"]
    box, frame = label.get_window_extent(renderer), ax.get_window_extent(renderer)
    assert frame.y0 < box.y0 and box.y1 < frame.y1, (box, frame)
    assert math.copysign(1, label.xyann[1]) == sign  # above a minimum, below a maximum
