"""A charged state on a branch the package does not follow is no loss of the state.

Check round 28, D1: a bilayer whose coupling (I1-3)/2 + I5/2 (1 + 0.1 (I1-3)) stiffens
with I1, at a fixed Vbar 0.108, marched in the inner pressure. Past P_i ~ 4.4482 its
voltage branch runs inward from the uncharged state (the check's own quadrature: Vbar
0.1847, 0.3955, 0.7442 at r_i 9.25, 9.2223, 9.1667 for P_i = 4.45; a state at P_i = 4.46
with r_i 11.30), which the package does not follow (threshold kind "closing"). The march
reported that point as the state's loss, threshold 4.448189975629997, status ok, where the
inflation asymptote lies at ~4.4684: the states past it exist."""

import pytest

from electrogrowth import Layer, Material, Tube, solve_base_state
from electrogrowth.bifurcation.along import LoadMargin, TubeAt
from electrogrowth.bifurcation.state_loss import _fate, threshold_between
from electrogrowth.errors import BaseStateError, BranchNotFollowed

COUP = Material("coup", "(I1-3)/2 + I5/2*(1 + 0.1*(I1-3))")
COUP4 = Material("coupi4", "(I1-3)/2 + 0.45*I5 + 0.05*I4*(1 + 0.1*(I1-3))")
P_O = 0.04364916679215165
TUBE = Tube(
    [
        Layer(
            1.8084397861935206,
            material=COUP,
            shear_modulus=2.6200505657523743,
            permittivity=0.9122528046112701,
        ),
        Layer(
            2.2693066463787863,
            material=COUP4,
            shear_modulus=7.860779293048664,
            permittivity=0.652746813978254,
            growth=(1.150437756076137, 1.1313952076652471, 1.1219382139347056),
        ),
    ],
    length=4.1481538834933875,
    stretch=0.8109099045777046,
    voltage=0.1083518738228662,
    inner_pressure=P_O,
    outer_pressure=P_O,
)


def test_a_state_not_followed_is_refused_as_such_and_not_as_lost():
    at = TubeAt(TUBE, "pressure")
    with pytest.raises(BranchNotFollowed, match="closes the bore"):
        solve_base_state(at(4.45))
    assert issubclass(BranchNotFollowed, BaseStateError)  # callers that refuse it still do
    assert _fate(at, 4.45) == "unresolved"  # was "lost"
    with pytest.raises(BranchNotFollowed):  # the held voltage's margin: not its threshold 0
        LoadMargin(at, (("voltage", TUBE.voltage),))(4.45)
    assert _fate(at, 4.448) == "solved"


@pytest.mark.slow  # ~30 s: the bisection's state solves
def test_the_march_does_not_end_where_the_branch_turns_inward():
    at = TubeAt(TUBE, "pressure")
    value, ok, err = threshold_between(at, TUBE, 4.4480, 4.4490)
    assert value is None and err is not None  # was 4.448189975629997, an established loss
    assert "closes the bore" in str(err) and "not established" in str(err)
    assert ok == pytest.approx(4.4481899756, rel=1e-9)


def test_the_crease_march_reads_a_branch_not_followed_as_existing():
    """crease.py's bisection for where the states end counted it as lost."""
    from electrogrowth.bifurcation.crease import _not_lost

    def state(x):
        raise BranchNotFollowed("closes the bore")

    assert _not_lost(state)(4.45)  # was False: an edge the march would have reported
