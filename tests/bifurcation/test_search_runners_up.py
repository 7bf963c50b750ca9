"""The runners-up of a scan whose fold number comes from the coarse-to-fine m search must be
the next modes, not the next modes the search happened to march.

A neo-Hookean film [1, 1.001] with shear modulus 10 on a neo-Hookean substrate to
Rbar_o = 2 (modulus 1), L = 5, hoop growth of the film: it folds at (640, 0),
g_theta,cr = 1.12236096 (the search's m is right: every m within 3 of it and n = 0, 1, 2
checked by single modes). Single modes (impedance): (639, 0) 1.12236115, (641, 0)
1.12236127, (638, 0) 1.12236182, (642, 0) 1.12236207, (637, 0) 1.12236298, (643, 0) 1.12236335.

Found by probing: the scan's runners-up were (639, 0), (641, 0), (638, 0), (643, 0): (642, 0) and
(637, 0), which come before (643, 0), were left out, because the search's last bracket marched only
some integers near its best and the runners-up were taken from what it marched (now
the top - 1 integers either side of the best are all marched). Likewise a
Mooney-Rivlin film [1, 1.00035] (mu 10) to Rbar_o = 1.5 folding at (1823, 0) lists
(1819, 0) fourth, after which come (1821, 0) and (1820, 0). About 25 s.
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, scan_modes

FILM = Tube((Layer(1.001, shear_modulus=10.0), Layer(2.0)), length=5.0, stretch=1.0)


@pytest.mark.slow
def test_runners_up_of_the_searched_fold_number_are_the_next_modes():
    scan = scan_modes(FILM, "growth[1].theta")
    assert (scan.critical.m, scan.critical.n) == (640, 0)
    last = scan.runners_up[-1].value
    for m in range(636, 645):
        if m == 640:
            continue
        value = critical_value(FILM, m, 0, "growth[1].theta").value
        listed = any((r.m, r.n) == (m, 0) for r in scan.runners_up)
        assert listed or value >= last - 1e-9, f"({m}, 0) at {value} comes before {last}"
