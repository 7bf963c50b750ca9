"""An energy that loses strong ellipticity in the r-theta plane at the tube's stretch: the
unloaded state exists (homogeneous, l_r = l_theta = lambda_z^(-1/2)) but its in-plane shear
modulus, the Baker-Ericksen quotient of tau_2 - tau_1, is <= 0 there, so the wall's
hoop/radial response falls as it opens and no state is followed (basestate/ellipticity.py).

A Mooney-Rivlin solid with a negative I2 weight, (c1 (I1-3) + c2 (I2-3)) / 2 + I5 / 2,
c1 = 2.36, c2 = -1.36, has gamma_12 = (c1 + c2 lambda^2) / lambda there, zero at
lambda = sqrt(c1 / -c2) = 1.3173 (check round 27, case 3-23): it was refused as "Vbar(lambda_i)
does not rise from lambda_i0" even at V = 0 (one layer), or "no unloaded state found"
(layered).
"""

import math

import pytest

from electrogrowth import Layer, Material, Tube, solve_base_state
from electrogrowth.basestate.ellipticity import in_plane_shear, shear_moduli
from electrogrowth.basestate.tube import voltage_threshold
from electrogrowth.cli.app import main
from electrogrowth.errors import BaseStateError
from electrogrowth.model.moduli import neo_hookean_moduli

C1, C2 = 2.36, -1.36
SOFTENING = Material("mr-", f"({C1}*(I1-3) + ({C2})*(I2-3))/2 + I5/2")
LIMIT = math.sqrt(C1 / -C2)


@pytest.mark.parametrize("stretch", [0.8, 1.2, 1.5, 2.0])
def test_the_in_plane_shear_modulus_is_the_closed_form(stretch):
    assert in_plane_shear(SOFTENING, stretch) == pytest.approx(
        (C1 + C2 * stretch**2) / stretch, rel=1e-12
    )


def test_the_shear_moduli_of_the_neo_hookean_dielectric():
    """Its moduli in closed form: the field's share leaves gamma_12 = gamma_13 = l1^2."""
    l1, l2, l3, d = 0.8, 1.1, 1 / 0.88, 0.7
    got = shear_moduli(neo_hookean_moduli(l1, l2, l3, d))
    assert got == pytest.approx([l1**2, l1**2, l2**2, l3**2, l2**2, l3**2], rel=1e-14)


@pytest.mark.parametrize("stretch", [1.4, 1.5, 2.0])
def test_a_uniform_tube_past_the_limit_is_refused_naming_it(stretch):
    tube = Tube.uniform(2.0, stretch=stretch, material=SOFTENING)
    for call in (solve_base_state, voltage_threshold):  # was "does not rise" at V = 0
        with pytest.raises(BaseStateError, match="not strongly elliptic") as e:
            call(tube)
        assert f"elliptic below lambda_z / g_z = {LIMIT:.10g}" in str(e.value)
        assert f"{LIMIT:.6g}" in e.value.remedy


def test_inside_the_limit_the_state_is_the_homogeneous_one():
    state = solve_base_state(Tube.uniform(2.0, stretch=1.3, material=SOFTENING))
    assert state.lambda_i == pytest.approx(1.3**-0.5, rel=1e-12)


def test_a_layer_past_the_limit_is_named():
    """Stiff layer of that energy under a soft one (check round 27, c323b.py): "no unloaded
    state (V = 0, P_i = P_o) found for this tube" before."""
    soft = Material("b", "(0.0878*(I1-3) + 0.9122*(I2-3))/2 + (-0.0826)*(I1-3)*(I2-3) + I5/2")
    layers = (Layer(1.00148, material=SOFTENING, shear_modulus=6177.0), Layer(1.01077, soft))
    with pytest.raises(BaseStateError, match="layer 1 of this tube .* not strongly elliptic"):
        solve_base_state(Tube(layers, length=8.787, stretch=1.5))
    inside = solve_base_state(Tube(layers, length=8.787, stretch=1.3))
    assert inside.lambda_i == pytest.approx(1.3**-0.5, rel=1e-12)


def test_the_command_line_says_so_with_exit_status_2(capsys):
    energy = f"({C1}*(I1-3) + ({C2})*(I2-3))/2 + I5/2"
    args = ["state", "--energy", energy, "--outer-radius", "2", "--stretch", "1.5"]
    assert main(args) == 2  # was the same status, blaming the voltage's scan
    err = capsys.readouterr().err
    assert "not strongly elliptic" in err and "use a stretch with lambda_z / g_z below" in err
