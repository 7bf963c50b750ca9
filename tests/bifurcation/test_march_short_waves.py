"""A single mode's march must find short axial waves unstable only in a narrow window.

Found by probe12b (D6): ``critical_value`` raised NoBifurcationFound ("no mode bifurcates for
growth between 1 and 6") for short waves near the mode cap, whose targets are negative only
on a window narrower than the march's steps:

* Tube.uniform(3, L 1), (0, 2000): negative on [2.253531, 2.25358] (5e-5). The march
  predicted the zero (2.253531) and stepped 0.1 of the distance past it, to 2.253585, where
  the target is positive again; the dip test (a sample below 0.25 of both neighbours) did not
  fire (1.3e-14 between 1.4e-13 and 3.7e-14). Now a step that passes a predicted zero and
  lands positive is examined by a bounded minimisation (march.overstepped).
* Tube.uniform(100, L 1), (0, 1400): the same, 2.253543 .. 2.253595.
* A film ring (film 1e-3 thick, 100 times as stiff), (0, 2000) "growth[1]": negative on
  [1.7643, 1.779], between the march's samples 1.76 and 1.81; its bounded target keeps its
  size (2.4e-9) through both roots, so no sample sees the window coming. The window lies
  next to the mode's ray limit (surface.ray_limit: x_s = 1.7678), where the march now looks
  when it finds nothing (critical._surface_window). Root by the probe's bracketed solve:
  1.764323161. The same for a film 2e-3 thick, 1000 times as stiff, whose windows of
  (0, 2000) and (2000, 2000) begin just past their ray limits.
"""

import numpy as np
import pytest

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.bifurcation.along import TubeAt, root_mode
from electrogrowth.bifurcation.march import ONE_MODE_STEPS, first_bifurcations
from electrogrowth.incremental.targets import ImpedanceTarget

RING = Tube([Layer(1.001, shear_modulus=100.0), Layer(2.5)], length=1.0)
STIFF = Tube([Layer(1.002, shear_modulus=1000.0), Layer(3.0)], length=1.0)


def test_a_step_past_a_predicted_zero_is_examined():
    """The march alone (no fall-back on the ray limit) finds the 5e-5 window of (0, 2000)."""
    mode = np.array([[0.0, 2000.0]])
    res = first_bifurcations(
        Tube.uniform(3, length=1.0),
        "growth",
        None,
        mode,
        ImpedanceTarget(1e-8),
        brent_targets=ImpedanceTarget(1e-12),
        steps=ONE_MODE_STEPS,
    )  # raised NoBifurcationFound
    assert 2.253530 < res.found[0].value < 2.253535


def test_thick_tube_short_wave():
    t = Tube.uniform(100, length=1.0)
    assert abs(critical_value(t, 0, 1300, "growth").value - 2.2535428) < 1e-6
    c = critical_value(t, 0, 1400, "growth")  # raised NoBifurcationFound
    assert abs(c.value - 2.25355) < 2e-5


def test_film_ring_window_next_to_its_ray_limit():
    c = critical_value(RING, 0, 2000, "growth[1]")  # raised NoBifurcationFound
    assert abs(c.value - 1.764323161) < 1e-8
    assert c.error_estimate < 1e-8


@pytest.mark.parametrize("m, n", [(0, 2000), (2000, 2000)])
def test_stiff_film_window_past_its_ray_limit(m, n):
    c = critical_value(STIFF, m, n, "growth[1]")  # raised NoBifurcationFound
    g = root_mode(TubeAt(STIFF, "growth[1]"), ImpedanceTarget(1e-12), np.array([[m, n]]), 1.0)
    w = 1e-6 * c.value
    assert g(c.value - w) * g(c.value + w) < 0  # a root of the mode's own target
    assert 2.17 < c.value < 2.25
