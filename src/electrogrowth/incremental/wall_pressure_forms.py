"""The potential of the follower pressures on a tube's faces in three-dimensional
deformations, expanded about the axisymmetric state: the load terms of the wrinkles (m, n)
(docs/derivation-koiter.md, "Pressures on the faces, wrinkles (m, n)").

The load's potential is Pi = -P_i V_i + P_o V_o (pressure_forms.py), V the volume a face
encloses between the end planes (the ends slide in their planes: u_z = 0 there). With the
face x = (r0 + a) e_r + b e_th + (lambda_z Z + c) e_z (a, b, c = U_r, U_th, U_z there), the
divergence theorem with the field (x e_x + y e_y) / 2, which has no flux through the end
planes, gives per radian and unit reference length

    V = 1/2 < (r0 + a)[(r0 + a + b_T)(lambda_z + c_Z) - c_T b_Z]
              + b [c_T a_Z - (a_T - b)(lambda_z + c_Z)] >,

< > the mean over Theta and Z, _T = d/dTheta, _Z = d/dZ: **exactly cubic** in the
displacement. At c = 0, d/dZ = 0 it is the plane section's area times lambda_z, at b = 0,
d/dTheta = 0 the volume of revolution (pressure_forms.py).
"""

from __future__ import annotations

import numpy as np

from .monomial_forms import by_degree
from .ring_basis import face_rows
from .strain_energy_forms import times
from .wall_forms import Block, WallForms, angular_grid

#: the face fields: a, b, c and their derivatives along Theta (T) and Z
FACE_FIELDS = ("a", "aT", "aZ", "b", "bT", "bZ", "c", "cT", "cZ")


class WallFaceForms(WallForms):
    """The faces' fields of a WallForms' unknowns: the two "radial points" are the inner
    and the outer face (ring_basis.face_rows of each displacement harmonic)."""

    @classmethod
    def of(cls, wall: WallForms, *, angular_points: int = 8) -> WallFaceForms:
        T, Z = angular_grid(wall.m, wall.K, angular_points)
        blocks: dict = {k: [] for k in FACE_FIELDS}
        for (field, j, l), part in zip(wall.harmonics, wall.slices):
            if field > 2:
                continue
            face = face_rows(wall.rings)  # the faces' values from the unknowns
            for name, angular in _face_factors(field, j * wall.m, l * wall.K, T, Z):
                if np.any(angular):
                    blocks[name].append(Block(part, angular, face))
        radii = np.array([wall.rings[0].inner, wall.rings[-1].outer])
        weight = np.outer(np.full(T.size, 1.0 / T.size), np.ones(2))
        layer = np.array([wall.rings[0].layer, wall.rings[-1].layer])
        return cls(
            wall.rings,
            wall.m,
            wall.K,
            wall.harmonics,
            blocks,
            radii,
            layer,
            weight,
            wall.slices,
            wall.size,
        )

    def potential(self, state) -> dict[int, list]:
        """The monomials of Pi = -P_i V_i + P_o V_o order by order (1 to 3) in the faces'
        displacements; no quartic term."""
        tube = state.tube
        r0 = state.radius(self.R)
        load = np.array([-tube.inner_pressure, tube.outer_pressure])
        lz = np.full(2, state.stretch)
        f = {k: {(k,): 1.0} for k in FACE_FIELDS}
        ra = {(): r0, ("a",): 1.0}
        hoop = {(): r0, ("a",): 1.0, ("bT",): 1.0}  # r0 + a + b_T
        axial = {(): lz, ("cZ",): 1.0}  # lambda_z + c_Z
        turn = {("aT",): 1.0, ("b",): -1.0}  # a_T - b
        V = _sum(
            (1.0, times(ra, times(hoop, axial))),
            (-1.0, times(ra, times(f["cT"], f["bZ"]))),
            (1.0, times(f["b"], times(f["cT"], f["aZ"]))),
            (-1.0, times(f["b"], times(turn, axial))),
        )
        out = by_degree((load / 2, V))
        return {k: out.get(k, []) for k in (1, 2, 3)}


def _sum(*terms) -> dict:
    out: dict = {}
    for scale, poly in terms:
        for k, v in poly.items():
            out[k] = out.get(k, 0.0) + scale * v
    return out


def _face_factors(field, nt, nz, T, Z):
    """(face field, angular factor) of one harmonic of U_r, U_th or U_z."""
    ct, st, cz, sz = np.cos(nt * T), np.sin(nt * T), np.cos(nz * Z), np.sin(nz * Z)
    if field == 0:  # a cos cos
        return [("a", ct * cz), ("aT", -nt * st * cz), ("aZ", -nz * ct * sz)]
    if field == 1:  # b sin cos
        return [("b", st * cz), ("bT", nt * ct * cz), ("bZ", -nz * st * sz)]
    return [("c", ct * sz), ("cT", -nt * st * sz), ("cZ", nz * ct * cz)]  # c cos sin
