"""The flat bilayer's nominal compression read off the tube's cross-section.

A film on a substrate compressed as a whole (Cao and Hutchinson 2012: no pre-stretch, the
film and the substrate shortened together by the nominal strain eps, plane strain) has
its counterpart in a thick tube under an external pressure: the film and the substrate
next to it share the hoop stretch. The tube's prescribed quantity is a load, so the strain
is read from the state: far from the film, where the wrinkles have decayed (like
exp(-m (R - 1))), the wall is axisymmetric and incompressible, so in plane strain at the
axial stretch lambda_z its radius r(R) obeys

    lambda_z (r_o^2 - r(R)^2) = R_N^2 - R^2,

r_o the outer face's radius. Extrapolated to the film's reference radius R = 1 this is
the hoop stretch the far field imposes there, the counterpart of the flat bilayer's
prescribed shortening 1 - eps:

    eps = 1 - r_1 / 1,    r_1^2 = r_o^2 - (R_N^2 - 1) / lambda_z.

On the unperturbed path it is exactly the inner face's hoop strain 1 - r_i (the same
identity through the whole wall); on the wrinkled branch it is the mean compression the
wrinkles accommodate. The stretch varies through the substrate like 1/R^2 at fixed
r^2 - R^2, which over the wrinkles' depth 1/m is the curvature correction O(1/m).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import ParameterError
from .branch import AmplitudeBranch


def nominal_compression(section, x: np.ndarray) -> float:
    """eps = 1 - r_1, the far field's hoop compression extrapolated to R = 1, of the state
    ``x`` of ``section`` (a cross-section of an ungrown tube; r_o the mean radius of its
    outer face's vertices)."""
    tube = section.tube
    for k, layer in enumerate(tube.layers, 1):
        if tuple(layer.growth) != (1.0, 1.0, 1.0):
            raise ParameterError(
                f"layers[{k}].growth = {layer.growth!r}; the nominal compression is read off"
                " an ungrown tube (growth 1 in every layer)"
            )
    dofs, _ = section.face_dofs("outer")
    outer = tube.radii[-1]
    r_o = outer + float(np.mean(x[dofs]))
    r_1 = math.sqrt(r_o**2 - (outer**2 - 1.0) / float(tube.stretch))
    return 1.0 - r_1


def compression_at(result, amplitude: float) -> float:
    """The nominal compression on ``result``'s branch (a :class:`~.result.PostbuckleResult`
    of a cross-section) at ``amplitude``, e.g. a secondary point's: the branch point solved
    there from the nearest computed one."""
    i = int(np.argmin(np.abs(result.amplitude - amplitude)))
    section = result.section
    branch = AmplitudeBranch(section, result.tube, result.solve_for, face=result.face)
    x, _, _ = branch.solve(result.states[i], float(result.control[i]), amplitude)
    return nominal_compression(section, x)


__all__ = ["compression_at", "nominal_compression"]
