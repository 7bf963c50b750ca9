"""The crease criterion (bifurcation/crease.py, docs/derivation-crease.md).

Checks, each against something independent: the published onset strains of a neo-Hookean
half-space from the ratios (Hong, Zhao & Suo 2009; Cao & Hutchinson 2012; Biot's cubic);
the reduction of a three-dimensional face state to its ratio, by the package's own
half-space solver (Biot's ratio in a state that is not plane strain); the closed forms of
homogeneous tubes under axial compression and under growth; the electro-crease field from
the voltage and the current radii (not from the state's field).
"""

import math

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.crease import (
    BIOT_RATIO,
    CREASE_FIELD,
    CREASE_RATIO,
    FaceCrease,
    biot_ratio,
    crease_onset,
    criterion_text,
    face_creases,
    onset_strain,
    ratio_is_exact,
)
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.errors import ParameterError
from electrogrowth.model.layer import Layer
from electrogrowth.model.layers import Tube as LayeredTube
from electrogrowth.model.materials import Material, gent, mooney_rivlin, neo_hookean
from electrogrowth.outcomes import Kind


def test_the_ratio_gives_the_published_onset_strain():
    # Hong, Zhao & Suo (2009): 0.35 in plane strain; Cao & Hutchinson (2012): 0.354
    assert onset_strain() == pytest.approx(0.354, abs=1e-3)
    assert onset_strain() == pytest.approx(0.35, abs=5e-3)
    assert CREASE_RATIO < BIOT_RATIO  # creases come before Biot's wrinkles


def test_biot_ratio_is_the_root_of_biots_cubic():
    roots = np.roots([1.0, 1.0, 3.0, -1.0])  # x^3 + x^2 + 3x - 1 = 0, x = lambda_s / lambda_n
    x = float(next(r.real for r in roots if abs(r.imag) < 1e-12))
    assert 1 / x == pytest.approx(BIOT_RATIO, rel=1e-10)
    assert onset_strain(BIOT_RATIO) == pytest.approx(0.456, abs=5e-4)  # Biot (1963)


def test_the_out_of_plane_stretch_drops_out_by_the_half_space_solver():
    """An axially compressed tube has lambda_theta = lambda_r, not 1 (no plane strain): the
    reduction says its faces wrinkle at lambda_r / lambda_z = Biot's ratio, lambda_z =
    3.383^(-2/3); the half-space solver (surface.py) knows nothing of that argument."""
    s = short_wave_limit(Tube.uniform(2.0, length=1.0), "stretch", side="compression")
    assert s.kind == "surface" and s.psi == pytest.approx(math.pi / 2)
    assert s.value == pytest.approx(BIOT_RATIO ** (-2 / 3), rel=1e-12)


@pytest.mark.parametrize("outer_radius", [1.6, 1.8, 2.0])
def test_axial_compression_creases_at_the_closed_form(outer_radius):
    c = crease_onset(Tube.uniform(outer_radius, length=1.0), "stretch", side="compression")
    # homogeneous: lambda_r = lambda_z^(-1/2), so lambda_r / lambda_z = lambda_z^(-3/2) = 2.4
    assert c.kind == "crease" and c.trigger == "axial" and c.face in ("inner", "outer")
    assert c.value == pytest.approx(CREASE_RATIO ** (-2 / 3), rel=1e-12)
    # the criterion's accuracy (2.4 +- 0.03) moves lambda_z by (2/3) lambda_z 0.03 / 2.4
    assert c.error_estimate == pytest.approx(2 / 3 * c.value * 0.03 / 2.4, rel=1e-3)


def test_growth_at_fixed_length_creases_at_the_closed_form():
    # lambda_z = 1, isotropic growth g: elastic lambda_z = 1/g, lambda_r = g^(1/2)
    c = crease_onset(Tube.uniform(1.4, length=1.0, stretch=1.0), "growth")
    assert c.kind == "crease" and c.trigger == "axial"
    assert c.value == pytest.approx(CREASE_RATIO ** (2 / 3), rel=1e-12)


def test_extension_never_creases():
    c = crease_onset(Tube.uniform(2.0), "stretch", side="extension")
    assert c.kind == "none" and math.isnan(c.value)


