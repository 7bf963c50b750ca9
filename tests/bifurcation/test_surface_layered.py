"""Short waves at the faces and interfaces of layered, pressurised tubes: the follower-pressure
face condition and the bonded interface of the half-space problem (incremental/halfspace.py)
and their critical values (bifurcation/surface.py, directions.py).

Derivation and the numbers quoted here: docs/derivation-layered-modes.md, section "Short waves
at faces with pressure and at interfaces".
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation import directions
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.surface import ray_limit, short_wave_limit
from electrogrowth.errors import ParameterError
from electrogrowth.incremental.halfspace import (
    FaceProblem,
    InterfaceProblem,
    surface_problem,
    surfaces,
)
from electrogrowth.incremental.impedance import ALL_PAIRS, face_impedance
from electrogrowth.incremental.stroh_limit import decaying_solutions, limit_matrix
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.materials import neo_hookean_moduli

HALF_PI = 0.5 * math.pi
PSI = np.linspace(0.0, HALF_PI, 9)


def pressure_impedance(P, psi) -> np.ndarray:
    """The scaled limit Z of the follower-pressure impedance (docs)."""
    c, s = math.cos(psi), math.sin(psi)
    return -P * np.array([[0, c, s, 0], [c, 0, 0, 0], [s, 0, 0, 0], [0, 0, 0, 0.0]])


def schur_z(mod, p, psi, face) -> np.ndarray:
    """z = Y X^-1 of the decaying subspace from the ordered real Schur form (independent of
    the projector route of the compiled kernels)."""
    Q, _, _ = decaying_solutions(limit_matrix(mod, p, psi), face)
    return Q[4:] @ np.linalg.inv(Q[:4])


def normalised(z) -> float:
    return 1.0 / math.sqrt(np.linalg.det(np.eye(4) + z.T @ z))


def random_face(rng):
    """Neo-Hookean moduli at random stretches and field, p at random (not a free face)."""
    l2, l3 = rng.uniform(0.7, 1.4, 2)
    d = rng.uniform(-0.6, 0.6)
    l1 = 1.0 / (l2 * l3)
    return neo_hookean_moduli(l1, l2, l3, d), l1 * l1 + d * d + rng.uniform(-0.5, 0.5)


# -- the half-space problems --------------------------------------------------------------------


def test_pressure_impedance_is_the_scaled_limit():
    """T_S^-1 z_P T_U -> Z (S~ = S / Lam, U~_4 = U_4 / Lam) with an O(1/Lam) error."""
    P, psi = 0.7, 0.4
    errs = []
    for lam in (1e3, 1e6):
        m, kr = lam * math.cos(psi), lam * math.sin(psi)
        zp = face_impedance(P, m, kr, ALL_PAIRS, 1.0)
        scaled = np.diag([1 / lam] * 3 + [1.0]) @ zp @ np.diag([1.0] * 3 + [lam])
        errs.append(np.max(np.abs(scaled - pressure_impedance(P, psi))))
    assert errs[1] < 1e-5 and errs[0] / errs[1] > 0.5e3


def test_pressure_face_target_equals_schur_route():
    """sign(det X) det(Y - Z X) / sqrt(det M^T M) (projector, compiled) = det(z - Z) /
    sqrt(det(I + z^T z)) (Schur), both faces, random states and pressures; P = 0 gives the
    traction-free target exactly."""
    rng = np.random.default_rng(7)
    for _ in range(6):
        mod, p = random_face(rng)
        P = rng.uniform(-1.0, 1.0)
        for face in ("inner", "outer"):
            prob = FaceProblem.from_moduli(mod, p, face, pressure=P)
            f = prob.target(PSI)
            ref = [
                np.linalg.det(schur_z(mod, p, x, face) - pressure_impedance(P, x))
                * normalised(schur_z(mod, p, x, face))
                for x in PSI
            ]
            np.testing.assert_allclose(f, ref, rtol=0, atol=1e-12)
            assert np.all(np.abs(f) <= 1 + P * P)
            free = FaceProblem.from_moduli(mod, p, face)
            assert np.array_equal(
                FaceProblem.from_moduli(mod, p, face, pressure=0.0).target(PSI), free.target(PSI)
            )


def test_interface_target_equals_schur_route_and_is_bounded():
    rng = np.random.default_rng(11)
    for _ in range(6):
        (mb, pb), (ma, pa) = random_face(rng), random_face(rng)
        prob = InterfaceProblem.from_moduli(mb, pb, ma, pa)
        f = prob.target(PSI)
        ref = []
        for x in PSI:
            zb, za = schur_z(mb, pb, x, "outer"), schur_z(ma, pa, x, "inner")
            assert np.allclose(zb, zb.T, atol=1e-10) and np.allclose(za, za.T, atol=1e-10)
            ref.append(np.linalg.det(zb - za) * normalised(zb) * normalised(za))
        np.testing.assert_allclose(f, ref, rtol=0, atol=1e-12)
        assert np.all(np.abs(f) <= 1.0)
        np.testing.assert_allclose([prob.target_scalar(x) for x in PSI], f, rtol=0, atol=1e-15)


def test_unloaded_layered_tube_is_stable_at_every_surface():
    """On the reference state z_b > 0 and z_a < 0 at an interface (so f > 0), and the faces
    have their one-layer signs."""
    tube = Tube((Layer(1.1, shear_modulus=10.0), Layer(1.5, shear_modulus=0.3), Layer(2.0)))
    state = solve_base_state(tube.reference())
    assert surfaces(state) == ("inner", "outer", "interface-1", "interface-2")
    assert directions.stable_signs(tube) == {s: 1.0 for s in surfaces(state)}
    for name in ("interface-1", "interface-2"):
        prob = surface_problem(state, name)
        k = int(name[-1])
        R = tube.radii[k]
        for x in PSI:
            zb = schur_z(
                state.moduli(R, side="inner"), state.pressure(R, side="inner"), x, "outer"
            )
            za = schur_z(
                state.moduli(R, side="outer"), state.pressure(R, side="outer"), x, "inner"
            )
            assert np.all(np.linalg.eigvalsh(zb) > 0) and np.all(np.linalg.eigvalsh(za) < 0)
        assert np.all(prob.target(PSI) > 0)
    with pytest.raises(ParameterError, match="interface-3"):
        surface_problem(state, "interface-3")


def test_psi_symmetry_with_pressure_and_interface():
    """f(psi) = f(pi - psi): [0, pi/2] covers every direction with pressure and at
    interfaces too."""
    rng = np.random.default_rng(3)
    mod, p = random_face(rng)
    (mb, pb), (ma, pa) = random_face(rng), random_face(rng)
    for prob in (
        FaceProblem.from_moduli(mod, p, "inner", pressure=0.6),
        FaceProblem.from_moduli(mod, p, "outer", pressure=-0.4),
        InterfaceProblem.from_moduli(mb, pb, ma, pa),
    ):
        np.testing.assert_allclose(prob.target(math.pi - PSI), prob.target(PSI), atol=1e-13)


# -- critical values ----------------------------------------------------------------------------


def test_identical_layers_equal_one_layer():
    """Splitting a tube into identical layers changes no short-wave limit (1e-10), and the
    interface between identical layers is never critical (its target stays far from 0)."""
    one = Tube.uniform(outer_radius=1.4, voltage=0.4)
    two = Tube((Layer(1.15), Layer(1.4)), voltage=0.4)
    a = short_wave_limit(one, "stretch", side="extension")
    b = short_wave_limit(two, "stretch", side="extension")
    assert b.kind == "surface" and b.face == a.face == "outer"
    assert abs(a.value - 2.456221128743075) < 1e-10  # the closed form (derivation-surface §5)
    assert abs(b.value - a.value) < 1e-10 and b.psi == a.psi
    # the interface along the whole path up to the critical state
    for x in np.linspace(1.0, b.value, 5):
        state = solve_base_state(two.at("stretch", x))
        v, _ = directions.worst_direction(surface_problem(state, "interface-1"))
        assert v > 0.05
    only = short_wave_limit(two, "stretch", side="extension", faces=("interface-1",))
    assert only.kind in ("none", "threshold")


def test_one_layer_tube_equals_parameters_and_neo_hookean_closed_form():
    """A one-layer Tube gives the TubeParameters values, which equal the closed form (NH) of
    the traction-free face (derivation-surface.md §5 table) to 1e-10."""
    cases = [
        (Tube.uniform(outer_radius=1.4), "voltage", None, 0.8478824129396783, "inner"),
        (
            Tube.uniform(outer_radius=2.0, stretch=1.2, voltage=0.2),
            "growth",
            None,
            2.7006482944111054,
            "inner",
        ),
    ]
    for params, solve_for, side, closed, face in cases:
        tube = Tube(
            (Layer(params.outer_radius, params.material, growth=params.growth),),
            length=params.length,
            stretch=params.stretch,
            voltage=params.voltage,
        )
        lim = short_wave_limit(tube, solve_for, side=side)
        assert lim.kind == "surface" and lim.face == face
        assert abs(lim.value - closed) < 1e-10
        assert abs(lim.value - short_wave_limit(params, solve_for, side=side).value) < 1e-10


def test_equal_pressure_on_both_faces_changes_nothing():
    """P_i -> P_i + c, P_o -> P_o + c: the deformation is the same, p shifts by c, Sigma by
    c L, and the follower-pressure face condition compensates exactly (docs): the short-wave
    limit and a finite mode's critical value agree to 1e-10."""
    layers = (Layer(1.2, shear_modulus=2.0), Layer(1.6))
    base = Tube(layers, inner_pressure=0.15, outer_pressure=0.05)
    shifted = Tube(layers, inner_pressure=0.55, outer_pressure=0.45)
    a = short_wave_limit(base, "voltage")
    b = short_wave_limit(shifted, "voltage")
    assert a.kind == b.kind == "surface" and a.face == b.face
    assert abs(a.value - b.value) < 1e-10
    ca = critical_value(base, 3, 2, "voltage").value
    cb = critical_value(shifted, 3, 2, "voltage").value
    assert abs(ca - cb) < 1e-10


