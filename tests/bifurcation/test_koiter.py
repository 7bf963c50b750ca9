"""The Koiter coefficient of a film on a half-space (bifurcation/koiter.py,
docs/derivation-koiter.md): the linear problem against the exact determinant, the
super/subcritical boundary against the literature, convergence, symmetry, invariances,
and the curvature of the branch from a direct Newton solve of the nonlinear problem."""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest
import scipy.optimize

from electrogrowth.bifurcation.koiter import koiter_coefficient, tube_expansion
from electrogrowth.bifurcation.koiter_film import (
    MODE,
    FilmOnHalfSpace,
    critical_mode,
    critical_stretch,
    expansion,
    sign_change_ratio,
)
from electrogrowth.errors import NoBifurcationFound, ParameterError
from electrogrowth.incremental.plane_forms import Forms, Segment, Space
from electrogrowth.model.layer import Layer
from electrogrowth.model.layers import Tube
from tests.bifurcation.koiter_newton import peak_row

FAST = {"nodes": 10, "substrate_nodes": 14}
#: For checks of the discrete problem against itself (same discretisation on both sides).
COARSE = {"nodes": 8, "substrate_nodes": 10, "depth": 20.0}


# ---- an independent route to the linear problem: the exact determinant ---------------


def _columns(s: float, k: float, mu: float, l2: float, y: float) -> np.ndarray:
    """(u1, u2, t1, t2) at y of psi = e^{s y} e^{ikx} (u1 = psi_y, u2 = -psi_x) in a
    neo-Hookean layer at stretches (1 / l2, l2), p0 = mu l2^2, with the traction on
    y = const S_2i = mu l2^2 u_i,2 + p0 u_2,i - p delta_2i and p from the x1 equation
    (Ogden's incremental equations, as in tools/derive_film.py), current coordinates."""
    l1 = 1 / l2
    e = np.exp(s * y)
    u1, u2 = s * e, -1j * k * e
    p = mu * (-(l1**2) * k**2 * s + l2**2 * s**3) / (1j * k) * e
    p0 = mu * l2**2
    t1 = mu * l2**2 * s**2 * e + p0 * 1j * k * u2
    t2 = mu * l2**2 * s * u2 + p0 * s * u2 - p
    return np.array([u1, u2, t1, t2])


def _determinant(lam: float, K: float, ratio: float) -> float:
    """The 6 x 6 determinant of the compressed bilayer (film [0, 1/lam] current, on a
    half-space, both at stretch lam along the wave, reference wavenumber K, k = K / lam):
    four film exponentials +-k, +-k lam^2, two decaying ones k, k lam^2 below."""
    k, h = K / lam, 1 / lam
    rates = (k, -k, k * lam**2, -k * lam**2)
    M = np.zeros((6, 6), complex)
    for j, s in enumerate(rates):
        M[0:2, j] = _columns(s, k, ratio, 1 / lam, h)[2:]
        M[2:6, j] = _columns(s, k, ratio, 1 / lam, 0.0)
    for j, s in enumerate((k, k * lam**2)):
        M[2:6, 4 + j] = -_columns(s, k, 1.0, 1 / lam, 0.0)
    M /= np.abs(M).max(axis=1, keepdims=True)
    return float(np.real(np.linalg.det(M) / 1j))


@pytest.mark.parametrize("ratio", [2.0, 5.0])
def test_linear_problem_against_the_exact_determinant(ratio):
    """The critical stretch of a fixed wavenumber from the discrete energy is a root of
    the exact determinant (independent: closed-form exponentials, no discretisation)."""
    film = FilmOnHalfSpace(ratio, **FAST)
    forms = Forms.build(Space(film.segments(), MODE))
    for K in (0.5, 0.9):
        lam = critical_stretch(forms, K).lam
        exact = scipy.optimize.brentq(_determinant, lam - 2e-3, lam + 2e-3, args=(K, ratio))
        assert lam == pytest.approx(exact, abs=1e-9)


def test_unstressed_substrate_matches_the_flat_film_table():
    """docs/derivation-film.md (tools/derive_film.py, exact): mu_f / mu_s = 2 on an
    unstressed half-space folds at k h = 1.3907973 (current), lambda_cr = 0.7295973."""
    K, lam = critical_mode(FilmOnHalfSpace(2.0, substrate="unstressed", **FAST))
    assert lam == pytest.approx(0.7295973, abs=1e-7)
    assert K / lam**2 == pytest.approx(1.3907973, abs=1e-6)  # k h = (K / lam) (1 / lam)


