"""The Koiter coefficient of a tube's mode under follower pressures on its faces, as loads
or the inner pressure as the control (docs/derivation-koiter.md, "Pressures on the
faces"), and of the axisymmetric modes under a radial voltage ("The radial voltage,
axisymmetric family"): the wall's forms (polar, meridian, with the potential under a
voltage; the wrinkles' 3D forms) plus the load's potential (incremental/pressure_forms.py,
wall_pressure_forms.py for the wrinkles), in the expansion of koiter_tube.py,

    c_2 = (2 A[psi, psi] - 4 E4(phi)) / A'[phi, phi],   A psi = -grad E3(phi),

A, E3 the wall's and the load's together (the load has no quartic part)."""

from __future__ import annotations

import dataclasses

import numpy as np

from ..basestate.tube import solve_base_state
from ..incremental.dielectric_forms import DielectricForms
from ..incremental.meridian_dielectric_forms import MeridianDielectricForms
from ..incremental.meridian_forms import MeridianForms
from ..incremental.polar_forms import PolarForms, rings
from ..incremental.pressure_forms import FaceForms
from ..incremental.ring_basis import nodal_values
from ..incremental.wall_pressure_forms import WallFaceForms
from ..model.layers import Tube
from .control_derivative import reach
from .koiter_film import MODE
from .koiter_tube import (
    SECOND,
    TubeExpansion,
    axial_wavenumber,
    numerator_rounding,
    on_the_energy,
    onset_value,
    quadratic_part,
    singular_point,
    slope_ratio,
)
from .koiter_wall import MODE as WALL_MODE
from .koiter_wall import POTENTIAL, wall_forms
from .koiter_wall import SECOND as WALL_SECOND


@dataclasses.dataclass
class LoadedEnergy:
    """The wall's forms on some harmonics with the faces' load on the same unknowns."""

    wall: object
    face: FaceForms | WallFaceForms

    def stiffness(self, state):
        """A: the wall's Hessian plus the load's."""
        load = self.face.hessian(self.face.potential(state)[2])
        return self.wall.hessian(self.wall.lagrangian(state)[2]) + load

    def third(self, state, phi_fields: dict, phi_face: dict):
        """grad E3 at the mode (= C[phi, phi, .] / 2), the wall's and the load's."""
        load = self.face.gradient(self.face.potential(state)[3], phi_face)
        return self.wall.gradient(self.wall.lagrangian(state)[3], phi_fields) + load

    def quadratic(self, state) -> list:
        """The quadratic monomials of the wall's Lagrangian and of the load's potential, each
        tagged with its part ("wall" or "face") in its field names' place."""
        wall = self.wall.lagrangian(state)[2]
        face = self.face.potential(state)[2]
        return [(k, ("wall", xs)) for k, xs in wall] + [(k, ("face", xs)) for k, xs in face]

    def energy(self, polynomial, fields: dict, face_fields: dict) -> float:
        """The integral of a tagged Polynomial (:meth:`quadratic`) at the wall's and the
        face's local fields."""
        parts: dict = {"wall": [], "face": []}
        for k, (part, xs) in polynomial.monomials():
            parts[part].append((k, xs))
        wall = self.wall.energy(parts["wall"], fields)
        return wall + self.face.energy(parts["face"], face_fields)

    def quartic(self, state, phi_fields: dict) -> float:
        """E4 at the mode (the wall's: the load has none)."""
        return self.wall.energy(self.wall.lagrangian(state)[4], phi_fields)