def test_pressurised_face_limit_is_approached_by_finite_modes():
    """One-layer tube inflated by P_i = 0.15 under voltage: the inner (pressurised) face is
    critical along z (psi = pi/2); the modes (0, j) approach the limit like 1/j (impedance
    kernel; its face condition is z_P, the half-space's is the limit Z). Without the Z term
    the limit would be 0.66751, with Z of the wrong sign 0.66819: both excluded here."""
    tube = Tube((Layer(1.4),), inner_pressure=0.15, voltage=0.3)
    lim = ray_limit(tube, 0, 1, "voltage")
    worst = short_wave_limit(tube, "voltage")
    assert lim.kind == worst.kind == "surface" and lim.face == worst.face == "inner"
    assert worst.psi == HALF_PI and abs(worst.value - lim.value) < 1e-12
    assert abs(lim.value - 0.6625868806198049) < 1e-9
    x = {j: critical_value(tube, 0, j, "voltage").value for j in (16, 32, 64)}
    d = {j: v - lim.value for j, v in x.items()}
    assert all(-1e-3 < d[j] < 0 for j in d)  # from below, shrinking
    assert 1.6 < d[16] / d[32] < 2.2 and 1.7 < d[32] / d[64] < 2.2
    assert abs(2 * x[64] - x[32] - lim.value) < 3e-5  # Richardson in 1/j


