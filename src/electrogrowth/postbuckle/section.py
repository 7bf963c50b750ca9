"""The finite-element model of a tube's cross-section: a sector of the wall in reference polar
coordinates (R, Theta), its unknowns and its energy's residual and tangent (scikit-fem).

The mesh is the rectangle [1, R_N] x [0, pi / m] of (R, Theta), quadrilaterals with element
edges on every layer interface, so the geometry is exact and each element lies in one layer.
Unknowns: the displacement in the reference polar frame (u_R, u_Theta) on Q2, the pressure p
on Q1 (Taylor-Hood: the mixed, stable pair for incompressibility), the electric potential
phi on Q2. The position is x = (R + u_R) e_R(Theta) + u_Theta e_Theta(Theta), so

    F = [[1 + u_R,R, (u_R,Theta - u_Theta) / R], [u_Theta,R, 1 + (u_R + u_Theta,Theta) / R]].

Symmetry: u_Theta = 0 on the rays Theta = 0 and Theta = pi / m (the sector then holds the
modes cos(j m Theta), j = 0, 1, 2, ...: other modes, period doubling included, are
suppressed). Electrodes: phi = V on R = 1, 0 on R = R_N. Follower pressures through the
potential -P_i lambda_z A_i + P_o lambda_z A_o, A the area the face encloses in the sector,
A = 1/2 int x cross x_Theta dTheta.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import skfem
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
from .energy import cauchy_stress, derivatives

#: quadrature order: 3 x 3 Gauss points, exact for the Q2 x Q2 mass (the energy is not
#: polynomial; the base-state test sees the rates of exact integration)
INTORDER = 4


def _avec(u, p0, p1, p2, phi, w):
    """The 7 variables (F - I flattened, Grad phi, p) linear in one (trial or test) field;
    p = p0 + p1 (R - R_c) / h_R + p2 (Theta - Theta_c) / h_Theta is linear in each element
    (P1, discontinuous; the slopes scaled by the element's sides keep the matrix balanced)."""
    R = w.x[0]
    g = u.grad
    return (
        g[0, 0],
        (g[0, 1] - u[1]) / R,
        g[1, 0],
        (g[1, 1] + u[0]) / R,
        phi.grad[0],
        phi.grad[1] / R,
        p0 + p1 * (R - w["Rc"]) / w["hR"] + p2 * (w.x[1] - w["Tc"]) / w["hT"],
    )


@BilinearForm
def _tangent(du, dp0, dp1, dp2, dphi, v, q0, q1, q2, psi, w):
    R = w.x[0]
    a = _avec(du, dp0, dp1, dp2, dphi, w)
    b = _avec(v, q0, q1, q2, psi, w)
    H = w["H"]
    # one field per basis function: skip the variables it does not touch
    ia = [i for i in range(7) if np.any(a[i])]
    jb = [j for j in range(7) if np.any(b[j])]
    out = 0.0
    for i in ia:
        row = H[i]
        out = out + a[i] * sum(row[j] * b[j] for j in jb)
    return out * R


@LinearForm
def _residual(v, q0, q1, q2, psi, w):
    R = w.x[0]
    b = _avec(v, q0, q1, q2, psi, w)
    g = w["G"]
    return sum(g[j] * b[j] for j in range(7) if np.any(b[j])) * R


@BilinearForm
def _mass(du, dp0, dp1, dp2, dphi, v, q0, q1, q2, psi, w):
    return (du[0] * v[0] + du[1] * v[1]) * w.x[0]


@Functional
def _integral(w):
    return w["f"] * w.x[0]


@Functional
def _face_integral(w):
    b = _face_vars(w["prev"], w.x[0])
    R = w.x[0]
    return w["load"] * 0.5 * ((R + b[0]) * (R + b[0] + b[3]) - b[1] * (b[2] - b[1]))


def _face_vars(u, R):
    """(u_R, u_Theta, u_R,Theta, u_Theta,Theta) on a face R = const."""
    return (u[0], u[1], u.grad[0, 1], u.grad[1, 1])


def _enclosed_gradient(b, R):
    """d c / d b of c = (R + b0)(R + b0 + b3) - b1 (b2 - b1) = x cross x_Theta."""
    return (2 * R + 2 * b[0] + b[3], 2 * b[1] - b[2], -b[1], R + b[0])


#: its constant Hessian (i, j, value), symmetric pairs listed both ways
_ENCLOSED_HESSIAN = (
    (0, 0, 2.0),
    (0, 3, 1.0),
    (3, 0, 1.0),
    (1, 1, 2.0),
    (1, 2, -1.0),
    (2, 1, -1.0),
)


@LinearForm
def _face_residual(v, q0, q1, q2, psi, w):
    R = w.x[0]
    g = _enclosed_gradient(_face_vars(w["prev"], R), R)
    b = _face_vars(v, R)
    return w["load"] * 0.5 * sum(gi * bi for gi, bi in zip(g, b))


@BilinearForm
def _face_tangent(du, dp0, dp1, dp2, dphi, v, q0, q1, q2, psi, w):
    a = _face_vars(du, w.x[0])
    b = _face_vars(v, w.x[0])
    return w["load"] * 0.5 * sum(h * a[i] * b[j] for i, j, h in _ENCLOSED_HESSIAN)


class _Where:
    """The coordinates and element centres as a form's ``w`` sees them."""

    def __init__(self, X, centres):
        self.x = np.asarray(X)
        self._c = centres

    def __getitem__(self, key):
        return self._c[key]


@dataclasses.dataclass(frozen=True)
class MeshSize:
    """Elements through each layer (radial) and along the sector (hoop)."""

    radial: tuple[int, ...]
    hoop: int

    @property
    def elements(self) -> int:
        return sum(self.radial) * self.hoop


def mesh_size(tube: Tube, m: int, density: float, *, hoop: int | None = None) -> MeshSize:
    """A mesh of about ``density`` elements per unit reference length across the wall (at
    least 2 per layer), and along the sector ``hoop`` elements (default: as many per unit
    arc length at R = 1 as across, at least 4)."""
    radii = tube.radii
    radial = tuple(max(2, math.ceil(density * (b - a))) for a, b in zip(radii, radii[1:]))
    if hoop is None:
        hoop = max(4, math.ceil(density * math.pi / m))
    return MeshSize(radial, int(hoop))


class Section:
    """The cross-section sector of ``tube`` for mode ``m``: mesh, bases, constraints and the
    energy's residual and tangent at a vector of unknowns ``x`` (the tube's loads as given;
    :meth:`at` swaps the tube)."""

    def __init__(self, tube: Tube, m: int, size: MeshSize):
        if m < 1:
            raise ParameterError(f"m = {m} is out of range; valid range: m >= 1")
        for k, layer in enumerate(tube.layers, 1):
            if layer.material.name != "neo-hookean":
                raise ParameterError(
                    f"layers[{k}] has the {layer.material.name} energy; the finite-element"
                    " model supports the neo-Hookean ideal dielectric only"
                )
        if tube.stretch is None:
            raise ParameterError(
                "the tube prescribes an axial force; the cross-section model needs a"
                " prescribed axial stretch (give stretch)"
            )
        if len(size.radial) != len(tube.layers):
            raise ParameterError(f"{len(size.radial)} radial counts for {len(tube.layers)} layers")
        self.m, self.size = m, size
        self.radii = radii = tube.radii
        nodes = [np.linspace(a, b, n + 1) for a, b, n in zip(radii, radii[1:], size.radial)]
        Rn = np.unique(np.concatenate(nodes))
        self.sector = math.pi / m
        Tn = np.linspace(0.0, self.sector, size.hoop + 1)
        self.mesh = MeshQuad.init_tensor(Rn, Tn)
        p1 = ElementQuad0()
        elem = ElementComposite(ElementVector(ElementQuad2()), p1, p1, p1, ElementQuad2())
        self.basis = Basis(self.mesh, elem, intorder=INTORDER)
        R_N = radii[-1]
        self.faces = {}
        for name, Rf in (("inner", 1.0), ("outer", R_N)):
            facets = self.mesh.facets_satisfying(lambda x, Rf=Rf: np.isclose(x[0], Rf))
            self.faces[name] = FacetBasis(self.mesh, elem, facets=facets, intorder=INTORDER)
        on_rays = self.basis.get_dofs(
            lambda x: np.isclose(x[1], 0.0) | np.isclose(x[1], self.sector)
        )
        self.hoop_fixed = on_rays.all("u^2^1")
        self.phi_inner = self.basis.get_dofs(lambda x: np.isclose(x[0], 1.0)).all("u^5")
        self.phi_outer = self.basis.get_dofs(lambda x: np.isclose(x[0], R_N)).all("u^5")
        self.phi_dofs = self.basis.get_dofs(elements=True).all("u^5")
        R_phi = self.basis.doflocs[0, self.phi_dofs]
        self.lift = np.log(radii[-1] / R_phi) / np.log(radii[-1])
        self.fixed = np.unique(np.concatenate([self.hoop_fixed, self.phi_inner, self.phi_outer]))
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
        X = self.basis.global_coordinates()
        self._w = _Where(X, self.centres)
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
        if tube.stretch is None:
            raise ParameterError("the cross-section model needs a prescribed axial stretch")
        shape = self.R.shape
        mu, eps = np.empty(shape), np.empty(shape)
        g = np.empty((3,) + shape)
        for k, layer in enumerate(tube.layers):
            sel = self.layer_of == k
            mu[sel], eps[sel] = layer.shear_modulus, layer.permittivity
            g[:, sel] = layer.growth_at(self.R[sel])
        lz = np.full(shape, float(tube.stretch))
        self.params = np.array([mu, eps, lz, g[0], g[1], g[2]])
        self.voltage = tube.voltage * (tube.radii[-1] - 1.0)
        self._tube = tube

    @property
    def tube(self) -> Tube:
        assert self._tube is not None  # set in __init__
        return self._tube

    # -- unknowns ---------------------------------------------------------------------------
    def dirichlet(self) -> np.ndarray:
        """The prescribed values (zero hoop displacement on the rays, the potentials)."""
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
        """The 7 variables (F, Grad phi, p) at the quadrature points, shape (7, ne, nq)."""
        u, p0, p1, p2, phi = self.basis.interpolate(x)
        s = np.array(_avec(u, p0, p1, p2, phi, self._w))
        s[0] += 1.0
        s[3] += 1.0
        return s

    # -- energy derivatives ---------------------------------------------------------------
    def residual(self, x: np.ndarray) -> np.ndarray:
        gradient, _ = derivatives()
        r = asm(_residual, self.basis, G=gradient(self.state(x), self.params), **self.centres)
        for face, load in self._face_loads():
            fb = self.faces[face]
            r += asm(_face_residual, fb, prev=fb.interpolate(x)[0], load=load)
        return r

    def energy(self, x: np.ndarray) -> float:
        """The total potential energy of the sector per unit reference length along the axis:
        int psi dA - P_i lambda_z A_i + P_o lambda_z A_o (a saddle in phi)."""
        gradient, _ = derivatives()
        psi = gradient.density(self.state(x), self.params)
        total = float(asm(_integral, self.basis, f=psi))
        for face, load in self._face_loads():
            fb = self.faces[face]
            total += float(asm(_face_integral, fb, prev=fb.interpolate(x)[0], load=load))
        return total

    def tangent(self, x: np.ndarray):
        _, hessian = derivatives()
        K = asm(_tangent, self.basis, H=hessian(self.state(x), self.params), **self.centres)
        for face, load in self._face_loads():
            K = K + asm(_face_tangent, self.faces[face], load=load)
        return K

    def _face_loads(self):
        t = self.tube
        lz = float(t.stretch)
        out = []
        if t.inner_pressure:
            out.append(("inner", -t.inner_pressure * lz))
        if t.outer_pressure:
            out.append(("outer", t.outer_pressure * lz))
        return out

    def stresses(self, x: np.ndarray) -> np.ndarray:
        """The in-plane Cauchy stress at the quadrature points, (2, 2, ne, nq)."""
        return cauchy_stress(self.state(x), self.params)

    # -- read-outs -------------------------------------------------------------------------
    def nodal(self, x: np.ndarray, name: str) -> np.ndarray:
        """Nodal values of u_R ('u_R'), u_Theta ('u_Theta') or phi ('phi') at the mesh
        vertices."""
        return x[self.basis.nodal_dofs[{"u_R": 0, "u_Theta": 1, "phi": 2}[name]]]

    def face_dofs(self, face: str) -> tuple[np.ndarray, np.ndarray]:
        """(u_R dofs at the vertices of ``face`` ordered by Theta, their Theta)."""
        Rf = 1.0 if face == "inner" else self.tube.radii[-1]
        verts = np.nonzero(np.isclose(self.mesh.p[0], Rf))[0]
        verts = verts[np.argsort(self.mesh.p[1, verts])]
        return self.basis.nodal_dofs[0, verts], self.mesh.p[1, verts]


__all__ = ["MeshSize", "Section", "mesh_size", "skfem"]
