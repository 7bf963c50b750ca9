"""A stiff layer growing against a Gent layer close to (not at) its locking stretch.

The unloaded state exists there; the expected radii come from an independent quadrature of the
radial equilibrium, sigma_rr(r_o) = int (sigma_tt - sigma_rr) dr / r = 0, written in principal
stretches (neo-Hookean film, Gent substrate, jm = 2), root in r_i by brentq. At hoop growth 1.9
the substrate's inner face has I1 - 3 = 1.755, 88 % of jm: a regular state, not a lock.
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, gent, solve_base_state
from electrogrowth.errors import ConvergenceError


def film_on_gent(g_theta: float) -> Tube:
    return Tube(
        (
            Layer(1.04, growth=(1.0, g_theta, 1.0)),
            Layer(1.6, shear_modulus=1e-3, material=gent(2.0)),
        )
    )


def test_state_exists_short_of_the_lock():
    # the independent quadrature: r_i = 1.895975806391151, interface 1.9364308039329923,
    # r_o = 2.286517933107146 (and at g_theta = 1.8 it agrees with the package to 1e-12)
    state = solve_base_state(film_on_gent(1.9))
    assert state.r_i == pytest.approx(1.895975806391151, rel=1e-9)
    assert state.interface_radii[0] == pytest.approx(1.9364308039329923, rel=1e-9)
    assert state.r_o == pytest.approx(2.286517933107146, rel=1e-9)


def test_no_threshold_where_the_state_exists():
    # states exist (independently) for every g_theta up to 1.97 (I1 - 3 = 1.947 < jm there),
    # and mode (30, 0) is still stable at 1.97; a loss of the axisymmetric state below that
    # is wrong. Nor is there a loss at the lock: the substrate's margin 1 - (I1 - 3) / jm at
    # its inner face falls slowly, 0.0038 at g = 2.0 and 0.0015 at 2.0096 (the package's
    # states), the state goes on towards the lock. Found by probing: the march's search for
    # the loss bisected into states whose profile no Chebyshev degree up to 4096 resolves,
    # and reported the edge of the states it could solve (2.0098) as a loss. It now says
    # how far no mode bifurcates, and that the states past it are not resolved.
    with pytest.raises(ConvergenceError, match="no mode bifurcates") as err:
        critical_value(film_on_gent(1.0), 30, 0, "growth[1].theta")
    reached = float(err.value.args[0].split(" up to ")[1].split(",")[0])
    assert 1.97 < reached < 2.0098
    assert "not established" in str(err.value)
    # a state just short of the edge is resolved: within ~5e-9 of it, whether a state's
    # profile resolves by degree 4096 turns on its last digits (cold solves on a grid of
    # step 1e-10 there alternate), so a warm and a cold state of one g can differ
    solve_base_state(film_on_gent(reached - 1e-8))


@pytest.mark.parametrize(
    ("g_z", "radii"),
    [
        # independent quadrature (as above); the film's I1 - 3 is at most 0.83 and 0.93 of jm = 1
        (1.7, (1.1674290804458525, 1.2398147675643523, 2.5854672030158588)),
        (1.8, (1.2637133769078053, 1.3347177600435713, 2.6322939613530494)),
    ],
)
def test_gent_film_growing_axially_short_of_its_lock(g_z, radii):
    # at g_z = 1.7 the unloaded-state search raised a bare ValueError from brentq ("The
    # function value at x=1.0068... is NaN") through solve_base_state (on the command line:
    # "internal error", exit 1); at 1.8 it said no unloaded state exists
    tube = Tube((Layer(1.05, material=gent(1.0), growth=(1.0, 1.0, g_z)), Layer(2.5)))
    state = solve_base_state(tube)
    got = (state.r_i, state.interface_radii[0], state.r_o)
    assert got == pytest.approx(radii, rel=1e-9)
