"""The post-buckling gallery's two branches (examples/gallery/postbuckle): the mucosal
bilayer folding under hoop growth, mode (12, 0), and a dielectric tube wrinkling into rings
under a radial voltage, mode (0, 1). Each takes minutes, beyond a page's budget, so
``tools/postbuckle_gallery.py`` computes it once into a small JSON (:func:`write_case`):
the branch, its onsets and stability, and the current vertices of the sector (window) at a
few points; the page reads it (:func:`read_case`) and draws it (:func:`plot_case`)."""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np
from matplotlib.collections import PolyCollection

from ..atomic import write_text
from ..model.layers import Layer, Tube
from ..postbuckle import postbuckle
from ..postbuckle.onset import fe_onset
from ..postbuckle.section import Section, mesh_size
from ..postbuckle.shape import deformed_vertices, meridian_vertices, ring_of_sector, tube_of_window
from .labels import axis_label, symbol_text
from .postbuckle import LAYER_COLOURS
from .style import new_figure


def mucosa() -> Tube:
    """examples/mucosa.toml: a stiff inner layer (R = 1 .. 1.1, mu_1 = 10) on a soft outer
    one (to R = 2, mu_2 = 1), lambda_z = 1; its control the inner layer's hoop growth."""
    return Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0)


def dielectric() -> Tube:
    """One neo-Hookean ideal dielectric, R = 1 .. 1.5, L = 1, lambda_z = 1; its control the
    radial voltage, whose critical mode is the axisymmetric (0, 1)."""
    return Tube((Layer(1.5),), stretch=1.0)


#: each case: the tube, mode, control and the branch's options (``postbuckle``'s keywords);
#: ``coarse``: a second mesh (density, hoop) on which the onset alone is computed
CASES = {
    "mucosa": {
        "tube": mucosa,
        "mode": (12, 0),
        "control": "growth[1].theta",
        "options": {"amplitude": 0.1, "points": 8, "density": 12.0, "hoop": 12},
        "coarse": (12.0, 6),
    },
    "dielectric": {
        "tube": dielectric,
        "mode": (0, 1),
        "control": "voltage",
        "options": {"amplitude": 0.08, "points": 8, "density": 16.0},
    },
}

#: the points of the branch whose shapes are stored (first to last)
SHAPES = 5


def write_case(name: str, path: Path, progress=None) -> dict:
    """Compute case ``name`` of :data:`CASES` and write its record to ``path``; the record."""
    case = CASES[name]
    tube, control = case["tube"](), case["control"]
    start = time.perf_counter()
    result = postbuckle(tube, case["mode"], control, progress=progress, **case["options"])
    record = {"case": name, "seconds": round(time.perf_counter() - start), **result.as_dict()}
    record["shapes"] = _shapes(result)
    if "coarse" in case:
        density, hoop = case["coarse"]
        size = mesh_size(tube, case["mode"][0], density, hoop=hoop)
        section = Section(tube, case["mode"][0], size)
        onset = fe_onset(section, tube, control, result.onset_linear).value
        record["coarse_onset"] = {
            "radial_elements": list(size.radial),
            "hoop_elements": size.hoop,
            "unknowns": section.unknowns,
            "onset_fe": onset,
        }
    write_text(path, json.dumps(record, indent=1) + "\n")
    return record


def _shapes(result) -> dict:
    """The current vertices of the sector (window) at :data:`SHAPES` points, its cells and
    their layers, and how many copies make the whole ring (tube)."""
    model = result.section
    picks = np.unique(np.linspace(0, len(result.states) - 1, SHAPES).round().astype(int))
    vertices = []
    for k in picks:
        model.set_tube(result.tube.at(result.solve_for, result.control[k]))
        x = result.states[k]
        pts = deformed_vertices(model, x) if result.n == 0 else meridian_vertices(model, x)
        vertices.append(np.round(pts, 6).tolist())
    periods = result.periods
    record = {
        "points": picks.tolist(),
        "vertices": vertices,
        "cells": model.mesh.t.T.tolist(),
        "layer": np.asarray(model.layer_of).tolist(),
        "copies": (result.m if result.n == 0 else result.n) // periods,
    }
    if result.n > 0:
        record["height"] = float(result.tube.stretch) * model.extent
    return record


def read_case(path: Path) -> dict:
    """A record of :func:`write_case`, the branch's lists as arrays."""
    record = json.loads(Path(path).read_text(encoding="utf-8"))
    branch = record["branch"]
    for key in ("control", "amplitude", "energy"):
        branch[key] = np.array(branch[key], dtype=float)
    branch["lowest_eigenvalue"] = np.array(
        [math.nan if v is None else v for v in branch["lowest_eigenvalue"]]
    )
    return record


