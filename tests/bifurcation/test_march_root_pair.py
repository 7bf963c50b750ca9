"""A compression march must not step over a pair of roots of one mode's target.

A neo-Hookean tube (Rbar_o = 2.7213, L = 6.8008) lined inside with a film 0.0089 thick of
shear modulus 33.36, compressed axially. The impedance target of mode (14, 1) is positive
down to lambda_z = 0.15 (0.0014), negative at 0.1 (-0.0004) and positive again at 0.07
(0.0002): the mode bifurcates at lambda_z = 0.134705156 (the impedance method given the
bracket (0.1, 0.15); collocation, without a bracket, 0.134705156 to 5e-9) and again at
0.0897146 (the bracket (0.07, 0.1); the outer face's own mode, the same in the unlined tube).

Found by probing: ``critical_value(tube, 14, 1, "stretch")`` raises NoBifurcationFound "no
mode bifurcates for stretch between 1 and 0.05": the march's samples straddle both roots.
"""

import pytest

from electrogrowth import Layer, Tube, critical_value

LINED = Tube(
    (Layer(1.008866183492619906, shear_modulus=33.35986377275543), Layer(2.7213386108914204)),
    length=6.800804207725232,
    stretch=1.0,
)


def test_first_root_of_a_pair_is_found():
    crit = critical_value(LINED, 14, 1, "stretch")
    assert crit.kind == "bifurcation"
    assert crit.value == pytest.approx(0.134705156, rel=1e-8)