class _GrownFilm(Forms):
    """The film alone compressed, written in the substrate's stress-free coordinates: the
    film grown by g = 1 / s along X (F_g = diag(g, 1), F0 = diag(1, g), p0 = mu g^2,
    J_g = g), the substrate undeformed; the control is s = 1 / g. A second parametrisation
    of the same bilayer (the period fixed in the substrate, not in the film)."""

    @functools.cached_property
    def _pieces(self):
        mu, f = self.mu, self.follows  # follows: the film
        fx, one = 1.0 - f, np.ones_like(self.mu)
        terms = [
            ("1/g", f * mu / 2, ("G11", "G11")),
            ("1/g", f * mu / 2, ("G21", "G21")),
            ("g", f * mu / 2, ("G12", "G12")),
            ("g", f * mu / 2, ("G22", "G22")),
            ("g2", -f * mu, ("G11", "G22")),
            ("g2", f * mu, ("G12", "G21")),
            ("g", -f * one, ("q", "G11")),
            ("1", -f * one, ("q", "G22")),
            ("1", fx * mu / 2, ("G11", "G11")),
            ("1", fx * mu / 2, ("G12", "G12")),
            ("1", fx * mu / 2, ("G21", "G21")),
            ("1", fx * mu / 2, ("G22", "G22")),
            ("1", -fx * mu, ("G11", "G22")),
            ("1", fx * mu, ("G12", "G21")),
            ("1", -fx * one, ("q", "G11")),
            ("1", -fx * one, ("q", "G22")),
        ]
        out: dict = {}
        for scale, coeff, (a, b) in terms:
            if coeff.any():
                power = sum(x in ("G11", "G21") for x in (a, b))
                M = self.maps[a].T @ ((coeff * self.weight)[:, None] * self.maps[b])
                out[scale, power] = out.get((scale, power), 0.0) + M + M.T
        return out

    def stiffness(self, K, lam, *, wrt=""):
        g = 1 / lam  # the control s = lam = 1 / g
        value = {"1": 1.0, "1/g": 1 / g, "g": g, "g2": g * g}
        dg = {"1": 0.0, "1/g": -1 / g**2, "g": 1.0, "g2": 2 * g}  # d/dg
        A = np.zeros((self.space.size,) * 2)
        for (name, power), M in self._pieces.items():
            if wrt == "lambda":
                c = dg[name] * K**power * (-(g**2))  # dg/ds = -g^2
            elif wrt == "K":
                c = value[name] * power * K ** (power - 1) if power else 0.0
            else:
                c = value[name] * K**power
            A += c * M
        return A


def test_film_alone_compressed_in_a_second_parametrisation():
    """The film alone compressed on an unstressed substrate, written in the substrate's
    coordinates with the film grown (_GrownFilm), gives the same lambda_c, K_c (scaled:
    K_f = K_s / g) and lambda_2 (eps_f = eps_s / g, s = 1 / g = lambda) as the film's
    coordinates with the substrate's stress-free state at diag(lambda, 1)."""
    segs = FilmOnHalfSpace(5.0, substrate="unstressed", **FAST).segments()
    film_frame = expansion(segs)
    substrate_frame = expansion(segs, forms=_GrownFilm)
    assert substrate_frame.lam == pytest.approx(film_frame.lam, abs=1e-11)
    assert substrate_frame.K * substrate_frame.lam == pytest.approx(film_frame.K, rel=1e-8)
    lam2 = substrate_frame.lambda_2 / substrate_frame.lam**2
    assert lam2 == pytest.approx(film_frame.lambda_2, rel=1e-8)


# ---- the sign change against the literature -----------------------------------------


def test_sign_change_ratio_matches_the_published_threshold():
    """Cao & Hutchinson (2012, J. Appl. Mech. 79, 031019): a compressed neo-Hookean
    bilayer wrinkles stably (supercritically) for mu_f / mu_s above about 1.74; Zhou, Cai
    & Fu (2021, Math. Mech. Solids, doi 10.1177/10812865211010886) quote the same boundary
    as mu_s / mu_f ~ 0.57. Both are given to two or three digits, which is what is tested;
    the computed ratio itself is converged to 1e-6 (test_sign_change_converges)."""
    r = sign_change_ratio(1.75, 1.755, xtol=1e-4, **FAST)
    assert abs(r - 1.74) < 0.015
    assert abs(1 / r - 0.57) <= 0.005
    assert koiter_coefficient(FilmOnHalfSpace(r + 0.01, **FAST)).branch == "supercritical"
    assert koiter_coefficient(FilmOnHalfSpace(r - 0.01, **FAST)).branch == "subcritical"


