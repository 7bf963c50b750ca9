"""The potential of the follower pressures on a tube's faces, expanded about the
axisymmetric state: the load terms the Koiter coefficient of a pressurised tube needs
(docs/derivation-koiter.md, "Pressures on the faces").

A follower pressure P_i in the bore and P_o outside do the work P_i dV_i - P_o dV_o, V_f the
volume a face encloses, so the load's potential is Pi = -P_i V_i + P_o V_o. Per radian and
unit reference length (the measure of the tube forms: R dR times the mean over Theta or Z),
with a = U_r and b = U_theta or U_z on the face of current radius r0:

    prismatic (m, 0):    V = lambda_z / 2 < (r0 + a)^2 + b^2 + (r0 + a) b_,Theta - b a_,Theta >
    axisymmetric (0, n): V = 1 / 2 < (r0 + a)^2 (lambda_z + b_,Z) >,

< > the mean over Theta or Z: the area of the plane section, exactly quadratic in the
displacement (no cubic or quartic term), and the volume of revolution, exactly cubic (no
quartic term). The faces' values are the first and last Lobatto nodes of each displacement
harmonic (bonded rings: the first node of the innermost ring is R_i, the last of the
outermost R_o).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._types import FloatArray
from .monomial_forms import MonomialForms
from .ring_basis import face_rows

#: the face fields: a = U_r, b the other component, t = b's derivative along the face,
#: s = a's (prismatic only); suffix i inner, o outer
FACES = ("i", "o")


@dataclasses.dataclass
class FaceForms(MonomialForms):
    """The maps from the unknowns of a tube form (``harmonics``, ``slices``: fields 0 = U_r,
    1 = U_theta or U_z) to a, b and their derivatives along each face at ``points``
    equispaced points of one period; ``weight`` the mean."""

    family: str
    maps: dict
    weight: FloatArray
    size: int

    @classmethod
    def build(cls, forms, family: str, wavenumber: float, *, points: int = 16) -> FaceForms:
        """``forms`` a PolarForms, DielectricForms or MeridianForms; ``wavenumber`` m of a
        prismatic mode or K of an axisymmetric one. ``points`` integrate trigonometric
        polynomials of degree below it exactly (16: the cubic term up to harmonic 5)."""
        x = 2 * np.pi * np.arange(points) / (points * wavenumber)
        maps = {f + s: np.zeros((points, forms.size)) for f in "abts" for s in FACES}
        for (field, j), sl in zip(forms.harmonics, forms.slices):
            if field not in (0, 1):
                continue
            k = j * wavenumber
            c, s = np.cos(k * x), np.sin(k * x)
            for side, row in zip(FACES, face_rows(forms.rings)):  # the face's value
                if field == 0:  # a = a_j cos, a' = -k a_j sin
                    maps["a" + side][:, sl] += np.outer(c, row)
                    maps["s" + side][:, sl] += np.outer(-k * s, row)
                else:  # b = b_j sin, b' = k b_j cos
                    maps["b" + side][:, sl] += np.outer(s, row)
                    maps["t" + side][:, sl] += np.outer(k * c, row)
        return cls(family, maps, np.full(points, 1.0 / points), forms.size)

    def potential(self, state) -> dict[int, list]:
        """The monomials of Pi = -P_i V_i + P_o V_o order by order in the displacement
        (orders 1 to 3; order 3 only for the axisymmetric family)."""
        P_i, P_o = state.tube.inner_pressure, state.tube.outer_pressure
        radii = state.tube.radii
        lz = state.stretch
        out: dict[int, list] = {1: [], 2: [], 3: []}
        for side, R, load in zip(FACES, (radii[0], radii[-1]), (-P_i, P_o)):
            r0 = float(state.radius(np.array([R]))[0])
            a, b, t, s = (f + side for f in "abts")
            if self.family == "prismatic":
                half = load * lz / 2
                out[1] += [(2 * half * r0, (a,)), (half * r0, (t,))]
                out[2] += [(half, (a, a)), (half, (b, b)), (half, (a, t)), (-half, (b, s))]
            else:
                half = load / 2
                out[1] += [(2 * half * r0 * lz, (a,)), (half * r0**2, (t,))]
                out[2] += [(half * lz, (a, a)), (2 * half * r0, (a, t))]
                out[3] += [(half, (a, a, t))]
        return {k: [(np.full(len(self.weight), c), xs) for c, xs in v] for k, v in out.items()}
