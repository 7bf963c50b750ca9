"""The wrinkled tube in 3D: displacement on the wall, its surfaces and a VTK mesh of the wall.

A mode shape (mode_shape.py) gives the incremental fields of paper eq.
incremental-solutions,

    u_r = U_r(r) cos(m th) cos(kz),  u_th = U_th(r) sin(m th) cos(kz),
    u_z = U_z(r) cos(m th) sin(kz),  phidot = Phi(r) cos(m th) cos(kz),

on the current (grown, stretched, charged) tube r_i <= r <= r_o, -pi <= th <= pi,
0 <= z <= l = lambda_z L; k = n pi / l, so the ends z = 0, l keep u_z = 0 (paper eq. 57).
The wrinkled tube is x = r e_r + z e_z + a u with a small ``amplitude`` a (the mode is
normalised to max |U| = 1, so a is the largest displacement in units of R_i).
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np

from .._types import FloatArray
from ..atomic import replaced_name
from ..errors import MissingDependencyError, ParameterError
from .mode_shape import ModeShape

FACES = ("outer", "inner")


def displacement(shape: ModeShape, eta: FloatArray, theta, z) -> tuple[FloatArray, ...]:
    """(u_r, u_th, u_z, phidot) of eq. incremental-solutions for the Stroh values ``eta``
    (8, ...) at the same points as theta and z (broadcast); amplitude 1."""
    m, k = shape.m, shape.k
    cc = np.cos(m * theta) * np.cos(k * z)
    return (
        eta[0] * cc,
        eta[1] * np.sin(m * theta) * np.cos(k * z),
        eta[2] * np.cos(m * theta) * np.sin(k * z),
        -eta[7] * cc,
    )


def cartesian(r, theta, z, u_r, u_th, u_z) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Cartesian (x, y, z) of the point r e_r + z e_z + u (cylindrical components)."""
    c, s = np.cos(theta), np.sin(theta)
    rr = r + u_r
    return rr * c - u_th * s, rr * s + u_th * c, z + u_z


@dataclasses.dataclass(frozen=True)
class Surface:
    """A deformed surface on a (theta, z) grid: Cartesian x, y, z, the radial displacement
    u_r (amplitude included) and the grid (theta from -pi to pi, z_ref from 0 to l)."""

    x: FloatArray
    y: FloatArray
    z: FloatArray
    u_r: FloatArray
    theta: FloatArray
    z_ref: FloatArray


