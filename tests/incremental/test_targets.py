"""Mode families: prismatic (n = 0), torsional (m = 0, u_theta only) and the paper's wrinkles.

Checks, each against something independent of the quantity tested (docs/derivation-families.md):
the prismatic modes are the L -> infinity limit of n = 1 (fitted rate 1/L^2); the torsional
impedance is the exact Bessel solution of a homogeneous tube; the kernel, its SciPy twin and
the collocation agree for every family; the targets factorise where the Stroh system
decouples; scans include the families and find a prismatic critical mode; bad modes fail in
one line.
"""

import json
import math

import numpy as np
import pytest
from scipy.special import iv, kv

from electrogrowth import ParameterError, Tube
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes
from electrogrowth.bifurcation.scan_grid import scan_grid
from electrogrowth.cli.app import main
from electrogrowth.errors import NoBifurcationFound
from electrogrowth.incremental.collocation import (
    collocation_matrix,
    collocation_target,
    critical_collocation,
)
from electrogrowth.incremental.collocation_impedance import collocation_impedance
from electrogrowth.incremental.impedance import integrate_one
from electrogrowth.incremental.impedance_reference import impedance_reference
from electrogrowth.incremental.radial_table import build_table
from electrogrowth.incremental.targets import (
    U_TH,
    U_Z,
    Family,
    check_mode,
    impedance_targets,
    wavenumber,
    with_family,
)
from electrogrowth.model.materials import gent, neo_hookean
from electrogrowth.shapes.mode_shape import mode_shape

ALL, IN_PLANE, AXISYMMETRIC = 0b1111, 0b1011, 0b1101


def _rate(lengths, values, limit):
    """Slope of log |value - limit| against log L, and the Richardson limit of the last two
    (error ~ 1/L^2: v_inf = (4 v(2L) - v(L)) / 3)."""
    d = np.abs(np.asarray(values) - limit)
    slope = np.polyfit(np.log(lengths), np.log(d), 1)[0]
    return slope, (4 * values[-1] - values[-2]) / 3


# -- prismatic n = 0 is the long-tube limit of n = 1 ----------------------------------------

LENGTHS = (10.0, 20.0, 40.0, 80.0)


def test_prismatic_is_the_long_tube_limit_neo_hookean_with_voltage_and_growth():
    """g = 1.2, Vbar = 0.4, extension, m = 12: lambda_z,cr(L) - lambda_z,cr(prismatic) falls
    like 1/L^2 (k^2 = (pi / (lambda_z L))^2; measured slope -1.996, local slopes -1.991,
    -1.998, -1.999) and its Richardson limit is the prismatic value to 1e-8."""
    p = Tube.uniform(1.4, 1.0, growth=1.2, voltage=0.4)
    prism = critical_value(p, 12, 0, "stretch", side="extension")
    assert prism.family == Family.PRISMATIC and prism.kind == "bifurcation"
    assert prism.value == pytest.approx(3.599760295002, abs=1e-10)
    vals = [
        critical_value(p.at("length", L), 12, 1, "stretch", side="extension").value
        for L in LENGTHS
    ]
    slope, limit = _rate(LENGTHS, vals, prism.value)
    assert -2.05 < slope < -1.95
    assert abs(limit - prism.value) < 2e-8 < abs(vals[-1] - prism.value)


def test_prismatic_is_the_long_tube_limit_gent():
    """gent(20), thick tube Rbar_o = 3, lambda_z = 1.5, m = 24, critical voltage: slope
    -1.9994, Richardson limit within 1e-9 of the prismatic value."""
    p = Tube.uniform(3.0, 1.0, stretch=1.5, material=gent(20.0))
    prism = critical_value(p, 24, 0, "voltage")
    assert prism.value == pytest.approx(0.714541308333, abs=1e-10)
    v0 = prism.value
    vals = [
        critical_value(p.at("length", L), 24, 1, "voltage", bracket=(v0 + 1e-9, v0 + 2e-4)).value
        for L in LENGTHS
    ]
    slope, limit = _rate(LENGTHS, vals, v0)
    assert -2.02 < slope < -1.98
    assert abs(limit - v0) < 1e-9 < abs(vals[-1] - v0)


# -- torsional modes: the exact Bessel solution of a homogeneous tube -----------------------


