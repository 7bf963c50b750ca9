"""The stability record of a branch: the pattern of an eigenvector on a sector of k half
wavelengths (exact on fields of known period), and the sign change of the lowest
eigenvalue located on a subcritical branch, where it must be the limit point of the
control (d c / d a = 0: at fixed control the tangent is singular exactly there)."""

import csv
import importlib.util
import json

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.model.layers import Layer, Tube  # noqa: E402
from electrogrowth.postbuckle.api import postbuckle  # noqa: E402
from electrogrowth.postbuckle.branch import AmplitudeBranch  # noqa: E402
from electrogrowth.postbuckle.section import MeshSize, Section  # noqa: E402
from electrogrowth.postbuckle.stability import classify  # noqa: E402

BILAYER = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0)
CONTROL = "growth[1].theta"


def field(section, *waves):
    """u_R = sum cos(q Theta), u_Theta = sum sin(q Theta) at the vertices."""
    z = np.zeros(section.basis.N)
    theta = section.mesh.p[1]
    for q in waves:
        z[section.basis.nodal_dofs[0]] += np.cos(q * theta)
        z[section.basis.nodal_dofs[1]] += np.sin(q * theta)
    return z


@pytest.mark.parametrize(
    "waves, fraction, period",
    [((12,), 0.0, 1), ((24, 0), 0.0, 1), ((6,), 1.0, 2), ((18, 12), 2**-0.5, 2), ((3,), 1.0, 4)],
    ids=["mode", "harmonics", "half", "half-and-mode", "quarter"],
)
def test_pattern_of_known_fields(waves, fraction, period):
    """In the sector 4 pi / 12 (periods 4): cos(12 Theta) and its harmonics are the mode's
    family, cos(6 Theta) and cos(18 Theta) period doubling, cos(3 Theta) period 4."""
    section = Section(BILAYER, 12, MeshSize((2, 2), 16), periods=4)
    sub, d = classify(section, field(section, *waves))
    assert sub == pytest.approx(fraction, abs=1e-12) and d == period


