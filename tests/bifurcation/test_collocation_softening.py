"""Collocation on a tube of a softening energy text (probe 13a D2).

For "0.5*(I1-3) + I5/2 - 0.25*(I1-3)**2" (A1111 + p = 0 unloaded) the collocation
matrix had a singular mode of tr L at the faces, which the continuous problem does not
have, at one growth for every mode and node count (g = 1.0488 at Vbar = 0.2): its march
took that sign change for the onset. The moduli are now shifted by c delta delta where
A1111 + p would fall below A1212 (incremental/nodal_law.py), which the pressure absorbs.
"""

import dataclasses

import pytest

from electrogrowth import Material, Tube, critical_value
from electrogrowth.bifurcation import critical as critical_module
from electrogrowth.errors import NoBifurcationFound
from electrogrowth.outcomes import Status

SOFTENING = Material("soft", "0.5*(I1-3) + I5/2 - 0.25*(I1-3)**2")
#: impedance and collocation's own root next to the march's (--certify), 7.8e-15 apart
ROOT = 1.37439202989


def test_collocation_finds_the_genuine_onset_of_a_softening_energy():
    """Was g = 1.04861, status inaccurate (exit 3 on the command line): the march accepted
    the face mode's sign change as a root."""
    tube = Tube.uniform(1.5, 1.0, voltage=0.2, material=SOFTENING)
    impedance = critical_value(tube, 2, 1, "growth")
    c = critical_value(tube, 2, 1, "growth", method="collocation")
    assert c.status == Status.OK
    assert c.value == pytest.approx(ROOT, abs=1e-10)
    assert c.value == pytest.approx(impedance.value, rel=1e-10)


def test_collocation_finds_no_prismatic_root_where_the_kernel_finds_none():
    """A second softening energy, unloaded: the kernel has no (3, 0) onset up to g = 6;
    collocation reported one at g = 1.04037 (the face mode again)."""
    energy = Material("y", "0.5*(I1-3) - 0.24*(I1-3)**2 + 0.05*(I1-3)**3 + I5/2")
    tube = Tube.uniform(1.5, 1.0, material=energy)
    with pytest.raises(NoBifurcationFound):
        critical_value(tube, 3, 0, "growth")
    with pytest.raises(NoBifurcationFound):
        critical_value(tube, 3, 0, "growth", method="collocation")


def test_an_uncertified_collocation_value_is_not_sent_back_to_collocation():
    """The remedy of an inaccurate collocation value said "certify the point with --method
    collocation", the method just used; it names the other method."""
    tube = Tube.uniform(1.5, 3.0)
    point = critical_value(tube, 2, 1, "stretch")
    for method, other in (("collocation", "impedance"), ("impedance", "collocation")):
        marked = critical_module._inaccurate(dataclasses.replace(point, method=method), 1e-12, "")
        assert f"--method {other}" in marked.remedy
        assert f"method='{other}'" in marked.remedy.python
