"""A march whose states are unresolved from its first step on says it examined nothing.

Before, a control that stopped at its start read "no mode bifurcates for voltage from 0 up
to 0, and the base states past it are not resolved" (probe round 11b, a cubic energy's
voltage march): a range from 0 to 0 is no range, and the sentence claimed one was examined.
"""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.march import first_bifurcations
from electrogrowth.errors import ConvergenceError
from electrogrowth.incremental.targets import ImpedanceTarget


class _ResolvedAt:
    """The impedance target on the unloaded tube and at ``limit`` or below only: past it,
    the tables 'fail' as a cubic energy's did."""

    def __init__(self, limit: float):
        self.limit, self.inner = limit, ImpedanceTarget(1e-5)

    def __call__(self, state, modes):
        if state.tube.voltage > self.limit:
            raise ConvergenceError("base state not resolved by 1025 Chebyshev points")
        return self.inner(state, modes)


MODES = np.array([[2.0, 1.0], [0.0, 1.0]])


def test_a_march_unresolved_at_its_first_step_claims_no_range():
    with pytest.raises(ConvergenceError) as err:
        first_bifurcations(Tube.uniform(1.4, 1.0), "voltage", None, MODES, _ResolvedAt(0.0))
    text = str(err.value)
    assert "no mode could be examined past voltage = 0: " in text
    assert "up to" not in text and "1025 Chebyshev points" in text


def test_a_march_unresolved_later_names_the_range_it_examined():
    with pytest.raises(ConvergenceError) as err:
        first_bifurcations(Tube.uniform(1.4, 1.0), "voltage", None, MODES, _ResolvedAt(0.05))
    text = str(err.value)
    assert "no mode bifurcates for voltage from 0 up to 0.0" in text
    assert "not resolved" in text
