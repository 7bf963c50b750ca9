"""What the two finite-element models of the wall share: the rectangle [1, R_N] x [0, extent]
of reference coordinates (R, Y) (Y = Theta for the cross-section, Z for the meridian), its
mixed unknowns, the constraints and the assembly of the energy's residual, tangent and mass
(scikit-fem).

Quadrilaterals with element edges on every layer interface, so the geometry is exact and
each element lies in one layer. Unknowns: the displacement (u_R, u_Y) on Q2, the pressure p
linear and discontinuous in each element (P1), the electric potential phi on Q2. The
in-plane displacement u_Y vanishes on the ends Y = 0 and Y = extent (the symmetry planes of
each model), the potential is V on R = 1 and 0 on R = R_N (electrodes). A model supplies
its kinematics (the state variables linear in a field, :func:`energy_forms`), its
parameters at the quadrature points and the potential of its follower pressures.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from skfem import (
    Basis,
    BilinearForm,
    ElementComposite,
    ElementQuad0,
    ElementQuad2,
    ElementVector,
    FacetBasis,
    Functional,
    LinearForm,
    MeshQuad,
    asm,
)

from ..errors import ParameterError
from ..model.layers import Tube
from .energy import derivatives

#: quadrature order: 3 x 3 Gauss points, exact for the Q2 x Q2 mass (the energy is not
#: polynomial; the base-state test sees the rates of exact integration)
INTORDER = 4


def pressure_field(p0, p1, p2, w):
    """p = p0 + p1 (R - R_c) / h_R + p2 (Y - Y_c) / h_Y, linear in each element (P1,
    discontinuous; the slopes scaled by the element's sides keep the matrix balanced)."""
    return p0 + p1 * (w.x[0] - w["Rc"]) / w["hR"] + p2 * (w.x[1] - w["Tc"]) / w["hT"]


def energy_forms(avec):
    """The tangent (bilinear) and residual (linear) forms of int psi R dR dY for the
    kinematics ``avec(u, p0, p1, p2, phi, w)``: the state variables' parts linear in one
    field. The weight R is the measure of both models (the sector's area element R dR dTheta
    per unit axial length, the meridian's volume element R dR dZ per radian)."""

    @BilinearForm
    def tangent(du, dp0, dp1, dp2, dphi, v, q0, q1, q2, psi, w):
        a = avec(du, dp0, dp1, dp2, dphi, w)
        b = avec(v, q0, q1, q2, psi, w)
        H = w["H"]
        # one field per basis function: skip the variables it does not touch
        ia = [i for i in range(len(a)) if np.any(a[i])]
        jb = [j for j in range(len(b)) if np.any(b[j])]
        out = 0.0
        for i in ia:
            row = H[i]
            out = out + a[i] * sum(row[j] * b[j] for j in jb)
        return out * w.x[0]

    @LinearForm
    def residual(v, q0, q1, q2, psi, w):
        b = avec(v, q0, q1, q2, psi, w)
        g = w["G"]
        return sum(g[j] * b[j] for j in range(len(b)) if np.any(b[j])) * w.x[0]

    return tangent, residual


@BilinearForm
def _mass(du, dp0, dp1, dp2, dphi, v, q0, q1, q2, psi, w):
    return (du[0] * v[0] + du[1] * v[1]) * w.x[0]


@Functional
def _integral(w):
    return w["f"] * w.x[0]


class _Where:
    """The coordinates and element centres as a form's ``w`` sees them."""

    def __init__(self, X, centres):
        self.x = np.asarray(X)
        self._c = centres

    def __getitem__(self, key):
        return self._c[key]


@dataclasses.dataclass(frozen=True)
class MeshSize:
    """Elements through each layer (radial) and along the second coordinate (``hoop``: the
    sector's Theta for the cross-section, the window's Z for the meridian)."""

    radial: tuple[int, ...]
    hoop: int

    @property
    def elements(self) -> int:
        return sum(self.radial) * self.hoop


def radial_counts(tube: Tube, density: float) -> tuple[int, ...]:
    """About ``density`` elements per unit reference length across each layer, at least 2."""
    radii = tube.radii
    return tuple(max(2, math.ceil(density * (b - a))) for a, b in zip(radii, radii[1:]))


def check_supported(tube: Tube, model: str) -> None:
    """ParameterError unless every layer is neo-Hookean and the axial stretch prescribed."""
    for k, layer in enumerate(tube.layers, 1):
        if layer.material.name != "neo-hookean":
            raise ParameterError(
                f"layers[{k}] has the {layer.material.name} energy; the finite-element"
                " model supports the neo-Hookean ideal dielectric only"
            )
    if tube.stretch is None:
        raise ParameterError(
            f"the tube prescribes an axial force; the {model} model needs a prescribed axial"
            " stretch (give stretch)"
        )


def check_periods(periods, count: int, name: str, largest: int | None = None) -> None:
    """ParameterError unless ``periods`` (half wavelengths of the mode in the sector or
    window) divides the mode number ``count`` (the patterns the model then holds repeat a
    whole number of times around the ring, along the tube) and is at most ``largest``."""
    top = count if largest is None else max(1, largest)
    ok = isinstance(periods, int) and not isinstance(periods, bool) and 1 <= periods <= top
    if not (ok and count % periods == 0):
        divisors = ", ".join(str(d) for d in range(1, top + 1) if count % d == 0)
        raise ParameterError(
            f"periods = {periods!r} is out of range for {name} = {count}; valid: a divisor"
            f" of {count} ({divisors})"
        )


class Wall:
    """The mesh, bases, constraints and energy of the rectangle [1, R_N] x [0, ``extent``]
    of ``tube``'s wall; a model (subclass) sets ``kind``, :meth:`kinematics` and ``forms``
    (``energy_forms(kinematics)``), :meth:`_parameters`, :meth:`_identity` and the follower
    pressures' potential (:meth:`_face_energy`, :meth:`_face_residual`,
    :meth:`_face_tangent`)."""

    kind = ""
    forms: tuple = ()
    #: half wavelengths of the mode in the sector or window (set by the model)
    periods = 1

    @staticmethod
    def kinematics(u, p0, p1, p2, phi, w) -> tuple:
        """The state variables' parts linear in one field (the model's F - I, Grad phi, p)."""
        raise NotImplementedError

    def __init__(self, tube: Tube, size: MeshSize, extent: float):
        check_supported(tube, self.kind)
        if len(size.radial) != len(tube.layers):
            raise ParameterError(f"{len(size.radial)} radial counts for {len(tube.layers)} layers")
        self.size, self.extent = size, extent
        self.radii = radii = tube.radii
        nodes = [np.linspace(a, b, n + 1) for a, b, n in zip(radii, radii[1:], size.radial)]
        Rn = np.unique(np.concatenate(nodes))
        Yn = np.linspace(0.0, extent, size.hoop + 1)
        self.mesh = MeshQuad.init_tensor(Rn, Yn)
        p1 = ElementQuad0()
        elem = ElementComposite(ElementVector(ElementQuad2()), p1, p1, p1, ElementQuad2())
        self.basis = Basis(self.mesh, elem, intorder=INTORDER)
        R_N = radii[-1]
        self.faces = {}
        for name, Rf in (("inner", 1.0), ("outer", R_N)):
            facets = self.mesh.facets_satisfying(lambda x, Rf=Rf: np.isclose(x[0], Rf))
            self.faces[name] = FacetBasis(self.mesh, elem, facets=facets, intorder=INTORDER)
        on_ends = self.basis.get_dofs(lambda x: np.isclose(x[1], 0.0) | np.isclose(x[1], extent))
        self.end_fixed = on_ends.all("u^2^1")
        self.phi_inner = self.basis.get_dofs(lambda x: np.isclose(x[0], 1.0)).all("u^5")
        self.phi_outer = self.basis.get_dofs(lambda x: np.isclose(x[0], R_N)).all("u^5")
        self.phi_dofs = self.basis.get_dofs(elements=True).all("u^5")
        R_phi = self.basis.doflocs[0, self.phi_dofs]
        self.lift = np.log(radii[-1] / R_phi) / np.log(radii[-1])
        self.fixed = np.unique(np.concatenate([self.end_fixed, self.phi_inner, self.phi_outer]))
        self.free = np.setdiff1d(np.arange(self.basis.N), self.fixed)
        self.R = np.asarray(self.basis.global_coordinates())[0]
        mid = self.mesh.p[0, self.mesh.t].mean(axis=0)
        self.layer_of = np.searchsorted(np.asarray(radii[1:-1]), mid)
        corners = self.mesh.p[:, self.mesh.t]
        centre = corners.mean(axis=1)
        sides = corners.max(axis=1) - corners.min(axis=1)
        self.centres = {
            "Rc": centre[0][:, None],
            "Tc": centre[1][:, None],
            "hR": sides[0][:, None],
            "hT": sides[1][:, None],
        }
        self._w = _Where(self.basis.global_coordinates(), self.centres)
        self.M = asm(_mass, self.basis)
        # the constant part p0 of each element's pressure, in element order
        p0 = set(self.basis.split_indices()[1].tolist())
        self.pressure_dofs = np.array(
            [next(d for d in col if d in p0) for col in self.basis.element_dofs.T]
        )
        self._tube: Tube | None = None
        self.set_tube(tube)

    # -- the tube's numbers at the quadrature points ---------------------------------------
    def set_tube(self, tube: Tube) -> None:
        """Take the loads and growth of ``tube`` (same layers' radii)."""
        if tube.radii != self.radii:
            raise ParameterError("the tube's radii differ from the mesh's")
        check_supported(tube, self.kind)
        shape = self.R.shape
        mu, eps = np.empty(shape), np.empty(shape)
        g = np.empty((3,) + shape)
        for k, layer in enumerate(tube.layers):
            sel = self.layer_of == k
            mu[sel], eps[sel] = layer.shear_modulus, layer.permittivity
            g[:, sel] = layer.growth_at(self.R[sel])
        self.params = self._parameters(tube, mu, eps, g)
        self.voltage = tube.voltage * (tube.radii[-1] - 1.0)
        self._tube = tube

    def _parameters(self, tube, mu, eps, g) -> np.ndarray:
        raise NotImplementedError

    def _identity(self) -> dict[int, float]:
        """The state variables' values in the undeformed wall (index: value)."""
        raise NotImplementedError

    @property
    def tube(self) -> Tube:
        assert self._tube is not None  # set in __init__
        return self._tube

    # -- unknowns ---------------------------------------------------------------------------
    def dirichlet(self) -> np.ndarray:
        """The prescribed values (zero u_Y on the ends, the potentials)."""
        x = np.zeros(self.basis.N)
        x[self.phi_inner] = self.voltage
        return x

    def with_fixed(self, x: np.ndarray) -> np.ndarray:
        """``x`` with its prescribed entries set to the current tube's values. When the
        voltage differs from the one ``x`` holds, the whole potential moves by the change
        times the lift L = log(R_N / R) / log R_N (1 on the inner electrode, 0 on the outer),
        not the electrodes' values alone (which would put the whole change into the first
        element): the free unknowns are in effect phi - V L, so a change of the control
        moves the state smoothly (Newton's start, and dR/dc of the branch)."""
        x = x.copy()
        change = self.voltage - x[self.phi_inner[0]]
        if change:
            x[self.phi_dofs] += change * self.lift
        d = self.dirichlet()
        x[self.fixed] = d[self.fixed]
        return x

    def state(self, x: np.ndarray) -> np.ndarray:
        """The state variables at the quadrature points, shape (nv, ne, nq)."""
        u, p0, p1, p2, phi = self.basis.interpolate(x)
        s = np.array(self.kinematics(u, p0, p1, p2, phi, self._w))
        for i, value in self._identity().items():
            s[i] += value
        return s

    # -- energy derivatives ---------------------------------------------------------------
    def residual(self, x: np.ndarray) -> np.ndarray:
        gradient, _ = derivatives(self.kind)
        G = gradient(self.state(x), self.params)
        r = asm(self.forms[1], self.basis, G=G, **self.centres)
        for face, load in self._face_loads():
            r += self._face_residual(self.faces[face], x, load)
        return r

    def energy(self, x: np.ndarray) -> float:
        """The total potential energy (a saddle in phi): int psi R dR dY plus the follower
        pressures' potential."""
        gradient, _ = derivatives(self.kind)
        psi = gradient.density(self.state(x), self.params)
        total = float(asm(_integral, self.basis, f=psi))
        for face, load in self._face_loads():
            total += self._face_energy(self.faces[face], x, load)
        return total

    def tangent(self, x: np.ndarray):
        _, hessian = derivatives(self.kind)
        H = hessian(self.state(x), self.params)
        K = asm(self.forms[0], self.basis, H=H, **self.centres)
        for face, load in self._face_loads():
            K = K + self._face_tangent(self.faces[face], x, load)
        return K

    def _face_loads(self) -> list[tuple[str, float]]:
        """(face, factor of the face's enclosed measure in the load potential)."""
        raise NotImplementedError

    def _face_residual(self, fb, x, load):
        raise NotImplementedError

    def _face_energy(self, fb, x, load) -> float:
        raise NotImplementedError

    def _face_tangent(self, fb, x, load):
        raise NotImplementedError

    # -- read-outs -------------------------------------------------------------------------
    def nodal(self, x: np.ndarray, name: str) -> np.ndarray:
        """Nodal values of u_R, u_Y ('u_Theta' or 'u_Z') or phi at the mesh vertices."""
        index = {"u_R": 0, "u_Theta": 1, "u_Z": 1, "phi": 2}[name]
        return x[self.basis.nodal_dofs[index]]

    def face_dofs(self, face: str) -> tuple[np.ndarray, np.ndarray]:
        """(u_R dofs at the vertices of ``face`` ordered by Y, their Y)."""
        Rf = 1.0 if face == "inner" else self.tube.radii[-1]
        verts = np.nonzero(np.isclose(self.mesh.p[0], Rf))[0]
        verts = verts[np.argsort(self.mesh.p[1, verts])]
        return self.basis.nodal_dofs[0, verts], self.mesh.p[1, verts]


__all__ = [
    "MeshSize",
    "Wall",
    "check_periods",
    "check_supported",
    "energy_forms",
    "radial_counts",
]