def test_hoop_growth_of_a_layer_creases_prismatically():
    """Hoop growth of the inner layer compresses it along theta: a prismatic crease at the
    inner face, where lambda_r / lambda_theta (read off the radii) reaches 2.4."""
    tube = LayeredTube(
        layers=(Layer(1.5, growth=(1.0, 1.0, 1.0)), Layer(3.0, shear_modulus=10.0)), stretch=1.0
    )
    c = crease_onset(tube, "growth[1].theta")
    assert c.kind == "crease" and (c.face, c.trigger) == ("inner", "prismatic")
    state = solve_base_state(c.params)
    l_theta = state.r_i / c.value  # r / (g_theta R) at R = 1
    l_r = 1.0 / (l_theta * state.stretch)  # incompressible, g_r = g_z = 1
    assert l_r / l_theta == pytest.approx(CREASE_RATIO, rel=1e-10)


def test_the_field_trigger_is_the_published_field_on_an_unstretched_face():
    assert FaceCrease("outer", 1.0, 1.0, CREASE_FIELD).margin == pytest.approx(0.0, abs=1e-15)
    assert FaceCrease("outer", 1.0, 1.0, -0.99 * CREASE_FIELD).margin < 0
    assert FaceCrease("outer", 1.0, 1.0, 1.01 * CREASE_FIELD).trigger == "field"


def test_the_voltage_creases_the_inner_face_at_the_field_from_the_potential():
    """E_r = c / r and V = c ln(r_o / r_i) (ideal dielectric, eps = 1): the inner face's
    field is V / (r_i ln(r_o / r_i)), V = Vbar (Rbar_o - 1); at the onset it is 1.03."""
    c = crease_onset(Tube.uniform(1.4, length=1.0), "voltage")
    assert c.kind == "crease" and (c.face, c.trigger) == ("inner", "field")
    s = solve_base_state(c.params)
    field = c.value * (1.4 - 1.0) / (s.r_i * math.log(s.r_o / s.r_i))
    assert field == pytest.approx(CREASE_FIELD, rel=1e-10)


def test_the_field_is_measured_in_the_face_layers_own_units():
    """A face layer of modulus 4 and permittivity 1: E sqrt(eps_k / mu_k) = E / 2."""
    tube = LayeredTube(
        layers=(Layer(1.2, shear_modulus=4.0), Layer(1.6)), stretch=1.0, voltage=0.3
    )
    state = solve_base_state(tube)
    inner, outer = face_creases(state)
    assert inner.field == pytest.approx(float(state.electric_field(1.0)) / 2, rel=1e-14)
    assert outer.field == pytest.approx(float(state.electric_field(1.6, side="inner")), rel=1e-14)


def test_the_criterion_says_when_it_is_not_the_energys_own():
    assert ratio_is_exact(neo_hookean()) and ratio_is_exact(mooney_rivlin(0.3))
    assert not ratio_is_exact(gent(20.0))
    text = criterion_text(Tube.uniform(1.4, material=gent(20.0)))
    assert "applied to gent(jm=20) (its Biot ratio 3.577 against 3.383, +5.7 %)" in text
    assert "not that energy's own" in text
    assert "applied" not in criterion_text(Tube.uniform(1.4))


def test_energies_linear_in_i1_and_i2_have_biots_ratio_along_the_axis():
    """The reduction of docs/derivation-crease.md section 2 for Mooney-Rivlin, by the
    half-space solver: waves along z at neo-Hookean's ratio (alpha = 0.3 wrinkles first
    obliquely, which the principal-direction ratio leaves out); Gent's own ratio is larger
    (it stiffens), and one that stiffens steeply has none."""
    assert biot_ratio(mooney_rivlin(0.3)) == pytest.approx(BIOT_RATIO, rel=1e-12)
    assert BIOT_RATIO < biot_ratio(gent(97.2)) < 1.02 * BIOT_RATIO
    assert biot_ratio(gent(5.0)) == math.inf


