"""Free ends (axial force 0) of a tube with a stiff core and a growing skin: the base state
must solve whatever the moduli's scale (found by probing layered tubes, round 5).

The axial force residual of a layered state was measured against max(1, |N_int|, |ends|),
but at free ends N_int (the wall's resultant) is itself ~0, while its integrand is of the
order of the stiff layer's modulus times the wall's area: its rounding alone exceeded
1e-12, and every node count failed with "layered base state not resolved". The same
tube with every modulus divided by 1000 (the same kinematics, stresses / 1000) solved. The
stretch control needs the free length (basestate.tube.free_stretch), so every critical
stretch of such a tube failed too.
"""

import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.materials import Material, mooney_rivlin, neo_hookean

ENERGIES = {
    "neo-hookean": neo_hookean(),
    "mooney-rivlin": mooney_rivlin(0.6),
    "text": Material("nh-text", "(I1 - 3)/2 + I5/2"),
}


def _tube(energy, mu, scale=1.0, **loads):
    return Tube(
        (
            Layer(2.9, material=ENERGIES[energy], shear_modulus=mu * scale),
            Layer(2.92, growth=1.1, shear_modulus=scale),
        ),
        **loads,
    )


@pytest.mark.parametrize("energy", sorted(ENERGIES))
def test_free_ends_of_a_stiff_core_depend_on_the_ratio_only(energy):
    """Moduli (1000, 1) and (1, 1e-3): the same free length lambda_z."""
    stiff = solve_base_state(_tube(energy, 1000.0, axial_force=0.0))
    soft = solve_base_state(_tube(energy, 1000.0, scale=1e-3, axial_force=0.0))
    assert stiff.stretch == pytest.approx(soft.stretch, rel=1e-12)
    assert stiff.lambda_i == pytest.approx(soft.lambda_i, rel=1e-12)


def test_critical_stretch_of_a_stiff_core_tube():
    """The stretch control's path starts from the free length: it must solve."""
    tube = _tube("mooney-rivlin", 1000.0, stretch=1.0, length=3.0)
    soft = _tube("mooney-rivlin", 1000.0, scale=1e-3, stretch=1.0, length=3.0)
    a = critical_value(tube, 2, 1, "stretch", side="compression")
    b = critical_value(soft, 2, 1, "stretch", side="compression")
    assert a.value == pytest.approx(b.value, rel=1e-9)
