"""What the two finite-element models of the wall share: the rectangle [1, R_N] x [0, extent]
of reference coordinates (R, Y) (Y = Theta for the cross-section, Z for the meridian), its
mixed unknowns, the constraints and the assembly of the energy's residual, tangent and mass
(scikit-fem).

Quadrilaterals with element edges on every layer interface, so the geometry is exact and
each element lies in one layer. Unknowns: the displacement (u_R, u_Y) on Q2, the pressure p
linear and discontinuous in each element (P1), and the stream function A of the Lagrangian
electric displacement on Q2 (D = curl A: Gauss's law holds identically; each model writes
D from Grad A). The in-plane displacement u_Y vanishes on the ends Y = 0 and Y = extent
(the symmetry planes of each model); no charge crosses them, so A is constant along each:
0 on Y = 0 and the unknown a on Y = extent, a the free charge the inner electrode carries
per unit of the model's measure (the flux of D through R = 1). The electrodes' potential
difference V does the work V a: the energy is int psi - V a, a minimum in (u, A) on the
incompressible displacements, and the electrodes' equipotentials are its natural
conditions. The unknowns the solvers see are the entries of x that are not prescribed,
with the tied values of A on Y = extent as one (:attr:`Wall.P`). A model supplies its
kinematics (the state variables linear in a field, :func:`energy_forms`), its parameters at
the quadrature points and the potential of its follower pressures.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import scipy.sparse as sps
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
    kinematics ``avec(u, p0, p1, p2, A, w)``: the state variables' parts linear in one
    field. The weight R is the measure of both models (the sector's area element R dR dTheta
    per unit axial length, the meridian's volume element R dR dZ per radian)."""

    @BilinearForm
    def tangent(du, dp0, dp1, dp2, dA, v, q0, q1, q2, vA, w):
        a = avec(du, dp0, dp1, dp2, dA, w)
        b = avec(v, q0, q1, q2, vA, w)
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
    def residual(v, q0, q1, q2, vA, w):
        b = avec(v, q0, q1, q2, vA, w)
        g = w["G"]
        return sum(g[j] * b[j] for j in range(len(b)) if np.any(b[j])) * w.x[0]

    return tangent, residual


@BilinearForm
def _mass(du, dp0, dp1, dp2, dA, v, q0, q1, q2, vA, w):
    return (du[0] * v[0] + du[1] * v[1]) * w.x[0]


