"""A scanned mode unstable in a window the scan's march steps over, before an interface's
short-wave limit (check round 18, D1 and D2).

Three neo-Hookean layers, soft / stiff / soft, the middle one growing, L = 0.02: the short
axial waves live at the two interfaces of the middle layer, and the target of (0, 1) turns
its sign at one interface's instability and back at the other's. The scan samples its modes
every 0.25 of the growth and stepped over that window; the exact limit at interface 1 was
the answer, status ok. An independent collocation of the whole tube (no package code, 60
and 80 nodes per layer) brackets the root of (0, 1) within 7e-12 of the values below, and an
independent half-space solver gives the limits.
"""

import pytest

from electrogrowth import Layer, Material, ScanOptions, Tube, scan_modes

NH = Material("m", "(I1-3)/2 + I5/2")


def _tube(inner: float, mid: float, outer: float, mu_soft: float, mu_mid: float = 1.0) -> Tube:
    return Tube(
        (
            Layer(inner, material=NH, shear_modulus=mu_soft),
            Layer(mid, material=NH, shear_modulus=mu_mid),
            Layer(outer, material=NH, shear_modulus=mu_soft),
        ),
        length=0.02,
        stretch=1.0,
    )


def test_a_mode_inside_the_ranges_before_the_limit_is_found():
    """D2, the ranges kept (extend=False): was the limit 2.149267040282233, status ok."""
    options = ScanOptions(m_range=(0, 2), n_range=(1, 3), extend=False)
    s = scan_modes(_tube(1.3, 1.4, 2.0, 0.5), "growth[2]", options=options)
    c = s.critical
    assert (c.kind, c.m, c.n, c.status) == ("bifurcation", 0, 1, "ok")
    assert c.value == pytest.approx(2.149166089445, rel=1e-11)  # collocation's bracket
    assert s.short_wave_limit == pytest.approx(2.1492670402822305, rel=1e-13)  # half-space
    assert [(r.m, r.n) for r in s.runners_up][:2] == [(1, 1), (0, 2)]
    assert all(c.value < r.value < s.short_wave_limit for r in s.runners_up)


@pytest.mark.slow  # 20 s: the default scan (m <= 12, n <= 30)
def test_the_default_scan_of_a_thin_stiff_middle_layer():
    """D1: was the limit at interface 1, 2.2446795607, status ok, no runners-up."""
    s = scan_modes(_tube(1.2, 1.25, 1.6, 0.05, 5.0), "growth[2]")
    c = s.critical
    assert (c.kind, c.m, c.n, c.status) == ("bifurcation", 0, 1, "ok")
    assert c.value == pytest.approx(2.243644972217, rel=2e-11)  # collocation's bracket
    assert s.short_wave_limit == pytest.approx(2.2446795607079726, rel=1e-13)
    assert (s.runners_up[0].m, s.runners_up[0].n) == (1, 1)


def test_without_the_surface_the_window_is_found_all_the_same():
    """Check round 18: with ``surface=False`` the limit is no result, but it is where the
    window lies; was "no mode bifurcates for growth[2] between 1 and 6"."""
    options = ScanOptions(m_range=(0, 2), n_range=(1, 3), extend=False, surface=False)
    s = scan_modes(_tube(1.3, 1.4, 2.0, 0.5), "growth[2]", options=options)
    c = s.critical
    assert (c.kind, c.m, c.n, c.status) == ("bifurcation", 0, 1, "ok")
    assert c.value == pytest.approx(2.149166089445, rel=1e-11)  # collocation's bracket
    assert not s.surface_instability
    assert [(r.m, r.n) for r in s.runners_up][:2] == [(1, 1), (0, 2)]
