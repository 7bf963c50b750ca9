"""The crease at a bonded interface (bifurcation/crease_interface.py, crease.py;
docs/derivation-crease.md section 8).

Checks with exact answers: a neighbour of vanishing modulus turns the interface into the
free face of the stiffer layer (its state, its onset, the closed form of a homogeneous
layer, the free face's error estimate); two identical layers have no interface to crease;
the onset depends on the moduli only through their ratio; Biot's interfacial wrinkle, the
linear analogue that measures the neighbour's delay, tends to the free face's ratio and
rises linearly with the neighbour's modulus. Then the interface as a competitor: first or
not in a layered tube as the derivation says, in the verdict and `critical --json`, along
a curve, and in the design's crease value and its sensitivity (two routes).
"""

import json
import math

import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.crease import (
    BIOT_RATIO,
    CREASE_RATIO,
    crease_onset,
    criterion_text,
    face_creases,
    neighbour_delay,
)
from electrogrowth.bifurcation.crease_interface import (
    SOFT_NEIGHBOUR,
    interfaces,
    interfacial_biot_ratio,
)
from electrogrowth.bifurcation.curve_crease import crease_along
from electrogrowth.bifurcation.verdict import crease_rival, judge
from electrogrowth.cli.app import main
from electrogrowth.design.onset import crease_sensitivities, crease_value
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.sweep.unit import verdict_fields

#: a homogeneous layer growing axially at fixed length creases where
#: lambda_r / lambda_z = g^(3/2) = 2.4 (test_crease.py, the free faces' closed form)
CLOSED_FORM = CREASE_RATIO ** (2 / 3)


def sandwich(soft: float, scale: float = 1.0, outer: float | None = None) -> Tube:
    """A stiff middle layer between two ungrown layers ``soft`` times as stiff (the third
    ``outer`` times): its free faces never crease under the middle layer's axial growth."""
    outer = soft if outer is None else outer
    return Tube(
        (
            Layer(1.2, shear_modulus=soft * scale),
            Layer(1.6, shear_modulus=scale),
            Layer(2.0, shear_modulus=outer * scale),
        ),
        stretch=1.0,
        length=1.0,
    )


def test_only_an_interface_to_a_much_softer_layer_is_a_candidate():
    stiff_inside = Tube((Layer(1.5, shear_modulus=10.0), Layer(2.0)), stretch=1.0)
    (i,) = interfaces(stiff_inside)
    assert (i.name, i.layer, i.side, i.neighbour, i.radius) == (
        "interface-1",
        1,
        "inner",
        0.1,
        1.5,
    )
    assert i.label == "interface 1|2 (R = 1.5), layer 1 folds"
    stiff_outside = Tube((Layer(1.5, shear_modulus=0.05), Layer(2.0)), stretch=1.0)
    (o,) = interfaces(stiff_outside)
    assert (o.layer, o.side, o.neighbour) == (2, "outer", 0.05)
    assert SOFT_NEIGHBOUR == 0.1
    assert interfaces(Tube((Layer(1.5, shear_modulus=1 / 0.11), Layer(2.0)))) == ()


def test_two_identical_layers_never_crease_at_their_interface():
    """One solid cut in three: no interface, and the middle layer's growth creases nothing
    (the free faces belong to ungrown layers, not compressed along their faces)."""
    tube = sandwich(1.0)
    assert interfaces(tube) == ()
    assert [f.face for f in face_creases(solve_base_state(tube))] == ["inner", "outer"]
    c = crease_onset(tube, "growth[2].z")
    assert c.kind == "none" and math.isnan(c.value)


def test_a_vanishing_neighbour_makes_the_interface_a_free_face():
    """The stiff layer's state with a neighbour 1e-8 times as stiff (the least supported
    ratio) is that of the same layer alone (a tube of its own, radii scaled by 1/1.5); the
    interface's drives are the lone layer's inner face's, under non-uniform (hoop) growth."""
    bonded = Tube((Layer(1.5, shear_modulus=1e-8), Layer(2.0)), stretch=1.0)
    alone = Tube((Layer(2.0 / 1.5),), stretch=1.0)
    s_bonded = solve_base_state(bonded.at("growth[2].theta", 1.3))
    s_alone = solve_base_state(alone.at("growth[1].theta", 1.3))
    f = next(f for f in face_creases(s_bonded) if f.face == "interface-1")
    inner = next(f for f in face_creases(s_alone) if f.face == "inner")
    assert f.hoop == pytest.approx(inner.hoop, rel=1e-7)
    assert f.axial == pytest.approx(inner.axial, rel=1e-7)
    assert f.field == 0.0 and f.neighbour == 1e-8


def test_a_vanishing_neighbour_gives_the_free_faces_onset_and_accuracy():
    c = crease_onset(sandwich(1e-6), "growth[2].z")
    assert c.kind == "crease" and c.face.startswith("interface-") and c.trigger == "axial"
    assert c.value == pytest.approx(CLOSED_FORM, rel=1e-6)
    # the free face's error estimate, (2/3) g 0.03 / 2.4 (test_crease.py), plus a delay ~1e-6
    assert c.error_estimate == pytest.approx(2 / 3 * c.value * 0.03 / 2.4, rel=1e-3)
    assert "layer 2 folds" in c.label and c.label.startswith("interface ")


