"""The interactive 3D pattern (figures/viewer.py): a self-contained page whose mesh is the
wall of the mode shape, triangulated cell by cell and coloured by u_r."""

import json
import re

import numpy as np
import pytest

from electrogrowth import Tube, critical_value, mode_shape
from electrogrowth.figures.viewer import mesh_arrays, pattern_html, write_pattern_html
from electrogrowth.shapes.wall import wall_surface


@pytest.fixture(scope="module")
def shape():
    tube = Tube.uniform(outer_radius=1.4, length=1.0, voltage=0.4)
    return mode_shape(critical_value(tube, 3, 1, "growth"), points=21)


def test_mesh_is_the_wall_triangulated(shape):
    surf = wall_surface(shape, amplitude=0.1, n_theta=24, n_z=9)
    rows, cols = surf.x.shape
    mesh = mesh_arrays(surf)
    position = np.reshape(mesh["position"], (-1, 3))
    index = np.reshape(mesh["index"], (-1, 3))
    assert len(position) == rows * cols and len(mesh["color"]) == 3 * rows * cols
    assert len(index) == 2 * (rows - 1) * (cols - 1)  # two triangles per grid cell
    assert index.min() == 0 and index.max() == rows * cols - 1
    assert np.linalg.norm(position, axis=1).max() == pytest.approx(1.0, abs=2e-3)
    # same shape up to the centring and scaling: distances keep their ratios
    P = np.stack([surf.x, surf.y, surf.z], axis=-1).reshape(-1, 3)
    i, j, k = 0, rows * cols // 2, cols // 4  # the grid closes: its last point is its first
    ratio = np.linalg.norm(P[i] - P[j]) / np.linalg.norm(P[i] - P[k])
    assert np.linalg.norm(position[i] - position[j]) / np.linalg.norm(
        position[i] - position[k]
    ) == pytest.approx(ratio, rel=1e-2)
    # colour: red where the wall moves out, blue where it moves in (RdBu_r)
    color = np.reshape(mesh["color"], (-1, 3))
    u = surf.u_r.reshape(-1)
    out, inward = np.argmax(u), np.argmin(u)
    assert color[out, 0] > color[out, 2] and color[inward, 2] > color[inward, 0]


def test_page_is_self_contained(shape, tmp_path):
    page = pattern_html(shape, amplitude=0.08, n_theta=24, n_z=9)
    assert page.startswith("<!DOCTYPE html>") and "<canvas" in page
    assert not re.search(r"(src|href)\s*=\s*[\"']?(https?:)?//", page), "nothing fetched"
    data = json.loads(re.search(r"const D = (\{.*?\});", page).group(1))
    assert set(data) == {"position", "normal", "color", "index"}
    assert "(m, n) = (3, 1)" in page
    path = write_pattern_html(shape, tmp_path / "a" / "p.html", n_theta=24, n_z=9)
    assert path.read_text(encoding="utf-8").count("<script>") == 1
