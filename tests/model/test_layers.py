"""The one tube type (model/layers.py): the paper's tube is Tube.uniform, and the former
TubeParameters a deprecated factory of it."""

import pytest

from electrogrowth import Layer, Tube


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
