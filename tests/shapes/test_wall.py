"""The wrinkled tube in 3D (surfaces, PNG, VTK) and the ``electrogrowth pattern`` command."""

import argparse
import json
import sys

import numpy as np
import pytest

from electrogrowth import ParameterError, Tube
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.cli.pattern import configure_pattern, run_pattern
from electrogrowth.errors import MissingDependencyError
from electrogrowth.figures.plots import render_pattern
from electrogrowth.shapes.mode_shape import mode_shape
from electrogrowth.shapes.wall import deformed_surface, export_vtk, wall_mesh, wall_surface

_SHAPES = {}


def shape_of(m: int, n: int):
    """A critical mode shape, computed once: (5, 1) of the grown tube without voltage,
    (5, 7) of the grown charged tube."""
    if (m, n) not in _SHAPES:
        params = Tube.uniform(1.4, 1.0, stretch=1.1, voltage=0.0 if n == 1 else 0.4)
        _SHAPES[m, n] = mode_shape(critical_value(params, m, n, "growth"))
    return _SHAPES[m, n]


def count_maxima(values, periodic: bool) -> int:
    v = np.asarray(values)
    left = np.roll(v, 1) if periodic else np.concatenate([[-np.inf], v[:-1]])
    right = np.roll(v, -1) if periodic else np.concatenate([v[1:], [-np.inf]])
    return int(np.sum((v > left) & (v > right)))


@pytest.mark.parametrize("face, index", [("outer", -1), ("inner", 0)])
def test_zero_amplitude_is_the_unwrinkled_cylinder(face, index):
    shape = shape_of(5, 1)
    s = deformed_surface(shape, amplitude=0.0, n_theta=37, n_z=11, face=face)
    th, z = np.meshgrid(s.theta, s.z_ref, indexing="ij")
    r = shape.r[index]
    assert np.allclose(s.x, r * np.cos(th), atol=1e-15, rtol=0)
    assert np.allclose(s.y, r * np.sin(th), atol=1e-15, rtol=0)
    assert np.array_equal(s.z, z) and not s.u_r.any()
    assert s.theta[0] == -np.pi and s.theta[-1] == np.pi
    assert s.z_ref[-1] == pytest.approx(1.1)  # l = lambda_z L


@pytest.mark.parametrize("m, n", [(5, 1), (5, 7)])
def test_m_lobes_around_and_n_half_waves_along(m, n):
    shape = shape_of(m, n)
    s = deformed_surface(shape, amplitude=0.05, n_theta=181, n_z=100)
    ring = s.u_r[:-1, 0]  # z = 0, the seam theta = pi dropped (it repeats -pi)
    assert count_maxima(ring, periodic=True) == m
    line = s.u_r[90, :]  # theta = 0: u_r = a U_r(r_o) cos(k z)
    assert np.count_nonzero(np.diff(np.sign(line))) == n
    assert np.abs(s.u_r).max() == pytest.approx(0.05 * np.abs(shape.U_r[-1]), rel=1e-3)
    # the displaced point is x + a u with u from paper eq. incremental-solutions
    i, j = 17, 33
    th, z = s.theta[i], s.z_ref[j]
    U = shape.eta[:3, -1]
    c, s_ = np.cos(shape.k * z), np.sin(shape.k * z)
    u = (U[0] * np.cos(m * th) * c, U[1] * np.sin(m * th) * c, U[2] * np.cos(m * th) * s_)
    rr = shape.r[-1] + 0.05 * u[0]
    expect = (
        rr * np.cos(th) - 0.05 * u[1] * np.sin(th),
        rr * np.sin(th) + 0.05 * u[1] * np.cos(th),
        z + 0.05 * u[2],
    )
    assert np.allclose((s.x[i, j], s.y[i, j], s.z[i, j]), expect, rtol=0, atol=1e-14)


def test_wall_surface_is_closed_and_matches_the_faces():
    shape = shape_of(5, 1)
    w = wall_surface(shape, amplitude=0.1, n_theta=41, n_z=21, n_r=5)
    outer = deformed_surface(shape, amplitude=0.1, n_theta=41, n_z=21)
    inner = deformed_surface(shape, amplitude=0.1, n_theta=41, n_z=21, face="inner")
    assert np.allclose(w.x[:, :21], outer.x) and np.allclose(w.z[:, :21], outer.z)
    assert np.allclose(w.x[:, 24:45], inner.x[:, ::-1])
    assert np.allclose(w.x[:, 0], w.x[:, -1]) and np.allclose(w.z[:, 0], w.z[:, -1])


