"""Newton's method of a tube's Koiter expansion kept in the control's range (probe 9b D5).

`koiter_coefficient(film, (70, 0), "growth[1].theta")` of a film [1, 1.001], 1e4 times as
stiff as its substrate to R = 2 (the scan's critical mode, g_theta = 1.0320382572), raised
ParameterError "growth g_theta = -0.0801432431112643 is out of range; valid range: > 0":
bifurcation/koiter_tube.py `singular_point` ran Newton's method on the eigenvalue nearest
zero of the 24-node discrete stiffness A(c), which does not resolve this film, stepped from
1.032 to -0.08, and the tube's refusal of that growth escaped as the user's input error
(`critical --koiter`: "amplitude equation not computed: growth g_theta = -0.08 ... is out
of range"). A step out of the control's range is now a ConvergenceError naming the
expansion; and the fold's coefficient is now computed (test_koiter_thin_stiff_film.py).
"""

import math

import numpy as np
import pytest

from electrogrowth import Layer, ParameterError, Tube, koiter_coefficient
from electrogrowth.bifurcation.control_derivative import Reach
from electrogrowth.bifurcation.koiter_tube import singular_point
from electrogrowth.errors import ConvergenceError


def test_a_step_out_of_range_is_no_parameter_error():
    """A stiffness singular only at c = -1, outside a growth's range c > 0."""

    def stiffness(c):
        return np.diag([c + 1.0, 3.0])

    with pytest.raises(ConvergenceError, match=r"expansion of the critical growth.*\(0, inf\)"):
        singular_point(stiffness, 1.0, "growth of mode (2, 0)", Reach(1.0, lo=0.0))
    c, _ = singular_point(stiffness, 1.0, "growth", Reach(1.0, lo=-math.inf))
    assert c == pytest.approx(-1.0, abs=1e-12)


@pytest.mark.slow  # the full coefficient now (three resolutions, ~85 s); the fast check of
# this fold is test_koiter_thin_stiff_film.py's 18-node expansion
def test_film_fold_koiter_is_not_a_parameter_error():
    film = Tube((Layer(1.001, shear_modulus=1e4), Layer(2.0)), stretch=1.0, length=1.0)
    try:
        k = koiter_coefficient(film, (70, 0), "growth[1].theta")
    except ConvergenceError as exc:
        assert "expansion" in str(exc) and "\n" not in str(exc)
        return  # an honest internal failure
    except ParameterError as exc:
        pytest.fail(f"internal Newton step blamed on the user: {exc}")
    assert k.branch in ("supercritical", "subcritical")


def test_a_slender_tubes_bending_mode_converges_to_the_elastica():
    """`koiter_coefficient(Tube.uniform(1.2, length=80), (1, 1), "growth")` raised
    ConvergenceError (check round 23): at 32 nodes the eigenvalue sits at A's rounding
    (~1e-13 at |A| ~ 1e3) while the bending mode's slope is tiny, so Newton stepped by
    > 1e-9 back and forth. Independent route: the inextensible elastica, whose end
    shortening gives g_2 -> g_c pi^2 / (4 L^2) (check round 23 derived it for the stretch
    control; growth g scales lengths as 1 / lambda_z), approached like 1 / L^2."""
    gap = {}
    for length in (80.0, 120.0):
        k = koiter_coefficient(Tube.uniform(1.2, length=length), (1, 1), "growth")
        assert k.branch == "supercritical"
        elastica = k.critical_value * math.pi**2 / (4 * length**2)
        gap[length] = 1.0 - k.coefficient / elastica
        assert 0 < gap[length] < 5e-3  # 2.7e-3 and 1.15e-3
    assert gap[120.0] / gap[80.0] == pytest.approx((80 / 120) ** 2, rel=0.1)


def test_an_expansion_that_does_not_converge_names_a_remedy_it_takes(monkeypatch):
    """The ConvergenceError's own remedy named `rtol` and `method`, which
    koiter_coefficient does not take (check round 23)."""
    from electrogrowth.bifurcation import koiter

    def fails(*args):
        raise ConvergenceError("the critical growth of mode (1, 1) did not converge")

    monkeypatch.setattr(koiter, "_expansion", fails)
    with pytest.raises(ConvergenceError) as err:
        koiter_coefficient(Tube.uniform(1.2, length=8.0), (1, 1), "growth")
    assert "postbuckle" in err.value.remedy.python and "rtol" not in err.value.remedy.python
    assert "--koiter" in str(err.value.remedy)
