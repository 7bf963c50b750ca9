"""Where a wall stops being strongly elliptic (incremental/halfspace.py ``not_elliptic``).

The inner layer of ``DIELECTRIC_BILAYER`` stores the electric energy
(-0.0323 I4 + 0.6943 I5 - 0.162 I6) / eps; with no field its incremental permittivity in
a principal direction of stretch lambda is positive while q(lambda) = -0.0323 + 0.6943
lambda^2 - 0.162 lambda^4 is, so the layer loses strong ellipticity where its largest
stretch, the hoop stretch r_i / R_i at its inner face, passes the larger root of q: a
closed form, independent of the half-space matrix that ``not_elliptic`` reads.
"""

from __future__ import annotations

import math
import warnings

import pytest

from electrogrowth import Layer, LinearGrowth, Material, Tube, solve_base_state
from electrogrowth.incremental.halfspace import not_elliptic

#: a soft bilayer grown in hoop in its outer layer (check round 24, D2): mode (7, 4) of
#: growth[2].theta took 190 s to end "inaccurate", its march past the loss of ellipticity
DIELECTRIC_BILAYER = Tube(
    (
        Layer(
            1.14255,
            material=Material("a", "(I1-3)/2 + (-0.0323)*I4 + (0.6943)*I5 + (-0.162)*I6"),
            shear_modulus=0.0003271,
        ),
        Layer(
            1.16939,
            material=Material("b", "(I1-3)/2 + -0.0886*(I1-3)**2 + 0.00769*(I1-3)**3 + I5/2"),
            shear_modulus=0.0008777,
            permittivity=0.1066,
        ),
    ),
    length=0.6364,
    stretch=1.066,
    outer_pressure=-3.593e-05,
)
CONTROL = "growth[2].theta"

#: the hoop stretch at which q(lambda) = -0.0323 + 0.6943 lambda^2 - 0.162 lambda^4 = 0
EDGE_STRETCH = math.sqrt((0.6943 + math.sqrt(0.6943**2 - 4 * 0.162 * 0.0323)) / (2 * 0.162))


@pytest.mark.parametrize("growth", [1.0, 2.0, 2.025])
def test_the_wall_is_elliptic_while_the_inner_hoop_stretch_is_below_the_edge(growth):
    state = solve_base_state(DIELECTRIC_BILAYER.at(CONTROL, growth))
    assert state.r_i < EDGE_STRETCH  # R_i = 1
    assert not_elliptic(state) is None


@pytest.mark.parametrize("growth", [2.03, 2.2965])
def test_the_inner_layer_loses_ellipticity_at_its_inner_face_past_the_edge(growth):
    state = solve_base_state(DIELECTRIC_BILAYER.at(CONTROL, growth))
    assert state.r_i > EDGE_STRETCH
    assert not_elliptic(state) == (1, 1.0)


#: a thin bilayer under voltage whose outer layer's shear modulus gamma_12 is ~0 across it
#: (-1.1e-6 at its inner face, exactly 0 in double precision at its outer one; check round
#: 27, case 3-146): prismatic (16, 0) of growth[2].z spent 160 s retrying the kernel there
SHEARLESS_FILM = Tube(
    (
        Layer(
            1.00251,
            material=Material("t_i2stiff", "(I1-3)/2 + 0.448*(I2-3)**2 + I5/2"),
            shear_modulus=3.37,
            permittivity=1.375,
            growth=LinearGrowth(1.0, 1.00251, 1.077, 1.315),
        ),
        Layer(
            1.01341,
            material=Material(
                "t_mix", "(0.505*(I1-3) + 0.495*(I2-3))/2 + (-0.0688)*(I1-3)*(I2-3) + I5/2"
            ),
            shear_modulus=0.0002327,
            growth=1.011,
        ),
    ),
    length=1.124,
    stretch=1.234,
    voltage=1.386,
    outer_pressure=-0.004408,
)


def test_a_vanishing_shear_modulus_is_the_edge_without_a_warning():
    state = solve_base_state(SHEARLESS_FILM.at("growth[2].z", 1.0110637466867167))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # gamma_12 = 0 divided numpy's matrix: no warning
        assert not_elliptic(state) == (2, 1.00251)
