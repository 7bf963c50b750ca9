"""The flat bilayer's nominal compression read off the tube (postbuckle/strain.py): on the
unperturbed path it is the inner face's hoop strain exactly (incompressibility through the
whole wall), checked against the package's base state, an independent route."""

import pytest

pytest.importorskip("skfem")

from electrogrowth.basestate.tube import solve_base_state  # noqa: E402
from electrogrowth.errors import ParameterError  # noqa: E402
from electrogrowth.model.layers import Layer, Tube  # noqa: E402
from electrogrowth.postbuckle.newton import loaded  # noqa: E402
from electrogrowth.postbuckle.section import Section, mesh_size  # noqa: E402
from electrogrowth.postbuckle.strain import nominal_compression  # noqa: E402

#: a stiff film under an external pressure, at an axial stretch other than 1 (which enters
#: the incompressibility relation)
FILM = Tube(
    (Layer(1.02, shear_modulus=20.0), Layer(1.3), Layer(2.0)), stretch=1.1, outer_pressure=0.4
)


def test_compression_of_the_unperturbed_tube_is_the_inner_hoop_strain():
    """1 - r_1 from the outer radius equals 1 - r_i of the base state (the package's, to
    the FE radii's 1e-6) and of the FE state itself (to its incompressibility)."""
    section = Section(FILM, 8, mesh_size(FILM, 8, 16, hoop=1))
    x = loaded(section, FILM, steps=3)
    eps = nominal_compression(section, x)
    r_i = solve_base_state(FILM).radius(1.0)
    assert 0.05 < eps < 0.5  # a real compression, not a trivial zero
    assert eps == pytest.approx(1 - r_i, abs=1e-7)  # measured 1.7e-9
    dofs, _ = section.face_dofs("inner")
    assert eps == pytest.approx(-x[dofs].mean(), abs=1e-12)  # measured 2e-14


def test_a_grown_tube_is_refused():
    grown = Tube((Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)), stretch=1.0)
    section = Section(grown, 8, mesh_size(grown, 8, 4, hoop=1))
    with pytest.raises(ParameterError, match=r"layers\[1\].growth = .* ungrown tube") as err:
        nominal_compression(section, section.with_fixed(section.basis.zeros()))
    assert "\n" not in str(err.value)
