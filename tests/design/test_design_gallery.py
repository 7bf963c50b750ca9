"""The gallery of designed tubes (figures/design_gallery.py), quick mode: the gut-like
bilayer's boundary between 12 and 11 folds over (h, mu_1/mu_2), checked by full solves and
by the independent collocation route, and the design for 12 folds."""

from __future__ import annotations

import pytest

from electrogrowth import critical_value
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.figures.design_gallery import CONTROL, designed_folds, gut_bilayer


@pytest.mark.slow
def test_gut_bilayer_designed_for_12_folds():
    from electrogrowth.incremental.targets import collocation_targets

    res = designed_folds(quick=True)
    (b,) = res.map.boundaries
    assert {b.left, b.right} == {(12, 0), (11, 0)} and b.certified
    k = len(b.x) // 2
    r1, mu, v = b.x[k], b.y[k], b.value[k]
    tube = gut_bilayer(r1 - 1.0, mu)  # the interface at r1, the outer radius 2
    for m in (11, 12):  # both critical there: full solves, and collocation's sign change
        assert abs(critical_value(tube, m, 0, CONTROL).value - v) < 1e-8
        below, above = (
            collocation_targets(solve_base_state(tube.at(CONTROL, v + d)), [(m, 0)])[0]
            for d in (-1e-9, 1e-9)
        )
        assert below * above < 0, m
    d = res.designs[12]
    assert d.status == "found" and d.mode[0] == 12 and d.margin > 0
    # thicker or stiffer inner layers fold into fewer folds (the region of 12 is on the
    # thin, soft side of the boundary): the published trend (docs/design.md)
    assert res.map.pattern_at(1.09, 9.5) == (12, 0)
    assert res.map.pattern_at(1.096, 10.5) == (11, 0)
