"""A charged state on a branch the package does not follow is no loss of the state; and
the branch of check round 28 D1 is followed now.

Check round 28, D1: a bilayer whose coupling (I1-3)/2 + I5/2 (1 + 0.1 (I1-3)) stiffens
with I1, at a fixed Vbar 0.108, marched in the inner pressure. Past P_i ~ 4.4482 its
voltage branch runs inward from the uncharged state (the check's own quadrature: Vbar
0.1847, 0.3955, 0.7442 at r_i 9.25, 9.2223, 9.1667 for P_i = 4.45; a state at P_i = 4.46
with r_i 11.30). Not followed (threshold kind "closing"), the march first reported that
point as the state's loss, threshold 4.448189975629997, status ok, then as unresolved,
where the inflation asymptote lies at ~4.4684: the states past it exist."""

import pytest

from electrogrowth import Layer, Material, Tube, critical_value
from electrogrowth.bifurcation.along import LoadMargin, TubeAt
from electrogrowth.bifurcation.state_loss import _fate
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


def test_a_state_not_followed_is_unresolved_not_lost(monkeypatch):
    import electrogrowth.bifurcation.state_loss as state_loss

    def not_followed(at, x, rtol):
        raise BranchNotFollowed("closes the bore")

    monkeypatch.setattr(state_loss, "_solved", not_followed)
    assert issubclass(BranchNotFollowed, BaseStateError)  # callers that refuse it still do
    assert _fate(TubeAt(TUBE, "pressure"), 4.45) == "unresolved"  # was "lost"


def test_the_states_on_the_inward_branch_are_solved():
    # on main: BranchNotFollowed at 4.45 and 4.46 ("unresolved"); the check: r_i in
    # (9.25004, 9.259299) at 4.45, 11.31 at 4.46
    at = TubeAt(TUBE, "pressure")
    assert [_fate(at, x) for x in (4.448, 4.45, 4.46)] == ["solved"] * 3
    held = LoadMargin(at, (("voltage", TUBE.voltage),))(4.45)
    assert held == pytest.approx(float("inf"))  # the inward branch locks: Vbar unbounded


@pytest.mark.slow  # 15 s on one BLAS thread, ~100 s with more under load: the (6, 2) march
def test_the_march_goes_past_the_turn_towards_the_asymptote():
    # on main: the march ended at 4.4481899756 (threshold, ok; later unresolved); the states
    # exist up to ~4.4683 (the check's quadrature), below the uncharged asymptote 4.468374838
    point = critical_value(TUBE, 6, 2, "pressure")
    assert point.status.value == "ok"
    assert 4.46 < point.value < 4.468374838


def test_the_crease_march_reads_a_branch_not_followed_as_existing():
    """crease.py's bisection for where the states end counted it as lost."""
    from electrogrowth.bifurcation.crease import _not_lost

    def state(x):
        raise BranchNotFollowed("closes the bore")

    assert _not_lost(state)(4.45)  # was False: an edge the march would have reported
