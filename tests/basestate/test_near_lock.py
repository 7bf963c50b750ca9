"""A stiff layer growing against a Gent layer close to (not at) its locking stretch.

The unloaded state exists there; the expected radii come from an independent quadrature of the
radial equilibrium, sigma_rr(r_o) = int (sigma_tt - sigma_rr) dr / r = 0, written in principal
stretches (neo-Hookean film, Gent substrate, jm = 2), root in r_i by brentq. At hoop growth 1.9
the substrate's inner face has I1 - 3 = 1.755, 88 % of jm: a regular state, not a lock.
"""

import dataclasses

import pytest

from electrogrowth import Layer, Tube, critical_value, gent, mooney_rivlin, solve_base_state
from electrogrowth.errors import BaseStateError, ConvergenceError, python_remedy


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


@pytest.mark.slow  # 10-25 s: make test-slow runs it
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
    # 2.0098 before the cold search refined its Gauss rule next to the lock (probe 11a, D4);
    # now 2.0177, with states that are right: at 2.0176 (margin 6.1e-4) the independent
    # quadrature (40 digits, the root bracketed short of the lock) gives r_i 1.9673686973637
    assert 1.97 < reached < 2.02
    assert solve_base_state(film_on_gent(2.0176)).r_i == pytest.approx(1.9673686973637, rel=1e-11)
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


def stiff_film_in_gent(g_theta: float, voltage: float = 0.0) -> Tube:
    """A film 10 times as stiff grown in the hoop direction inside a Gent (jm 3) layer (probe
    11a, D4): the Gent layer's inner face nears its lock (1 - (I1 - 3) / jm = 0.0018 at
    g_theta 5.41), the film is compressed, and the state goes on towards the lock."""
    layers = (
        Layer(1.04, shear_modulus=10.0, growth=(1.0, g_theta, 1.0)),
        Layer(1.6, material=gent(3.0)),
    )
    return Tube(layers, length=3.0, stretch=1.0, voltage=voltage)


@pytest.mark.parametrize(
    ("g_theta", "r_i"),
    [
        # independent: the radial equilibrium above, in mpmath (40 digits, tanh-sinh), the
        # root bracketed short of the Gent face's lock; margins 0.0018, 0.0016, 0.00092
        (5.41, 2.175912909683),
        (5.45, 2.175371753466),
        (5.58, 2.173436043256),
    ],
)
def test_cold_search_next_to_a_lock_finds_the_state(g_theta, r_i):
    # the cold solve raised "no unloaded state (V = 0, P_i = P_o) found" from 5.4 on, with
    # the remedy "move the growth ... back towards 1" (with Vbar 0.2: "lower the voltage"),
    # while the states exist: the unloaded search ran at the Gauss rule chosen at the
    # homogeneous guess (12 nodes), whose T errs by tenths next to the lock and put the
    # root past the Gent layer's edge; the search now refines the rule before giving up
    assert solve_base_state(stiff_film_in_gent(g_theta)).r_i == pytest.approx(r_i, rel=1e-11)


def stretched_gent_pair(stretch: float) -> Tube:
    """Check round 15 (D1): a Mooney-Rivlin core inside two Gent (jm 3) layers, stretched
    towards the outer layer's point lock lambda_z^2 + 2 / lambda_z = 6 (at 2.2618102)."""
    layers = (
        Layer(1.495939775554611, mooney_rivlin(0.8), shear_modulus=48.89900100283162),
        Layer(1.7057300432216378, gent(3.0), shear_modulus=3.9436486226610885, growth=1.034),
        Layer(2.2701926109254207, gent(3.0), shear_modulus=0.33345072666259745),
    )
    return Tube(layers, stretch=stretch)


@pytest.mark.parametrize(
    ("stretch", "r_i"),
    [
        # independent: the radial balance int (s_tt - s_rr) / r dr = 0 of the three layers
        # in mpmath (30 digits), root in r_i by bisection (check15 probe/indep5.py); the
        # continued states (bifurcation.along.TubeAt) agree to 1e-14
        (2.26175, 0.6432968996301939),
        (2.2618, 0.6410425573468315),
    ],
)
def test_cold_search_finds_a_window_narrower_than_its_steps(stretch, r_i):
    # the finite states form a window in r_i around the least-stretched state, 7 % wide at
    # 2.26175 and 1.2 % at 2.2618, between the guess (0.6706, past the lock) and its
    # neighbours 1.1 times away: the cold search met none and raised "no unloaded state
    # ... found before a layer's lock"; it now starts from the least-stretched state
    assert solve_base_state(stretched_gent_pair(stretch)).r_i == pytest.approx(r_i, rel=1e-12)


def test_no_window_past_the_point_lock():
    # 2.2619^2 + 2 / 2.2619 - 3 = 3.0004 > jm: no r_i gives the outer layer a finite energy
    with pytest.raises(BaseStateError, match="no unloaded state"):
        solve_base_state(stretched_gent_pair(2.2619))


def test_no_unloaded_state_does_not_blame_the_voltage():
    # past the kinematic lock (lambda_z = 2.3: lambda^2 + 2 / lambda - 3 = 3.16 > jm) no
    # unloaded state exists; the search is at V = 0, so the remedy must not name the voltage
    tube = dataclasses.replace(stiff_film_in_gent(1.0, voltage=0.2), stretch=2.3)
    with pytest.raises(BaseStateError, match="no unloaded state") as err:
        solve_base_state(tube)
    assert "voltage" not in err.value.remedy
    assert "voltage" not in python_remedy(err.value.remedy)


def test_the_voltage_stage_of_a_pressurised_tube_names_its_pressure():
    """Probe 13a (doubt): a closed-ended three-layer tube near its lock at P_i = 1.35 was
    refused as "Vbar = 0.1 lies too close to the locking stretch" while the pressure was what
    moved: the voltage stage is applied at the tube's pressure, and its words now say so."""
    from electrogrowth.basestate.layered import _voltage_stage
    from electrogrowth.model.layers import Layer, Tube

    tube = Tube([Layer(1.2), Layer(1.8)], voltage=0.1)
    assert _voltage_stage(tube) == "Vbar = 0.1"
    assert _voltage_stage(tube.at("pressure", 1.35)) == "Vbar = 0.1 at P_i - P_o = 1.35"
