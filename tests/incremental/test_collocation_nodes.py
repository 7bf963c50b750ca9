"""Collocation resolves short waves in thick walls (issue 21, bug 5): its node count grows
with the mode's decay through the wall (incremental/targets.py resolving_nodes)."""

import math

import numpy as np
import pytest
from numpy.polynomial import chebyshev as cheb

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.incremental.targets import resolving_nodes, targets_for
from electrogrowth.model.layers import Tube
from electrogrowth.model.materials import gent, mooney_rivlin


@pytest.mark.parametrize("q", [10.0, 100.0, 347.0, 1000.0])
@pytest.mark.parametrize("rtol", [1e-12, 1e-8])
def test_node_count_resolves_the_decay(q, rtol):
    """The premise: N = sqrt(q ln(1 / rtol)) + 4 Chebyshev coefficients of exp(-q (x + 1) / 2)
    on [-1, 1] reach rtol of the largest (and N / 2 do not, for a fast decay)."""
    n = math.ceil(math.sqrt(q * math.log(1.0 / rtol))) + 4
    coef = cheb.chebinterpolate(lambda x: np.exp(-q * (x + 1) / 2), 400)
    assert abs(coef[n:]).max() <= rtol * abs(coef).max()
    if q >= 100:
        assert abs(coef[n // 2 :]).max() > rtol * abs(coef).max()


def test_mooney_rivlin_short_wave_roots_agree():
    """The issue's tube: impedance 2.69801240399, collocation 2.69787714312 (5e-5 apart).
    The orthonormalised shooting twin agrees with the impedance's target (6.475e-8 at
    g = 2.6978) and collocation converges to it with the nodes (56: 2.697877143, 72:
    2.698012067, 88: 2.6980124037604, 104: 2.6980124039946): collocation was under-resolved
    (q = k (r_o - r_i) = 347 e-folds across the wall). At 102 nodes its target changes sign
    within 1e-8 of the impedance's root."""
    params = Tube.uniform(
        outer_radius=3.765, length=0.337, stretch=1.202, voltage=0.2, material=mooney_rivlin(0.7)
    )
    root = critical_value(params, 0, 4, "growth", bracket=(2.6975, 2.6985)).value
    assert root == pytest.approx(2.69801240399, abs=1e-10)
    state = solve_base_state(params.at("growth", root))
    assert resolving_nodes(state, 0, 4, 1e-12) == 102
    f = targets_for("collocation", 1e-12)
    below, above = (
        f(solve_base_state(params.at("growth", g)), [[0, 4]])[0]
        for g in (root - 1e-8, root + 1e-8)
    )
    assert below * above < 0


def test_nodes_resolve_the_moduli_next_to_a_lock():
    """A Gent tube whose inner face is 0.2 % short of its lock (drawn by the slow property
    test): its moduli are steep, the mode (5, 5) is not (its decay asks for 11 nodes). At
    the default 40-72 nodes collocation put the voltage root 1.3e-4 to 3.4e-3 high; with
    the nodes the moduli need (221 at 1e-12) its target changes sign within 1e-9 of the
    impedance kernel's root, whose tables resolve the moduli."""
    g = 1.7917252832408428
    params = Tube.uniform(
        outer_radius=1.5410808488080756,
        length=1.5410808488080756,
        stretch=2.7611935203276876,
        voltage=1.3169698150196,
        growth=g,
        material=gent(2.559),
    )
    root = critical_value(params, 5, 5, "voltage", bracket=(3.1358, 3.136)).value
    assert root == pytest.approx(3.135888372183, abs=1e-9)  # its error estimate: 5e-10
    state = solve_base_state(params.at("voltage", root))
    assert resolving_nodes(state, 5, 5, 1e-12) >= 200
    f = targets_for("collocation", 1e-12)
    below, above = (
        f(solve_base_state(params.at("voltage", v)), [[5, 5]])[0]
        for v in (root - 3e-9, root + 3e-9)
    )
    assert below > 0 > above
