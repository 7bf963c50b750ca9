"""A critical value is not read past a loss of strong ellipticity the axes do not show
(incremental/targets.py ``_lost_ellipticity``).

Mode (7, 4) of the dielectric bilayer (tests/incremental/test_halfspace.py) is marched past
growth 2.029, where its inner layer's hoop permittivity turns negative (a closed form) while
its six shear moduli stay above 0.17 of its own. The kernel fails at every state from there
(step size underflow, also at 1e-14), and the march went on on collocation, whose sign there
changes with its nodes (+, -, +, - at 40, 56, 72, 100 at growth 2.2965): a root at 2.2965,
estimate 9.3e-3, and another at 2.2773 at rtol 1e-14, "inaccurate" after 190 s (check round
24, D2).
"""

from __future__ import annotations

import pytest

from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.errors import ConvergenceError
from electrogrowth.incremental import targets
from tests.incremental.test_halfspace import CONTROL, DIELECTRIC_BILAYER


def test_the_march_stops_where_the_permittivity_turns_negative(monkeypatch):
    asked = []
    monkeypatch.setattr(targets, "collocation_targets", lambda *a, **k: asked.append(a))
    with pytest.raises(ConvergenceError, match="layer 1 at R = 1: a real wave vector") as err:
        critical_value(DIELECTRIC_BILAYER, 7, 4, CONTROL)
    assert asked == []  # no collocation value read (was: 126 states of the march)
    # the march examined every state up to the loss: it ends past growth 2.0
    last = float(str(err.value).split(" up to ")[1].split(",")[0])
    assert 2.0 < last < 2.1  # the edge, r_i = EDGE_STRETCH, is at growth 2.029
