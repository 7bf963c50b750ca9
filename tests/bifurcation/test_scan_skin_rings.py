"""Found by probing (round 6b, 2026-12-05): a stiff skin [1.98, 2] (mu 1, hoop growth)
on a substrate 100 times softer, Vbar = 0.07672 (near the substrate's electro-mechanical
short-wave instability): the default scan returned (0, 120) at 1.2222726540, status ok.
Single-mode solves (rtol 1e-12): (35, 0) 1.2219493301 (2.6e-4 earlier), (0, 132)
1.2222725684 (also earlier).

Two mechanisms:
* bifurcation/grid_scan.py `reused` / march.first_bifurcations(until=...): the widened
  grid (n to 240) marches its new rows only up to the earlier top-th value v (here
  1.2222727319); the rows (0, 121..150), whose roots lie 1e-7 below v, still have a
  positive loose (rtol 1e-5) sign at v and are dropped (the march ends at v with none).
* bifurcation/beyond.py: the fold samples m = 29, 37 (ratio 1.25 from the edge 12) are
  both stable at the scan's value, the minimum (35, 0) between them is never searched.

Now a march cut at ``until`` goes UNTIL_MARGIN of the scale past it (march.py), and the
folds beyond the m range are read at every m up to EVERY_M = 64 (beyond.py).
"""

import numpy as np
import pytest

from electrogrowth import Layer, ScanOptions, Tube, certify, critical_value, scan_modes
from electrogrowth.bifurcation.march import first_bifurcations
from electrogrowth.bifurcation.scan_record import ScanResult
from electrogrowth.errors import ConvergenceError
from electrogrowth.incremental.accuracy import SCAN_SIGNS, Accuracy
from electrogrowth.incremental.targets import Family, ImpedanceTarget

CTRL = "growth[2].theta"


def skin():
    return Tube(
        [Layer(1.98, shear_modulus=0.01), Layer(2.0, shear_modulus=1.0, growth=(1, 1.0, 1))],
        length=1.0,
        stretch=1.0,
        voltage=0.07672,
    )


def test_default_scan_finds_the_first_mode():
    s = scan_modes(skin(), CTRL)
    # a scan with m_range (0, 40) finds (35, 0) at 1.2219493300539874
    assert (s.critical.m, s.critical.n) == (35, 0)


@pytest.mark.slow  # 10-25 s: make test-slow runs it
def test_grid_scan_widened_equals_direct_grid():
    opts = ScanOptions(m_range=(0, 12), n_range=(1, 240), extend=False, surface=False)
    direct = scan_modes(skin(), CTRL, options=opts)
    assert (direct.critical.m, direct.critical.n) == (0, 132)  # passes
    widened = scan_modes(skin(), CTRL, options=ScanOptions(m_range=(0, 12), surface=False))
    assert widened.critical.value <= direct.critical.value * (1 + 1e-10)  # was (0, 120)


def test_march_until_keeps_roots_before_it():
    modes = np.array([(0, n, Family.WRINKLE.code) for n in range(121, 151)], float)
    kw = dict(top=5, brent_targets=ImpedanceTarget(Accuracy(1e-12).runners_up))
    free = first_bifurcations(skin(), CTRL, None, modes, ImpedanceTarget(SCAN_SIGNS), **kw)
    assert (free.found[0].m, free.found[0].n) == (0, 132)  # root 1.22227256643
    cut = first_bifurcations(
        skin(), CTRL, None, modes, ImpedanceTarget(SCAN_SIGNS), until=1.2222727319111522, **kw
    )
    assert [(v.m, v.n) for v in cut.found][:1] == [(0, 132)]  # was []


def test_certify_does_not_pass_a_mode_with_an_earlier_scanned_root():
    """`electrogrowth critical --certify` on this tube printed 'certified by collocation ...;
    all 3371 scanned modes stable before it' for (0, 120) at 1.22227265402, while the scanned
    (0, 132) bifurcates at 1.2222725684 (7e-8 before): bifurcation/certify.py read the signs
    at value - max(1e-6 |value|, 10 error), coarser than the spacing of a film's modes. The
    scan finds (0, 132) and (35, 0) now; the certificate is asked of (0, 120) directly, with
    the rings n = 120..140 as its scan."""
    t = skin()
    c = critical_value(t, 0, 120, CTRL)
    with pytest.raises(ConvergenceError, match=r"mode \(0, 1[2-4]\d\) is already unstable"):
        certify(t, c, scan=ScanResult(c, (), (0, 0), (120, 140)))
