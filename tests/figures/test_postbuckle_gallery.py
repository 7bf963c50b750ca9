"""The post-buckling gallery's stored branches (examples/gallery/postbuckle/*.json): the
stored shapes agree with the stored amplitudes (read off the shapes' vertices alone, the
model's definition a = (u_R(0) - u_R(half wavelength)) / 2 on the inner face), the stored
tube is the case's, and the dev tool's record round-trips to a figure."""

import math
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.figures import postbuckle_gallery as gallery  # noqa: E402

FOLDER = Path(__file__).resolve().parents[2] / "examples" / "gallery" / "postbuckle"


def inner_face_amplitude(record: dict, j: int) -> float:
    """Half the difference of the inner face's radius on the two symmetry planes of the
    stored sector (window) j: the rays Theta = 0 and pi/m, or the planes z = 0 and L/n."""
    x, y = np.array(record["shapes"]["vertices"][j])
    if record["n"] == 0:  # the current radius along the two rays (u_Theta = 0 on them)
        r, angle = np.hypot(x, y), np.arctan2(y, x)
        ends = (np.isclose(angle, 0.0, atol=1e-9), np.isclose(angle, math.pi / record["m"]))
    else:  # the radius on the planes z = 0 and z = height (u_Z = 0 on them)
        r, h = x, record["shapes"]["height"]
        ends = (np.isclose(y, 0.0, atol=1e-9), np.isclose(y, h, atol=1e-9))
    return (r[ends[0]].min() - r[ends[1]].min()) / 2


@pytest.mark.parametrize("name", list(gallery.CASES))
def test_stored_shapes_have_the_stored_amplitudes(name):
    record = gallery.read_case(FOLDER / f"{name}.json")
    amplitudes = record["branch"]["amplitude"]
    for j, k in enumerate(record["shapes"]["points"]):
        assert inner_face_amplitude(record, j) == pytest.approx(amplitudes[k], abs=2e-6)
    assert record["tube"] == gallery.CASES[name]["tube"]().record()
    assert record["amplitude_face"] == "inner"


@pytest.mark.parametrize("name", list(gallery.CASES))
def test_whole_shape_is_the_ring_or_tube(name):
    """The onset shape (a = 0) is axisymmetric: the whole ring is a circle of the stored
    sector's radii, the whole section its window repeated."""
    record = gallery.read_case(FOLDER / f"{name}.json")
    pts, cells, layer = gallery.whole_shape(record, 0)
    sector = np.array(record["shapes"]["vertices"][0])
    copies = record["shapes"]["copies"]
    assert pts.shape[1] == 2 * copies * sector.shape[1]
    assert len(cells) == len(layer) == 2 * copies * len(record["shapes"]["cells"])
    if record["n"] == 0:
        r = np.hypot(*pts)
        assert r.min() == pytest.approx(np.hypot(*sector).min(), abs=1e-6)
        assert r.max() == pytest.approx(np.hypot(*sector).max(), abs=1e-6)
    else:
        assert np.abs(pts[0]).max() == pytest.approx(sector[0].max())
        assert pts[1].max() == pytest.approx(copies * record["shapes"]["height"], abs=1e-6)


@pytest.mark.slow  # 10-25 s: make test-slow runs it
def test_tool_record_round_trips_to_a_figure(tmp_path, monkeypatch):
    """A small case through ``write_case``, ``read_case`` and ``plot_case``."""
    small = dict(
        gallery.CASES["dielectric"], options={"amplitude": 0.01, "points": 2, "density": 16.0}
    )
    monkeypatch.setitem(gallery.CASES, "small", small)
    written = gallery.write_case("small", tmp_path / "small.json")
    record = gallery.read_case(tmp_path / "small.json")
    assert record["onset_fe"] == written["onset_fe"]
    assert list(record["branch"]["amplitude"]) == pytest.approx([0.0, 0.005, 0.01])
    assert inner_face_amplitude(record, len(record["shapes"]["points"]) - 1) == pytest.approx(
        0.01, abs=2e-6
    )
    fig = gallery.plot_case(record)
    assert len(fig.axes) == len(record["shapes"]["points"]) + 1
