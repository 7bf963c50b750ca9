"""The record of a post-buckled branch: its onsets, mesh, points and stability, as JSON and
as an ``xarray.Dataset``."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..model.layers import Tube
from .section import MeshSize
from .stability import ELEMENT_SCALE, Secondary, pattern_name


@dataclasses.dataclass(frozen=True)
class PostbuckleResult:
    """The post-buckled branch of mode (m, 0) (cross-section) or (0, n) (meridian).

    ``onset_linear`` the package's critical value, ``onset_fe`` the sign change of the FE
    tangent's lowest eigenvalue on the unperturbed path; ``control``, ``amplitude``,
    ``energy`` the branch (amplitude a: the cos(m Theta) radial displacement of ``face``,
    the face where the critical mode is larger, units R_i; for the meridian the cos(k z)
    radial displacement; energy: the whole tube's per unit reference length (the ring's;
    the meridian's averaged over a wavelength), units mu R_i^2), ``curvature``
    d(control) / d(a^2) at onset on the perfect branch and ``curvature_error`` its change
    between the last two amplitude scales (api.initial_curvature); ``imperfection`` the load
    imperfection's size (0: the perfect bifurcated branch); ``eigenvalue`` the lowest
    eigenvalue of the tangent at fixed control at each point (< 0: unstable; NaN at the
    onset itself), ``subharmonic`` its eigenvector's fraction outside the mode's family and
    ``pattern`` the period of that eigenvector's pattern in wavelengths of the mode (1: the
    mode's family, "symmetric"; 2: "period-doubling"; only a sector of ``periods`` > 1 half
    wavelengths holds the others); ``secondary`` where the lowest eigenvalue changes sign
    on the branch; ``ended`` why the branch stopped short of the amplitude asked ("" if it
    did not); ``states`` the unknowns of each point, ``section`` the FE model (for shapes
    and VTK)."""

    tube: Tube
    solve_for: str
    m: int
    onset_linear: float
    onset_fe: float
    mesh: MeshSize
    unknowns: int
    control: np.ndarray
    amplitude: np.ndarray
    energy: np.ndarray
    curvature: float
    imperfection: float
    eigenvalue: np.ndarray
    states: tuple = dataclasses.field(repr=False, compare=False)
    section: object = dataclasses.field(repr=False, compare=False)
    ended: str = ""
    face: str = "inner"
    n: int = 0
    periods: int = 1
    subharmonic: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0))
    pattern: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0, int))
    secondary: tuple[Secondary, ...] = ()
    curvature_error: float = math.nan
    #: each point's lowest eigenvector's share in patterns the mesh does not resolve
    element_scale: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0))
    #: the first amplitude where the lowest eigenvalue is negative in a pattern of the
    #: elements' size (its ``eigenvalue`` is NaN there: the tube's stability is not known),
    #: NaN if none
    unresolved_from: float = math.nan

    @property
    def stability_note(self) -> str:
        """Why the branch's stability is not established past some amplitude, or ""."""
        if math.isnan(self.unresolved_from):
            return ""
        where = "sector (--hoop)" if self.n == 0 else "window (--axial)"
        return (
            f"from amplitude {self.unresolved_from:.6g} on the lowest eigenvalue is negative in"
            " a pattern of the elements' size (half a wavelength shorter than two elements),"
            " the mixed elements' artefact under compression, not the tube's: the branch's"
            " stability there is not established on this mesh (lowest_eigenvalue null) and"
            " no secondary point is reported there; compare a mesh with another ratio of"
            f" elements along the {where} to elements across the wall (--density)"
        )

    @property
    def lowest_mode(self) -> list[str | None]:
        """The name of each point's lowest eigenvector's pattern (None: not computed;
        "element-scale" where its negative eigenvalue is the mesh's, ``eigenvalue`` NaN)."""
        names = [pattern_name(int(d)) if d > 0 else None for d in self.pattern]
        unresolved = self.element_scale > ELEMENT_SCALE
        return [
            "element-scale" if k < len(unresolved) and unresolved[k] and np.isnan(v) else name
            for k, (name, v) in enumerate(zip(names, self.eigenvalue))
        ]

    @property
    def mode(self) -> tuple[int, int]:
        return (self.m, self.n)

    def _mesh_record(self) -> dict:
        k = "" if self.periods == 1 else str(self.periods)
        along = (
            {"hoop_elements": self.mesh.hoop, "sector": f"{k}pi/{self.m}"}
            if self.n == 0
            else {"axial_elements": self.mesh.hoop, "window": f"{k}L/{self.n}"}
        )
        return {
            "radial_elements": list(self.mesh.radial),
            **along,
            "elements": self.mesh.elements,
            "unknowns": self.unknowns,
        }

    def as_dict(self) -> dict:
        """The JSON record."""
        return {
            "solve_for": self.solve_for,
            "m": self.m,
            "n": self.n,
            "onset_linear": self.onset_linear,
            "onset_fe": self.onset_fe,
            "onset_relative_difference": (self.onset_fe - self.onset_linear)
            / abs(self.onset_linear),
            "curvature": self.curvature,
            "curvature_error": self.curvature_error,
            "amplitude_face": self.face,
            "imperfection": self.imperfection,
            "periods": self.periods,
            "mesh": self._mesh_record(),
            "branch": {
                "control": self.control.tolist(),
                "amplitude": self.amplitude.tolist(),
                "energy": self.energy.tolist(),
                "lowest_eigenvalue": [None if np.isnan(v) else v for v in self.eigenvalue],
                "lowest_mode": self.lowest_mode,
                "subharmonic_fraction": [None if np.isnan(v) else v for v in self.subharmonic],
                "element_scale_fraction": [None if np.isnan(v) else v for v in self.element_scale],
            },
            "secondary": [s.as_dict() for s in self.secondary],
            "stability_unresolved_from": (
                None if math.isnan(self.unresolved_from) else self.unresolved_from
            ),
            "stability_note": self.stability_note or None,
            "ended": self.ended or None,
            "tube": self.tube.record(),
        }

    def to_xarray(self):
        """The branch as an ``xarray.Dataset`` on dimension ``point``."""
        import xarray as xr

        return xr.Dataset(
            {
                "control": ("point", self.control, {"long_name": self.solve_for}),
                "energy": ("point", self.energy, {"units": "mu R_i^2"}),
                "lowest_eigenvalue": ("point", self.eigenvalue, {"units": "mu / R_i^2"}),
                "subharmonic_fraction": ("point", self.subharmonic),
                "pattern_period": ("point", self.pattern, {"units": "wavelengths"}),
                "element_scale_fraction": ("point", self.element_scale),
            },
            coords={"amplitude": ("point", self.amplitude, {"units": "R_i"})},
            attrs={
                "m": self.m,
                "n": self.n,
                "onset_linear": self.onset_linear,
                "onset_fe": self.onset_fe,
                "curvature": self.curvature,
                "curvature_error": self.curvature_error,
                "periods": self.periods,
                "stability_unresolved_from": self.unresolved_from,
            },
        )


__all__ = ["PostbuckleResult"]
