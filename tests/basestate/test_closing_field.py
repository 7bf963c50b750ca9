"""An energy whose electric field closes the bore: no charged state rises from the
unloaded state, the threshold is 0, kind "closing" (check round 24, D1;
basestate/voltage.py `_rises`).

`(I1-3)/2 + 0.2*I4 + 0.4*I5 - 0.1*I6` passes the unit check. In a uniform tube
(Rbar_o 2) compressed to lambda_z <= 0.49, the charge makes the hoop residual of (*) rise
just above lambda_i0 (below it, it rises through zero): the branch falls in lambda_i, which
the package does not follow. The threshold's scan (8 % steps) jumped the gap to states of
another branch beyond it: "internal error: LinAlgError" at 0.46-0.48 (its limit point's
interpolant met the gap), a locking stretch 1.7076 at 0.4, "none (unbounded)" at 0.49.
The crease criterion's Biot ratio compresses a tube through that range, so every
critical value, curve and design with such a layer ended in that internal error.
"""

import dataclasses
import math

import numpy as np
import pytest

from electrogrowth import Layer, Material, Tube, gent, neo_hookean, solve_base_state
from electrogrowth.basestate import thresholds, voltage
from electrogrowth.basestate.tube import voltage_threshold
from electrogrowth.bifurcation.crease import biot_ratio, crease_onset
from electrogrowth.errors import BaseStateError

CLOSING = Material("closing", "(I1-3)/2 + 0.2*I4 + 0.4*I5 - 0.1*I6")


@pytest.mark.parametrize("stretch", [0.40, 0.47, 0.49])
def test_no_charged_state_rises_from_the_unloaded_state(stretch):
    tube = Tube.uniform(2.0, stretch=stretch, material=CLOSING)
    value, kind, lam = voltage_threshold(tube)  # was LinAlgError, "locking", "none"
    assert (value, kind) == (0.0, "closing")
    state = solve_base_state(tube)  # the uncharged state stands
    assert state.lambda_i == lam == pytest.approx(math.sqrt(1 / stretch), rel=1e-12)
    with pytest.raises(BaseStateError, match="closes the bore"):
        solve_base_state(tube.at("voltage", 0.1))


def test_the_charge_raises_the_hoop_residual_above_lambda_i0():
    """Why: the traction's residual (*) above lambda_i0 grows with the charge q (an ideal
    dielectric's falls through zero), and below lambda_i0 it rises through zero."""
    lam0, nodes = voltage._mechanical(CLOSING, 2.0, 1.0, 0.47, 1e-12)
    wall = voltage.UniformWall(CLOSING, 2.0, 1.0, 0.47, nodes)
    qs = (0.0, 1e-2, 1e-1, 1.0)
    above = [wall.hoop(np.array([lam0 * 1.001]), q)[0][0] for q in qs]
    below = [wall.hoop(np.array([lam0 * 0.999]), q)[0][0] for q in qs]
    assert above[0] > 0 and np.all(np.diff(above) > 0)
    assert below[0] < 0 < below[-1]


def test_an_opening_branch_of_the_same_energy_is_unchanged():
    value, kind, _ = voltage_threshold(Tube.uniform(2.0, stretch=0.6, material=CLOSING))
    assert (value, kind) == (math.inf, "none")


def test_the_crease_criterion_of_such_an_energy_is_evaluated():
    """Its Biot ratio compresses an uncharged tube through that range: LinAlgError before
    (every critical value's verdict, curve and design with such a layer)."""
    # uncharged, the energy is neo-Hookean: its Biot ratio and crease onset are that
    # solid's (the crease at lambda_z = 2.4^(-2/3), docs/derivation-crease.md)
    assert biot_ratio(CLOSING) == pytest.approx(biot_ratio(neo_hookean()), rel=1e-12)
    onset = crease_onset(Tube.uniform(1.4, material=CLOSING), "stretch", side="compression")
    assert onset.kind == "crease" and onset.value == pytest.approx(2.4 ** (-2 / 3), rel=1e-3)


def test_a_lock_next_to_the_unloaded_state_is_no_closing_field():
    """A Gent layer (J_m 0.5) whose unloaded state lies next to its lock has no finite Vbar
    just above lambda_i0 either: the energy's edge, not a field closing the bore (a second
    read of the change: it was called closing and every charged state refused)."""
    tube = Tube.uniform(2.0, material=gent(0.5))
    assert voltage_threshold(tube)[1] == "locking"
    assert solve_base_state(tube.at("voltage", 0.05)).lambda_i > 1.0


