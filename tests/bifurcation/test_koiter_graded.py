"""The amplitude equation with graded growth (docs/derivation-koiter.md, "Graded growth"):
the forms take g(R) at their quadrature points; a graded layer whose ends are equal is the
constant one, a graded substrate's A(c) is singular at the package's critical value (the
impedance route, which integrates the graded layer independently), and its coefficient
converges in the node count."""

from __future__ import annotations

import pytest

from electrogrowth.bifurcation.koiter import koiter_coefficient
from electrogrowth.bifurcation.koiter_tube import axisymmetric_expansion, tube_expansion
from electrogrowth.bifurcation.koiter_wall import wrinkle_expansion
from electrogrowth.errors import ParameterError
from electrogrowth.model.layer import Layer
from electrogrowth.model.layers import LinearGrowth, Tube

AXIAL, THETA = "growth[1].z", "growth[1].theta"


def _tube(substrate, film=(1, 1, 1.0)) -> Tube:
    """A film [1, 1.1] (mu = 1, growing) inside a substrate to 2 (mu = 0.2) of growth
    ``substrate``, L = 1, lambda_z = 1."""
    return Tube(
        [
            Layer(1.1, shear_modulus=1.0, growth=film),
            Layer(2.0, shear_modulus=0.2, growth=substrate),
        ],
        length=1.0,
        stretch=1.0,
    )


CONSTANT = (1, 1, 1.05)
EQUAL_ENDS = LinearGrowth(1.1, 2.0, CONSTANT, CONSTANT)
GRADED = LinearGrowth(1.1, 2.0, (1, 1, 1.1), (1, 1, 1.0))


@pytest.mark.parametrize("family", ["prismatic", "axisymmetric", "wrinkle"])
def test_equal_ends_are_the_constant_layer(family):
    """The same critical value (1e-12) and coefficient (1e-9: the graded base state is
    solved by another quadrature) for a graded layer with equal ends as for the constant
    one, in each family's forms."""

    def run(substrate):
        if family == "prismatic":
            return tube_expansion(_tube(substrate, (1, 1.0, 1)), 12, THETA, nodes=16)
        if family == "axisymmetric":
            return axisymmetric_expansion(_tube(substrate), 3, AXIAL, nodes=16)
        return wrinkle_expansion(_tube(substrate, (1, 1.0, 1)), (4, 1), THETA, nodes=8)

    constant, graded = run(CONSTANT), run(EQUAL_ENDS)
    assert graded.control_value == pytest.approx(constant.control_value, rel=1e-12)
    assert graded.coefficient == pytest.approx(constant.coefficient, rel=1e-9)


FAMILIES = pytest.mark.parametrize(
    "family, mode, control, film",
    [("prismatic", (12, 0), THETA, (1, 1.0, 1)), ("axisymmetric", (0, 3), AXIAL, (1, 1, 1.0))],
)


def _graded_run(family, mode, control, film, substrate=GRADED, nodes=16):
    if family == "prismatic":
        return tube_expansion(_tube(substrate, film), mode[0], control, nodes=nodes)
    return axisymmetric_expansion(_tube(substrate, film), mode[1], control, nodes=nodes)


@FAMILIES
def test_graded_substrate_is_singular_at_the_critical_value(family, mode, control, film):
    """A substrate whose axial growth falls linearly from 1.1 to 1 across it: A(c) is
    singular where the impedance route puts the critical growth (to 1e-11; measured
    6e-14 and 7e-13 at 16 points), and the coefficient differs from either end's constant
    growth (the grading is seen)."""
    e = _graded_run(family, mode, control, film)
    assert e.control_value == pytest.approx(e.impedance_value, rel=1e-11)
    for ends in ((1, 1, 1.1), (1, 1, 1.0)):
        other = _graded_run(family, mode, control, film, substrate=ends)
        assert abs(other.coefficient - e.coefficient) > 1e-3


@pytest.mark.slow
@FAMILIES
def test_graded_coefficient_converges(family, mode, control, film):
    """24 against 32 points a segment: 1e-8 (measured 4e-10 for the prismatic mode; the
    constant layer's own floor at 16 points is 1e-8, so 16 is not compared)."""
    fine, finer = (_graded_run(family, mode, control, film, nodes=n) for n in (24, 32))
    assert fine.coefficient == pytest.approx(finer.coefficient, rel=1e-8)


def test_door_on_a_graded_tube_and_a_graded_control_refused():
    """The door computes a graded tube's coefficient (the 32-point expansion's, the finest
    of koiter.RESOLUTIONS) and refuses the growth of a graded layer as the control in one
    line."""
    r = koiter_coefficient(_tube(GRADED), (0, 3), AXIAL)
    assert r.coefficient == pytest.approx(
        axisymmetric_expansion(_tube(GRADED), 3, AXIAL, nodes=32).coefficient, rel=1e-12
    )
    assert r.branch == "supercritical" and r.error_estimate < 1e-7 * r.coefficient
    with pytest.raises(ParameterError, match="graded") as err:
        koiter_coefficient(_tube(GRADED), (0, 3), "growth[2].z")
    assert "\n" not in str(err.value)
