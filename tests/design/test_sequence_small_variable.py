"""A switch along a small design variable is refined on the variable's own scale (check
round 22; bifurcation/curve_switches.py `_refined`).

An outer film 1e-3 thick, 100 times stiffer than its core (to Rbar 1.5, L 2), compressed
axially: along the film's thickness the rings switch (0, 188) -> (0, 187) -> (0, 186). The
refinement's threshold was 1e-9 max(1, |x|), 1e-9 absolute for x ~ 1e-3: the switches kept
x_error 3.2e-11, 3.2e-8 of x, while the two modes tie much closer (check round 22's
independent solver: within its own noise, 4.5e-9 of x).
"""

from scipy.optimize import brentq

from electrogrowth import Layer, ScanOptions, Tube, critical_value
from electrogrowth.design import mode_sequence

FILM = Tube((Layer(1.499), Layer(1.5, shear_modulus=100.0)), length=2.0, stretch=1.0)
KEY = "layers[2].thickness"


def _ring(mode, h):
    tube = FILM.at(KEY, h)
    return critical_value(tube, *mode, "stretch", side="compression", rtol=1e-14).value


def test_switches_along_a_thin_films_thickness_are_refined():
    seq = mode_sequence(
        FILM, "stretch", (KEY, 0.00100, 0.00102), side="compression", points=3,
        options=ScanOptions((0, 2), (180, 220), torsional=False),
    )  # fmt: skip
    switches = [s for s in seq.switches if s.kind == "switch"]
    assert [s.mode_before for s in switches] == [(0, 189), (0, 188), (0, 187)]
    for s in switches:
        assert s.x_error < 1e-9 * s.x  # was 3.2e-8 of x
        # the tie of the two modes by Brent on single-mode solves at rtol 1e-14
        d = lambda h, s=s: _ring(s.mode_before, h) - _ring(s.mode_after, h)  # noqa: E731
        tie = brentq(d, s.x * (1 - 1e-7), s.x * (1 + 1e-7), xtol=1e-17, rtol=1e-15)
        assert abs(s.x - tie) <= s.x_error