def bessel_torsional_impedance(lz, n, Ro, L, two_w1=1.0):
    """z = r Sigma_rth / U_th at r_o of u_th = U(r) cos kz with Sigma_rth(r_i) = 0.

    Homogeneous tube (Vbar = 0, g = 1) of an energy W(I1): lambda_r = lambda_th = l =
    lambda_z^{-1/2}, p = 2 W1 l^2, so Sigma_rth = 2 W1 l^2 (U' - U/r) and the theta
    equilibrium is 2 W1 l^2 (U'' + U'/r - U/r^2) = 2 W1 lambda_z^2 k^2 U: U = A I_1(kappa r)
    + B K_1(kappa r), kappa = k lambda_z / l. With U' - U/r = kappa (A I_2 - B K_2), the
    inner face gives A = K_2(kappa r_i), B = I_2(kappa r_i).
    """
    l2 = 1 / lz
    ri, ro = math.sqrt(l2), Ro * math.sqrt(l2)
    k = n * math.pi / (lz * L)
    kap = k * lz / math.sqrt(l2)
    a, b = kap * ri, kap * ro
    U = kv(2, a) * iv(1, b) + iv(2, a) * kv(1, b)
    dU = kap * (kv(2, a) * iv(2, b) - iv(2, a) * kv(2, b))  # U' - U/r at r_o
    return ro * two_w1 * l2 * dU / U, k, ro


def bessel_dispersion(kap, ri, ro):
    """det of the traction conditions on A, B: zero at a torsional bifurcation."""
    return iv(2, kap * ri) * kv(2, kap * ro) - iv(2, kap * ro) * kv(2, kap * ri)


@pytest.mark.parametrize("material", ["neo-hookean", "gent"])
@pytest.mark.parametrize("lz, Ro, n", [(0.7, 1.4, 1), (1.0, 2.5, 3), (1.6, 1.4, 10)])
def test_torsional_impedance_is_the_exact_bessel_solution(material, lz, Ro, n):
    mat = neo_hookean() if material == "neo-hookean" else gent(20.0)
    two_w1 = 1.0 if material == "neo-hookean" else 20.0 / (20.0 - (2 / lz + lz**2 - 3))
    L = 2.0
    exact, k, ro = bessel_torsional_impedance(lz, n, Ro, L, two_w1)
    state = solve_base_state(Tube.uniform(Ro, L, stretch=lz, material=mat))
    twin = impedance_reference(state, 0, k, pairs=U_TH, rtol=1e-13, atol=1e-15)
    assert twin.shape == (1, 1) and twin[0, 0] == pytest.approx(exact, rel=1e-10)
    col = collocation_impedance(state, 0, n, nodes=24, pairs=U_TH)
    assert col[0, 0] == pytest.approx(exact, rel=1e-10)
    zs = exact / max(1.0, k * ro)  # the kernel's pole-free target of the 1x1 block
    f = impedance_targets(state, with_family(0, n, "torsional"))[0]
    assert f == pytest.approx(zs / math.sqrt(1 + zs * zs), rel=1e-10)


def test_exact_torsional_dispersion_has_no_root():
    """I_2(kappa r_i) K_2(kappa r_o) < I_2(kappa r_o) K_2(kappa r_i) for r_i < r_o (I_2
    grows, K_2 falls): the homogeneous tube never buckles in torsion; nor does the charged
    tube, by the energy identity of docs/derivation-families.md."""
    kap = np.geomspace(1e-3, 60.0, 400)
    assert np.all(bessel_dispersion(kap, 1.0, 1.4) < 0)
    with pytest.raises(NoBifurcationFound):
        critical_value(
            Tube.uniform(1.4, 1.0, voltage=0.4),
            0,
            1,
            "stretch",
            family="torsional",
            side="compression",
        )


# -- impedance vs collocation for every family ----------------------------------------------


