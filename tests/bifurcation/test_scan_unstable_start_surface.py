"""A scan whose tube is past a face's short-wave instability at the control's start is
already unstable (check round 20, D1).

Three layers (Gent / an I5 coupling text / an I4 text) held at Vbar = 0.79, the growth of
layer 3 as the control: the ungrown tube is past its inner face's short-wave limit (the
voltage scan's surface at Vbar = 0.75502), (0, 40) bifurcates at Vbar = 0.7619176717 (the
package's single mode; an independent shooting and collocation of the whole tube, 2e-13
apart), and (0, 24)-(0, 60) are all unstable at g = 1, restabilised as layer 3 grows. The
scan read only its own modes at the start (n <= 5) and weighed the limit only against its
critical value, where the face is stable again: (2, 1) at g = 1.38034, status ok.
"""

import pytest

from electrogrowth import Layer, Material, ScanOptions, Tube, critical_value, gent, scan_modes
from electrogrowth.errors import UnstableAtStart

COUPLED = Material("coup", "(I1-3)/2 + I5/2*(1 + 0.1*(I1-3))")
STIFFENED = Material("i4", "(I1-3)/2 + 0.4*I5 + 0.1*I4")
TUBE = Tube(
    [
        Layer(1.15, material=gent(20.0), shear_modulus=0.5, permittivity=1.0),
        Layer(1.5, material=COUPLED, shear_modulus=2.0, permittivity=0.7),
        Layer(1.8, material=STIFFENED, shear_modulus=1.0, permittivity=1.3),
    ],
    length=4.0,
    stretch=1.0,
    voltage=0.79,
)
OPTIONS = ScanOptions((0, 8), (1, 5), torsional=False)


def test_a_scan_past_the_inner_faces_limit_at_its_start_is_unstable_at_start():
    with pytest.raises(UnstableAtStart, match="inner face is past its short-wave"):
        scan_modes(TUBE, "growth[3]", options=OPTIONS)  # was (2, 1) at 1.38034, ok
    with pytest.raises(UnstableAtStart, match=r"mode \(0, 40\)"):  # as its single mode says
        critical_value(TUBE, 0, 40, "growth[3]")


def test_below_the_limit_the_scan_stands():
    c = scan_modes(TUBE.at("voltage", 0.75), "growth[3]", options=OPTIONS).critical
    assert (c.kind, c.m, c.n, c.status) == ("bifurcation", 2, 1, "ok")
