"""A case without growth and voltage against a classical result: a thin neo-Hookean tube in
plane strain under external hydrostatic (follower) pressure, mode (2, 0), against the
inextensible elastic ring (docs/postbuckling.md, "A classical check"):

* onset: Levy's p_c = 3 D / R^3 with D = E' h^3 / 12, E' = E / (1 - nu^2) = 4 mu for the
  incompressible solid in plane strain, so p_c = mu (h / R)^3, R the mid radius;
* post-buckling: the elastica's p / p_c = 1 + (27/32) (a / R)^2 + ... (derived in the docs,
  Poincare-Lindstedt on Levy's equation), and its whole branch up to the contact of the
  opposite sides at p = 5.247 D / R^3 (Flaherty, Keller and Rubinow 1972), by shooting
  (ring_elastica.py).

The pressure is the outer minus the inner: the control is P_i, lowered from P_o = 0
(``side="compression"``); the shear modulus mu = 1 / h^3 puts p_c near 1.
"""

import numpy as np
import pytest

from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.model.layers import Layer, Tube

from .ring_elastica import Elastica


def ring(h: float) -> Tube:
    return Tube((Layer(1 + h, shear_modulus=h**-3),), stretch=1.0)


def levy(h: float) -> float:
    """mu (h / R)^3, the thin ring's p_c = 3 D / R^3."""
    return h**-3 * (h / (1 + h / 2)) ** 3


def test_onset_tends_to_levys_at_second_order():
    """The package's exact onset of the thick tube over mu (h / R)^3: 1 + 0.48 h^2 ...
    (measured 1.19e-3, 3.05e-4, 7.72e-5 at h = 0.05, 0.025, 0.0125); mode 3 at 8/3 of it."""
    hs = (0.05, 0.025, 0.0125)
    err = []
    for h in hs:
        p2 = -critical_value(ring(h), 2, 0, "pressure", side="compression").value
        err.append(p2 / levy(h) - 1)
    assert all(0 < e < 0.5 * h**2 for e, h in zip(err, hs))
    orders = np.log2(np.array(err[:-1]) / np.array(err[1:]))
    assert orders == pytest.approx(2.0, abs=0.05)
    p3 = -critical_value(ring(hs[-1]), 3, 0, "pressure", side="compression").value
    assert p3 / levy(hs[-1]) == pytest.approx(8 / 3, rel=1e-3)


def test_elastica_initial_coefficient():
    """The shooting solution's (p / p_c - 1) / a^2 at a = 1e-3 is the expansion's 27/32
    (the next term is O(a^2))."""
    p = Elastica().pressure(1e-3)
    assert (p / 3 - 1) / 1e-6 == pytest.approx(27 / 32, rel=1e-5)


@pytest.mark.slow
def test_elastica_contact_pressure_is_the_published_one():
    """Flaherty, Keller and Rubinow (1972): the opposite sides of the mode-2 ring meet at
    p = 5.247 D / R^3; measured 5.246887 at a = 0.684773 R."""
    p, a = Elastica().contact()
    assert p == pytest.approx(5.247, abs=5e-4)
    assert a == pytest.approx(0.684773, abs=1e-6)


@pytest.mark.slow
def test_thick_ring_branch_tends_to_the_elastica():
    """The FE branch (4 and 3 elements through h = 0.1 and 0.05, 16 along pi/2), p over its
    own onset against the elastica at the same a / R, a/R from 0.098 to the contact 0.6848:
    measured differences -2.8e-4 .. -2.70e-2 (h = 0.1) and -6.9e-5 .. -6.61e-3 (h = 0.05),
    a factor 4.06-4.09 at every point: second order in h / R. Richardson's extrapolation
    of the two meets the elastica within 2e-4, and puts p at the contact amplitude at
    5.2479 D / R^3 (5.2122 at h = 0.05): the published 5.247."""
    pytest.importorskip("skfem")
    from electrogrowth.postbuckle.api import postbuckle

    elastica = Elastica()
    a_contact = 0.6847728793
    ratio, exact = {}, None
    for h, density, radial in ((0.1, 30.0, 4), (0.05, 40.0, 3)):
        R = 1 + h / 2
        res = postbuckle(
            ring(h),
            2,
            "pressure",
            side="compression",
            amplitude=a_contact * R,
            points=7,
            density=density,
            hoop=16,
        )
        assert res.ended == "" and res.face == "inner" and res.mesh.radial == (radial,)
        # the quarter's 16 elements: 3.6e-4 and 1.18e-3 above (9e-5 with 32 at h = 0.05)
        assert res.onset_fe == pytest.approx(res.onset_linear, rel=1.5e-3)
        # supercritical and stable all the way (the ring stiffens as it flattens)
        assert np.all(res.eigenvalue[1:] > 0) and res.secondary == ()
        ratio[h] = res.control[1:] / res.onset_fe
        if exact is None:  # the same a / R for both rings
            exact = np.array([elastica.pressure(a) / 3 for a in res.amplitude[1:] / R])
    diff = {h: r / exact - 1 for h, r in ratio.items()}
    assert np.all(np.abs(diff[0.05]) < 7e-3)
    assert np.all((diff[0.1] / diff[0.05] > 3.8) & (diff[0.1] / diff[0.05] < 4.3))
    extrapolated = (4 * ratio[0.05] - ratio[0.1]) / 3
    assert extrapolated == pytest.approx(exact, rel=5e-4)
    # p at the contact, units D / R^3 = p_c / 3
    assert 3 * extrapolated[-1] == pytest.approx(5.247, abs=2e-3)