@pytest.mark.parametrize(
    "params, m, solve_for, side, want",
    [
        (Tube.uniform(3.0, 1.0, stretch=2.0), 30, "voltage", None, 0.499891281791),
        (
            Tube.uniform(1.4, 1.0, growth=1.2, voltage=0.4),
            12,
            "stretch",
            "extension",
            3.599760295002,
        ),
        (
            Tube.uniform(3.0, 1.0, stretch=1.5, material=gent(20.0)),
            24,
            "voltage",
            None,
            0.714541308333,
        ),
    ],
    ids=["neo-hookean", "neo-hookean-grown", "gent20"],
)
def test_prismatic_critical_values_agree_by_both_methods(params, m, solve_for, side, want):
    imp = critical_value(params, m, 0, solve_for, side=side)
    assert imp.value == pytest.approx(want, abs=1e-10) and imp.error_estimate < 1e-10
    v = imp.value
    col = critical_collocation(
        params, m, 0, solve_for, (v - 1e-6, v + 1e-6), nodes=56, xtol=1e-14, pairs=IN_PLANE
    )
    assert col == pytest.approx(v, abs=1e-9 * v)


@pytest.mark.parametrize("material", [neo_hookean(), gent(20.0)], ids=lambda m: m.name)
@pytest.mark.parametrize(
    "m, n, pairs",
    [(0, 3, U_TH), (0, 3, AXISYMMETRIC), (5, 0, IN_PLANE), (5, 0, U_Z), (2, 2, ALL)],
    ids=["torsional", "axisymmetric", "prismatic", "anti-plane", "wrinkle"],
)
def test_impedance_of_every_family_by_both_methods(material, m, n, pairs):
    """The conditional impedance z(r_o) of each block with voltage and growth: Riccati
    (SciPy twin) against collocation (outer-face U prescribed, no Stroh matrix), 1e-9."""
    state = solve_base_state(
        Tube.uniform(1.6, 2.0, growth=1.15, stretch=1.1, voltage=0.3, material=material)
    )
    k = wavenumber(state.tube, n)
    z = impedance_reference(state, m, k, pairs=pairs, rtol=1e-12, atol=1e-14)
    zc = collocation_impedance(state, m, n, nodes=24, pairs=pairs)
    assert z.shape == zc.shape == (bin(pairs).count("1"),) * 2
    assert np.abs(zc - z).max() < 1e-9 * np.abs(z).max()


def test_kernel_family_targets_equal_the_reduced_twin():
    """The kernel keeps a family's block by masking the 4x4 Riccati equation; its SciPy twin
    integrates the reduced (kept x kept) equation: same target."""
    from electrogrowth.incremental.impedance_reference import target_reference

    state = solve_base_state(Tube.uniform(1.4, 2.0, growth=1.2, stretch=1.1, voltage=0.4))
    for m, n, fam in [(3, 0, "prismatic"), (0, 2, "torsional"), (0, 2, "wrinkle")]:
        f = impedance_targets(state, with_family(m, n, fam))[0]
        ref = target_reference(
            state,
            m,
            wavenumber(state.tube, n),
            pairs=Family(fam).pairs(m),
            rtol=1e-12,
            atol=1e-14,
        )
        assert f == pytest.approx(ref, rel=1e-8)


# -- factorisation where the Stroh system decouples -----------------------------------------


@pytest.mark.parametrize("V", [0.0, 0.4])
def test_k0_target_is_in_plane_times_exact_anti_plane(V):
    """At k = 0 today's 4x4 target is the prismatic (in-plane) target times the anti-plane
    one, and for the neo-Hookean dielectric the anti-plane factor is exact at any voltage:
    z = (g / lambda_z) m tanh(m ln Rbar_o) (anti-plane shear of a neo-Hookean solid is
    Laplace's equation in the reference radius), scaled by s = m."""
    g, lz, Ro = 1.1, 1.05, 1.4
    state = solve_base_state(Tube.uniform(Ro, 1.0, growth=g, stretch=lz, voltage=V))
    table = build_table(state)
    for m in (2, 3, 6):
        full, in_plane, anti = (
            integrate_one(float(m), 0.0, keep, table, 1e-12, 20000)[0]
            for keep in (ALL, IN_PLANE, U_Z)
        )
        assert full == pytest.approx(in_plane * anti, rel=1e-12, abs=1e-16)
        zs = g / lz * math.tanh(m * math.log(Ro))
        assert anti == pytest.approx(zs / math.sqrt(1 + zs * zs), rel=1e-11)
        assert in_plane == impedance_targets(state, [(m, 0)])[0]  # the prismatic family


