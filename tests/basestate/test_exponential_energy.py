"""An uncharged tube of an exponentially stiffening energy (Fung type, an energy text of the
grammar's ``exp``) has its homogeneous state at every axial stretch, and the commands that
need it do not crash.

Omega = exp((I1 - 3)/2) - 1 + I5/2 has mu = eps = 1 in the reference state. An ungrown,
uncharged tube at the axial stretch lambda_z is homogeneous: lambda_r = lambda_theta =
lambda_z^(-1/2) through the wall, lambda_i = lambda_z^(-1/2), whatever the energy.

Found by probing: ``solve_base_state`` of that tube at lambda_z = 0.245 raised numpy's
LinAlgError ("Array must not contain infs or NaNs", from the voltage threshold's limit-point
search, basestate/voltage.py ``_limit_point``: the tube carries no voltage), and at
lambda_z <= 0.215 ConvergenceError "quadrature not converged"; the voltage threshold scans
Vbar(lambda_i) far beyond the state asked for, where exp(I1 / 2) overflows. Through the crease
criterion's Biot ratio (its half-space march runs to lambda_z = 0.05) the verdict of a
(0, 1) wrinkle crashed too: ``electrogrowth critical ... --energy "(exp(0.5*(I1-3))-1) + I5/2"
--mode 0 1`` printed "internal error: LinAlgError" and no value, exit status 1, while the
value itself is fine (lambda_z,cr = 0.418141270798; collocation agrees to 3e-13).

The same with a milder exponent, Omega = (exp(0.2 (I1 - 3)) - 1) / 0.4 + I5/2, at ordinary
strains: ``solve_base_state(Tube.uniform(1.4, growth=g, material=...))`` raised LinAlgError
at g = 1.18, 1.38, 1.88, 2.98, ... (sporadic points of a 0.02 grid), where the same tube cut
into two identical layers (the layered solver) gives its state (lambda_i = 1.2818080979616
at g = 1.18), and ``critical_value(tube, 3, 1, "growth")`` crashed with it (either method).
"""

import json
import warnings

import numpy as np
import pytest

from electrogrowth import Layer, Material, Tube, critical_value, gent, solve_base_state
from electrogrowth.cli.app import main

FUNG_TEXT = "(exp(0.5*(I1-3))-1) + I5/2"
FUNG = Material("fung", FUNG_TEXT)
MILD = Material("fung-0.2", "(exp(0.2*(I1-3))-1)/0.4 + I5/2")


@pytest.mark.parametrize("stretch", [0.3, 0.245, 0.21])
def test_homogeneous_state_of_an_exponential_energy(stretch):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        state = solve_base_state(Tube.uniform(2.0, 1.0, stretch=stretch, material=FUNG))
    assert state.lambda_i == pytest.approx(stretch**-0.5, rel=1e-10)


