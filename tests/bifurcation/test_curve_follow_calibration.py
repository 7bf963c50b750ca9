"""A curve's follower checks that every other mode of its grid is still stable just before
the followed mode's value (curve_follow._Follower._all_stable), on loose signs. On a stiff
film under axial force (ratio 1e4, h = 1e-3, free ends) the loose signs at SCAN_SIGNS do not
resolve the targets (probe round 9a, D1: ~1e-11 against ~1e-13 near the roots): the check
called the first ring (0, 110) not first, a mode's loose sign negative before its root. Its
loose signs are now calibrated as a march's (march.calibrated): the check is right on both
sides, (0, 110) comes first and (0, 111) does not."""

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.bifurcation.curve_follow import _Follower
from electrogrowth.bifurcation.scan import ScanOptions

FILM = Tube(
    (Layer(2.0, shear_modulus=1e-4), Layer(2.001, shear_modulus=1.0)), length=5.0, axial_force=0.0
)
RANGES = ((0, 4), (100, 120))


def _follower():
    options = ScanOptions(*RANGES)
    f = _Follower(FILM, "force", "length", "compression", options, None, scan=None, solve=None,
                  limit=None)  # fmt: skip
    f.ranges = RANGES
    return f


def test_the_follower_s_check_reads_a_stiff_film_s_signs_right():
    f = _follower()
    first = critical_value(FILM, 0, 110, "force", side="compression").value
    later = critical_value(FILM, 0, 111, "force", side="compression").value
    assert first > later  # compression: (0, 110) is reached first
    assert f._all_stable(FILM, (0, 110), first)
    assert not f._all_stable(FILM, (0, 111), later)