def test_m0_target_is_axisymmetric_times_torsional_and_never_torsional():
    """At m = 0 today's 4x4 target is the axisymmetric target times the torsional one. At the
    (0, 1) critical growth of the paper's headline tube the full target vanishes with the
    axisymmetric factor while the torsional factor is ~0.48: the root was never torsional."""
    p = Tube.uniform(1.4, 1.0, voltage=0.4)
    crit = critical_value(p, 0, 1, "growth")
    assert crit.value == pytest.approx(1.2661115622623, abs=1e-11)  # unchanged value
    for params in (p.at("growth", 1.1), crit.params):
        state = solve_base_state(params)
        k = wavenumber(params, 1)
        table = build_table(state)
        full, axi, tors = (
            integrate_one(0.0, k, keep, table, 1e-12, 20000)[0]
            for keep in (ALL, AXISYMMETRIC, U_TH)
        )
        assert full == pytest.approx(axi * tors, rel=1e-12, abs=1e-16)
    assert abs(full) < 1e-13 and abs(axi) < 1e-13 and 0.45 < tors < 0.5


def test_collocation_blocks_at_k0():
    """The collocation matrix at k = 0 is block diagonal after a permutation: its singular
    values are the in-plane and anti-plane blocks' together, its determinant's sign their
    product; the targets have the unloaded tube's sign convention (f > 0 there)."""
    state = solve_base_state(Tube.uniform(1.4, 1.0, growth=1.1, voltage=0.5))
    M, A, B = (collocation_matrix(state, 3, 0, nodes=16, pairs=q) for q in (ALL, IN_PLANE, U_Z))
    s = np.linalg.svd(M, compute_uv=False)
    both = np.sort(np.concatenate([np.linalg.svd(X, compute_uv=False) for X in (A, B)]))
    np.testing.assert_allclose(np.sort(s), both, rtol=1e-10, atol=1e-12 * s[0])
    signs = [np.linalg.slogdet(X)[0] for X in (M, A, B)]
    assert signs[0] == signs[1] * signs[2]
    unloaded = solve_base_state(Tube.uniform(1.4, 1.0))
    for nodes in (9, 10, 24):
        for m, n, q in [(3, 0, IN_PLANE), (3, 0, U_Z), (0, 2, U_TH), (0, 2, AXISYMMETRIC)]:
            assert collocation_target(unloaded, m, n, nodes=nodes, pairs=q) > 0


# -- scans ----------------------------------------------------------------------------------


def test_scan_includes_the_families_by_default():
    opt = ScanOptions()
    assert opt.prismatic and opt.torsional
    grid = scan_grid(opt.m_range, opt.n_range, False, (opt.prismatic, opt.torsional))
    rows = {(int(m), int(n), int(c)) for m, n, c in grid}
    assert (2, 0, Family.PRISMATIC.code) in rows and (1, 0, Family.PRISMATIC.code) not in rows
    assert (0, 30, Family.TORSIONAL.code) in rows and (0, 0, Family.TORSIONAL.code) not in rows
    assert len(grid) == 13 * 30 + 11 + 30


def test_scan_finds_a_prismatic_critical_mode():
    """Thick tube Rbar_o = 3, L = 1, lambda_z = 2 under voltage: the plane-strain mode
    (30, 0) comes first, Vbar_cr = 0.499891281791, below every wrinkle and the short-wave
    limit 0.500105 (outer face, along theta); the default scan finds the same (slow test)."""
    p = Tube.uniform(3.0, 1.0, stretch=2.0)
    res = scan_modes(p, "voltage", options=ScanOptions(m_range=(0, 40), n_range=(1, 4)))
    c = res.critical
    assert (c.kind, c.m, c.n, c.family) == ("bifurcation", 30, 0, "prismatic")
    assert c.value == pytest.approx(0.499891281791, abs=1e-11)
    assert [r.family for r in res.runners_up] == ["prismatic"] * 4
    assert {r.m for r in res.runners_up} == {28, 29, 31, 32}
    rec = res.as_dict()  # the field criterion's crease (at Vbar 0.406) informs, never first
    assert rec["wrinkle"]["family"] == rec["runners_up"][0]["family"] == "prismatic"
    one = critical_value(p, 30, 0, "voltage")  # the family's single-mode solver
    assert one.value == pytest.approx(c.value, abs=1e-13)
    col = critical_collocation(
        p, 30, 0, "voltage", (c.value - 1e-6, c.value + 1e-6), nodes=40, xtol=1e-14, pairs=IN_PLANE
    )
    assert col == pytest.approx(c.value, abs=1e-9)


