"""A compression march must find the first root of a mode whose target crosses zero steeply.

A Mooney-Rivlin tube (alpha = 0.3458, Rbar_o = 2.4453, L = 3.4556) lined inside with a film
0.0417 thick of shear modulus 18.41, compressed axially. Mode (10, 1) bifurcates first at
lambda_z = 0.43910128: collocation without a bracket gives 0.4391012835 (its target, at 40
and 60 nodes, changes sign once between 0.44 and 0.435), the impedance method given the
bracket (0.43, 0.45) 0.4391012840. The impedance target jumps there from +0.0031 (0.44) to
-0.0030 (0.435) and turns positive again before 0.3.

Found by probing: ``critical_value(tube, 10, 1, "stretch")`` returns 0.16835964 with status
OK, a later root, with nothing to say that an earlier one was passed. A grid of 300 states
from lambda_z = 1 to 0.06 on 14 random film-lined tubes found the same for 21 of 168 modes
(a later root, or NoBifurcationFound), every one with the film inside.
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, mooney_rivlin

MR = mooney_rivlin(0.3457631506656905)
LINED = Tube(
    (Layer(1.0417270604297943, MR, 18.413279016417057), Layer(2.4452988535533775, MR)),
    length=3.4555972511486335,
    stretch=1.0,
)


def test_first_root_of_a_steep_target_is_found():
    crit = critical_value(LINED, 10, 1, "stretch")
    assert crit.kind == "bifurcation"
    assert crit.value == pytest.approx(0.43910128, rel=1e-7)