def test_only_the_ratio_of_the_moduli_matters():
    a = crease_onset(sandwich(0.01), "growth[2].z")
    b = crease_onset(sandwich(0.01, scale=7.0), "growth[2].z")
    assert (
        (a.kind, a.face, a.trigger) == (b.kind, b.face, b.trigger) == ("crease", a.face, "axial")
    )
    assert b.value == pytest.approx(a.value, rel=1e-9)
    assert b.error_estimate == pytest.approx(a.error_estimate, rel=1e-6)


#: a core of modulus 0.1 in a sheath of 1, every modulus scaled by c in 0.7, 1.3, 10, 1e-3
#: (written as decimals, as a user would: 0.07 / 0.7 = 0.10000000000000002)
SCALED_PAIRS = [(0.07, 0.7), (0.13, 1.3), (1.0, 10.0), (1e-4, 1e-3)]


@pytest.mark.parametrize("soft, stiff", SCALED_PAIRS)
def test_a_neighbour_on_the_threshold_is_one_at_any_unit_of_the_moduli(soft, stiff):
    """Probe 8b D10: the tube (0.07 | 0.7) is (0.1 | 1.0) in other units, yet it creased at
    g_z = 1.77971 on the outer face where (0.1 | 1.0) creases at 1.76956 at interface-1:
    ``ratio <= SOFT_NEIGHBOUR`` was compared exactly, and 0.07 / 0.7 rounds above 0.1. The
    comparison is now relative (SOFT_NEIGHBOUR_RTOL); the onset, face and trigger are the
    unscaled tube's (the README's mucosa, 10 | 1, sits on the threshold too)."""

    def onset(a: float, b: float):
        tube = Tube((Layer(1.5, shear_modulus=a), Layer(2.0, shear_modulus=b)), stretch=1.0)
        return crease_onset(tube, "growth[2].z")

    ref, c = onset(0.1, 1.0), onset(soft, stiff)
    assert (ref.kind, ref.face) == ("crease", "interface-1")
    assert (c.kind, c.face, c.trigger) == (ref.kind, ref.face, ref.trigger)
    assert c.value == pytest.approx(ref.value, rel=1e-9)
    mucosa = Tube((Layer(1.1, shear_modulus=10.0 * stiff), Layer(2.0, shear_modulus=stiff)))
    assert [i.name for i in interfaces(mucosa)] == ["interface-1"]


def test_the_linear_analogue_starts_at_the_free_face_and_rises_linearly():
    """Biot's interfacial wrinkle by the half-space solver: the free face's ratio 3.383 as
    the neighbour vanishes, a delay linear in its modulus at first (first-order
    perturbation), growing without bound towards one solid."""
    assert interfacial_biot_ratio(1e-5) == pytest.approx(BIOT_RATIO, rel=1e-4)
    d1, d2 = neighbour_delay(1e-3), neighbour_delay(2e-3)
    assert d2 / d1 == pytest.approx(2.0, rel=0.02)
    assert 0 < neighbour_delay(0.01) < neighbour_delay(0.1) < neighbour_delay(0.5)
    assert neighbour_delay(0.0) == 0.0


def test_the_error_estimate_carries_the_neighbours_delay():
    """A nearly homogeneous middle layer: h = g^(3/2) / 2.4 - 1, so the estimate is
    (2/3) g (0.03 / 2.4 + delay) (section 4 with the delay added)."""
    c = crease_onset(sandwich(0.01), "growth[2].z")
    expected = 2 / 3 * c.value * (0.03 / 2.4 + neighbour_delay(0.01))
    assert c.error_estimate == pytest.approx(expected, rel=1e-2)
    assert c.error_estimate > 2 * (2 / 3 * c.value * 0.03 / 2.4)  # the delay dominates


def test_the_interface_creases_first_only_next_to_a_much_softer_layer():
    """The middle layer's growth compresses its own faces, which are interfaces: with
    neighbours a hundred times softer they crease near the closed form; with neighbours
    five times softer the interfaces are no candidates and nothing creases."""
    c = crease_onset(sandwich(0.01), "growth[2].z")
    assert c.kind == "crease" and c.face in ("interface-1", "interface-2")
    assert abs(c.value - CLOSED_FORM) < c.error_estimate
    assert "interface 1|2 (R = 1.2), layer 2 folds" in c.criterion
    assert crease_onset(sandwich(0.2), "growth[2].z").kind == "none"
    assert "interface" not in criterion_text(sandwich(0.2))


THICK = """
stretch = 1.0
length = 0.5

[[layers]]
outer_radius = 1.2
shear_modulus = 0.001

[[layers]]
outer_radius = 3.0
shear_modulus = 1.0

[[layers]]
outer_radius = 3.2
shear_modulus = 0.001
"""


