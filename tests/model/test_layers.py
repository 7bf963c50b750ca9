"""The one tube type (model/layers.py): the paper's tube is Tube.uniform, and the former
TubeParameters a deprecated factory of it."""

import pytest

from electrogrowth import Layer, Tube
from electrogrowth.errors import ParameterError


def test_the_former_tube_type_is_a_deprecated_factory_of_the_uniform_tube():
    from electrogrowth import TubeParameters, gent

    with pytest.warns(DeprecationWarning, match="Tube.uniform"):
        old = TubeParameters(2.0, 3.0, 1.2, 1.1, 0.3, gent(50.0))
    assert old == Tube.uniform(2.0, 3.0, 1.2, 1.1, 0.3, gent(50.0)) and old.is_uniform
    assert (old.outer_radius, old.length, old.growth, old.stretch, old.voltage) == (
        2.0,
        3.0,
        1.2,
        1.1,
        0.3,
    )
    assert not Tube((Layer(2.0, shear_modulus=2.0),)).is_uniform  # a modulus: not the paper's


@pytest.mark.parametrize("growth", [1.0, 1.37, 2.5])
def test_the_uniform_tube_builds_the_layer_a_checked_one_is(growth):
    """Tube.uniform builds its layer without Layer's checks (its numbers are checked as the
    paper's): the same layer, equal and hashed alike, at every value a march sets."""
    tube = Tube.uniform(outer_radius=1.4, voltage=0.4).at("growth", growth)
    checked = Layer(1.4, growth=growth)
    assert tube.layers[0] == checked and hash(tube.layers[0]) == hash(checked)
    assert tube == Tube((checked,), voltage=0.4) and tube.is_uniform
    with pytest.raises(ParameterError, match="growth factor g"):
        tube.at("growth", 200.0)


def test_a_layers_initial_moduli_are_its_own_times_its_energys():
    """Layer.initial_moduli: shear_modulus and permittivity times the energy's reference
    2 (Omega_1 + Omega_2) and 1 / (2 (Omega_4 + Omega_5 + Omega_6)), so a text carrying its
    moduli (check_units=False) is the built-in layer with them."""
    from electrogrowth import Material, gent

    assert Layer(2.0, shear_modulus=3.0, permittivity=0.5).initial_moduli == (3.0, 0.5)
    assert Layer(2.0, material=gent(20.0), shear_modulus=3.0).initial_moduli == (3.0, 1.0)
    text = Material("t", "10*((I1 - 3)/2) + 3*I5/2", check_units=False)
    mu, eps = Layer(2.0, material=text, shear_modulus=0.5, permittivity=2.0).initial_moduli
    assert mu == pytest.approx(5.0, rel=1e-15) and eps == pytest.approx(2.0 / 3.0, rel=1e-15)
    nonideal = Material("nh+I6", "(I1 - 3)/2 + I5/2 + I6/10", check_units=False)
    assert Layer(2.0, material=nonideal).initial_moduli[1] == pytest.approx(1 / 1.2, rel=1e-15)