def test_two_layers_of_such_an_energy_read_the_one_layer_threshold():
    """Two identical layers are the one-layer tube: threshold 0 of kind "closing" at its
    lambda_i0, the uncharged state solved, a charged one refused naming why (the layered
    walk met the gap: 'no state somewhere in it' at 0.47, "locking" at lambda_i0 at 0.45)."""
    for stretch in (0.45, 0.47):
        one = Tube.uniform(2.0, stretch=stretch, material=CLOSING)
        two = Tube((Layer(1.5, material=CLOSING), Layer(2.0, material=CLOSING)), stretch=stretch)
        v1, k1, lam1 = voltage_threshold(one)
        v2, k2, lam2 = voltage_threshold(two)
        assert (v2, k2) == (v1, k1) == (0.0, "closing")
        assert lam2 == pytest.approx(lam1, rel=1e-15)
        state = solve_base_state(two)
        assert (state.threshold_kind, state.voltage_threshold) == ("closing", 0.0)
        assert state.lambda_i == pytest.approx(stretch**-0.5, rel=1e-12)
        with pytest.raises(BaseStateError, match="closes the bore"):
            solve_base_state(two.at("voltage", 0.1))


def _residual_with_charge(tube: Tube, qs) -> list[float]:
    """The wall's hoop residual T of (*) 0.1 % above its unloaded r_i, at charges q = c^2:
    the layered derivation's test, read off the wall's integrals (not the walk's probe)."""
    prep = thresholds.prepare(tube, 1e-12)
    x0, lz0 = prep.loaded
    r, lz = np.array([x0 * 1.001]), np.array([lz0])
    return [float(prep.wall.integrals(r, lz, np.sqrt(q))[0][0]) for q in qs]


@pytest.mark.parametrize(
    ("inner", "outer_material", "kind"),
    [(1.9, neo_hookean(), "closing"), (1.5, neo_hookean(), "none")],
)
def test_a_mixed_stack_closes_where_the_charge_raises_its_residual(inner, outer_material, kind):
    """The energy over a neo-Hookean layer at lambda_z = 0.45: with a thin neo-Hookean skin
    the charge still raises the wall's residual above the start (closing), with a thick one
    it lowers it (the branch opens: unchanged, "none")."""
    tube = Tube(
        (Layer(inner, material=CLOSING), Layer(2.0, material=outer_material)), stretch=0.45
    )
    residual = _residual_with_charge(tube, (0.0, 1e-2, 1e-1))
    rises = bool(np.all(np.diff(residual) > 0))
    assert rises == (kind == "closing")
    value, got, lam = voltage_threshold(tube)
    assert got == kind
    if kind == "closing":
        assert value == 0.0 and lam == solve_base_state(tube).lambda_i
        with pytest.raises(BaseStateError, match="closes the bore"):
            solve_base_state(tube.at("voltage", 0.05))


#: check round 28 D1: a bilayer whose coupling stiffens with I1 at fixed lambda_z and P_o
COUP = Material("coup", "(I1-3)/2 + I5/2*(1 + 0.1*(I1-3))")
COUPI4 = Material("coupi4", "(I1-3)/2 + 0.45*I5 + 0.05*I4*(1 + 0.1*(I1-3))")


def _stiffening_bilayer(inner_pressure: float) -> Tube:
    inner = Layer(1.8084397861935206, COUP, shear_modulus=2.6200505657523743)
    outer = Layer(2.2693066463787863, COUPI4, shear_modulus=7.860779293048664)
    growth = (1.150437756076137, 1.1313952076652471, 1.1219382139347056)
    return Tube(
        (
            dataclasses.replace(inner, permittivity=0.9122528046112701),
            dataclasses.replace(outer, permittivity=0.652746813978254, growth=growth),
        ),
        length=4.1481538834933875,
        stretch=0.8109099045777046,
        inner_pressure=inner_pressure,
        outer_pressure=0.04364916679215165,
    )


def test_a_branch_running_inward_past_the_couplings_limit_is_closing_not_a_lock():
    # on 9b16ae6: kind "locking" of zero width at the uncharged state (lambda_i
    # 9.259299375132048) and a charged state refused as "too close to the locking stretch";
    # the check's own quadrature: uncharged r_i 9.259299375131839, the charged branch runs
    # inward (Vbar 0.1847 at r_i 9.25): not followed, said so
    tube = _stiffening_bilayer(4.45)
    value, kind, lam = voltage_threshold(tube)
    assert (value, kind) == (0.0, "closing")
    assert lam == pytest.approx(9.259299375131839, rel=1e-12)
    with pytest.raises(BaseStateError, match="closes the bore"):
        solve_base_state(tube.at("voltage", 0.1083518738228662))
    # below the crossing (uncharged r_i 9.0111) the branch opens, to the coupling's limit
    value, kind, lam = voltage_threshold(_stiffening_bilayer(4.448))
    assert kind == "locking" and lam == pytest.approx(9.0334, abs=1e-4)
