"""The deformed wall: the cross-section's sector moved, and the whole ring by reflecting the
sector k pi / m about its first ray and turning the pair by 2 k pi / m (the symmetry it was
solved with, k = ``periods``); the meridian's window moved, and the tube's whole
longitudinal section by reflecting it about its end planes."""

from __future__ import annotations

import math

import numpy as np


def deformed_vertices(section, x: np.ndarray) -> np.ndarray:
    """Current Cartesian positions of the sector's mesh vertices, shape (2, nvertices)."""
    R, T = section.mesh.p
    uR = x[section.basis.nodal_dofs[0]]
    uT = x[section.basis.nodal_dofs[1]]
    c, s = np.cos(T), np.sin(T)
    return np.array([(R + uR) * c - uT * s, (R + uR) * s + uT * c])


def ring(section, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The whole ring: (points (2, n), quadrilaterals (n_cells, 4), layer of each cell), the
    sector reflected and turned 2 m / k times (vertices on the rays repeated)."""
    copies = section.m // section.periods
    return ring_of_sector(
        deformed_vertices(section, x), section.mesh.t.T, section.layer_of, copies
    )


def ring_of_sector(
    pts: np.ndarray, cells: np.ndarray, layer_of: np.ndarray, copies: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`ring` from the sector's current vertices ``pts`` (2, n), its quadrilaterals and
    their layers: the sector and its mirror image turned by 2 pi j / ``copies``."""
    mirror = np.array([pts[0], -pts[1]])
    all_pts, all_cells, layers = [], [], []
    n = pts.shape[1]
    for k in range(copies):
        a = 2 * math.pi * k / copies
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        for j, (p, c) in enumerate(((pts, cells), (mirror, cells[:, ::-1]))):
            all_pts.append(rot @ p)
            all_cells.append(c + n * (2 * k + j))
            layers.append(layer_of)
    return np.hstack(all_pts), np.vstack(all_cells), np.concatenate(layers)


def face_curve(section, x: np.ndarray, face: str) -> np.ndarray:
    """The current face (inner or outer) around the whole ring, closed, shape (2, n)."""
    dofs, theta = section.face_dofs(face)
    R = 1.0 if face == "inner" else section.tube.radii[-1]
    verts = np.nonzero(np.isclose(section.mesh.p[0], R))[0]
    verts = verts[np.argsort(section.mesh.p[1, verts])]
    pts = deformed_vertices(section, x)[:, verts]
    m = section.m // section.periods
    parts = []
    for k in range(m):
        a = 2 * math.pi * k / m
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        mirror = np.array([pts[0], -pts[1]])[:, ::-1]
        parts.append(rot @ mirror[:, :-1])
        parts.append(rot @ pts[:, :-1])
    curve = np.hstack(parts)
    # sector 0 starts at the reflected half (-pi/m .. 0): rotate so it starts at angle 0
    return np.hstack([curve, curve[:, :1]])


def meridian_vertices(meridian, x: np.ndarray) -> np.ndarray:
    """Current (r, z) of the meridian window's mesh vertices, shape (2, nvertices)."""
    R, Z = meridian.mesh.p
    uR = x[meridian.basis.nodal_dofs[0]]
    uZ = x[meridian.basis.nodal_dofs[1]]
    return np.array([R + uR, float(meridian.tube.stretch) * Z + uZ])


def meridian_tube(meridian, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The tube's longitudinal section over its whole length: (points (2, n) as (x, z),
    quadrilaterals (n_cells, 4), layer of each cell). The window is reflected about its end
    planes n / k times along z (the symmetry it was solved with), and the meridian drawn on both
    sides of the axis (x = +-r)."""
    height = float(meridian.tube.stretch) * meridian.extent
    copies = meridian.n // meridian.periods
    pts = meridian_vertices(meridian, x)
    return tube_of_window(pts, meridian.mesh.t.T, meridian.layer_of, copies, height)


def tube_of_window(
    pts: np.ndarray, cells: np.ndarray, layer_of: np.ndarray, copies: int, height: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`meridian_tube` from the window's current (r, z) vertices ``pts``, its
    quadrilaterals and their layers: ``copies`` windows of current ``height`` along z, every
    other one reflected, each drawn on both sides of the axis."""
    n = pts.shape[1]
    all_pts, all_cells, layers = [], [], []
    for j in range(copies):
        z = pts[1] if j % 2 == 0 else height - pts[1]
        flip = j % 2  # a reflection reverses the cells' orientation
        for side in (1.0, -1.0):
            all_pts.append(np.array([side * pts[0], z + j * height]))
            c = cells if (side > 0) != bool(flip) else cells[:, ::-1]
            all_cells.append(c + n * (len(all_pts) - 1))
            layers.append(layer_of)
    return np.hstack(all_pts), np.vstack(all_cells), np.concatenate(layers)


def whole(model, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The whole ring of a cross-section, or the whole longitudinal section of a meridian."""
    return ring(model, x) if model.kind == "section" else meridian_tube(model, x)
