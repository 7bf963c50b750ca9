"""Sensitivities of modes that live at a stiff inner layer (probe round 7b): the implicit
derivative is taken of det(M2), not of the kernel's normalised target (a step of constant
size about such a root), with steps relative to the parameter, and one-sided where the
kernel's table units bend. The reference: central differences of full critical_value
solves at rtol 1e-13 (steps 1e-5 relative; 1e-4 agrees to <= 2e-7)."""

import pytest

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.design.sensitivity import sensitivities
from electrogrowth.figures.design_gallery import gut_bilayer

HOOP = "growth[1].theta"
THICK = "layers[1].thickness"
SUB_MU = "layers[2].shear_modulus"


def _fd(tube, mode, control, key, rel=1e-5):
    """d(critical value)/d(key) by a central difference of full solves."""
    p = tube.value_of(key)
    h = rel * abs(p)
    a = critical_value(tube.at(key, p + h), *mode, control, rtol=1e-13).value
    b = critical_value(tube.at(key, p - h), *mode, control, rtol=1e-13).value
    return (a - b) / (2 * h)


def _check(tube, mode, control, keys, rel):
    v = critical_value(tube, *mode, control, rtol=1e-13).value
    s = sensitivities(tube, mode, control, v, keys=keys)
    for key in keys:
        assert s[key] == pytest.approx(_fd(tube, mode, control, key), rel=rel), key
    return s


def test_a_film_100_times_stiffer_folding_at_its_inner_face():
    """prescribe's own design for (40, 0) along the film's thickness (0.0083): 6.3486289 and
    0.0658798 (the package said 1.07392 and 1.07393, the critical value itself)."""
    film = Tube((Layer(1.01, growth=(1, 1.0, 1)), Layer(3.0, shear_modulus=0.01)), length=10.0).at(
        THICK, 0.008311034881460892
    )
    _check(film, (40, 0), HOOP, (THICK, SUB_MU), rel=1e-6)


def test_rings_of_a_film_and_a_field_the_tube_does_not_have():
    """(0, 100) of a film growing axially: d/dlength -2.37e-7 (the package said -0.1198);
    without a voltage the permittivity changes nothing (it said -0.147 for the next mode)."""
    film = Tube((Layer(1.01, growth=1.0), Layer(3.0, shear_modulus=0.01)), length=9.8330586)
    v = critical_value(film, 0, 100, "growth[1].z", rtol=1e-13).value
    s = sensitivities(film, (0, 100), "growth[1].z", v, keys=("length", "layers[1].permittivity"))
    assert s["length"] == pytest.approx(_fd(film, (0, 100), "growth[1].z", "length"), rel=1e-4)
    assert abs(s["layers[1].permittivity"]) < 1e-8


def test_the_gallery_gut_bilayer_to_1e_6():
    """The design gallery's gut-like bilayer, (11, 0): 9.2303980 (the package said 9.2302622)."""
    _check(gut_bilayer(0.1, 10.0), (11, 0), HOOP, (THICK,), rel=1e-6)


@pytest.mark.parametrize("outer", [2.0, 3.0])
def test_a_substrate_of_modulus_1_under_a_film_of_10(outer):
    """The table's unit modulus is min(mu) when that is above 1: it bends at the substrate's
    mu = 1, and a central difference there was off by 5e-5 (h / 2); the inner layer's
    thickness and the substrate's modulus (one-sided across the bend) to 1e-7. The
    normalised target was 1.1 % (R = 2) and 70 % (R = 3) off."""
    tube = Tube((Layer(1.1, shear_modulus=10.0, growth=(1, 1.0, 1)), Layer(outer)), length=2.0)
    _check(tube, (12, 1), HOOP, (THICK, SUB_MU), rel=1e-7)
