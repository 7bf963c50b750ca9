"""An energy whose electric field closes the bore above lambda_i0: the charged branch runs
inward (check round 24, D1; check round 28, D1; basestate/voltage.py `_runs_inward`,
thresholds.inward).

`(I1-3)/2 + 0.2*I4 + 0.4*I5 - 0.1*I6` passes the unit check. In a uniform tube
(Rbar_o 2) compressed to lambda_z <= 0.49, the charge makes the hoop residual of (*) rise:
just above lambda_i0 no charge balances it, just below it one does, and Vbar rises as
lambda_i falls, to a limit point. The threshold's scan in rising lambda_i (8 % steps) once
jumped the gap to states of another branch: "internal error: LinAlgError" at 0.46-0.48,
a locking stretch 1.7076 at 0.4, "none (unbounded)" at 0.49; then (check round 24) the
branch was called "closing" (threshold 0) and every charged state refused, while they
exist. The crease criterion's Biot ratio compresses a tube through that range.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from electrogrowth import Layer, Material, Tube, gent, neo_hookean, solve_base_state
from electrogrowth.basestate import thresholds, voltage
from electrogrowth.basestate.tube import voltage_threshold
from electrogrowth.bifurcation.crease import biot_ratio, crease_onset

CLOSING = Material("closing", "(I1-3)/2 + 0.2*I4 + 0.4*I5 - 0.1*I6")


def _inward_limit_point(stretch: float) -> tuple[float, float]:
    """(Vbar, lambda_i) at the top of the inward branch by another route: q from the
    one-layer hoop residual by scipy's brentq at each lambda_i, V by its quadrature,
    maximised by scipy's bounded Brent (not the package's scan and Chebyshev interpolant)."""
    lam0 = stretch**-0.5
    wall = voltage.UniformWall(CLOSING, 2.0, 1.0, stretch, 64)

    def vbar(lam):
        def f(q):
            return float(wall.hoop(np.array([lam]), q)[0][0])

        hi = 1e-3
        while np.sign(f(hi)) == np.sign(f(0.0)):
            hi *= 2.0
        return wall._voltage_of_charge(lam, math.sqrt(brentq(f, 0.0, hi, rtol=1e-15)))

    top = minimize_scalar(
        lambda x: -vbar(x),
        bounds=(0.8 * lam0, 0.99 * lam0),
        method="bounded",
        options={"xatol": 1e-10},
    )
    return -top.fun, top.x


@pytest.mark.parametrize("stretch", [0.40, 0.47, 0.49])
def test_the_charged_branch_runs_inward_to_a_limit_point(stretch):
    # check round 24: LinAlgError, "locking", "none"; then (0, "closing") and every
    # charged state refused ("closes the bore")
    tube = Tube.uniform(2.0, stretch=stretch, material=CLOSING)
    value, kind, lam = voltage_threshold(tube)
    top, at = _inward_limit_point(stretch)
    assert kind == "limit point" and value == pytest.approx(top, rel=1e-12)
    assert lam == pytest.approx(at, rel=1e-6)  # a flat maximum: located to sqrt(eps)
    assert solve_base_state(tube).lambda_i == pytest.approx(stretch**-0.5, rel=1e-12)
    state = solve_base_state(tube.at("voltage", 0.5 * value))
    assert at < state.lambda_i < stretch**-0.5


def test_the_charge_raises_the_hoop_residual_above_lambda_i0():
    """Why: the traction's residual (*) above lambda_i0 grows with the charge q (an ideal
    dielectric's falls through zero), and below lambda_i0 it rises through zero."""
    lam0, nodes = voltage._mechanical(CLOSING, 2.0, 1.0, 0.47, 1e-12)
    wall = voltage.UniformWall(CLOSING, 2.0, 1.0, 0.47, nodes)
    qs = (0.0, 1e-2, 1e-1, 1.0)
    above = [wall.hoop(np.array([lam0 * 1.001]), q)[0][0] for q in qs]
    below = [wall.hoop(np.array([lam0 * 0.999]), q)[0][0] for q in qs]
    assert above[0] > 0 and np.all(np.diff(above) > 0)
    assert below[0] < 0 < below[-1]


def test_an_opening_branch_of_the_same_energy_is_unchanged():
    value, kind, _ = voltage_threshold(Tube.uniform(2.0, stretch=0.6, material=CLOSING))
    assert (value, kind) == (math.inf, "none")


