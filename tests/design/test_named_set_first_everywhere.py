"""A named target set that comes first over the whole range is found, with its margin.

Found by probing (round 6b, 2026-12-05): it was reported 'not_reached'.
design/prescribe.py `_best_in_region` takes competitors only from scans of top 6
(`scan_opts`); for a thin film the first six modes are all prismatic folds m +- 3, so a
'prismatic' target has no competitor, every interval is skipped (`if not others:
continue`) and `_unreached` reports NOT_REACHED ('no target mode among the scanned modes:
widen --m-max / --n-max' on the command line) although the region, printed above it,
spans the whole range. `_closest` widened to TOP_MAX for a set; now `_best_in_region`
does too where a scan's list holds no competitor.
"""

import pytest

from electrogrowth import Layer, Tube
from electrogrowth.design import prescribe

CTRL = "growth[1].theta"


def film(length):
    # film [1, 1.005] (mu 1, hoop growth) on a substrate to 3, 30 times softer
    return Tube(
        [Layer(1.005, shear_modulus=1.0, growth=(1, 1.0, 1)), Layer(3.0, shear_modulus=1 / 30)],
        length=length,
        stretch=1.0,
    )


@pytest.mark.slow
def test_prismatic_set_first_everywhere_is_found():
    d = prescribe(film(0.5), CTRL, "prismatic", ("voltage", 0.0, 0.02), points=3)
    # the region: (93, 0) on [0, 0.0144021], (94, 0) on [0.0144021, 0.02] (whole range)
    assert [tuple(iv.mode) for iv in d.region] == [(93, 0), (94, 0)]
    # was: status 'not_reached', x / mode / margin None; the first non-prismatic mode is
    # (93, 1) at 1.0764115426 (single-mode solve, V = 0), after 10 prismatic folds
    assert d.status == "found"
