"""A critical value is not read past a loss of strong ellipticity the axes do not show
(incremental/targets.py ``_lost_ellipticity``).

Mode (7, 4) of the dielectric bilayer (tests/incremental/test_halfspace.py) is marched past
growth 2.029, where its inner layer's hoop permittivity turns negative (a closed form) while
its six shear moduli stay above 0.17 of its own. The kernel fails at every state from there
(step size underflow, also at 1e-14), and the march went on on collocation, whose sign there
changes with its nodes (+, -, +, - at 40, 56, 72, 100 at growth 2.2965): a root at 2.2965,
estimate 9.3e-3, and another at 2.2773 at rtol 1e-14, "inaccurate" after 190 s (check round
24, D2).
"""

from __future__ import annotations

import pytest

from electrogrowth import Layer, Material, Tube
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.errors import ConvergenceError
from electrogrowth.incremental import targets
from tests.incremental.test_halfspace import CONTROL, DIELECTRIC_BILAYER


def test_the_march_stops_where_the_permittivity_turns_negative(monkeypatch):
    asked = []
    monkeypatch.setattr(targets, "collocation_targets", lambda *a, **k: asked.append(a))
    with pytest.raises(ConvergenceError, match="layer 1 at R = 1: a real wave vector") as err:
        critical_value(DIELECTRIC_BILAYER, 7, 4, CONTROL)
    assert asked == []  # no collocation value read (was: 126 states of the march)
    # the march examined every state up to the loss: it ends past growth 2.0
    last = float(str(err.value).split(" up to ")[1].split(",")[0])
    assert 2.0 < last < 2.1  # the edge, r_i = EDGE_STRETCH, is at growth 2.029


#: three layers of tanh and mixed texts, inflated to r_i = 6.7 at the march's start: the
#: inner tanh layer's shear stiffness has saturated there (check round 24, case 2-11)
TANH_SANDWICH = Tube(
    (
        Layer(
            1.58445,
            material=Material("t_tanh", "0.171*tanh((I1-3)/(2*0.171)) + I5/2"),
            shear_modulus=0.000166,
            permittivity=3.22,
        ),
        Layer(
            1.76259,
            material=Material(
                "t_mix", "(0.255*(I1-3) + 0.745*(I2-3))/2 + (0.0501)*(I1-3)*(I2-3) + I5/2"
            ),
        ),
        Layer(
            1.7941,
            material=Material("t_tanh", "1.12*tanh((I1-3)/(2*1.12)) + I5/2"),
            shear_modulus=0.01825,
        ),
    ),
    length=0.06475,
    stretch=0.8431,
    voltage=0.5979,
    inner_pressure=0.04056,
)


def test_a_short_wave_past_the_loss_at_the_start_is_refused_before_any_collocation(
    monkeypatch,
):
    # the kernel fails for (3, 400) at the first state at every tolerance: the loose signs'
    # fallback collocated it at ~300 nodes a layer and the unloaded tube for its sign (60 s),
    # then the fine one asked 355 nodes and refused (CollocationTooLarge after 94-150 s)
    asked = []
    monkeypatch.setattr(targets, "collocation_targets", lambda *a, **k: asked.append(a))
    with pytest.raises(ConvergenceError, match="not strongly elliptic .layer 1 at R = 1"):
        critical_value(TANH_SANDWICH, 3, 400, "growth[1].r+theta")
    assert asked == []