SUBCRITICAL = Tube(
    (Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0, voltage=0.3, inner_pressure=0.05
)


@pytest.mark.slow
def test_sign_change_on_a_subcritical_branch_is_the_control_limit_point(tmp_path):
    """The charged, pressurised bilayer (Vbar = 0.3, P_i = 0.05) folds subcritically
    (d g / d a^2 = -1.77 on (2, 5) x 3 elements per pi / 12); in 2 pi / 12 the growth falls
    along the branch to a minimum and rises: measured there, the lowest eigenvalue goes
    from -0.012 (a = 0.09) to +0.015 (a = 0.1), located at a = 0.0952, g = 2.01987,
    symmetric (subharmonic fraction 1e-12). Independently, the control's parabola through
    three branch points at a* - h, a*, a* + h has its vertex at a* to O(h^2)."""
    res = postbuckle(
        SUBCRITICAL, 12, CONTROL, amplitude=0.1, points=10, density=6, hoop=3, periods=2
    )
    assert res.curvature < 0 and res.ended == ""
    assert len(res.secondary) == 1
    s = res.secondary[0]
    assert s.located and s.kind == "symmetric" and s.subharmonic < 1e-9
    assert 0.09 < s.amplitude < 0.1
    assert s.control <= res.control.min()
    # the limit point of the control: d c / d a = 0 where the eigenvalue vanishes. The
    # vertex of the parabola through a* - h, a*, a* + h is off by c3 h^2 / (6 c2) (c2, c3
    # the second and third derivatives): measured 4.0e-5 at h = 2e-3, a quarter of it at
    # h = 1e-3, so Richardson's extrapolation removes it
    branch = AmplitudeBranch(res.section, SUBCRITICAL, CONTROL, face=res.face)
    x0, c0 = res.states[-2], res.control[-2]

    def vertex(h):
        c = [branch.solve(x0, c0, s.amplitude + t * h)[1] for t in (-1, 0, 1)]
        assert c[1] == pytest.approx(s.control, abs=1e-9)
        return s.amplitude - h / 2 * (c[2] - c[0]) / (c[2] - 2 * c[1] + c[0])

    coarse, fine = vertex(2e-3), vertex(1e-3)
    assert 3.5 < (coarse - s.amplitude) / (fine - s.amplitude) < 4.5
    assert (4 * fine - coarse) / 3 == pytest.approx(s.amplitude, abs=1e-6)
    # the record: JSON and the CSV of --out
    rec = json.loads(json.dumps(res.as_dict()))
    assert rec["periods"] == 2 and rec["mesh"]["sector"] == "2pi/12"
    assert rec["secondary"][0]["kind"] == "symmetric"
    assert rec["branch"]["lowest_mode"] == ["symmetric"] * 11
    from electrogrowth.cli.postbuckle import _write

    _write(res, tmp_path)
    rows = list(csv.DictReader(open(tmp_path / "branch.csv")))
    assert [r["lowest_mode"] for r in rows] == ["symmetric"] * 11
    signs = [float(r["lowest_eigenvalue"]) < 0 for r in rows[1:]]
    assert signs == [True] * 9 + [False]


# -- element-scale eigenvectors (probe 12a D1) -------------------------------------------
# The Q2 / discontinuous-P1 elements lose stability under finite compression in patterns of
# their own size, at loads that fall as the mesh is refined. Before the check, such a mode
# came out as a located "secondary (symmetric)" point and as negative eigenvalues on
# uncharged tubes whose continuum is stable (the default mesh of the uniform tube below:
# a secondary at a = 0.070, -1142 at a = 0.1; (5) x 16: a secondary at 0.069, -285).


def test_element_scale_fraction_of_known_fields():
    """cos(q Theta) with q up to half the elements along the sector is resolved (share 0),
    the vertices' alternation (q = 2 N m / 2, N = 8 elements along pi / m) is not (1)."""
    from electrogrowth.postbuckle.stability import element_scale_fraction

    section = Section(BILAYER, 12, MeshSize((1, 2), 8))
    for q, share in ((12, 0.0), (48, 0.0), (96, 1.0), (84, 1.0)):
        z = np.zeros(section.basis.N)
        for comp, wave in (("u^1^1", np.cos), ("u^2^1", np.sin)):
            dofs = section.basis.get_dofs(elements=True).all(comp)
            z[dofs] = wave(q * section.basis.doflocs[1, dofs])
        assert element_scale_fraction(section, z) == pytest.approx(share, abs=1e-9), q


def test_uniform_tube_s_spurious_mode_is_element_scale():
    """Tube.uniform(1.8, length=1) grown to g = 1.4, far below its first (0, j) root (1.956):
    on (8) x 16 the lowest eigenvalue is -485 in the face's harmonic 16 of 16 (the mesh's),
    on (8) x 4 positive in a resolved pattern."""
    from electrogrowth.postbuckle.meridian import Meridian
    from electrogrowth.postbuckle.newton import loaded
    from electrogrowth.postbuckle.onset import lowest_eigenvalue
    from electrogrowth.postbuckle.stability import is_element_scale

    tube = Tube.uniform(1.8, length=1.0)
    for axial, spurious in ((16, True), (4, False)):
        model = Meridian(tube, 1, MeshSize((8,), axial))
        x = loaded(model, tube.at("growth", 1.4), steps=3)
        lam, z = lowest_eigenvalue(model, x, vector=True)
        assert (lam < 0) == spurious and is_element_scale(model, z) == spurious


def test_no_sign_change_is_sought_across_an_element_scale_point():
    """A negative lowest eigenvalue of the elements' size has no known sign for the tube:
    ``secondaries`` neither locates a zero next to it (it used to: the branch below is
    never touched, so any attempt fails) nor elsewhere."""
    from electrogrowth.postbuckle.branch import BranchPoint
    from electrogrowth.postbuckle.stability import secondaries

    x = np.zeros(3)
    pts = [
        BranchPoint(1.0, 0.05, 0.0, x, eigenvalue=0.03, element_scale=0.004),
        BranchPoint(1.1, 0.10, 0.0, x, eigenvalue=-1142.0, element_scale=0.99),
        BranchPoint(1.2, 0.15, 0.0, x, eigenvalue=-3472.0, element_scale=0.99),
    ]
    assert pts[1].unresolved and not pts[0].unresolved
    assert secondaries(None, pts) == ()


@pytest.mark.slow
def test_element_scale_instability_is_no_secondary_and_says_so():
    """probe 12a D1 (about 40 s): Tube.uniform(1.5, length=3), mode (0, 2), growth, on
    (5) x 16 reported a located secondary at a = 0.0694 and -285 at a = 0.1, where (5) x 4
    gives +0.119; now the point at 0.1 has no eigenvalue (NaN: the mesh's mode), no
    secondary, and ``unresolved_from`` says where the stability stops being known."""
    tube = Tube.uniform(1.5, length=3.0)
    fine = postbuckle(tube, (0, 2), "growth", amplitude=0.1, points=2, density=10, axial=16)
    assert fine.secondary == ()
    assert np.isnan(fine.eigenvalue[-1]) and fine.lowest_mode[-1] == "element-scale"
    assert fine.eigenvalue[1] > 0 and fine.unresolved_from == pytest.approx(0.1)
    record = fine.as_dict()
    assert record["stability_unresolved_from"] == pytest.approx(0.1)
    assert "not established on this mesh" in record["stability_note"]
    if importlib.util.find_spec("xarray") is not None:
        data = fine.to_xarray()
        assert data["element_scale_fraction"].values[-1] > 0.5
        assert data.attrs["stability_unresolved_from"] == pytest.approx(0.1)
    coarse = postbuckle(tube, (0, 2), "growth", amplitude=0.1, points=2, density=10, axial=4)
    assert coarse.secondary == () and coarse.eigenvalue[-1] > 0
    assert np.isnan(coarse.unresolved_from) and coarse.as_dict()["stability_note"] is None