@pytest.mark.slow
def test_sign_change_converges():
    """Finer nodes and a deeper truncation move the ratio by less than 1e-6."""
    coarse = sign_change_ratio(1.74, 1.76, **FAST)
    fine = sign_change_ratio(1.74, 1.76, nodes=20, substrate_nodes=30, depth=60.0)
    assert fine == pytest.approx(coarse, abs=1e-6)


@pytest.mark.parametrize("substrate", ["compressed", "unstressed"])
def test_stiff_film_limit_is_a_quarter(substrate):
    """A stiff thin film on a compliant substrate (small strains, Foppl-von Karman plate on
    a half-space) wrinkles with amplitude A = h sqrt(e / e_c - 1) (Chen & Hutchinson 2004,
    J. Appl. Mech. 71, 597), e_c = (1/4)(3 mu_s / mu_f)^(2/3) at K h = (3 mu_s / mu_f)^(1/3):
    lambda - lambda_c = -e_c (A / h)^2 = -(e_c / (K h)^2) eps^2, so lambda_2 -> -1/4 as
    mu_f / mu_s -> infinity, whatever the substrate's prestress."""
    r = koiter_coefficient(FilmOnHalfSpace(1000.0, substrate=substrate, **FAST))
    assert r.coefficient == pytest.approx(-0.25, abs=1e-3)
    assert r.wavenumber == pytest.approx(0.3 ** (1 / 3) / 10 ** (2 / 3), rel=1e-2)


# ---- convergence, symmetry, invariances ---------------------------------------------


def test_coefficient_converges_and_estimates_its_error():
    r = koiter_coefficient(FilmOnHalfSpace(5.0, **FAST))
    fine = expansion(FilmOnHalfSpace(5.0, nodes=12, substrate_nodes=18, depth=30.0).segments())
    assert r.branch == "supercritical" and r.coefficient < 0
    assert r.coefficient == pytest.approx(fine.lambda_2, rel=1e-7)
    assert r.error_estimate < 1e-6 * abs(r.coefficient)
    assert r.as_dict()["branch"] == "supercritical"


def test_cubic_term_vanishes_by_symmetry():
    """lambda_1 = -C[phi, phi, phi] / (2 A'[phi, phi]) = 0 for the symmetric wrinkle; and
    the correction is orthogonal to the mode by construction (other harmonics)."""
    e = expansion(FilmOnHalfSpace(3.0, **COARSE).segments())
    f = e.first.fields(e.phi, e.K)
    cubic = e.first.cubic_gradient(f, f, e.K) @ e.phi
    second_order = e.second.cubic_gradient(f, f, e.K) @ e.psi  # C[phi, phi, psi], not 0
    assert abs(second_order) > 1e-3
    assert abs(cubic) < 1e-12 * abs(second_order)


def _scaled(segments, mu=1.0, length=1.0):
    return tuple(
        dataclasses.replace(s, bottom=s.bottom * length, top=s.top * length, mu=s.mu * mu)
        for s in segments
    )


@pytest.mark.parametrize(
    "scale", [{"mu": 7.0}, pytest.param({"length": 1.6}, marks=pytest.mark.slow)]
)
def test_invariant_under_moduli_and_length_scales(scale):
    """Multiplying every modulus, or every length, leaves lambda_c and lambda_2 unchanged
    (eps = K w is dimensionless); K_c scales as 1 / length."""
    segs = FilmOnHalfSpace(2.5, **COARSE).segments()
    base, e = expansion(segs), expansion(_scaled(segs, **scale))
    assert e.lam == pytest.approx(base.lam, abs=1e-11)
    assert e.lambda_2 == pytest.approx(base.lambda_2, rel=1e-8)
    assert e.K * scale.get("length", 1.0) == pytest.approx(base.K, rel=1e-8)


# ---- a second route: the branch of the full nonlinear discrete problem ---------------