def test_png_is_written_and_not_blank(tmp_path):
    import matplotlib.image as mpimg

    path = tmp_path / "deep" / "pattern.png"
    fig = render_pattern(shape_of(5, 7), amplitude=0.1, path=path, n_theta=61, n_z=41, dpi=80)
    assert path.stat().st_size > 20_000
    img = mpimg.imread(path)[..., :3]
    coloured = np.ptp(img, axis=-1) > 0.1  # saturated pixels: red or blue wrinkles
    assert 0.1 < coloured.mean() < 0.9
    assert "(5, 7)" in fig._suptitle.get_text()


def test_vtk_round_trip(tmp_path):
    meshio = pytest.importorskip("meshio")
    shape = shape_of(5, 7)  # 101 samples: n_r = 11 puts the mesh radii on samples
    n_r, n_t, n_z, a = 11, 24, 15, 0.2
    path = export_vtk(shape, tmp_path / "wall.vtu", amplitude=a, n_r=n_r, n_theta=n_t, n_z=n_z)
    mesh = meshio.read(path)
    assert mesh.points.shape == (n_r * n_t * n_z, 3)
    cells = mesh.cells_dict["hexahedron"]
    assert cells.shape == ((n_r - 1) * n_t * (n_z - 1), 8)
    data = mesh.point_data
    assert data["displacement"].shape == (mesh.points.shape[0], 3)
    for key in ("potential", "r_reference", "radial_displacement"):
        assert data[key].shape == (mesh.points.shape[0],)
    # every hexahedron has positive volume (VTK node order)
    p = mesh.points[cells]
    assert np.all(
        np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 3] - p[:, 0]), p[:, 4] - p[:, 0])
        > 0
    )
    # the displacement at some points is the analytic field
    for idx in (0, 777, 1234, mesh.points.shape[0] - 1):
        x, y, z = mesh.points[idx]
        th, R = np.arctan2(y, x), data["r_reference"][idx]
        j = int(round((R - 1.0) / (shape.params.outer_radius - 1.0) * 100))
        assert shape.R[j] == pytest.approx(R, abs=1e-14)
        assert np.hypot(x, y) == pytest.approx(shape.r[j], rel=1e-12)
        Ur, Ut, Uz, Phi = shape.U_r[j], shape.U_th[j], shape.U_z[j], shape.Phi[j]
        m, k = shape.m, shape.k
        ur = Ur * np.cos(m * th) * np.cos(k * z)
        ut = Ut * np.sin(m * th) * np.cos(k * z)
        uz = Uz * np.cos(m * th) * np.sin(k * z)
        expect = a * np.array(
            [ur * np.cos(th) - ut * np.sin(th), ur * np.sin(th) + ut * np.cos(th), uz]
        )
        assert np.allclose(data["displacement"][idx], expect, rtol=0, atol=1e-12)
        assert data["potential"][idx] == pytest.approx(
            a * Phi * np.cos(m * th) * np.cos(k * z), abs=1e-12
        )


def test_wall_mesh_defaults_and_bad_inputs(tmp_path, monkeypatch):
    shape = shape_of(5, 1)
    mesh = wall_mesh(shape)
    assert mesh["points"].shape[0] == 17 * 96 * 41
    with pytest.raises(ParameterError, match=".vtu"):
        export_vtk(shape, tmp_path / "wall.txt")
    with pytest.raises(ParameterError, match="amplitude"):
        deformed_surface(shape, amplitude=-0.1)
    with pytest.raises(ParameterError, match="face"):
        deformed_surface(shape, face="middle")
    with pytest.raises(ParameterError, match="n_r"):
        wall_mesh(shape, n_r=1)
    monkeypatch.setitem(sys.modules, "meshio", None)  # as if not installed
    with pytest.raises(MissingDependencyError, match="meshio"):
        export_vtk(shape, tmp_path / "wall.vtu")


# -- the command line ------------------------------------------------------------------------


def run(argv) -> int:
    parser = argparse.ArgumentParser()
    configure_pattern(parser)
    return run_pattern(parser.parse_args(argv))