def test_the_criterion_is_exact_for_a_linear_energy_of_any_modulus_and_permittivity():
    """W(I1, I2) + c I5, linear in I1 and I2, is a neo-Hookean (Mooney-Rivlin) ideal
    dielectric whatever its moduli (check_units=False keeps them); anything else in the
    field (I4, I6, I5 squared, I5 times I1) or in the strain (Gent, I1 squared) is not."""
    exact = ("(I1 - 3)/2 + 3*I5/2", "10*((I1 - 3)/2) + I5/2", "0.3*(I1 - 3) + 0.2*(I2 - 3) + I5")
    other = (
        "(I1 - 3)/2 + I5/2 + I6/10",
        "(I1 - 3)/2 + I5/2 + I4/5",
        "(I1 - 3)/2 + I5/2 + I5**2/10",
        "(I1 - 3)/2 + I5/2 + (I1 - 3)*I5/10",
        "(I1 - 3)/2 + (I1 - 3)**2/10 + I5/2",
        "(I1 - 3)/2 + exp(I5)/2 - 1/2",
    )
    assert all(ratio_is_exact(Material(t, t, check_units=False)) for t in exact)
    assert not any(ratio_is_exact(Material(t, t, check_units=False)) for t in other)


def test_a_gent_crease_carries_its_energys_distance_from_neo_hookean():
    """The neo-Hookean criterion applied to a Gent face is off by about as much as Gent's own
    Biot ratio is from neo-Hookean's (docs/derivation-crease.md section 2): its error estimate
    carries that shift (+5.7 % at J_m = 20), not the criterion's published digits alone; a
    Gent solid with no Biot wrinkle (J_m = 3) may not crease at all, and says so."""
    from electrogrowth.bifurcation.crease import (
        BIOT_RATIO,
        CREASE_RATIO,
        CREASE_RATIO_ACCURACY,
        biot_ratio,
    )
    from electrogrowth.outcomes import Status

    onset = lambda material: crease_onset(  # noqa: E731
        Tube.uniform(2.0, length=1.0, material=material), "stretch", side="compression"
    )
    nh, g20, g3 = onset(None), onset(gent(20.0)), onset(gent(3.0))
    # a homogeneous compression: the same stretches, the same onset and margin slope
    assert g20.value == pytest.approx(nh.value, rel=1e-14)
    digits = CREASE_RATIO_ACCURACY / CREASE_RATIO
    shift = biot_ratio(gent(20.0)) / BIOT_RATIO - 1.0
    assert 0.05 < shift < 0.06
    assert g20.error_estimate / nh.error_estimate == pytest.approx((shift + digits) / digits)
    assert (nh.status, g20.status) == (Status.OK, Status.OK)
    assert g3.error_estimate == math.inf and g3.status == Status.INACCURATE
    assert "may not crease" in g3.message


def test_a_tie_goes_to_the_face_whose_criterion_is_exact():
    """An ungrown Gent core in a neo-Hookean sheath compressed axially: both faces reach the
    crease ratio at once (lambda_z = 0.5578607917, ratio 2.4 through the whole wall). The
    Gent face "may not crease" (no Biot ratio), the neo-Hookean one creases there: the onset
    is the outer face's, status ok (it reported the inner face, INACCURATE, probe 7a)."""
    from electrogrowth import Layer
    from electrogrowth.model.materials import gent

    tube = Tube((Layer(1.5, material=gent(3.0)), Layer(2.5, shear_modulus=0.3)), length=0.5)
    c = crease_onset(tube, "stretch", side="compression")
    assert c.face == "outer" and c.status == "ok" and math.isfinite(c.error_estimate)
    margins = {
        f.face: f.margin for f in face_creases(solve_base_state(tube.at("stretch", c.value)))
    }
    assert margins["inner"] == pytest.approx(margins["outer"], abs=1e-12)  # the tie
    assert c.value == pytest.approx(1 / CREASE_RATIO ** (2 / 3), rel=1e-9)


def _outer_axial_ratio(tube, g):
    """lambda_r / lambda_z of the outer face at growth g, from the base state directly."""
    s = solve_base_state(tube.at("growth", g))
    lr, _, lz = (float(v) for v in s.elastic_stretches(tube.outer_radius, side="inner"))
    return lr / lz


def test_a_field_crease_at_the_start_does_not_hide_the_mechanical_one():
    """Probe 8b D1: with Vbar = 0.75 the inner face is past the (advisory) field criterion
    where the growth march starts, g = 1; the march stopped there and no mechanical onset
    was computed, although the outer face reaches lambda_r / lambda_z = 2.4 at g = 1.80202
    (Brent on the base state's stretches). The mechanical criteria are now marched on their
    own beside it (``mechanical``, ``ranked``)."""
    from scipy.optimize import brentq

    tube = Tube.uniform(1.8, length=1.0, voltage=0.75)
    exact = brentq(lambda g: _outer_axial_ratio(tube, g) - CREASE_RATIO, 1.5, 1.89, xtol=1e-13)
    c = crease_onset(tube, "growth")
    assert (c.kind, c.trigger, c.value) == ("crease", "field", 1.0)
    m = c.mechanical
    assert m is c.ranked and (m.kind, m.face, m.trigger) == ("crease", "outer", "axial")
    assert m.value == pytest.approx(exact, rel=1e-10)
    assert m.mechanical is None and c.as_dict()["mechanical"]["value"] == m.value
    # a mechanical onset first needs no second march: it is its own ranked onset
    plain = crease_onset(Tube.uniform(1.8, length=1.0, voltage=0.7), "growth")
    assert plain.trigger == "axial" and plain.ranked is plain