@pytest.mark.slow
def test_default_scan_finds_the_prismatic_mode():
    res = scan_modes(Tube.uniform(3.0, 1.0, stretch=2.0), "voltage")
    c = res.critical
    assert (c.m, c.n, c.family) == (30, 0, "prismatic") and res.m_range == (0, 51)
    assert c.value == pytest.approx(0.499891281791, abs=1e-11)


# -- mode shapes ----------------------------------------------------------------------------


def test_prismatic_mode_shape_by_both_routes():
    crit = critical_value(
        Tube.uniform(1.4, 1.0, growth=1.2, voltage=0.4), 12, 0, "stretch", side="extension"
    )
    a, b = (mode_shape(crit, method=meth, points=41) for meth in ("impedance", "collocation"))
    assert (a.route, b.route, a.family, a.k) == ("impedance", "collocation", "prismatic", 0.0)
    assert not a.U_z.any() and not b.U_z.any() and not a.eta[6].any()  # plane strain
    assert np.abs(a.eta[:3] - b.eta[:3]).max() < 1e-7  # measured 4.5e-8
    assert a.boundary_residual < 1e-12 and b.boundary_residual < 1e-7


def test_torsional_mode_shape_is_u_theta_only():
    p = Tube.uniform(1.4, 1.0, voltage=0.4)
    for meth in ("impedance", "collocation"):
        s = mode_shape((p, 0, 2, "torsional"), method=meth, points=21)
        assert s.family == "torsional" and s.U_th.max() == 1.0
        assert not (s.U_r.any() or s.U_z.any() or s.Phi.any() or s.eta[[3, 4, 6]].any())


# -- bad input ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "m, n, family, needle",
    [
        (0, 0, None, r"\(0, 0\) is invalid: it is the breathing mode.*need m >= 2"),
        (1, 0, None, r"\(1, 0\) is invalid: it is a rigid translation.*need m >= 2"),
        (2, 3, "torsional", r"\(2, 3\) is invalid for the torsional family.*m = 0, n >= 1"),
        (0, 0, "torsional", r"\(0, 0\) is invalid for the torsional family"),
        (3, 0, "wrinkle", r"\(3, 0\) is not a wrinkle \(n >= 1\)"),
        (3, 2, "prismatic", r"\(3, 2\) is not prismatic"),
        (0, 1, "twisting", r"family = 'twisting' is unknown"),
    ],
)
def test_bad_modes_are_one_line_parameter_errors(m, n, family, needle):
    with pytest.raises(ParameterError, match=needle) as err:
        check_mode(m, n, family)
    assert "\n" not in str(err.value)
    with pytest.raises(ParameterError, match=needle):
        critical_value(Tube.uniform(1.4, 1.0), m, n, "growth", family=family)


# -- command line ---------------------------------------------------------------------------

BASE = ["critical", "--outer-radius", "1.4", "--length", "1.0"]


def test_cli_prismatic_and_torsional(capsys):
    argv = BASE + [
        "--solve-for",
        "stretch",
        "--side",
        "extension",
        "--growth",
        "1.2",
        "--voltage",
        "0.4",
        "--mode",
        "12",
        "0",
        "--json",
    ]
    assert main(argv) == 0
    rec = json.loads(capsys.readouterr().out)
    assert (rec["m"], rec["n"], rec["family"]) == (12, 0, "prismatic")
    assert rec["value"] == pytest.approx(3.599760295002, abs=1e-10)
    assert main(BASE + ["--solve-for", "growth", "--mode", "0", "1", "--family", "torsional"]) == 2
    assert "no mode bifurcates" in capsys.readouterr().err
    for extra, needle in [
        (["--mode", "1", "0"], "rigid translation"),
        (["--mode", "2", "1", "--family", "torsional"], "torsional family"),
        (["--family", "torsional"], "--family torsional needs --mode"),
    ]:
        assert main(BASE + ["--solve-for", "growth"] + extra) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and needle in err


@pytest.mark.parametrize("command", ["critical", "pattern"])
def test_help_states_the_mode_family_coverage(command, capsys):
    assert main([command, "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    for phrase in (
        "'prismatic' = n = 0",
        "'torsional' = m = 0",
        "A scan examines by default all three",
        "computed exactly from the half-space problem",
        "--family {wrinkle,prismatic,torsional}",
    ):
        assert phrase in text, phrase
