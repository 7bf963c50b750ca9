"""Plots readable for any tube: titles wrapped inside the figure, no offset on the ticks,
control labels in words with units, isolated points drawn."""

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

from electrogrowth.figures.labels import axis_label
from electrogrowth.figures.style import new_figure, wrapped_title

LONG = (
    "2 layer(s) [R <= 1.1 neo-hookean mu 10 g [1.0, 1.2, 1.0]; R <= 2 gent(jm=97.2) mu 1"
    " g [1.0, 1.0, 1.0]], L = 3, lambda_z = 1, Vbar = 0.1, P_i = 0.05, P_o = 0"
)
MATH = (
    r"$(m, n) = (3, 1)$, $\bar R_o = 1.4$, $L = 1$, $g = 1.51163$, $\lambda_z = 1.2$,"
    r" $\bar V = 0.4$, $P_i = 0.05$, $P_o = 0$, neo-hookean, amplitude $0.1\,R_i$"
)


@pytest.mark.parametrize("text", [LONG, MATH])
@pytest.mark.parametrize("width", [3.0, 4.4, 7.0])
def test_a_wrapped_title_stays_inside_the_figure(text, width):
    fig, axes = new_figure(width, 3.0, 1, 1)
    wrapped_title(axes[0, 0], text, 8)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    box = axes[0, 0].title.get_window_extent(canvas.get_renderer())
    assert box.x0 >= 0 and box.x1 <= fig.bbox.x1 and box.y1 <= fig.bbox.y1
    assert axes[0, 0].title.get_text().count("$") % 2 == 0  # no math span cut
    for line in axes[0, 0].title.get_text().split("\n"):
        assert line.count("$") % 2 == 0


def test_ticks_show_values_not_an_offset():
    fig, axes = new_figure(4.0, 3.0, 1, 1)
    ax = axes[0, 0]
    ax.plot([1.1470, 1.1471, 1.1472], [2.00001, 2.00002, 2.00003])
    FigureCanvasAgg(fig).draw()
    assert ax.xaxis.get_major_formatter().get_offset() == ""
    assert ax.yaxis.get_major_formatter().get_offset() == ""


@pytest.mark.parametrize(
    "name, words",
    [
        ("growth[1].theta", r"growth $g_\theta$ of layer 1 (–)"),
        ("growth[2]", "growth factor $g$ of layer 2 (–)"),
        ("growth[1].r+theta", r"growth $g_{r,\theta}$ of layer 1 (–)"),
        ("layers[2].thickness", r"thickness $H_{2}$ of layer 2 ($R_i$)"),
        ("force", r"axial force $F$ ($\mu R_i^2$)"),
        ("pressure", r"inner pressure $P_i$ ($\mu$)"),
    ],
)
def test_controls_are_labelled_in_words_with_units(name, words):
    assert axis_label(name) == words


def test_critical_labels():
    assert axis_label("growth[1].theta", critical=True) == (
        r"critical growth $g_{\theta,\rm cr}$ of layer 1 (–)"
    )
    assert (
        axis_label("stretch", critical=True) == r"critical axial stretch $\lambda_{z,\rm cr}$ (–)"
    )


def test_a_branch_of_one_point_is_drawn():
    """A mode critical at one grid point only (a branch of one row) gets a marker: a line
    through one point draws nothing."""
    from types import SimpleNamespace

    from electrogrowth.figures.plots import plot_curve

    curve = SimpleNamespace(
        x=np.array([1.0, 1.1, 1.2]),
        value=np.array([2.0, 2.1, 2.2]),
        m=np.array([0, 2, 0]),
        n=np.array([1, 1, 1]),
        kind=np.array(["bifurcation"] * 3),
        surface=np.zeros(3, bool),
        switches=(),
        ends=(),
        along="stretch",
        solve_for="growth",
    )
    curve.branches = lambda: [
        ((0, 1), np.array([0])),
        ((2, 1), np.array([1])),
        ((0, 1), np.array([2])),
    ]
    ax = plot_curve(curve)
    drawn = [line for line in ax.get_lines() if len(line.get_xdata()) == 1]
    assert len(drawn) == 3 and all(line.get_marker() not in ("None", "", None) for line in drawn)
    assert {t.get_text() for t in ax.texts} == {"(0, 1)", "(2, 1)"}
