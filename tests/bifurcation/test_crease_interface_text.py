"""A layer written as an energy text that carries its own modulus is the same layer as the
built-in energy with that shear modulus, for the crease at an interface and for the
field of electro-creasing too.

README: ``check_units=False`` keeps a deliberately scaled energy, "a layer written with its
own moduli"; "0.001*((I1 - 3)/2) + I5/2" is a neo-Hookean layer a thousand times softer,
as ``Layer(..., shear_modulus=0.001)`` is (the loads' scale already reads the modulus off the
energy: model/controls.py ``initial_modulus``, tests/bifurcation/test_pressure_to_lock.py).

The tube is the thick stiff layer between two much softer ones of
test_crease_interface.py (``THICK``, L = 0.5), its middle layer growing axially: its
interfaces crease at g_z = 2.4^(2/3) (docs/derivation-crease.md section 8) before the
axisymmetric wrinkle (0, 1) at 2.2343.

Found by probing: with the soft layers written as energy texts the base state and the
wrinkle are the built-in tube's (g_z,cr of (0, 1) equal to 1e-15), but the crease rule
reads the modulus ratio off ``Layer.shear_modulus`` alone (crease_interface.interfaces:
1 / 1, no candidate), so ``crease_onset`` is "none", the criterion names no interface and
the verdict is the wrinkle (0, 1) at 2.234 instead of the interface crease at 1.792.
"""

import math

import pytest

from electrogrowth import Layer, Material, Tube, crease_onset, critical_value
from electrogrowth.bifurcation.crease import criterion_text

SOFT_TEXT = Material("soft", "0.001*((I1 - 3)/2) + I5/2", check_units=False)
BUILTIN = Tube(
    (Layer(1.2, shear_modulus=0.001), Layer(3.0), Layer(3.2, shear_modulus=0.001)),
    stretch=1.0,
    length=0.5,
)
WRITTEN = Tube(
    (Layer(1.2, material=SOFT_TEXT), Layer(3.0), Layer(3.2, material=SOFT_TEXT)),
    stretch=1.0,
    length=0.5,
)


def test_the_written_soft_layers_are_the_builtin_ones():
    built = critical_value(BUILTIN, 0, 1, "growth[2].z")
    written = critical_value(WRITTEN, 0, 1, "growth[2].z")
    assert written.value == pytest.approx(built.value, rel=1e-10)


def test_the_interface_creases_with_written_soft_layers_too():
    built = crease_onset(BUILTIN, "growth[2].z")
    written = crease_onset(WRITTEN, "growth[2].z")
    assert built.kind == "crease" and built.face in ("interface-1", "interface-2")
    assert written.kind == built.kind and written.face == built.face
    assert written.value == pytest.approx(built.value, rel=1e-10)
    assert written.error_estimate == pytest.approx(built.error_estimate, rel=1e-6)


def test_the_verdict_does_not_depend_on_how_the_modulus_is_written():
    built = critical_value(BUILTIN, 0, 1, "growth[2].z").verdict
    written = critical_value(WRITTEN, 0, 1, "growth[2].z").verdict
    assert built.kind == "crease"
    assert written.kind == built.kind and written.face == built.face
    assert written.value == pytest.approx(built.value, rel=1e-10)


def test_the_electro_crease_field_reads_the_modulus_off_the_energy_too():
    """The field drive E sqrt(eps_k / mu_k) of a face: a one-layer tube ten times as stiff,
    written as a text or as shear_modulus = 10, is one tube (the wrinkle (0, 1) under the
    voltage agrees to 1e-13). Found by probing: the field crease of the text was at
    Vbar = 0.7122 against 2.1483, the field scaled by the layer's shear_modulus (1) instead
    of its energy's modulus (10)."""
    stiff = Material("stiff10", "10*((I1 - 3)/2) + I5/2", check_units=False)
    built = Tube((Layer(2.0, shear_modulus=10.0),), stretch=1.0, length=1.0)
    written = Tube((Layer(2.0, material=stiff),), stretch=1.0, length=1.0)
    assert critical_value(written, 0, 1, "voltage").value == pytest.approx(
        critical_value(built, 0, 1, "voltage").value, rel=1e-10
    )
    b, w = crease_onset(built, "voltage"), crease_onset(written, "voltage")
    assert b.kind == "crease" and b.trigger == "field"
    assert (w.kind, w.face, w.trigger) == (b.kind, b.face, b.trigger)
    assert w.value == pytest.approx(b.value, rel=1e-10)


def test_the_interface_crease_of_the_written_tube_is_the_closed_form():
    """Independently of the built-in tube: the middle layer grows axially in a tube held at
    stretch 1, so its elastic stretches at the interface are (g^(1/2), g^(1/2), 1/g) and the
    axial ratio reaches 2.4 at g_z = 2.4^(2/3) (docs/derivation-crease.md section 8), within
    the criterion's error estimate."""
    written = crease_onset(WRITTEN, "growth[2].z")
    assert written.value == pytest.approx(2.4 ** (2 / 3), abs=written.error_estimate)


def test_the_field_crease_of_a_written_modulus_scales_as_its_square_root():
    """Independently of the built-in layer: the field enters through V sqrt(eps_k / mu_k)
    only (the tube is uniform: the modulus and permittivity scale out of its state), so the
    field crease of a layer ten times as stiff is sqrt(10) times the unit layer's Vbar."""
    stiff = Material("stiff10", "10*((I1 - 3)/2) + I5/2", check_units=False)
    unit = crease_onset(Tube((Layer(2.0),), stretch=1.0, length=1.0), "voltage")
    written = crease_onset(Tube((Layer(2.0, material=stiff),), stretch=1.0, length=1.0), "voltage")
    assert written.trigger == unit.trigger == "field"
    assert written.value == pytest.approx(math.sqrt(10.0) * unit.value, rel=1e-10)


def test_a_written_permittivity_is_the_builtin_permittivity_for_the_field_crease():
    """ "(I1 - 3)/2 + 3*I5/2" is a neo-Hookean layer of permittivity 1/3 (eps = 1 / (2
    Omega_5)), as Layer(..., permittivity=1/3) is: the same field crease, at sqrt(3) times
    the unit layer's Vbar, and the same criterion (exact for both: an ideal dielectric of
    any permittivity). Found with the fix: 0.7068 against 1.1767, and the text's criterion
    said "not that energy's own onset"."""
    low = Material("eps1/3", "(I1 - 3)/2 + 3*I5/2", check_units=False)
    built = Tube((Layer(2.0, permittivity=1 / 3),), stretch=1.0, length=1.0)
    written = Tube((Layer(2.0, material=low),), stretch=1.0, length=1.0)
    unit = crease_onset(Tube((Layer(2.0),), stretch=1.0, length=1.0), "voltage")
    b, w = crease_onset(built, "voltage"), crease_onset(written, "voltage")
    assert (b.kind, b.face, b.trigger) == ("crease", "inner", "field")
    assert (w.kind, w.face, w.trigger) == (b.kind, b.face, b.trigger)
    assert w.value == pytest.approx(b.value, rel=1e-10)
    assert w.value == pytest.approx(math.sqrt(3.0) * unit.value, rel=1e-10)
    assert criterion_text(written) == criterion_text(built)
