"""The check that an FE onset has the mode's own pattern on the faces: one harmonic
cos(i pi Y / extent) of the sector, i = its half wavelengths; a mesh too coarse along a
face loses stability first in its highest harmonic, or (the potential's former artefact)
in a mode that leaves the faces still."""

import types

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.errors import ConvergenceError  # noqa: E402
from electrogrowth.model.layers import Layer, Tube  # noqa: E402
from electrogrowth.postbuckle.api import _check_onset_pattern  # noqa: E402
from electrogrowth.postbuckle.section import MeshSize, Section  # noqa: E402
from electrogrowth.postbuckle.stability import face_harmonic  # noqa: E402

TUBE = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0)


def pattern(section, i, face="inner", scale=1.0):
    """u_R = scale cos(i pi Y / extent) at the vertices of ``face``, zero elsewhere."""
    z = np.zeros(section.basis.N)
    dofs, y = section.face_dofs(face)
    z[dofs] = scale * np.cos(i * np.pi * y / section.extent)
    return z


@pytest.mark.parametrize("periods", [1, 2])
def test_each_harmonic_is_found_alone(periods):
    section = Section(TUBE, 12, MeshSize((2, 3), 4 * periods), periods=periods)
    for i in range(4 * periods + 1):
        found, share = face_harmonic(section, pattern(section, i))
        assert found == i
        assert share == pytest.approx(1.0, abs=1e-12)


def test_the_larger_face_names_the_pattern():
    """The mode's own harmonic on the inner face, a smaller element-sized one outside."""
    section = Section(TUBE, 12, MeshSize((2, 3), 4))
    z = pattern(section, 1) + pattern(section, 4, "outer", scale=0.5)
    assert face_harmonic(section, z) == (1, pytest.approx(1.0))
    z = pattern(section, 1, scale=0.5) + pattern(section, 4, "outer")
    assert face_harmonic(section, z)[0] == 4


def test_the_check_accepts_the_mode_and_refuses_the_rest():
    section = Section(TUBE, 12, MeshSize((2, 3), 4))

    def check(z):
        onset = types.SimpleNamespace(value=1.7, mode=z)
        _check_onset_pattern(section, onset, 1.7159, (12, 0), "growth")

    check(pattern(section, 1) + 1e-3 * pattern(section, 3))
    with pytest.raises(ConvergenceError, match="4 half wavelengths along the sector pi/12"):
        check(pattern(section, 4, "outer"))
    with pytest.raises(ConvergenceError, match="leaves the faces still"):
        z = np.zeros(section.basis.N)
        z[section.basis.nodal_dofs[0][~np.isin(section.mesh.p[0], (1.0, 2.0))]] = 1.0
        check(z)
