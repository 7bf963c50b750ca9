"""A layered tube's branch ends where a polynomial energy overflows a double (probe 11b, D2).

(I1-3)/2 + I5/2 + 1e-30 (I1-3)^60 is finite in exact arithmetic but overflows at I1 ~ 1.4e5
(lambda_i ~ 370). The one-layer path treats that as the end of the energy ("none before the
locking stretch"), but the layered threshold walk took polynomial energies as finite
everywhere (plies.Ply.finite): the stress raised ParameterError "deformation outside the
domain ... the energy is not finite there", and `state --tube` of the unloaded tube, whose
state was solved, exited 2, blaming the energy.
"""

from __future__ import annotations

import math

import pytest

from electrogrowth import Layer, Material, Tube, threshold
from electrogrowth.cli.app import main

ENERGY = "(I1-3)/2 + I5/2 + 1e-30*(I1-3)^60"


def _tube():
    mat = Material("p", ENERGY)
    return Tube([Layer(1.1, shear_modulus=10.0, material=mat), Layer(2.0)], length=1.0)


def test_layered_threshold_ends_at_the_overflow_as_a_lock():
    """As the one-layer tube of this energy (kind locking at lambda_i = 370.63)."""
    thr = threshold(_tube(), "voltage")
    assert thr.kind == "locking" and thr.value == math.inf
    assert 300.0 < thr.lambda_i < 400.0
    one = threshold(Tube.uniform(2.0, length=1.0, material=Material("p", ENERGY)), "voltage")
    assert one.kind == "locking" and one.lambda_i == pytest.approx(thr.lambda_i, rel=0.01)


def test_state_of_the_unloaded_layered_tube(tmp_path, capsys):
    """`state --tube` exited 2 ("the energy is not finite there")."""
    path = tmp_path / "tube.toml"
    path.write_text(
        "length = 1.0\n"
        f'[[layers]]\nouter_radius = 1.1\nenergy = "{ENERGY}"\nshear_modulus = 10.0\n'
        "[[layers]]\nouter_radius = 2.0\n"
    )
    assert main(["state", "--tube", str(path)]) == 0
    assert "none before the locking stretch" in capsys.readouterr().out