def _branch_point(e, eps: float) -> float:
    """lambda on the bifurcated branch at amplitude eps = K_c w, by Newton's method on the
    full equations A(lambda) w + C[w, w, .] / 2 = 0 of the discrete energy (harmonics 0-3,
    exact in X), with the amplitude of harmonic 1 at the free face prescribed: no
    expansion, no Koiter formula."""
    segs = e.first.space.segments
    harmonics = tuple((f, j) for j in range(4) for f in range(3) if not (f == 0 and j == 0))
    forms = Forms.build(Space(segs, harmonics, x_points=16))
    layout, n = forms.space._layout
    w = np.zeros(n)
    one = dict(zip(harmonics, layout))
    mode_layout = e.first.space._layout[0]
    for f in range(3):
        w[one[(f, 1)]] = eps * e.phi[mode_layout[f]]
    for (f, j), sl in zip(e.second.space.harmonics, e.second.space._layout[0]):
        w[one[(f, j)]] = eps**2 * e.psi[sl]
    top = one[(1, 1)].stop - 1
    lam, K = e.lam, e.K
    for _ in range(30):
        fw = forms.fields(w, K)
        R = forms.stiffness(K, lam) @ w + 0.5 * forms.cubic_gradient(fw, fw, K)
        J = np.zeros((n + 1, n + 1))
        J[:n, :n] = forms.stiffness(K, lam) + forms.cubic_hessian(fw, K)
        J[:n, n] = forms.stiffness(K, lam, wrt="lambda") @ w
        J[n, top] = K
        rhs = np.concatenate([R, [K * w[top] - eps]])
        step = np.linalg.solve(J, rhs)
        w -= step[:n]
        lam -= step[n]
        if abs(step[n]) < 1e-15 and np.abs(step[:n]).max() < 1e-13:
            break
    return lam


@pytest.mark.parametrize("ratio", [1.3, pytest.param(3.0, marks=pytest.mark.slow)])
def test_branch_curvature_from_a_direct_nonlinear_solve(ratio):
    """(lambda(eps) - lambda_c) / eps^2 of the Newton branch, Richardson-extrapolated in
    eps^2, equals lambda_2 of the expansion: sub- (1.3) and supercritical (3.0)."""
    e = expansion(FilmOnHalfSpace(ratio, **COARSE).segments())
    eps = 0.004
    d1, d2 = (_branch_point(e, a) - e.lam for a in (eps, 2 * eps))
    curvature = (16 * d1 - d2) / (12 * eps**2)
    assert curvature == pytest.approx(e.lambda_2, rel=1e-4)
    assert np.sign(e.lambda_2) == (1 if ratio < 1.75 else -1)


# ---- what is not covered raises one line ---------------------------------------------


def test_uncovered_cases_raise_one_line():
    with pytest.raises(ParameterError, match="flat film on a half-space"):
        koiter_coefficient("film")
    with pytest.raises(ParameterError, match="prismatic modes"):
        koiter_coefficient(Tube.uniform(1.5, 1.0, 1.0, 1.0, 0.0))
    with pytest.raises(ParameterError, match="axisymmetric modes"):
        koiter_coefficient(Tube.uniform(1.5, 1.0, 1.0, 1.0, 0.0), mode=(1, 0), control="growth")
    with pytest.raises(ParameterError, match="covers growth, voltage, stretch, pressure"):
        koiter_coefficient(Tube.uniform(1.5, 1.0, 1.0, 1.0, 0.0), mode=(4, 0), control="force")
    with pytest.raises(ParameterError, match="axial stretch prescribed under a voltage"):
        koiter_coefficient(
            dataclasses.replace(_film_tube(0.1), stretch=None, axial_force=0.0, voltage=0.1),
            (12, 0),
            THETA,
        )
    with pytest.raises(ParameterError, match="only the critical wrinkle"):
        koiter_coefficient(FilmOnHalfSpace(3.0, **FAST), mode=(4, 0))
    with pytest.raises(ParameterError, match="modulus_ratio"):
        FilmOnHalfSpace(-1.0)
    with pytest.raises(ParameterError, match="substrate"):
        FilmOnHalfSpace(2.0, substrate="glued")
    with pytest.raises(ParameterError, match="segment"):
        Segment(1.0, 0.0, 1.0)


def test_soft_film_has_no_finite_critical_wavenumber():
    with pytest.raises(NoBifurcationFound, match="no maximum"):
        critical_mode(FilmOnHalfSpace(0.8, **FAST))


# ---- the tube's prismatic family: what is verified so far -----------------------------

THETA = "growth[1].theta"


def _film_tube(h: float, mu_s: float = 0.2, outer: float = 2.0) -> Tube:
    """A film [1, 1 + h] (mu = 1, hoop growth) bonded inside a substrate to ``outer``."""
    return Tube(
        [Layer(1 + h, shear_modulus=1.0, growth=(1, 1.0, 1)), Layer(outer, shear_modulus=mu_s)],
        length=1.0,
        stretch=1.0,
    )


def test_tube_energy_is_singular_at_the_impedance_critical_value():
    """The polar energy's A(g) (incremental/polar_forms.py, Chebyshev nodes, exact
    quadrature) is singular where the package's impedance route (Stroh/Riccati, an
    independent formulation) puts the critical hoop growth of mode (12, 0)."""
    e = tube_expansion(_film_tube(0.1), 12, THETA, nodes=16)
    assert e.control_value == pytest.approx(e.impedance_value, rel=1e-10)


