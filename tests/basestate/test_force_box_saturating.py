"""A force-controlled tube whose unloaded forces do not rise across the stretch box: its
edges' forces bound nothing, and the force is not blamed (check round 27;
basestate/force_box.py `_rises_between`).

A saturating energy, 0.572 tanh((I1 - 3) / 1.144) + I5/2, gives ~0 axial force at both
edges of the box. With pressures past their threshold, no state was found, and the refusal
read "axial force F = -0.16 is outside the supported range 0 to 0", though without the
pressures the same force holds a state (lambda_z 0.994)."""

import dataclasses

import pytest

from electrogrowth import Layer, Material, Tube, solve_base_state
from electrogrowth.errors import BaseStateError

SATURATING = Material("t", "0.572*tanh((I1-3)/(2*0.572)) + I5/2")
TUBE = Tube(
    (Layer(1.894, material=SATURATING, permittivity=0.1013),), length=19.24, axial_force=-0.16,
    closed_ends=True, inner_pressure=-0.123, outer_pressure=-0.6036,
)  # fmt: skip


def test_the_force_holds_a_state_without_the_pressures():
    """Independent of the force control: under prescribed stretches, P_i = P_o, the end
    force runs through F = -0.16 between lambda_z 0.99 and 1.0 (-0.246, 0)."""
    free = TUBE.at("pressure", TUBE.outer_pressure)  # P_i = P_o: unloaded but for F
    lo, hi = (
        solve_base_state(dataclasses.replace(free, stretch=s, axial_force=None)).end_force
        for s in (0.99, 1.0)
    )
    assert lo < TUBE.axial_force < hi
    assert 0.99 < solve_base_state(free).stretch < 1.0


def test_the_pressure_is_named_not_the_force():
    with pytest.raises(BaseStateError, match="inner pressure P_i = -0.123 is at or beyond"):
        solve_base_state(TUBE)
