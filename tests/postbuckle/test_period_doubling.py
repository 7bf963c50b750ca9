"""The prismatic branch in the sector of two wavelengths, 2 pi / m (a Section of m / 2, which
holds the subharmonic m / 2 that the sector pi / m suppresses): its onset and branch are
those of the sector pi / m at the same resolution (the doubled mesh is the mirrored one, an
exact identity), and the lowest eigenvector along the branch shows whether the subharmonic
(antisymmetric about Theta = pi / m) takes over: period doubling."""

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.bifurcation.critical import critical_value  # noqa: E402
from electrogrowth.model.layers import Layer, Tube  # noqa: E402
from electrogrowth.postbuckle.branch import AmplitudeBranch, BranchPoint  # noqa: E402
from electrogrowth.postbuckle.onset import fe_onset, lowest_eigenvalue  # noqa: E402
from electrogrowth.postbuckle.section import MeshSize, Section  # noqa: E402

BILAYER = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), stretch=1.0)
CONTROL = "growth[1].theta"
M = 12


def branch(section, amplitudes):
    """Onset and branch of mode M in ``section``, the amplitude a = (u_R(1, 0) -
    u_R(1, pi / M)) / 2 in either sector; each point's lowest eigenvector's antisymmetry
    about Theta = pi / M (0: the mode's family, 1: the subharmonic's)."""
    linear = critical_value(BILAYER, M, 0, CONTROL).value
    onset = fe_onset(section, BILAYER, CONTROL, linear)
    dofs, theta = section.face_dofs("inner")
    mid = int(np.argmin(np.abs(theta - np.pi / M)))
    a = np.zeros(section.basis.N)
    a[dofs[0]] += 0.5
    a[dofs[mid]] -= 0.5
    follower = AmplitudeBranch(section, BILAYER, CONTROL)
    follower.a = a
    start = BranchPoint(onset.value, 0.0, section.energy(onset.x), onset.x)
    pts = follower.follow(start, amplitudes, direction=onset.mode / (a @ onset.mode))
    face = dofs[: 2 * mid + 1]
    out = []
    for p in pts:
        lam, z = lowest_eigenvalue(section, p.x, vector=True)
        u = z[face]
        out.append((p.control, lam, np.abs(u - u[::-1]).max() / np.abs(u).max()))
    return onset.value, out


@pytest.mark.slow
def test_doubled_sector_follows_the_same_branch_without_period_doubling():
    """Measured on (2, 9) x 4 elements in pi / 12 and (2, 9) x 8 in 2 pi / 12: the same onset
    (1.7162616) and controls to rounding; up to a = 0.1 (g_theta = 1.79358) the lowest
    eigenvalue stays positive (0.33) and its eigenvector symmetric (antisymmetry 1e-12): no
    period doubling for this bilayer in that range."""
    amps = [0.05, 0.1]
    single, pts1 = branch(Section(BILAYER, M, MeshSize((2, 9), 4)), amps)
    double, pts2 = branch(Section(BILAYER, M // 2, MeshSize((2, 9), 8)), amps)
    assert double == pytest.approx(single, rel=1e-10)
    for (c1, _, _), (c2, lam, antisym) in zip(pts1, pts2):
        assert c2 == pytest.approx(c1, rel=1e-9)
        assert lam > 0 and antisym < 1e-6