@pytest.mark.slow
def test_thin_film_tube_tends_to_the_flat_coefficient():
    """g = g_c + g_2 eps_t^2 against the flat film alone compressed (mu_f / mu_s = 5):
    lambda = r_i / g and eps_flat = K_f w = (m / g) w give g_2 -> -lambda_2 m^2 as h -> 0,
    with w the same amplitude in both: the free face's (the tube's eps_t is the peak of
    u_r, inside the film: 0.925 of it at the face). Measured g_2 / (m f)^2 = 0.224728
    (h = 0.004, m = 198), 0.226961 (0.002, 394), linear extrapolation 0.229195 against the
    flat 0.229868 (the integer m is off the flat optimum by 1.4 % in K)."""
    flat = koiter_coefficient(FilmOnHalfSpace(5.0, substrate="unstressed", **FAST))
    values = []
    for h, m in ((0.004, 198), (0.002, 394)):
        e = tube_expansion(_film_tube(h, outer=3.0), m, THETA, nodes=16)
        values.append(e.coefficient / (m * e.inner_face) ** 2)
    assert values[0] < values[1] < -flat.coefficient
    assert 2 * values[1] - values[0] == pytest.approx(-flat.coefficient, rel=5e-3)


def test_tube_result_record():
    """koiter_coefficient on a tube: the film [1, 1.1] in a substrate to 2 (mu 0.2), hoop
    growth, mode (12, 0): supercritical (the branch continues as the film grows); 18 and 24
    points a segment agree to 1e-6 (measured 1e-9: g_2 = 8.878947141 at 24, 8.8789470541
    at 16, 8.878947146 at 32)."""
    r = koiter_coefficient(_film_tube(0.1), (12, 0), THETA)
    assert r.branch == "supercritical" and r.coefficient > 0
    assert r.wavenumber == 12 and r.critical_value == pytest.approx(1.674022279, rel=1e-9)
    assert r.error_estimate < 1e-6 * r.coefficient


@pytest.mark.slow
def test_tube_branch_curvature_from_a_direct_nonlinear_solve():
    """The tube's expansion against Newton's method on the full polar equations
    (harmonics 0-3, the control unknown, u_r of harmonic 1 prescribed at the mode's
    largest node): the same g_2 to 1e-6 (measured 8.8789471395 against 8.8789470543)."""
    from electrogrowth.basestate.tube import solve_base_state
    from electrogrowth.bifurcation.koiter_film import _nearest_zero
    from electrogrowth.incremental.polar_forms import PolarForms, rings

    tube, m, N = _film_tube(0.1), 12, 16
    e = tube_expansion(tube, m, THETA, nodes=N)
    harmonics = ((0, 0), (2, 0)) + tuple((f, j) for j in (1, 2, 3) for f in range(3))
    full = PolarForms.build(rings(tube, m, N), m, harmonics)
    first = PolarForms.build(rings(tube, m, N), m, MODE)
    one = dict(zip(harmonics, full.slices))
    phi = _nearest_zero(first.stiffness(solve_base_state(tube.at(THETA, e.control_value))))[1]
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    row = peak_row(first.rings, phi[first.slices[0]], one[(0, 1)].start, full.size)
    peak = row[one[(0, 1)]] @ phi[first.slices[0]]  # the mode's u_r at that node

    def stiffness(c):
        return full.stiffness(solve_base_state(tube.at(THETA, c)))

    def branch(eps):
        w = np.zeros(full.size)
        for f, sl in zip(range(3), first.slices):
            w[one[(f, 1)]] = eps * phi[sl]
        c, n = e.control_value, full.size
        for _ in range(30):
            A, fw = stiffness(c), full.fields(w)
            h = 1e-3 * c
            dA = (stiffness(c + h) - stiffness(c - h)) / (2 * h)
            J = np.zeros((n + 1, n + 1))
            J[:n, :n] = A + full.cubic_hessian(fw, 1.0)
            J[:n, n] = dA @ w
            J[n, :n] = row
            rhs = np.concatenate(
                [A @ w + 0.5 * full.cubic_gradient(fw, fw, 1.0), [row @ w - eps * peak]]
            )
            step = np.linalg.solve(J, rhs)
            w, c = w - step[:n], c - step[n]
            if abs(step[n]) < 1e-14:
                break
        return c

    eps = 0.002
    d1, d2 = (branch(x) - e.control_value for x in (eps, 2 * eps))
    assert (16 * d1 - d2) / (12 * eps**2) == pytest.approx(e.coefficient, rel=1e-6)