def test_cli_one_mode_writes_everything(tmp_path, capsys):
    pytest.importorskip("meshio")
    out = tmp_path / "out"
    status = run(
        [
            "--solve-for",
            "stretch",
            "--outer-radius",
            "1.4",
            "--growth",
            "1.1",
            "--voltage",
            "0.3",
            "--mode",
            "2",
            "1",
            "--amplitude",
            "0.08",
            "--points",
            "41",
            "--out",
            str(out),
            "--vtk",
            str(tmp_path / "w.vtu"),
            "--json",
        ]
    )
    assert status == 0
    rec = json.loads(capsys.readouterr().out)
    assert (rec["m"], rec["n"], rec["route"]) == (2, 1, "impedance")
    assert rec["value"] == pytest.approx(0.812013, abs=1e-6)
    assert rec["boundary_residual"] < 1e-12 and rec["max_abs"]["U_r"] == 1.0
    names = sorted(p.name for p in out.iterdir())
    assert names == ["mode-shape-m2-n1.csv", "mode-shape-m2-n1.png", "pattern-m2-n1.png"]
    table = np.loadtxt(out / "mode-shape-m2-n1.csv", delimiter=",", skiprows=1)
    assert table.shape == (41, 10)
    assert len(rec["files"]) == 4 and (tmp_path / "w.vtu").stat().st_size > 0


def test_cli_scan_text(capsys):
    status = run(
        [
            "--solve-for",
            "growth",
            "--outer-radius",
            "1.4",
            "--stretch",
            "1.1",
            "--voltage",
            "0.4",
            "--m-max",
            "2",
            "--n-max",
            "2",
            "--points",
            "21",
        ]
    )
    assert status == 0
    text = capsys.readouterr().out
    assert text.startswith("g_cr = 1.3999") and "mode (m, n) = (0, 1)" in text
    assert "mode shape by the impedance method" in text


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--amplitude", "-1"], "amplitude"),
        (["--vtk", "wall.txt"], ".vtu"),
        (["--side", "extension"], "--side"),
        (["--points", "1"], "points"),
        (["--mode", "1", "0"], "mode"),  # -1 is refused by the option's type, before
    ],
)
def test_cli_bad_input_is_a_parameter_error(extra, message):
    base = ["--solve-for", "growth", "--outer-radius", "1.4", "--mode", "0", "1"]
    if "--mode" in extra:
        base = base[:-3]
    with pytest.raises(ParameterError, match=message):
        run(base + extra)


def test_cli_without_meshio_fails_before_computing(monkeypatch, tmp_path):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util, "find_spec", lambda name, *a: None if name == "meshio" else real(name, *a)
    )
    with pytest.raises(MissingDependencyError, match="meshio"):
        run(
            [
                "--solve-for",
                "growth",
                "--outer-radius",
                "1.4",
                "--mode",
                "0",
                "1",
                "--vtk",
                str(tmp_path / "w.vtu"),
                "--out",
                str(tmp_path / "out"),
            ]
        )
    assert not (tmp_path / "out").exists()


def test_cli_help_names_every_option():
    parser = argparse.ArgumentParser()
    configure_pattern(parser)
    text = parser.format_help()
    for option in (
        "--solve-for",
        "--side",
        "--mode",
        "--amplitude",
        "--out",
        "--vtk",
        "--json",
        "--method",
        "--outer-radius",
        "--material",
    ):
        assert option in text
    assert "Riccati equation" in text and "two_Riccati" not in text  # words, not labels


def test_cells_draw_what_plot_surface_draws():
    """The pattern's faces built with arrays (figures/plots.py ``_cells``) render the same
    pixels as matplotlib's own plot_surface(facecolors=..., rstride=1, cstride=1)."""
    import matplotlib as mpl
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from electrogrowth.figures.plots import _cells

    p = Tube.uniform(outer_radius=1.4, length=1.0, growth=1.2, voltage=0.4)
    surf = wall_surface(mode_shape((p, 3, 1)), n_theta=24, n_z=7)
    rgb = mpl.colormaps["RdBu_r"](np.linspace(0, 1, surf.x.size).reshape(surf.x.shape))

    def pixels(draw):
        fig = Figure(figsize=(3, 3), dpi=80)
        ax = fig.add_axes((0, 0, 1, 1), projection="3d")
        draw(ax)
        ax.set(xlim=(-1.6, 1.6), ylim=(-1.6, 1.6), zlim=(surf.z.min(), surf.z.max()))
        ax.set_axis_off()
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        return np.asarray(canvas.buffer_rgba(), dtype=float)

    ours = pixels(lambda ax: ax.add_collection3d(_cells(surf, rgb)))
    theirs = pixels(
        lambda ax: ax.plot_surface(
            surf.x,
            surf.y,
            surf.z,
            facecolors=rgb,
            rstride=1,
            cstride=1,
            linewidth=0,
            antialiased=False,
            shade=False,
        )
    )
    assert (ours != 255).any()  # something was drawn
    np.testing.assert_array_equal(ours, theirs)