def biot_stretch() -> float:
    from scipy.optimize import brentq

    beta = brentq(lambda b: b**3 + b**2 + 3 * b - 1, 0.0, 1.0, xtol=1e-17, rtol=1e-15)
    return beta ** (2.0 / 3.0)


def test_interface_with_a_vanishing_neighbour_is_a_free_face():
    """Uniform axial compression (g = 1, no field) strains every layer alike. The interface
    between a layer and one of vanishing modulus ratio r is the free face of the stiffer
    layer: its limit tends to Biot's stretch linearly in r, whichever side is soft (mirror
    symmetry), and a stiffer neighbour (r = 3) stabilises it (interfacial wrinkling needs
    more compression than surface wrinkling)."""
    biot = biot_stretch()
    x = {}
    for below, above in ((1e-4, 1.0), (1e-3, 1.0), (1.0, 1e-3), (1.0, 3.0)):
        tube = Tube((Layer(1.2, shear_modulus=below), Layer(1.4, shear_modulus=above)))
        lim = short_wave_limit(tube, "stretch", faces=("interface-1",))
        assert lim.kind == "surface" and lim.face == "interface-1" and lim.psi == HALF_PI
        x[below, above] = lim.value
    assert 0 < biot - x[1e-4, 1.0] < 1e-4
    assert abs((biot - x[1e-3, 1.0]) / (biot - x[1e-4, 1.0]) - 10.0) < 0.1
    assert abs(x[1e-3, 1.0] - x[1.0, 1e-3]) < 1e-12
    assert x[1.0, 3.0] < biot - 0.1


