"""Collocation's error estimate on a very thin, very stiff film at a large fold number.

A neo-Hookean film [1, 1.003] with shear modulus 1e4 on a neo-Hookean substrate to
Rbar_o = 2 (modulus 1), hoop growth of the film, prismatic mode (379, 0). The reference
g_theta,cr = 2.77728873 comes from the impedance method (estimate 5e-10) and agrees with
Chebyshev collocation at 96 and 128 nodes per layer to 2e-9 (2.77728873079, 2.77728873312).

Found by probing: ``method="collocation"`` returned 2.777286747 with status OK and an error
estimate of 2e-10, 2.0e-6 below the reference. Its first solve (56 nodes) was not certified,
so it was solved again at rtol / 100, where the fine target (1e-14) and its second resolution
(1e-12) both took 56 nodes: the "error estimate" was Brent's tolerance. The second resolution
of collocation is now 3/4 of its nodes, and rtol < 1e-13 takes 72 nodes: the value is
2.7772887084 (72 nodes), its estimate 3.3e-6 covers the distance to the reference (2e-8),
and the status says the tolerance is missed. About 10 s.
"""

import pytest

from electrogrowth import Layer, Status, Tube, critical_value

FILM = Tube((Layer(1.003, shear_modulus=1e4), Layer(2.0)), length=1.0, stretch=1.0)
REFERENCE = 2.77728873
REFERENCE_ERROR = 5e-9


@pytest.mark.slow
def test_collocation_value_within_its_estimate_on_a_thin_stiff_film():
    crit = critical_value(FILM, 379, 0, "growth[1].theta", method="collocation")
    off = abs(crit.value - REFERENCE)
    assert off <= crit.error_estimate + REFERENCE_ERROR
    if crit.status is Status.OK:
        assert off <= 1e4 * 1e-12 * abs(crit.value) + REFERENCE_ERROR
    else:
        assert crit.status is Status.INACCURATE
