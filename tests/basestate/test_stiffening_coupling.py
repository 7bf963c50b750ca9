"""A dielectric whose coupling stiffens with stretch, Omega = (I1 - 3)/2 + I5/2 exp((I1 - 3)/10):
its branch Vbar(lambda_i) ends where no charge balances the traction any more (the charge needed
grows without bound), inside the energy's domain.

Found by probing: ``electrogrowth state`` at Vbar = 0.3 exited 2 with "deformation outside the
domain ... the energy is not finite", the user's error, for a valid state. The threshold scan's
charge search doubled c^2 until the energy overflowed at a lambda_i past the branch's end. Such
a lambda_i now has no state (NaN on the scanned curve), and the end of the branch is located
like Gent's lock.
"""

import numpy as np
import pytest
from scipy.integrate import quad

from electrogrowth import Layer, Tube, solve_base_state
from electrogrowth.cli.app import main
from electrogrowth.model.energy_text import energy_material

TEXT = "(I1 - 3)/2 + I5/2*exp((I1-3)/10)"
MATERIAL = energy_material(TEXT)


def residuals(state) -> tuple[float, float]:
    """Traction int (tau_2 - tau_1) dr / r and Vbar - int E dr / (Rbar_o - 1), by adaptive
    quadrature in R of the material's stresses at the state's stretches (independent of the
    solver's Gauss and Chebyshev rules)."""
    t = state.tube

    def local(R):
        r = float(state.radius(np.array([R]))[0])
        l1, l2, l3 = (float(x[0]) for x in state.elastic_stretches(np.array([R])))
        d = state.charge / r
        drdR = R * t.growth**3 / (t.stretch * r)
        return r, (l1, l2, l3), d, drdR

    def traction(R):
        r, s, d, drdR = local(R)
        tau = MATERIAL.stress(*s, d)
        return float(tau[1] - tau[0]) * drdR / r

    def field(R):
        r, s, d, drdR = local(R)
        return float(MATERIAL.electric_field(*s, d)) * drdR

    Ro = t.outer_radius
    m = quad(traction, 1.0, Ro, epsabs=1e-13, epsrel=1e-12)[0]
    v = quad(field, 1.0, Ro, epsabs=1e-14, epsrel=1e-13)[0] / (Ro - 1.0)
    return m, t.voltage - v


# quad's roundoff warning at Vbar = 30: stresses ~3e3 cancel to the traction (checked below)
@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
@pytest.mark.parametrize("voltage", [0.3, 3.0, 30.0])
def test_states_on_the_branch_solve(voltage):
    state = solve_base_state(Tube.uniform(1.6, 1.0, material=MATERIAL, voltage=voltage))
    assert state.threshold_kind == "locking" and state.voltage_threshold == np.inf
    traction, volt = residuals(state)
    # the stresses grow like the Maxwell stress, Vbar^2: the traction's rounding with them
    assert abs(traction) <= 1e-12 * max(1.0, voltage**2) and abs(volt) <= 1e-11 * voltage


def test_the_branch_ends_inside_the_domain():
    low = solve_base_state(Tube.uniform(1.6, 1.0, material=MATERIAL, voltage=30.0))
    high = solve_base_state(Tube.uniform(1.6, 1.0, material=MATERIAL, voltage=300.0))
    end = low.threshold_lambda_i  # where the charge needed leaves the energy's domain
    assert low.lambda_i < high.lambda_i < end < 4.0
    assert high.charge > 10 * low.charge


def test_command_line_state(capsys):
    code = main(["state", "--energy", TEXT, "--voltage", "0.3", "--outer-radius", "1.6"])
    assert code == 0, capsys.readouterr().err


@pytest.mark.filterwarnings("error::RuntimeWarning")
@pytest.mark.parametrize("voltage", [0.3, 3.0])
def test_split_into_two_identical_layers(voltage):
    # the layered solver's charge search meets the same end of the branch (quietly: its
    # probes past it are NaN, not warnings)
    split = Tube((Layer(1.3, MATERIAL), Layer(1.6, MATERIAL)), length=1.0, voltage=voltage)
    whole = Tube.uniform(1.6, 1.0, material=MATERIAL, voltage=voltage)
    a, b = solve_base_state(split), solve_base_state(whole)
    assert a.lambda_i == pytest.approx(b.lambda_i, rel=1e-13)
