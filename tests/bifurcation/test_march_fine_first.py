"""A march reads its fine targets at the start before its loose ones (march.calibrated).

Where the kernel fails at the start, the fine tolerance's fallback is the larger collocation
(targets.resolving_nodes grows with 1 / rtol): one over its memory budget refuses before the
loose tolerance's fallback spends its time. Mode (3, 400) of a three-layer tube of tanh
texts (check round 24, case 2-11) failed the kernel at its first state at every tolerance;
the loose signs' fallback collocated it at rtol 1e-8 (and collocated the unloaded tube for
its sign), 60 s, before the fine one asked 355 nodes a layer (1.19 GiB: refused).
"""

from __future__ import annotations

import pytest

from electrogrowth import Layer, Material, Tube, critical_value
from electrogrowth.errors import CollocationTooLarge
from electrogrowth.incremental import targets
from electrogrowth.incremental.collocation import MEMORY_BUDGET, collocation_bytes

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


def test_a_collocation_over_budget_refuses_before_any_collocation_is_computed(monkeypatch):
    asked, collocate = [], targets.collocation_targets

    def over_budget_only(state, modes, *, nodes=40):
        asked.append(nodes)  # the refusal is collocation's own, before any array
        assert collocation_bytes(nodes, 3) > MEMORY_BUDGET, f"collocated at {nodes} nodes"
        return collocate(state, modes, nodes=nodes)

    monkeypatch.setattr(targets, "collocation_targets", over_budget_only)
    with pytest.raises(CollocationTooLarge, match="would need 355 nodes a layer"):
        critical_value(TANH_SANDWICH, 3, 400, "growth[1].r+theta")
    assert asked == [355]
