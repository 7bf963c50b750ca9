"""The march's last look where the states past its end do not resolve (march._last_look)."""

from types import SimpleNamespace

import numpy as np
import pytest

from electrogrowth.bifurcation.march import RETREAT_ROUNDS, _last_look
from electrogrowth.errors import ConvergenceError


def _signed(edge):
    """Targets g_i(x) = 1 - x + i that resolve only up to ``edge``."""

    def signed(x, idx):
        if x > edge:
            raise ConvergenceError(f"not resolved at {x}")
        return 1.0 - x + idx

    return signed


WATCH = SimpleNamespace(xa=np.array([0.2, 0.5, 0.4]), g=np.zeros((3, 3)), sense=1.0)
IDX = np.array([0, 1, 2])


def test_resolved_end_is_looked_at_as_it_is():
    assert _last_look(_signed(2.0), WATCH, IDX, 1.5)[0] == 1.5


def test_unresolved_end_retreats_to_the_edge():
    x, g = _last_look(_signed(1.2), WATCH, IDX, 1.5)
    # past every mode's last sample (0.5), at the edge to within 2^-RETREAT_ROUNDS of the gap
    assert 1.2 - (1.5 - 0.5) * 2.0**-RETREAT_ROUNDS <= x <= 1.2
    assert np.array_equal(g, 1.0 - x + IDX)


def test_nothing_resolved_past_the_last_samples_is_an_error():
    # the modes were last seen at 0.2, 0.5, 0.4: their old values are not one look at one x
    with pytest.raises(ConvergenceError):
        _last_look(_signed(0.5), WATCH, IDX, 1.5)