def whole_shape(record: dict, j: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The whole ring (prismatic) or longitudinal section (axisymmetric) of stored shape j:
    (points (2, n), quadrilaterals, layer of each)."""
    shapes = record["shapes"]
    pts = np.array(shapes["vertices"][j])
    cells, layer = np.array(shapes["cells"]), np.array(shapes["layer"])
    if record["n"] == 0:
        return ring_of_sector(pts, cells, layer, shapes["copies"])
    return tube_of_window(pts, cells, layer, shapes["copies"], shapes["height"])


def plot_case(record: dict):
    """The strip of stored shapes (top) and the amplitude against the control (bottom,
    filled: stable, open: unstable at fixed control; the onsets and the branch's initial
    parabola c = c_c + c_2 a^2 marked); a Figure."""
    shapes = record["shapes"]
    count = len(shapes["points"])
    fig, axes = new_figure(1.6 * count, 5.6, 2, count)
    grid = axes[1, 0].get_gridspec()
    # the rings are drawn square, the meridian's wall tall and narrow
    grid.set_height_ratios([1.0, 1.5] if record["n"] == 0 else [1.6, 1.2])
    for ax in axes[1]:
        ax.remove()
    _draw_strip(record, axes[0])
    _draw_branch(record, fig.add_subplot(grid[1, :]))
    return fig


def plot_strip(record: dict):
    """The strip of stored shapes alone (docs/images/postbuckle-folding.png); a Figure."""
    count = len(record["shapes"]["points"])
    fig, axes = new_figure(1.9 * count, 2.5, 1, count)
    _draw_strip(record, axes[0])
    mesh = record["mesh"]
    along = mesh.get("hoop_elements", mesh.get("axial_elements"))
    fig.suptitle(
        f"folding of mode (m, n) = ({record['m']}, {record['n']}), current shapes, on"
        f" {tuple(mesh['radial_elements'])} x {along} elements",
        fontsize=8,
    )
    return fig


def _draw_strip(record, axes):
    branch = record["branch"]
    extent = top = 0.0
    inner = math.inf
    for j, ax in enumerate(axes):
        pts, cells, layer = whole_shape(record, j)
        inner = min(inner, np.abs(pts[0]).min())
        colours = [LAYER_COLOURS[i % len(LAYER_COLOURS)] for i in layer]
        ax.add_collection(
            PolyCollection(pts.T[cells], facecolors=colours, edgecolors="face", linewidths=0.3)
        )
        extent, top = max(extent, np.abs(pts[0]).max()), max(top, pts[1].max())
        k = record["shapes"]["points"][j]
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(
            f"a / $R_i$ = {branch['amplitude'][k]:.3g}\n{symbol_text(record['solve_for'])} = "
            f"{branch['control'][k]:.5g}",
            fontsize=7,
        )
    for ax in axes:
        if record["n"] == 0:  # the whole ring
            ax.set_xlim(-1.05 * extent, 1.05 * extent)
            ax.set_ylim(-1.05 * extent, 1.05 * extent)
        else:  # one wall of the longitudinal section, z from 0 to the current length
            ax.set_xlim(inner - 0.1, extent + 0.1)
            ax.set_ylim(-0.02 * top, 1.02 * top)
            ax.tick_params(labelsize=6)
            ax.set_xticks([1.0, round(extent, 1)], minor=False)
    if record["n"] > 0:
        axes[0].set_yticks([0.0, round(top, 2)])
        axes[0].set_xlabel("r / $R_i$", fontsize=7)
        axes[0].set_ylabel("z / $R_i$", fontsize=7)


def _draw_branch(record, ax):
    branch = record["branch"]
    c, a, lam = branch["control"], branch["amplitude"], branch["lowest_eigenvalue"]
    ax.plot(c, a, "-", lw=1.0, color="k")
    stable, unstable = lam > 0, lam < 0
    stable[0] = unstable[0] = False  # the onset: eigenvalue zero to its tolerance
    if stable.any():
        ax.plot(c[stable], a[stable], "o", ms=4, color="k", label="stable (lowest eigenvalue > 0)")
    if unstable.any():
        label = "unstable (lowest eigenvalue < 0)"
        ax.plot(c[unstable], a[unstable], "o", ms=4, mfc="w", color="C3", label=label)
    ax.plot(c[0], a[0], "s", ms=5, color="C0", label="FE onset (eigenvalue zero)")
    ax.axvline(record["onset_linear"], color="C0", ls="--", lw=1, label="linear onset")
    s = np.linspace(0, a.max(), 60)
    fit = record["onset_fe"] + record["curvature"] * s**2
    ax.plot(fit, s, color="C1", ls=":", lw=1.2, label=f"onset + {record['curvature']:.3g} a$^2$")
    face = record["amplitude_face"]
    wave = "cos m$\\Theta$" if record["n"] == 0 else "cos kZ"
    ax.set_xlabel(axis_label(record["solve_for"]), fontsize=8)
    ax.set_ylabel(f"fold amplitude a / $R_i$ ({face} face, {wave})", fontsize=8)
    ax.legend(fontsize=7, frameon=False, loc="best")
    ax.set_ylim(bottom=-0.003)
    what = "folding" if record["n"] == 0 else "rings"
    ax.set_title(f"{what} of mode (m, n) = ({record['m']}, {record['n']})", fontsize=9)


__all__ = ["CASES", "plot_case", "plot_strip", "read_case", "whole_shape", "write_case"]