def _march_with(monkeypatch, fail):
    """crease_onset of axial compression of the paper's tube with the base state at the
    stretches ``fail`` picks raising its error instead; the march's solved stretches."""
    from electrogrowth.bifurcation import along

    solved = []

    def state(tube, **kw):
        err = fail(tube.stretch)
        if err is not None:
            raise err
        solved.append(tube.stretch)
        return solve_base_state(tube, **kw)

    monkeypatch.setattr(along, "solve_base_state", state)  # the march's states (TubeAt)
    return lambda: crease_onset(
        Tube.uniform(2.0, length=1.0), "stretch", side="compression"
    ), solved


def test_an_unresolved_state_is_not_the_loss_of_the_state(monkeypatch):
    """Probe 11a D2: a ConvergenceError (a state that exists but is not resolved) was bisected
    as the loss of the axisymmetric state: a Fung bilayer's verdict said "next: the loss of
    the axisymmetric state at growth[1].theta = 3.026" where states past it solve. The march
    ends as not resolved instead, with no threshold."""
    from electrogrowth.errors import ConvergenceError

    onset, _ = _march_with(
        monkeypatch, lambda lz: ConvergenceError("not resolved") if lz < 0.8 else None
    )
    with pytest.raises(
        ConvergenceError, match=r"no crease for stretch from 1 up to .* is not resolved"
    ):
        onset()


def test_the_loss_is_bisected_over_unresolved_states_as_existing(monkeypatch):
    """Only a failed state search (BaseStateError) is a loss: a state between the last solved
    one and the lost one that is not resolved exists, and the edge is past it. Unresolved
    states alternating with solved ones had moved the bisected edge onto themselves."""
    from electrogrowth.errors import BaseStateError, ConvergenceError

    onset, solved = _march_with(monkeypatch, lambda lz: None)
    onset()
    x_ok, x_lost = solved[1], solved[2]  # two successive steps of the march
    gap = (x_lost - x_ok) * np.array([0.3, 0.7])  # around the bisection's first midpoint

    def fail(lz):
        if (lz - x_lost) * (x_lost - x_ok) >= 0:
            return BaseStateError("no state")
        if min(x_ok + gap) < lz < max(x_ok + gap):
            return ConvergenceError("not resolved")
        return None

    onset, _ = _march_with(monkeypatch, fail)
    c = onset()
    assert c.kind == "none" and c.threshold == pytest.approx(x_lost, abs=1e-6)


def test_a_march_until_a_rival_stops_there(monkeypatch):
    """``until`` (a design's nearest rival): no state is solved past it, the onset past it
    is NONE, and an onset before it is the whole march's."""
    from electrogrowth.bifurcation import along

    tube = Tube.uniform(2.0, length=1.0)
    full = crease_onset(tube, "stretch", side="compression")
    solved = []

    def state(t, **kw):
        solved.append(t.stretch)
        return solve_base_state(t, **kw)

    monkeypatch.setattr(along, "solve_base_state", state)
    early = crease_onset(tube, "stretch", side="compression", until=full.value + 0.01)
    assert early.kind == Kind.NONE and min(solved) >= full.value + 0.01
    assert early.message == f"none before {full.value + 0.01:.12g}" and full.message == ""
    late = crease_onset(tube, "stretch", side="compression", until=full.value - 0.01)
    assert late.kind == Kind.CREASE and late.trigger == full.trigger
    assert late.value == pytest.approx(full.value, rel=1e-12, abs=0)
    assert crease_onset(tube, "stretch", side="compression", until=1.5).kind == Kind.NONE
    with pytest.raises(ParameterError, match="until = nan must be a finite value"):
        crease_onset(tube, "stretch", side="compression", until=math.nan)