def test_verdict_of_an_exponential_energy_does_not_crash(capsys):
    tube = Tube.uniform(2.2, 1.5, material=FUNG)
    crit = critical_value(tube, 0, 1, "stretch", side="compression")
    assert crit.value == pytest.approx(0.418141270798, rel=1e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        verdict = crit.verdict
    assert verdict.wrinkle is not None and verdict.wrinkle.value == crit.value
    args = ["critical", "--solve-for", "stretch", "--side", "compression"]
    args += ["--outer-radius", "2.2", "--length", "1.5", "--energy", FUNG_TEXT]
    assert main([*args, "--mode", "0", "1", "--json", "--quiet"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["value"] == pytest.approx(crit.value, rel=1e-10)


@pytest.mark.parametrize("growth", [1.18, 1.38])
def test_grown_state_of_a_mild_exponential_energy_equals_two_identical_layers(growth):
    split = Tube(
        (Layer(1.2, material=MILD, growth=growth), Layer(1.4, material=MILD, growth=growth)),
        stretch=1.0,
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        uniform = solve_base_state(Tube.uniform(1.4, growth=growth, material=MILD))
    assert uniform.lambda_i == pytest.approx(solve_base_state(split).lambda_i, rel=1e-10)


def test_critical_growth_of_a_mild_exponential_energy():
    tube = Tube.uniform(1.4, material=MILD)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        imp = critical_value(tube, 3, 1, "growth")
        col = critical_value(tube, 3, 1, "growth", method="collocation")
    assert imp.status == "ok"
    assert col.value == pytest.approx(imp.value, rel=1e-8)


#: Fung type with a quadratic exponent: its stresses ~ (I1 - 3) exp((I1 - 3)^2) overflow a
#: double while the energy itself is still finite (I1 - 3 ~ 26.6)
FUNG_SQUARED = Material("fung-squared", "(I1-3)/2 + I5/2 + 0.1*(exp((I1-3)**2) - 1)")


def test_states_of_an_energy_whose_stresses_overflow_first_solve_everywhere():
    """The voltage threshold's scan of Vbar(lambda_i) (basestate/voltage.py
    ``charge_and_voltage``, run for every state, charged or not) reached lambda_i where the
    energy is finite but its stresses overflow; the material raised ParameterError
    ("deformation outside the domain ... derivatives are not finite") instead of the scan
    ending its branch there. Sporadic in g (1.335, 1.565, 1.83 of a 0.005 grid over
    [1, 3]), so a growth scan of this tube stopped at g = 1.335 blaming the user, while the
    single mode (0, 1) marched on to g = 4.28. Every state of the grid now solves, and
    equals the same tube cut into two identical layers (the layered solver, which never
    scans the threshold)."""
    tube = Tube.uniform(1.5, length=1.0, material=FUNG_SQUARED)
    for g in (1.0 + 0.005 * np.arange(400)).tolist():
        solve_base_state(tube.at("growth", g))
    two = Tube(
        (Layer(1.2, material=FUNG_SQUARED, growth=1.335),
         Layer(1.5, material=FUNG_SQUARED, growth=1.335)),
        length=1.0,
    )  # fmt: skip
    one = solve_base_state(tube.at("growth", 1.335)).lambda_i
    assert one == pytest.approx(solve_base_state(two).lambda_i, rel=1e-12)


def _mucosa(g_theta: float) -> Tube:
    """Probe 11a's Fung mucosa, 0.1 thick and 10 times as stiff, growing in the hoop
    direction."""
    return Tube(
        (Layer(1.1, material=FUNG_SQUARED, shear_modulus=10.0, growth=(1.0, g_theta, 1.0)),
         Layer(2.0, material=FUNG_SQUARED)),
        length=4.0,
    )  # fmt: skip


def test_a_layered_state_whose_node_probe_overflows_solves():
    """``solve_base_state`` of this bilayer at g_theta = 3.475 raised ParameterError
    ("deformation outside the domain of 'fung-squared' (I1 = 29.6251): the energy's
    derivatives are not finite there") while 3.45 and 3.5 solved. The state lies far inside
    the double range (I1 < 5); the node count's probe at 3 times the guess
    (basestate/plies.py ``choose_nodes``) met a point of the outer layer where the energy
    is finite, exp(708.9), but its derivative overflows. ``Ply.finite`` looked at the
    energy alone, so the point reached ``Material.stress``, which blames the user. Such a
    point is now no state to use (NaN, as beyond a lock), and the probe is left out.

    The state: continued by Newton from its neighbour at 3.45, and independently the root of
    the traction integral (*) by mpmath's adaptive quadrature at 30 digits, r_i =
    2.04274157844085094524."""
    cold = solve_base_state(_mucosa(3.475))
    warm = solve_base_state(_mucosa(3.475), near=solve_base_state(_mucosa(3.45)))
    assert cold.r_i == pytest.approx(2.04274157844085094524, rel=1e-13)
    assert cold.r_i == pytest.approx(warm.r_i, rel=1e-13)
    assert cold.quadrature_error <= 1e-12


def test_a_trial_stress_that_overflows_is_nan_but_the_users_is_refused():
    """The two ways to meet a deformation where the stresses are not finite: the solver's
    own trial point (``Material.finite_stress``: NaN there, finite values elsewhere
    unchanged) and the user's (``Material.stress``: one ParameterError naming it), the
    same for an exponential past the double range and a Gent layer past its lock."""
    from electrogrowth.errors import ParameterError

    # plane strain (1 / l, l, 1): I1 = l^2 + l^-2 + 1, 29.6251 (energy finite) and 4.5625
    band = ((28.6251 + (28.6251**2 - 4.0) ** 0.5) / 2.0) ** 0.5
    assert np.isfinite(FUNG_SQUARED.numeric()[0](band**2 + band**-2 + 1.0, 0, 0, 0, 0))
    for material, bad in ((FUNG_SQUARED, band), (gent(3.0), 2.5)):  # Gent: I1 - 3 = 4.41
        l = np.array([1.1, bad])
        stretches = (1.0 / l, l, 1.0)
        tau = material.finite_stress(*stretches, 0.0)
        assert np.isfinite(tau[:, 0]).all() and np.isnan(tau[:, 1]).all()
        assert tau[:, 0] == pytest.approx(material.stress(1 / 1.1, 1.1, 1.0, 0.0), rel=1e-15)
        with pytest.raises(ParameterError, match="outside the domain"):
            material.stress(*stretches, 0.0)


@pytest.mark.parametrize(
    "tube",
    [
        Tube.uniform(1.5, material=FUNG_SQUARED, stretch=5.41),  # I1 = 29.64: energy finite
        Tube.uniform(1.5, material=FUNG_SQUARED, stretch=6.0),  # I1 = 36.3: energy too
        Tube(
            (
                Layer(1.1, material=FUNG_SQUARED, shear_modulus=10.0),
                Layer(2.0, material=FUNG_SQUARED),
            ),
            length=4.0,
            stretch=5.4075,
        ),
    ],  # fmt: skip
    ids=["uniform-stresses", "uniform-energy", "layered-stresses"],
)
def test_a_state_whose_own_stresses_overflow_is_not_blamed_on_the_user(tube):
    """A state that lies where the stresses themselves pass the largest double (axial
    stretch 5.41: I1 = 29.64 through the uniform wall) cannot be computed, yet it exists
    (exp is finite everywhere). The uniform tube raised the material's ParameterError
    ("deformation outside the domain ... derivatives are not finite", at 5.4075 and 5.41
    of a 0.0025 grid) or, where the energy overflows too, BaseStateError "the energy ...
    is undefined in the homogeneous state"; the layered tube "no unloaded state found"
    (BaseStateError, once the node-count probe no longer raised). Each is now a
    ConvergenceError naming the overflow, whose remedy is less load, not a looser rtol."""
    from electrogrowth import ConvergenceError
    from electrogrowth.errors import OVERFLOW

    with pytest.raises(ConvergenceError, match="overflow a double") as exc:
        solve_base_state(tube)
    assert exc.value.remedy is OVERFLOW


@pytest.mark.parametrize(
    "tube",
    [
        Tube.uniform(1.5, material=gent(1.0), stretch=3.0),
        Tube((Layer(1.5, material=gent(1.0)), Layer(2.0)), length=4.0, stretch=3.0),
    ],
    ids=["uniform", "layered"],
)
def test_a_gent_layer_stretched_past_its_lock_still_has_no_state(tube):
    """The other end of an energy's domain, a lock (Gent's energy is NaN past it), keeps
    its BaseStateError: there no state exists (lambda_z = 3 gives I1 - 3 > 1 = J_m)."""
    from electrogrowth import BaseStateError

    with pytest.raises(BaseStateError, match="no unloaded state|undefined"):
        solve_base_state(tube)


@pytest.mark.parametrize("stretch", [5.385, 5.39])
def test_next_to_the_overflow_band_an_honest_error_and_no_warnings(stretch):
    """A uniform tube of FUNG_SQUARED just below the stretch where its own stresses pass the
    double range (5.4075): its state solves, its moduli or their products do not fit a
    double. The result was already a ConvergenceError, but NumPy's RuntimeWarnings (the
    chain rule's products, the table's DCT, the collocation fallback's NaN algebra)
    reached the Python API's stderr; and at 5.39 the table doubled its points to 1025
    before calling the state "not resolved". Now: the same error class, no warning, and a
    table of non-finite moduli is named as the overflow at once."""
    from electrogrowth import ConvergenceError, critical_value
    from electrogrowth.errors import OVERFLOW

    tube = Tube.uniform(1.4, 1.0, stretch=stretch, material=FUNG_SQUARED)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(ConvergenceError) as err:
            critical_value(tube, 1, 1, "growth")
    if stretch == 5.39:
        assert "moduli overflow a double" in str(err.value)
        assert err.value.remedy == OVERFLOW