def test_the_crease_criterion_of_such_an_energy_is_evaluated():
    """Its Biot ratio compresses an uncharged tube through that range: LinAlgError before
    (every critical value's verdict, curve and design with such a layer)."""
    # uncharged, the energy is neo-Hookean: its Biot ratio and crease onset are that
    # solid's (the crease at lambda_z = 2.4^(-2/3), docs/derivation-crease.md)
    assert biot_ratio(CLOSING) == pytest.approx(biot_ratio(neo_hookean()), rel=1e-12)
    onset = crease_onset(Tube.uniform(1.4, material=CLOSING), "stretch", side="compression")
    assert onset.kind == "crease" and onset.value == pytest.approx(2.4 ** (-2 / 3), rel=1e-3)


def test_a_lock_next_to_the_unloaded_state_is_no_closing_field():
    """A Gent layer (J_m 0.5) whose unloaded state lies next to its lock has no finite Vbar
    just above lambda_i0 either: the energy's edge, not a field closing the bore (a second
    read of the change: it was called closing and every charged state refused)."""
    tube = Tube.uniform(2.0, material=gent(0.5))
    assert voltage_threshold(tube)[1] == "locking"
    assert solve_base_state(tube.at("voltage", 0.05)).lambda_i > 1.0


def test_two_layers_of_such_an_energy_read_the_one_layer_threshold():
    """Two identical layers are the one-layer tube: the inward branch's limit point, the
    uncharged state, a charged one (the layered walk met the gap: 'no state somewhere in
    it' at 0.47, "locking" at lambda_i0 at 0.45; then "closing")."""
    for stretch in (0.45, 0.47):
        one = Tube.uniform(2.0, stretch=stretch, material=CLOSING)
        two = Tube((Layer(1.5, material=CLOSING), Layer(2.0, material=CLOSING)), stretch=stretch)
        v1, k1, lam1 = voltage_threshold(one)
        v2, k2, lam2 = voltage_threshold(two)
        assert k2 == k1 == "limit point" and v2 == pytest.approx(v1, rel=1e-14)
        assert lam2 == pytest.approx(lam1, rel=1e-8)
        state = solve_base_state(two)
        assert state.lambda_i == pytest.approx(stretch**-0.5, rel=1e-12)
        charged = [solve_base_state(t.at("voltage", 0.1)).lambda_i for t in (one, two)]
        assert charged[1] == pytest.approx(charged[0], rel=1e-12)
        assert charged[0] < stretch**-0.5


def _residual_with_charge(tube: Tube, qs) -> list[float]:
    """The wall's hoop residual T of (*) 0.1 % above its unloaded r_i, at charges q = c^2:
    the layered derivation's test, read off the wall's integrals (not the walk's probe)."""
    prep = thresholds.prepare(tube, 1e-12)
    x0, lz0 = prep.loaded
    r, lz = np.array([x0 * 1.001]), np.array([lz0])
    return [float(prep.wall.integrals(r, lz, np.sqrt(q))[0][0]) for q in qs]


@pytest.mark.parametrize(
    ("inner", "outer_material", "kind"),
    [(1.9, neo_hookean(), "limit point"), (1.5, neo_hookean(), "none")],
)
def test_a_mixed_stack_runs_inward_where_the_charge_raises_its_residual(
    inner, outer_material, kind
):
    """The energy over a neo-Hookean layer at lambda_z = 0.45: with a thin neo-Hookean skin
    the charge still raises the wall's residual above the start (the branch runs inward),
    with a thick one it lowers it (the branch opens: unchanged, "none")."""
    tube = Tube(
        (Layer(inner, material=CLOSING), Layer(2.0, material=outer_material)), stretch=0.45
    )
    residual = _residual_with_charge(tube, (0.0, 1e-2, 1e-1))
    rises = bool(np.all(np.diff(residual) > 0))
    assert rises == (kind == "limit point")
    value, got, lam = voltage_threshold(tube)
    assert got == kind
    if rises:  # on main: (0, "closing"), every charged state refused
        start = solve_base_state(tube).lambda_i
        assert lam < start and value > 0
        assert lam < solve_base_state(tube.at("voltage", 0.5 * value)).lambda_i < start
