"""The published post-buckling sequence of a stiff film on a soft substrate compressed as a
whole (Brau et al. 2011; Cao and Hutchinson 2012: neo-Hookean film and substrate, plane
strain, no pre-stretch): sinusoidal wrinkles at the wrinkling strain, then period
doubling at a nominal compression of about 0.2, read here as [0.15, 0.25) (the precision
of one significant digit). Its counterpart in the package (docs/postbuckling.md, "The
published sequence"): a thin film (mu_f / mu_s = 100) lining a thick tube under an external
pressure, the compression read off the far field (postbuckle/strain.py)."""

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.basestate.tube import solve_base_state  # noqa: E402
from electrogrowth.model.layers import Layer, Tube  # noqa: E402
from electrogrowth.postbuckle.api import postbuckle  # noqa: E402
from electrogrowth.postbuckle.strain import compression_at, nominal_compression  # noqa: E402

#: the published period-doubling compression, about 0.2: one significant digit
PUBLISHED = (0.15, 0.25)


def graded_film(h: float, ratio: float, outer: float = 2.0) -> Tube:
    """A film [1, 1 + h] of shear modulus ``ratio`` on a substrate (mu = 1) to ``outer``,
    cut into layers doubling in thickness away from the film: with two elements each
    (the minimum), a mesh graded towards the film, where the wrinkles live."""
    radii, t = [1.0 + h], h
    while radii[-1] + 2 * t < outer:
        t *= 2
        radii.append(radii[-1] + t)
    radii.append(outer)
    layers = [Layer(r, shear_modulus=ratio if k == 0 else 1.0) for k, r in enumerate(radii)]
    return Tube(tuple(layers), stretch=1.0)


def test_graded_film_layers():
    tube = graded_film(0.008, 100.0)
    assert tube.radii[1] == pytest.approx(1.008) and tube.radii[-1] == 2.0
    assert np.diff(tube.radii)[1:-1] == pytest.approx(0.008 * 2.0 ** np.arange(1, 6))
    assert [layer.shear_modulus for layer in tube.layers] == [100.0] + [1.0] * 6


@pytest.mark.slow
def test_wrinkles_then_period_doubling_at_the_published_compression():
    """Film h = 0.008, mode m = 38 (the critical 37 within 5e-6 in the compression), in the
    sector 2 pi / 38 on 2 elements per layer and 4 per half wavelength (1723 unknowns), the
    branch in steps of 0.0055 in a. Measured: wrinkles at eps = 0.02393 (the package's
    0.02383), the branch stable and symmetric up to the period-doubling point at
    a = 0.02013, eps = 0.1853 (0.1856 on a mesh twice as fine; docs/postbuckling.md)."""
    tube = graded_film(0.008, 100.0)
    res = postbuckle(
        tube,
        38,
        "pressure",
        side="compression",
        amplitude=0.022,
        points=4,
        density=1.0,
        hoop=4,
        periods=2,
    )
    # the wrinkling strain, ~1/8 of the period doubling's: the FE onset's against the
    # package's linear one (the base state there), to the coarse mesh's 0.4 %
    linear = 1 - solve_base_state(tube.at("pressure", res.onset_linear)).radius(1.0)
    assert nominal_compression(res.section, res.states[0]) == pytest.approx(linear, rel=1e-2)
    first = res.secondary[0]
    assert first.kind == "period-doubling" and first.located and first.subharmonic > 0.99
    before = res.amplitude < first.amplitude
    assert np.all(res.eigenvalue[1:][before[1:]] > 0)  # stable wrinkles before it
    assert set(res.lowest_mode[1:3]) == {"symmetric"}
    assert res.lowest_mode[-1] == "period-doubling" and res.eigenvalue[-1] < 0
    eps = compression_at(res, first.amplitude)
    assert PUBLISHED[0] <= eps < PUBLISHED[1]
