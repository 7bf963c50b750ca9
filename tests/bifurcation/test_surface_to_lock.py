"""The short-wave limit of a Gent tube whose faces never wrinkle before the lock must end at
the lock, the same for every wall thickness.

An ungrown, uncharged tube compressed axially is homogeneous: lambda_r = lambda_theta =
lambda_z^(-1/2) through the wall, whatever Rbar_o, and a Gent solid locks where
I1 - 3 = lambda_z^2 + 2 / lambda_z - 3 = J_m (lambda_z = 0.28916854644831 for J_m = 4,
0.22346207166924 for J_m = 6). For J_m = 4 no face wrinkles before it (Biot's condition
alpha - gamma + 2 sqrt(alpha / gamma) (beta + gamma) = 0 has no root above the lock, in
either principal direction), and for J_m = 6 none in the hoop direction (psi = 0): the
limit is the loss of the state at the lock, kind "threshold" (surface.py: "a locking
stretch ... counts as lost"). The package's own scan reports that threshold to the last
digit (``scan_modes(Tube.uniform(3.0, material=gent(4.0)), "stretch")``:
0.28916854644830997).

Found by probing: ``short_wave_limit`` on the same homogeneous state gives
* Rbar_o = 3.0: kind "threshold" at 0.2891687178 (J_m = 4; 0.2234622232 for J_m = 6,
  psi = 0), 6e-7 above the lock, status OK, error estimate 0.0: where the base-state
  solver stops resolving the state at rtol 1e-12, not where the state ends;
* Rbar_o = 1.8: ConvergenceError "base state not resolved at stretch = 0.289168741703
  while marching from 1 (no surface instability before it)", in every direction;
* the energy text of the same Gent solid at Rbar_o = 3.0, psi = pi/2 or the worst
  direction: ConvergenceError "base-state profile not resolved".
"""

import math

import pytest
from scipy.optimize import brentq

from electrogrowth import Material, Tube, gent
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.bifurcation.state_loss import threshold_between
from electrogrowth.bifurcation.surface import short_wave_limit


def lock(jm: float) -> float:
    """The axial stretch at which the homogeneous compressed Gent tube locks."""
    return brentq(lambda lz: lz**2 + 2 / lz - 3 - jm, 0.05, 0.999, xtol=1e-16, rtol=1e-15)


GENT4_TEXT = Material("gent4-text", "-(4/2)*log(1-(I1-3)/4) + I5/2")


@pytest.mark.slow
@pytest.mark.parametrize(
    ("material", "jm", "outer_radius", "psi"),
    [
        (gent(4.0), 4.0, 1.8, None),
        (gent(4.0), 4.0, 3.0, None),
        (gent(6.0), 6.0, 1.8, 0.0),
        (gent(6.0), 6.0, 3.0, 0.0),
        (GENT4_TEXT, 4.0, 3.0, None),
    ],
)
def test_short_wave_limit_ends_at_the_lock(material, jm, outer_radius, psi):
    tube = Tube.uniform(outer_radius, 1.0, material=material)
    s = short_wave_limit(tube, "stretch", side="compression", psi=psi)
    assert s.kind == "threshold"
    assert s.value == pytest.approx(lock(jm), rel=1e-8)
    assert math.isfinite(s.error_estimate)


@pytest.mark.parametrize("material", [gent(4.0), GENT4_TEXT])
@pytest.mark.parametrize("landing", [-1e-3, 3e-7])
def test_loss_located_at_the_lock_wherever_the_step_lands(material, landing):
    # a march's step past the lock (-1e-3), or into the last LOCK_MARGIN before it (3e-7:
    # a state that exists and is not read): either way the loss is the lock, to rounding
    tube = Tube.uniform(3.0, 1.0, material=material)
    at = TubeAt(tube, "stretch", as_float=True)
    x_lock = lock(4.0)
    value, edge, pending = threshold_between(at, tube, x_lock * 1.001, x_lock * (1 + landing))
    assert pending is None
    assert value == pytest.approx(x_lock, rel=1e-13)
    assert x_lock < edge < x_lock * (1 + 1e-6)  # the last state read: clear of the lock