def _resolution(shape: ModeShape, n_theta: int | None, n_z: int | None) -> tuple[int, int]:
    n_theta = n_theta or max(181, 24 * shape.m + 1)
    n_z = n_z or max(61, 24 * shape.n + 1)
    for name, v in (("n_theta", n_theta), ("n_z", n_z)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 3:
            raise ParameterError(f"{name} = {v!r} is invalid; need an integer >= 3")
    return int(n_theta), int(n_z)


def _check_amplitude(amplitude) -> float:
    if (
        isinstance(amplitude, bool)
        or not isinstance(amplitude, (int, float))
        or not (math.isfinite(amplitude) and amplitude >= 0)
    ):
        raise ParameterError(
            f"amplitude = {amplitude!r} is invalid; need a finite number"
            " >= 0 (the largest displacement, units R_i)"
        )
    return float(amplitude)


def deformed_surface(
    shape: ModeShape,
    *,
    amplitude: float = 0.1,
    n_theta: int | None = None,
    n_z: int | None = None,
    face: str = "outer",
) -> Surface:
    """The outer (r = r_o) or inner (r = r_i) face of the wrinkled tube.

    x = r e_r + z e_z + amplitude u on -pi <= th <= pi, 0 <= z <= l = lambda_z L
    (both ends included, so the grid closes around the circumference).

    Parameters
    ----------
    shape : ModeShape
    amplitude : float
        Largest displacement a >= 0 (units R_i); 0 gives the unwrinkled cylinder.
    n_theta, n_z : int, optional
        Grid points around and along (default max(121, 24 m + 1), max(61, 24 n + 1)).
    face : {"outer", "inner"}

    Returns
    -------
    Surface
        Arrays of shape (n_theta, n_z).
    """
    if face not in FACES:
        raise ParameterError(f"face = {face!r} is unknown; choose outer or inner")
    a = _check_amplitude(amplitude)
    n_theta, n_z = _resolution(shape, n_theta, n_z)
    j = -1 if face == "outer" else 0
    th, z = np.meshgrid(
        np.linspace(-np.pi, np.pi, n_theta), np.linspace(0.0, shape.length, n_z), indexing="ij"
    )
    ur, ut, uz, _ = displacement(shape, shape.eta[:, j], th, z)
    x, y, zz = cartesian(shape.r[j], th, z, a * ur, a * ut, a * uz)
    return Surface(x, y, zz, a * ur, th[:, 0].copy(), z[0].copy())


def wall_surface(
    shape: ModeShape,
    *,
    amplitude: float = 0.1,
    n_theta: int | None = None,
    n_z: int | None = None,
    n_r: int = 17,
) -> Surface:
    """The whole boundary of the wall as one closed surface (for rendering): each column
    of the grid walks round the (r, z) section, outer face up, top annulus in, inner face
    down, bottom annulus out. ``z_ref`` then holds the arc parameter of that walk."""
    a = _check_amplitude(amplitude)
    n_theta, n_z = _resolution(shape, n_theta, n_z)
    Ro, l = shape.params.outer_radius, shape.length
    up, across = np.linspace(0.0, l, n_z), np.linspace(Ro, 1.0, n_r)[1:-1]
    R = np.concatenate([np.full(n_z, Ro), across, np.full(n_z, 1.0), across[::-1], [Ro]])
    z = np.concatenate([up, np.full(across.size, l), up[::-1], np.zeros(across.size), [0.0]])
    eta = shape.at(R)
    eta[:, R == Ro], eta[:, R == 1.0] = shape.eta[:, -1:], shape.eta[:, :1]
    r = np.interp(R, shape.R, shape.r)
    r[R == Ro], r[R == 1.0] = shape.r[-1], shape.r[0]
    th = np.linspace(-np.pi, np.pi, n_theta)[:, None]
    ur, ut, uz, _ = displacement(shape, eta[:, None, :], th, z[None, :])
    x, y, zz = cartesian(r[None, :], th, z[None, :], a * ur, a * ut, a * uz)
    return Surface(x, y, zz, a * ur, th[:, 0].copy(), np.arange(z.size, dtype=float))


def wall_mesh(
    shape: ModeShape,
    *,
    amplitude: float = 0.1,
    n_r: int = 17,
    n_theta: int | None = None,
    n_z: int | None = None,
) -> dict:
    """A structured hexahedral mesh of the whole wall in the current base configuration.

    Points (r_j, th_i, z_k), j < n_r (R equally spaced in [1, Rbar_o]), i < n_theta
    (th_i = -pi + 2 pi i / n_theta, no duplicate seam), k < n_z (z equally spaced in
    [0, l]), numbered (k n_theta + i) n_r + j. Cells wrap round in theta; each hexahedron
    lists its lower-z quad (r, th) counter-clockwise seen from +z, then the upper one (VTK
    order, positive volume).

    Returns
    -------
    dict
        points (N, 3), cells (C, 8) int, and point data displacement (N, 3) Cartesian,
        radial_displacement (N,), potential (N,) (these three times amplitude) and
        r_reference (N,). Default n_theta = max(96, 16 m), n_z = max(41, 16 n + 1).
    """
    a = _check_amplitude(amplitude)
    n_theta, n_z = _resolution(
        shape, n_theta or max(96, 16 * shape.m), n_z or max(41, 16 * shape.n + 1)
    )
    if isinstance(n_r, bool) or not isinstance(n_r, (int, np.integer)) or n_r < 2:
        raise ParameterError(f"n_r = {n_r!r} is invalid; need an integer >= 2")
    R = np.linspace(1.0, shape.params.outer_radius, n_r)
    eta = shape.at(R)
    r = np.interp(R, shape.R, shape.r)
    th = -np.pi + 2.0 * np.pi * np.arange(n_theta) / n_theta
    zs = np.linspace(0.0, shape.length, n_z)
    Z, TH, J = np.meshgrid(zs, th, np.arange(n_r), indexing="ij")  # (n_z, n_theta, n_r)
    ur, ut, uz, phi = displacement(shape, eta[:, J], TH, Z)
    c, s = np.cos(TH), np.sin(TH)
    points = np.stack([r[J] * c, r[J] * s, Z], axis=-1).reshape(-1, 3)
    disp = a * np.stack([ur * c - ut * s, ur * s + ut * c, uz], axis=-1).reshape(-1, 3)
    k, i, j = np.meshgrid(
        np.arange(n_z - 1), np.arange(n_theta), np.arange(n_r - 1), indexing="ij"
    )

    def node(kk, ii, jj):
        return (kk * n_theta + ii % n_theta) * n_r + jj

    def quad(kk):  # the four corners of the cells of one layer
        return [node(kk, i, j), node(kk, i, j + 1), node(kk, i + 1, j + 1), node(kk, i + 1, j)]

    cells = np.stack(quad(k) + quad(k + 1), axis=-1).reshape(-1, 8)
    return {
        "points": points,
        "cells": cells,
        "displacement": disp,
        "radial_displacement": a * ur.ravel(),
        "potential": a * phi.ravel(),
        "r_reference": R[J].ravel(),
    }


def export_vtk(
    shape: ModeShape,
    path: str | Path,
    *,
    amplitude: float = 0.1,
    n_r: int = 17,
    n_theta: int | None = None,
    n_z: int | None = None,
) -> Path:
    """Write :func:`wall_mesh` as a VTK file (``.vtu`` XML or ``.vtk`` legacy) with meshio.

    Open it in ParaView and apply "Warp By Vector" (vector: displacement) to see the
    wrinkled tube; colour by radial_displacement or potential. Needs the optional extra
    ``vtk`` (``pip install 'electrogrowth[vtk]'``, i.e. meshio).

    Raises
    ------
    ParameterError
        Unknown suffix, or meshio is not installed.
    """
    path = Path(path)
    if path.suffix not in (".vtu", ".vtk"):
        raise ParameterError(f"VTK file {str(path)!r} must end in .vtu (XML) or .vtk (legacy)")
    try:
        import meshio
    except ImportError:
        raise MissingDependencyError(
            "writing VTK needs the optional package meshio; install"
            " it with pip install 'electrogrowth[vtk]'"
        ) from None
    mesh = wall_mesh(shape, amplitude=amplitude, n_r=n_r, n_theta=n_theta, n_z=n_z)
    data = {
        key: mesh[key]
        for key in ("displacement", "radial_displacement", "potential", "r_reference")
    }
    with replaced_name(path) as name:  # whole or not at all
        meshio.write(
            name, meshio.Mesh(mesh["points"], [("hexahedron", mesh["cells"])], point_data=data)
        )
    return path