def test_cli_json_reports_the_interface_crease_first(tmp_path, capsys):
    """A thick stiff layer between two much softer ones, short (L = 0.5): its interfaces
    crease (g = 2.4^(2/3)) before the axisymmetric wrinkle (0, 1) (g = 2.23, the linear
    analysis); the record says where, which layer folds, and the verdict."""
    path = tmp_path / "thick.toml"
    path.write_text(THICK)
    args = ["critical", "--tube", str(path), "--solve-for", "growth", "--layer", "2"]
    assert main([*args, "--component", "z", "--mode", "0", "1", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    crease = rec["crease"]
    assert rec["verdict"] == "crease" and rec["verdict_face"] == crease["face"]
    assert crease["face"] in ("interface-1", "interface-2") and crease["trigger"] == "axial"
    assert "layer 2 folds" in crease["detail"]
    assert abs(crease["value"] - CLOSED_FORM) < crease["error_estimate"]
    assert rec["wrinkle"]["value"] > crease["value"] + crease["error_estimate"]
    assert rec["meaning"].startswith("the tube creases at interface ")
    assert main([*args, "--component", "z", "--mode", "0", "1"]) == 0
    text = capsys.readouterr().out
    assert "crease: interface " in text and "layer 2 folds" in text


def test_a_curve_row_creases_at_the_interface_while_the_neighbour_is_much_softer():
    """Along the inner neighbour's modulus: an interface crease at 0.001 and 0.05, none
    at 0.2 (no candidate; the outer neighbour, half as stiff, is none either)."""
    tube = sandwich(0.001, outer=0.5)
    x = [0.001, 0.05, 0.2]
    along = crease_along(tube, "growth[2].z", "layers[1].shear_modulus", None, x, [2.0] * 3)
    assert along.face == ("interface-1", "interface-1", "")
    assert along.first.tolist() == [True, True, False]
    first = crease_onset(tube.at("layers[1].shear_modulus", 0.001), "growth[2].z")
    assert along.value[0] == first.value and along.error[0] == first.error_estimate
    assert math.isnan(along.value[2])


def test_the_designs_crease_value_and_its_sensitivity_see_the_interface():
    """design/onset.py: the crease value is the onset's; its derivative with respect to
    the neighbour's modulus by implicit differentiation equals a central difference of
    two onsets (Brent roots)."""
    tube = sandwich(0.05, outer=0.5)
    onset = crease_onset(tube, "growth[2].z")
    v = crease_value(tube, "growth[2].z", None, 1.0)
    assert onset.face == "interface-1" and v == onset.value
    key, h = "layers[1].shear_modulus", 1e-3
    d = crease_sensitivities(tube, "growth[2].z", v, (key,))[key]
    up = crease_onset(tube.at(key, 0.05 + h), "growth[2].z").value
    down = crease_onset(tube.at(key, 0.05 - h), "growth[2].z").value
    assert d == pytest.approx((up - down) / (2 * h), rel=1e-4)
    assert d < 0  # a stiffer neighbour holds the layer: its face compresses sooner


def test_a_sweep_point_stores_the_interface_crease():
    """sweep/unit.py's verdict fields, from the verdict of the interface crease."""
    onset = crease_onset(sandwich(0.01), "growth[2].z")
    fields = verdict_fields(judge(None, crease=crease_rival(onset), name="g"))
    assert fields["verdict"] == "crease" and fields["crease_face"] == onset.face
    assert fields["crease_value"] == onset.value and fields["crease_trigger"] == "axial"
    assert fields["crease_error"] == onset.error_estimate
    assert fields["meaning"].startswith(f"the tube creases at {onset.label} (sharp folds")


def test_the_march_continues_its_layered_states(monkeypatch):
    """The crease march takes each layered state from its last one (basestate/warm.py), not
    from a walk of the loading branches from the unloaded tube: the same onset as the march
    of cold states, with one walk (its start) instead of one per state (a design's margin
    marches the crease at every trial design: 2.4 s -> 0.13 s for the bilayer example)."""
    import inspect

    from electrogrowth.basestate import layered
    from electrogrowth.basestate.tube import solve_base_state
    from electrogrowth.bifurcation.along import TubeAt

    walks = []
    walk = layered._prepare

    def for_the_march() -> bool:  # called for one of the march's own states (its margin's)
        return any(
            f.function == "margin" and f.filename.endswith("crease.py") for f in inspect.stack()
        )

    def counted(*args):
        walks.append(for_the_march())
        return walk(*args)

    monkeypatch.setattr(layered, "_prepare", counted)
    tube = sandwich(0.01)
    warm = crease_onset(tube, "growth[2].z")
    continued, walks[:] = sum(walks), []
    monkeypatch.setattr(TubeAt, "solved", lambda at, x, rtol: solve_base_state(at(x), rtol=rtol))
    cold = crease_onset(tube, "growth[2].z")
    assert (warm.kind, warm.face, warm.trigger) == (cold.kind, cold.face, cold.trigger)
    assert warm.value == pytest.approx(cold.value, rel=1e-10, abs=0)
    assert continued == 1 and sum(walks) >= 15, (continued, sum(walks))
