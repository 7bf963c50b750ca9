"""An inflation march that runs into a Gent layer's lock must not report a loss of the
axisymmetric state that does not happen.

A Gent inner layer (jm = 45, R 1 to 1.4) inside a neo-Hookean one (to 2.2), inflated by a
follower pressure P_i: ``threshold(tube, "pressure")`` says the branch never turns (value inf,
kind "locking" at lambda_i = 6.854: the pressure grows without bound towards the lock), and
solve_base_state gives the state at P_i = 2 (lambda_i = 6.7112); closer to the lock it is not
resolved.

Found by probing: ``critical_value(tube, 3, 1, "pressure")`` returned kind THRESHOLD at
P_i = 4.0794 with status OK, "the axisymmetric state is lost (pressure threshold)": where the
march stopped resolving states, not a property of the tube (the same tube with the Gent
layer's shear modulus 3 gave 11.3415 with the built-in energy and 11.3617 with the identical
energy text). The march now says that no mode bifurcates up to there and that the states
past it are not resolved, without claiming a loss: since the pressure's own threshold is
that lock (the state is never lost), as NoBifurcationBeforeLock, a NoBifurcationFound that
names the layer and the lock (check round 35b; tests/bifurcation/test_march_into_lock.py).
"""

import math

import pytest

from electrogrowth import Layer, Material, Tube, critical_value, gent, threshold
from electrogrowth.errors import NoBifurcationBeforeLock

GENT_INSIDE = Tube((Layer(1.4, gent(45.0)), Layer(2.2)), length=5.0, stretch=1.0)


def test_no_threshold_where_the_branch_only_locks():
    assert math.isinf(threshold(GENT_INSIDE, "pressure").value)
    with pytest.raises(NoBifurcationBeforeLock, match="grows without bound") as err:
        critical_value(GENT_INSIDE, 3, 1, "pressure")
    assert "no mode bifurcates for pressure" in str(err.value)
    assert "the Gent layer 1 is next to its lock" in str(err.value)


@pytest.mark.slow
def test_energy_text_gives_the_builtin_outcome():
    text = Material("gent3", "3*(-45/2*log(1 - (I1 - 3)/45)) + I5/2", check_units=False)
    builtin = Tube((Layer(1.4, gent(45.0), shear_modulus=3.0), Layer(2.2)), length=5.0)
    written = Tube((Layer(1.4, text), Layer(2.2)), length=5.0)
    for tube in (builtin, written):
        with pytest.raises(NoBifurcationBeforeLock, match="grows without bound"):
            critical_value(tube, 3, 1, "pressure")


@pytest.mark.parametrize("control", ["force", "pressure"])
def test_load_scale_of_an_energy_text_in_other_units(control):
    # found by probing: the load's scale was read off shear_modulus alone, so a layer whose
    # text carries its stiffness (3 times Gent) got a force range 6x shorter than the same
    # layer as a built-in energy with shear_modulus 3
    from electrogrowth.bifurcation.march import control_path

    text = Material("gent3", "3*(-45/2*log(1 - (I1 - 3)/45)) + I5/2", check_units=False)
    builtin = Tube((Layer(1.4, gent(45.0), shear_modulus=3.0), Layer(2.2)), axial_force=0.0)
    written = Tube((Layer(1.4, text), Layer(2.2)), axial_force=0.0)
    assert control_path(written, control, None) == pytest.approx(
        control_path(builtin, control, None), rel=1e-12
    )
