"""A compression march must find the first root of one mode's target on film-lined tubes.

Found by probing: a grid of 300 states from lambda_z = 1 to 0.06 on 14 random film-lined
tubes (film inside) found 21 of 168 modes where ``critical_value(tube, m, n, "stretch")``
returned a later root with status OK, or raised NoBifurcationFound: the march's samples
straddled the first root. Two of them:

* steep: a Mooney-Rivlin tube (alpha = 0.3458, Rbar_o = 2.4453, L = 3.4556) lined with a film
  0.0417 thick of shear modulus 18.41. Mode (10, 1) bifurcates first at lambda_z =
  0.43910128: collocation without a bracket gives 0.4391012835 (its target, at 40 and 60
  nodes, changes sign once between 0.44 and 0.435), the impedance method given the bracket
  (0.43, 0.45) 0.4391012840. The impedance target jumps there from +0.0031 (0.44) to -0.0030
  (0.435) and turns positive again before 0.3. The march returned 0.16835964, status OK.
* pair: a neo-Hookean tube (Rbar_o = 2.7213, L = 6.8008) lined with a film 0.0089 thick of
  shear modulus 33.36. The target of (14, 1) is positive down to lambda_z = 0.15 (0.0014),
  negative at 0.1 (-0.0004) and positive again at 0.07 (0.0002): the mode bifurcates at
  0.134705156 (the impedance method given the bracket (0.1, 0.15); collocation, without a
  bracket, 0.134705156 to 5e-9) and again at 0.0897146 (the outer face's own mode). The march
  raised NoBifurcationFound "no mode bifurcates for stretch between 1 and 0.05".
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, mooney_rivlin

MR = mooney_rivlin(0.3457631506656905)
CASES = {
    "steep": (
        Tube(
            (Layer(1.0417270604297943, MR, 18.413279016417057), Layer(2.4452988535533775, MR)),
            length=3.4555972511486335,
            stretch=1.0,
        ),
        (10, 1),
        0.43910128,
        1e-7,
    ),
    "pair": (
        Tube(
            (
                Layer(1.008866183492619906, shear_modulus=33.35986377275543),
                Layer(2.7213386108914204),
            ),
            length=6.800804207725232,
            stretch=1.0,
        ),
        (14, 1),
        0.134705156,
        1e-8,
    ),
}


@pytest.mark.parametrize("name", CASES)
def test_first_root_is_found(name):
    tube, (m, n), first, rel = CASES[name]
    crit = critical_value(tube, m, n, "stretch")
    assert crit.kind == "bifurcation"
    assert crit.value == pytest.approx(first, rel=rel)