def energies(tube: Tube, mode, control: str, nodes: int) -> tuple[LoadedEnergy, LoadedEnergy]:
    """The mode's and the correction's loaded energies of ``mode`` ((m, 0), (0, n) or a
    wrinkle (m, n): koiter_wall.py's forms with incremental/wall_pressure_forms.py)."""
    m, n = mode
    if m != 0 and n != 0:
        charged = tube.voltage != 0 or control == "voltage"
        extra = POTENTIAL if charged else ((), ())
        harmonics = (WALL_MODE + extra[0], WALL_SECOND + extra[1])
        walls = [wall_forms(tube, mode, h, nodes, charged=charged) for h in harmonics]
        first, second = (LoadedEnergy(w, WallFaceForms.of(w)) for w in walls)
        return first, second
    if n == 0:
        cut = rings(tube, m, nodes)
        if tube.voltage != 0 or control == "voltage":
            walls = (
                DielectricForms.build(cut, m, MODE + ((3, 1),)),
                DielectricForms.build(cut, m, SECOND + ((3, 0), (3, 2))),
            )
        else:
            walls = (PolarForms.build(cut, m, MODE), PolarForms.build(cut, m, SECOND))
        family, wavenumber = "prismatic", float(m)
    else:
        K = axial_wavenumber(tube, n)
        cut = rings(tube, max(K, 1.0), nodes)
        if tube.voltage != 0 or control == "voltage":
            walls = (
                MeridianDielectricForms.build(cut, K, MODE + ((3, 1),)),
                MeridianDielectricForms.build(cut, K, SECOND + ((3, 0), (3, 2))),
            )
        else:
            walls = (MeridianForms.build(cut, K, MODE), MeridianForms.build(cut, K, SECOND))
        family, wavenumber = "axisymmetric", K
    first, second = (LoadedEnergy(w, FaceForms.build(w, family, wavenumber)) for w in walls)
    return first, second


def _numerator(tube: Tube, control: str, forms, c: float, phi):
    """(phi scaled to max |u_r| = R_i, its wall's and faces' fields, 2 A[psi, psi] - 4 E4)
    at c, as koiter_tube._numerator with the load: once the wall's rounding is gone
    (ring_basis.py) the numerator's rounding (~1e-11 relative on an outer film's fold,
    (57, 0) under pressure) is what the node count scatters, and the expansion samples it
    by nudging c, as koiter_tube's does."""
    first, second = forms
    phi = phi / first.wall.peak_radial(phi, first.wall.slices[0])[1]  # max |u_r| = R_i
    state = solve_base_state(tube.at(control, c))
    fields = first.wall.fields(phi), first.face.fields(phi)
    A2 = second.stiffness(state)
    psi = np.linalg.solve(A2, -second.third(state, *fields))
    return phi, fields, float(2 * (psi @ A2 @ psi) - 4 * first.quartic(state, fields[0]))


def loaded_expansion(
    tube: Tube, mode, control: str, *, nodes: int = 24, side: str | None = None
) -> TubeExpansion:
    """The expansion of ``mode`` in ``control`` with the tube's face pressures (and the
    inner pressure itself when ``control`` is "pressure"): at zero pressures the wall's own
    coefficient (koiter_tube.py)."""
    first, second = energies(tube, mode, control, nodes)

    def A(c):
        return first.stiffness(solve_base_state(tube.at(control, c)))

    start = onset_value(tube, mode, control, side)
    where = reach(tube, control)
    quadratic = quadratic_part(tube, control, first.quadratic)

    def energy(polynomial, phi):  # at phi's local fields, the wall's and the faces'
        return first.energy(polynomial, first.wall.fields(phi), first.face.fields(phi))

    what = f"{control} of mode {mode}"
    c, phi = singular_point(A, start, what, where)
    c, phi = on_the_energy(A, quadratic, energy, c, phi, where, what)
    phi, (f1, face1), numerator = _numerator(tube, control, (first, second), c, phi)
    rounding = numerator_rounding(
        lambda x, v: _numerator(tube, control, (first, second), x, v)[2],
        *(numerator, A, c, phi, where),
    )
    c2, error = slope_ratio(  # A' term by term, the wall's and the load's (koiter_tube.py)
        numerator,
        quadratic,
        c,
        phi,
        where,
        along=lambda d: 2 * first.energy(d, f1, face1),
    )
    error += abs(c2 * rounding / numerator) if numerator else 0.0
    # u_r at the nodes, from R_i to R_N (the unknowns are each ring's differences)
    radial = nodal_values(first.wall.rings, phi[first.wall.slices[0]])
    return TubeExpansion(
        float(c),
        c2,
        float(start),
        float(radial[0]),
        outer_face=float(radial[-1]),
        derivative_error=error,
    )
