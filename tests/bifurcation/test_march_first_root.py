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
* window (check round 16, D1): a neo-Hookean core (mu 0.0988) in a Mooney-Rivlin (0.333)
  layer of mu 6.40, grown anisotropically, compressed: (1, 2) is unstable in the window
  0.42200953 < lambda_z < 0.42632183 (the roots of an independent collocation solver at 40
  and 56 nodes, to 1e-14; the package's own target bracketed gives both) and again from
  0.29286. A 5 % step landed 1.3e-3 past the window (target 1.49e-5 after 2.26e-4), the
  next, short one at 3.98e-5: not below 1/4 of both neighbours, no dip examined, and both
  methods returned 0.2928645687, status OK.
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
    "window": (
        Tube(
            (
                Layer(1.1301390736345303, shear_modulus=0.09878171425715293),
                Layer(
                    1.995814547016356,
                    mooney_rivlin(0.333),
                    6.4011527284369505,
                    growth=(1.1628604718694893, 1.2057713714926312, 0.956039101598253),
                ),
            ),
            length=0.7194435192286683,
            stretch=1.0,
        ),
        (1, 2),
        0.42632183211911,
        1e-12,
    ),
}


@pytest.mark.parametrize("name", CASES)
def test_first_root_is_found(name):
    tube, (m, n), first, rel = CASES[name]
    crit = critical_value(tube, m, n, "stretch")
    assert crit.kind == "bifurcation"
    assert crit.value == pytest.approx(first, rel=rel)
