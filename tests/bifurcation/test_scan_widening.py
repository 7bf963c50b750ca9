"""A widened scan marches only the modes it has not seen, up to its top-th value.

The earlier march found the first ``top`` roots of its grid: every mode of both grids that
bifurcates before the top-th of them is among those, so the wider grid's new rows are
marched alone and only that far (grid_scan.reused). The merged result must be the one a
march of the whole wider grid gives: the same modes in the same order and the same values.
"""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth import Layer, Tube
from electrogrowth.bifurcation import grid_scan
from electrogrowth.bifurcation.scan_grid import scan_grid

#: a film 0.02 thick, 50 times stiffer than its substrate: folds at m = 23, beyond the
#: default m range (0, 12), so scan_modes widens it
FILM = Tube((Layer(1.02, growth=1.0), Layer(2.0, shear_modulus=0.02)), length=1.0)
CONTROL = "growth[1].theta"
FAMILIES = (True, True)
N_RANGE = (1, 30)


def _scan(m_top, known=None):
    return grid_scan.scan_once(
        FILM, CONTROL, None, (0, m_top), N_RANGE, 5, 1e-12, False, FAMILIES, known
    )


def _listed(result):
    c = result.critical
    return [(c.m, c.n, c.family, c.value)] + [
        (r.m, r.n, r.family, r.value) for r in result.runners_up
    ]


def _same(got, want):
    assert [row[:3] for row in got] == [row[:3] for row in want]
    np.testing.assert_allclose([r[3] for r in got], [r[3] for r in want], rtol=1e-12)


@pytest.fixture(scope="module")
def narrow():
    return _scan(12)


@pytest.fixture(scope="module")
def wide():
    return _scan(25)


def test_a_new_best_mode_is_found_among_the_new_rows(narrow, wide, monkeypatch):
    marched = []
    march = grid_scan.first_bifurcations

    def counted(params, solve_for, side, modes, targets, **kw):
        marched.append((len(modes), kw["until"]))
        return march(params, solve_for, side, modes, targets, **kw)

    monkeypatch.setattr(grid_scan, "first_bifurcations", counted)
    reused = _scan(25, (scan_grid((0, 12), N_RANGE, False, FAMILIES), narrow))
    assert (narrow.critical.m, wide.critical.m) == (12, 23)  # the best moved to a new row
    _same(_listed(reused), _listed(wide))
    # only the rows of m = 13 ... 25 were marched, and only up to the narrow scan's 5th value
    new_rows = len(scan_grid((0, 25), N_RANGE, False, FAMILIES)) - len(
        scan_grid((0, 12), N_RANGE, False, FAMILIES)
    )
    assert marched == [(new_rows, narrow.runners_up[-1].value)]


def test_the_best_mode_stays_when_the_new_rows_come_later(wide):
    reused = _scan(30, (scan_grid((0, 25), N_RANGE, False, FAMILIES), wide))
    _same(_listed(reused), _listed(_scan(30)))
    assert reused.critical is wide.critical  # the best of (0, 25) stands, not solved again


def test_nothing_is_reused_when_a_found_mode_is_not_a_row_of_the_new_grid(narrow):
    """A found mode outside the new grid (as a probe beyond the new ranges would be): the
    old rows' roots after the top-th value are not known, so the whole grid is marched."""
    probed = scan_grid((0, 12), N_RANGE, True, FAMILIES)
    smaller = scan_grid((0, 6), N_RANGE, False, FAMILIES)
    assert grid_scan.reused(smaller, (probed, narrow), 5) is None


def test_a_cut_march_whose_margin_does_not_resolve_ends_empty(monkeypatch):
    """A march cut at ``until`` goes UNTIL_MARGIN past it (march.py); where the states of
    that margin do not resolve (the tube next to a lock), the march resolved up to
    ``until`` and found nothing there: an empty result, not the ConvergenceError of a march
    that could not reach its end. Here no state beyond g_theta = 1.0004 resolves, from a
    neighbour or from cold."""
    from electrogrowth.bifurcation import along, state_loss
    from electrogrowth.bifurcation.march import UNTIL_MARGIN, first_bifurcations
    from electrogrowth.errors import ConvergenceError
    from electrogrowth.incremental.accuracy import SCAN_SIGNS
    from electrogrowth.incremental.targets import ImpedanceTarget

    def locked(solve):
        def state(tube, *args, **kwargs):
            if tube.layers[0].growth[1] > 1.0004:
                raise ConvergenceError("not resolved next to the lock")
            return solve(tube, *args, **kwargs)

        return state

    monkeypatch.setattr(along, "solve_base_state", locked(along.solve_base_state))
    monkeypatch.setattr(state_loss, "solve_base_state", locked(state_loss.solve_base_state))
    modes = np.array([(0, 1, 0), (2, 1, 0)], float)
    loose = ImpedanceTarget(SCAN_SIGNS)
    assert UNTIL_MARGIN > 1e-4  # the margin reaches past 1.0004 (scale 1)
    res = first_bifurcations(FILM, CONTROL, None, modes, loose, top=2, until=1.0003)
    assert res.found == [] and res.threshold is None
    with pytest.raises(ConvergenceError):  # not resolved before ``until``: said
        first_bifurcations(FILM, CONTROL, None, modes, loose, top=2, until=1.0005)
