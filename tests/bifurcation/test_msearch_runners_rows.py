"""The runners-up of a searched fold include the neighbours on the other searched rows.

Found by probing (round 6b, 2026-12-05): bifurcation/msearch.py `_neighbourhood` marched
the top - 1 integers either side of the best on its own row only, so a later fold of the
best's row, (117, 0), was listed before the wrinkle (115, 1). Now it marches them on every
searched row."""

from electrogrowth import Layer, ScanOptions, Tube, scan_modes

CTRL = "growth[1].theta"


def test_runners_up_include_the_wrinkle_row():
    t = Tube(
        [Layer(1.005, shear_modulus=1.0, growth=(1, 1.0, 1)), Layer(3.0, shear_modulus=1 / 30)],
        length=1.0,
        stretch=1.0,
        voltage=0.1,
    )
    s = scan_modes(t, CTRL, options=ScanOptions(top=5))
    assert (s.critical.m, s.critical.n) == (115, 0)
    # single-mode solves (rtol 1e-12): (114,0) 1.3751110055, (116,0) 1.3751144797,
    # (115,1) 1.3751253874, (113,0) 1.3751285958, (114,1) 1.3751289801, (117,0) 1.3751350502
    # was: (114,0), (116,0), (113,0), (117,0)
    assert [(r.m, r.n) for r in s.runners_up] == [(114, 0), (116, 0), (115, 1), (113, 0)]
