"""The classical reference for a ring under external hydrostatic pressure: the inextensible
elastic ring (the elastica; Levy 1884, Carrier 1947, Flaherty, Keller and Rubinow 1972),
solved here by shooting, independently of the package.

Units R = D = 1 (R the ring's radius, D its bending stiffness), s the arc length
(= the reference angle Theta: the ring is inextensible), psi the tangent's angle,
kappa = psi'. Equilibrium with the follower pressure p (docs/postbuckling.md):

    kappa'' + kappa^3 / 2 - sigma kappa - p = 0,

sigma a constant of the hoop force (T = sigma - kappa^2 / 2). Mode 2 (the ring's first)
is symmetric about both axes: the quarter s in [0, pi/2] starts on the x axis
(psi = pi/2, kappa' = 0, kappa = kappa_0) and ends on the y axis (psi = pi, kappa' = 0).
Given kappa_0, Newton finds (p, sigma); the amplitude a = (u_R(0) - u_R(pi/2)) / 2 =
(x(0) - y(pi/2)) / 2 is the finite-element model's, read at the two rays.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, fsolve

QUARTER = np.pi / 2


def _shoot(kappa0: float, p: float, sigma: float) -> np.ndarray:
    """(psi - pi, kappa', x, y) at s = pi/2, starting from the origin on the x axis."""

    def rhs(s, y):
        psi, k, dk, _, _ = y
        return [k, dk, -(k**3) / 2 + sigma * k + p, np.cos(psi), np.sin(psi)]

    sol = solve_ivp(rhs, (0, QUARTER), [QUARTER, kappa0, 0, 0, 0], rtol=1e-12, atol=1e-13)
    psi, _, dk, x, y = sol.y[:, -1]
    return np.array([psi - np.pi, dk, x, y])


class Elastica:
    """The mode-2 branch, continued in kappa_0 from the circle (kappa_0 = 1, p = 3)."""

    def __init__(self):
        self._known = {1.0: (3.0, 0.5 - 3.0)}

    def point(self, kappa0: float) -> tuple[float, float, float]:
        """(p, a, y(pi/2)) at curvature kappa_0 on the x axis."""
        start = max(k for k in self._known if k <= kappa0)
        for k in [*np.arange(start, kappa0, 0.05)[1:], kappa0]:
            near = self._known[min(self._known, key=lambda q: abs(q - k))]
            found = fsolve(lambda v, k=k: _shoot(k, *v)[:2], near, xtol=1e-13, full_output=True)
            self._known[k] = tuple(found[0])
        p, sigma = self._known[kappa0]
        _, _, x, y = _shoot(kappa0, p, sigma)
        x0 = -x  # the quarter placed so that it ends on the y axis
        return float(p), float((x0 - y) / 2), float(y)

    def pressure(self, a: float) -> float:
        """p R^3 / D at amplitude a (units R)."""
        # kappa_0 - 1 = 3 a at small a, 4.27 a at the contact
        k = brentq(lambda k: self.point(k)[1] - a, 1 + 2.9 * a, 1 + 4.5 * a, xtol=1e-13)
        return self.point(k)[0]

    def contact(self) -> tuple[float, float]:
        """(p, a) where the ring's opposite sides meet at its centre, y(pi/2) = 0."""
        k = brentq(lambda k: self.point(k)[2], 3.5, 4.0, xtol=1e-12)
        p, a, _ = self.point(k)
        return p, a
