"""The crease march on a path with no threshold (bifurcation/crease.py _receding_step).

A charged bilayer with a coupled layer (check round 31, Doubt 3) creases by the field
criterion first; the mechanical criteria, marched again on their own, recede all the way to
the path's end at 1e3 voltage scales (the coupling stiffens: no threshold), and took 1e4
steps of 0.1 scale, each a base state (120 s). A one-layer tube of the same energy has the
same structure.
"""

import pytest

import electrogrowth.bifurcation.crease as crease
from electrogrowth import Material, Tube, crease_onset, threshold
from electrogrowth.outcomes import Kind

COUPLED = Material("coup", "(I1-3)/2 + I5/2*(1 + 0.1*(I1-3))")
#: base states the two marches may take: the fix's 108 (was about 1e4)
BUDGET = 300


def test_a_receding_mechanical_margin_reaches_the_far_end_in_few_steps(monkeypatch):
    """Before: the budget ran out in the mechanical march (10002 margins for the bilayer);
    after: 108 margins. The field crease is the same sample for sample up to its bracket
    (the step grows only where the margin recedes), and the mechanical one is none on the
    whole path (no "none before" message: the march reached the path's end)."""
    tube = Tube.uniform(1.5, length=1.0, material=COUPLED)
    assert threshold(tube, "voltage").kind == "none"
    calls = []
    margin = crease.crease_margin

    def counted(state, triggers=crease.TRIGGERS):
        calls.append(float(state.tube.voltage))
        assert len(calls) <= BUDGET, f"{len(calls)} base states, not <= {BUDGET}"
        return margin(state, triggers)

    monkeypatch.setattr(crease, "crease_margin", counted)
    c = crease_onset(tube, "voltage")
    assert (c.kind, c.face, c.trigger) == (Kind.CREASE, "inner", "field")
    assert c.value == pytest.approx(0.7395660124923312, rel=1e-12)  # the old march's value
    assert c.mechanical.kind == Kind.NONE and c.mechanical.message == ""
    assert max(calls) == pytest.approx(1e3)  # the path's end, 1e3 voltage scales (1 here)
