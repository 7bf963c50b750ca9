"""A state that has lost strong ellipticity has no target to fall back to (check round 27,
case 3-91: critical (6, 1) of growth[2] on a two-layer tube ended, after 65 s, in "the
bracketed root solve failed on [1.61..., 1.610000045...]: f(a) and f(b) must have
different signs").

Layer 1's A3131 (normal z, polarisation r) falls through 0 at growth[2] ~ 1.586; from 1.6 the
kernel's integration underflows at every tolerance, and the collocation fallback's sign
changes with its node count: the march read a 'dip' from the kernel's 2e-3 to collocation's
+-1e-7, and the fine value at the dip's start was already negative."""

import numpy as np
import pytest

from electrogrowth import Layer, Material, Tube, critical_value
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.errors import ConvergenceError
from electrogrowth.incremental.targets import collocation_targets
from electrogrowth.model.moduli import MODULI_INDEX

MIXED = Material("mix", "(0.665*(I1-3) + 0.335*(I2-3))/2 + (-0.0636)*(I1-3)*(I2-3) + I5/2")
TANH = Material("tanh", "1.48*tanh((I1-3)/(2*1.48)) + I5/2")
TUBE = Tube(
    (
        Layer(1.11476, material=MIXED, shear_modulus=0.1046, growth=(0.9648, 1.25, 0.6898)),
        Layer(1.19407, material=TANH, shear_modulus=2.478),
    ),
    length=16.66,
    stretch=0.6836,
    voltage=0.5792,
    inner_pressure=0.03629,
)


def test_the_state_there_is_not_elliptic_and_collocation_has_no_sign():
    state = TubeAt(TUBE, "growth[2]").state(1.61)
    R = np.linspace(1.0, 1.11476, 9)[1:-1]
    a3131 = state.moduli(R)[:, MODULI_INDEX["A3131"]] / 0.1046
    assert a3131.min() < -0.1
    mode = np.array([[6.0, 1.0]])
    signs = {np.sign(collocation_targets(state, mode, nodes=n)[0]) for n in (40, 60)}
    assert signs == {-1.0, 1.0}  # the fallback's sign is its discretisation's


def test_the_march_says_where_and_why_it_stops():
    with pytest.raises(ConvergenceError, match="not strongly elliptic") as e:
        critical_value(TUBE, 6, 1, "growth[2]")
    text = str(e.value)
    assert "up to 1.56, and past it none is resolved" in text
    assert "A3131 of layer 1" in text and "bracketed root solve" not in text
    assert "loses strong ellipticity" in e.value.remedy