def test_interface_is_critical_in_a_growing_embedded_layer():
    """A layer (thickness 0.1, modulus 1) growing between two soft ones (modulus 0.2): the
    faces stay stable and interface-1 wrinkles first, along z. The fixed-direction limit and
    the interface alone give the same value."""
    tube = Tube((Layer(1.3, shear_modulus=0.2), Layer(1.4), Layer(2.0, shear_modulus=0.2)))
    lim = short_wave_limit(tube, "growth[2]")
    assert lim.kind == "surface" and lim.face == "interface-1" and lim.psi == HALF_PI
    assert abs(lim.value - INTERFACE_LIMIT) < 1e-9 and lim.error_estimate < 1e-12
    assert lim.params.layers[1].growth == (lim.value,) * 3
    ray = ray_limit(tube, 0, 1, "growth[2]", faces=("interface-1",))
    assert abs(ray.value - lim.value) < 1e-12


#: short_wave_limit of the embedded-layer tube above (measured, docs)
INTERFACE_LIMIT = 2.1782747522850343


@pytest.mark.slow
def test_finite_modes_approach_the_interface_limit():
    """The embedded-layer tube: modes (0, j) by collocation (one Chebyshev domain per layer)
    close on the interface limit like 1/j once k h >> 1 (docs: j = 32, 64 give +1.661e-3,
    +7.93e-4)."""
    from scipy.optimize import brentq

    from electrogrowth.incremental.targets import collocation_targets

    tube = Tube((Layer(1.3, shear_modulus=0.2), Layer(1.4), Layer(2.0, shear_modulus=0.2)))

    def root(j, nodes, lo, hi):
        def f(x):
            state = solve_base_state(tube.at("growth[2]", x))
            return float(collocation_targets(state, np.array([[0.0, j]]), nodes=nodes)[0])

        return brentq(f, lo, hi, xtol=1e-12)

    d32 = root(32, 80, 2.176, 2.188) - INTERFACE_LIMIT
    d64 = root(64, 100, 2.176, 2.188) - INTERFACE_LIMIT
    assert 0 < d64 < d32 < 3e-3
    assert 1.7 < d32 / d64 < 2.4
    assert abs(2 * d64 - d32) < 2e-4


@pytest.mark.slow
def test_scan_of_a_layered_tube_ends_in_the_exact_limit():
    """scan_modes on a layered Tube: the optimum runs to short waves, the exact limit (at the
    inner face of two identical layers) is computed through past_surface / short_wave_limit
    and equals the one-layer value (measured: 0.781917528431796 vs 0.7819175284317958;
    ~8 min on a loaded machine)."""
    from electrogrowth.bifurcation.scan import ScanOptions, scan_modes

    tube = Tube((Layer(1.8), Layer(2.5)), length=3.0, stretch=0.8)
    res = scan_modes(tube, "voltage", options=ScanOptions((0, 2), (1, 6)))
    c = res.critical
    assert res.surface_instability and c.kind == "surface" and c.face == "inner"
    one = short_wave_limit(Tube.uniform(2.5, 3.0, stretch=0.8), "voltage")
    assert abs(c.value - one.value) < 1e-10
