"""The kernel's fallback to collocation must keep the kernel's sign on a layered tube
(found by probing layered tubes, round 5).

impedance_targets retries a mode whose integration failed (too many steps, a step size
underflow) at tighter tolerances, then by collocation, "whose target has the same sign and
the same zeros" (targets._retry). For one layer the collocation determinant is normalised by
the sign it has on the unloaded tube (collocation.stable_det_sign); for a layered tube it is
not (s0 = 1, collocation_target), and its sign is the kernel's for some modes and the
opposite for others. On an unloaded bilayer, stable in every mode, the fallback (forced here
by max_steps=3) flips the sign of (0, 3) and (5, 0); on the three-layer tube of docs L.3 of
(2, 1) and (1, 1). A march that meets a failing step then sees a sign change that is no
bifurcation (or misses one). Probing met the fallback for real: a film-lined tube's mode
(0, 278) at rtol 1e-14 ran out of steps next to its root, where collocation has the sign
opposite to the kernel's on both sides of it (-5.95e-7 and +3.92e-7 at lambda_z 0.52 and
0.49 against the kernel's +7.4e-10 and -5.8e-10).
"""

import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental.targets import impedance_targets, with_family
from electrogrowth.model.layers import Layer, Tube

BILAYER = Tube((Layer(1.5, shear_modulus=2.0), Layer(2.0)), length=1.0)


@pytest.mark.parametrize("mode", [(2, 1), (0, 3), (5, 0), (1, 1)])
def test_fallback_keeps_the_kernels_sign(mode):
    m, n = mode
    state = solve_base_state(BILAYER)
    row = with_family(m, n, "prismatic" if n == 0 else "wrinkle")
    kernel = impedance_targets(state, row)[0]
    fallback = impedance_targets(state, row, max_steps=3)[0]  # every integration fails
    assert kernel * fallback > 0, (kernel, fallback)


def test_the_unloaded_sign_is_collocated_once_for_a_tube_mode_and_nodes(monkeypatch):
    # a march's fallbacks ask it at every state (126 states of a bilayer's march, check
    # round 24 D2): it depends on the unloaded tube, the mode and the nodes alone
    from electrogrowth.incremental import targets

    targets._unloaded_sign.cache_clear()
    asked, collocate = [], targets.collocation_targets

    def counted(state, modes, *, nodes=40):
        asked.append(state.tube.stretch)
        return collocate(state, modes, nodes=nodes)

    monkeypatch.setattr(targets, "collocation_targets", counted)
    row = with_family(2, 1, "wrinkle")
    for stretch in (1.0, 1.05, 1.1):
        f = impedance_targets(solve_base_state(BILAYER.at("stretch", stretch)), row, max_steps=3)
        assert f[0] > 0  # stable: the kernel's sign (test above)
    # each state's own value, and the unloaded tube's sign once (not at every state)
    assert sorted(asked) == [1.0, 1.0, 1.05, 1.1]