def _prolongation(n: int, independent: np.ndarray, tied: np.ndarray) -> sps.csr_matrix:
    """The n x len(independent) matrix that puts each unknown at its entry of x and the
    first of ``tied`` (one of ``independent``) at all of them; prescribed entries stay 0."""
    column = {int(d): j for j, d in enumerate(independent)}
    rows = np.concatenate([independent, tied[1:]])
    cols = np.concatenate(
        [np.arange(len(independent)), np.full(len(tied) - 1, column[int(tied[0])])]
    )
    return sps.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(n, len(independent)))


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
    def kinematics(u, p0, p1, p2, A, w) -> tuple:
        """The state variables' parts linear in one field (the model's F - I, D, p)."""
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
        on_start = self.basis.get_dofs(lambda x: np.isclose(x[1], 0.0))
        on_end = self.basis.get_dofs(lambda x: np.isclose(x[1], extent))
        self.end_fixed = np.union1d(on_start.all("u^2^1"), on_end.all("u^2^1"))
        tied = on_end.all("u^5")
        #: a, the inner electrode's charge: A on the end Y = extent (the rest of it tied)
        self.charge_dof = int(tied[0])
        self.fixed = np.unique(np.concatenate([self.end_fixed, on_start.all("u^5")]))
        #: the entries of x the solvers' unknowns are, and P (N x unknowns): x = P x[independent]
        self.independent = np.setdiff1d(np.arange(self.basis.N), np.union1d(self.fixed, tied[1:]))
        self.P = _prolongation(self.basis.N, self.independent, tied)
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
        self.pressure_dofs = self._element_dofs(1)
        self.invariant = self._invariant_basis()
        self._tube: Tube | None = None
        self.set_tube(tube)

    def _element_dofs(self, field: int) -> np.ndarray:
        """The dof of the piecewise-constant ``field`` (1, 2, 3: p0, p1, p2) of each element."""
        own = set(self.basis.split_indices()[field].tolist())
        return np.array([next(d for d in col if d in own) for col in self.basis.element_dofs.T])

    def _invariant_basis(self) -> sps.csr_matrix:
        """The fields that do not depend on Y (the unperturbed, axisymmetric path), as the
        columns of an N x n matrix: u_R(R) (one column per radius of a node), u_Y = 0, the
        pressure's p0 and R-slope p1 of each row of elements (p2 = 0), and A = a Y / extent
        (D = (a / (extent R), 0)). Newton on the path moves in this space only: the onset's
        mode lies outside it, so the tangent's near-singularity at onset does not amplify
        rounding along the mode."""
        rows, cols, values = [], [], []

        def add(dofs, groups, weights=None):
            """One column per distinct value of ``groups``, ``weights`` (1) at ``dofs``."""
            _, index = np.unique(np.round(groups, 10), return_inverse=True)
            cols.append(index + (max(c.max() for c in cols) + 1 if cols else 0))
            rows.append(dofs)
            values.append(np.ones(len(dofs)) if weights is None else weights)

        u_R = self.basis.get_dofs(elements=True).all("u^1^1")
        add(u_R, self.basis.doflocs[0, u_R])
        row = self.centres["Rc"][:, 0]
        add(self.pressure_dofs, row)
        add(self._element_dofs(2), row)
        A = self.basis.get_dofs(elements=True).all("u^5")
        add(A, np.zeros(len(A)), self.basis.doflocs[1, A] / self.extent)
        n = max(c.max() for c in cols) + 1
        data = (np.concatenate(values), (np.concatenate(rows), np.concatenate(cols)))
        return sps.csr_matrix(data, shape=(self.basis.N, n))

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
    @property
    def unknowns(self) -> int:
        """The number of unknowns the solvers see (the columns of :attr:`P`)."""
        return self.P.shape[1]

    def restrict(self, r: np.ndarray) -> np.ndarray:
        """P^T r: a residual on all entries of x as the solvers see it."""
        return self.P.T @ r

    def reduced(self, K):
        """P^T K P: a matrix on all entries of x as the solvers see it (sparse CSC)."""
        return (self.P.T @ K @ self.P).tocsc()

    def expand(self, y: np.ndarray) -> np.ndarray:
        """P y: an increment of the solvers' unknowns on all entries of x."""
        return self.P @ y

    def with_fixed(self, x: np.ndarray) -> np.ndarray:
        """``x`` with its prescribed entries zero (u_Y on the ends, A on Y = 0) and A on
        Y = extent equal to the charge a (the voltage enters the energy, not x)."""
        return self.P @ x[self.independent]

    def state(self, x: np.ndarray) -> np.ndarray:
        """The state variables at the quadrature points, shape (nv, ne, nq)."""
        u, p0, p1, p2, A = self.basis.interpolate(x)
        s = np.array(self.kinematics(u, p0, p1, p2, A, self._w))
        for i, value in self._identity().items():
            s[i] += value
        return s

    # -- energy derivatives ---------------------------------------------------------------
    def residual(self, x: np.ndarray) -> np.ndarray:
        gradient, _ = derivatives(self.kind)
        G = gradient(self.state(x), self.params)
        r = asm(self.forms[1], self.basis, G=G, **self.centres)
        r[self.charge_dof] -= self.voltage
        for face, load in self._face_loads():
            r += self._face_residual(self.faces[face], x, load)
        return r

    def energy(self, x: np.ndarray) -> float:
        """The total potential energy: int psi R dR dY, the electrodes' work -V a and the
        follower pressures' potential."""
        gradient, _ = derivatives(self.kind)
        psi = gradient.density(self.state(x), self.params)
        total = float(asm(_integral, self.basis, f=psi)) - self.voltage * self.charge(x)
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
    def charge(self, x: np.ndarray) -> float:
        """The charge a on the inner electrode, per unit of the model's measure (the flux of
        the Lagrangian D through R = 1 over the rectangle's extent)."""
        return float(x[self.charge_dof])

    def nodal(self, x: np.ndarray, name: str) -> np.ndarray:
        """Nodal values of u_R, u_Y ('u_Theta' or 'u_Z') or A (the stream function of D)
        at the mesh vertices."""
        index = {"u_R": 0, "u_Theta": 1, "u_Z": 1, "A": 2}[name]
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
