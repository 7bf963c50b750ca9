"""An uncharged tube of an exponentially stiffening energy (Fung type, an energy text of the
grammar's ``exp``) has its homogeneous state at every axial stretch, and the commands that
need it do not crash.

Omega = exp((I1 - 3)/2) - 1 + I5/2 has mu = eps = 1 in the reference state. An ungrown,
uncharged tube at the axial stretch lambda_z is homogeneous: lambda_r = lambda_theta =
lambda_z^(-1/2) through the wall, lambda_i = lambda_z^(-1/2), whatever the energy.

Found by probing: ``solve_base_state`` of that tube at lambda_z = 0.245 raised numpy's
LinAlgError ("Array must not contain infs or NaNs", from the voltage threshold's limit-point
search, basestate/voltage.py ``_limit_point``: the tube carries no voltage), and at
lambda_z <= 0.215 ConvergenceError "quadrature not converged"; the voltage threshold scans
Vbar(lambda_i) far beyond the state asked for, where exp(I1 / 2) overflows. Through the crease
criterion's Biot ratio (its half-space march runs to lambda_z = 0.05) the verdict of a
(0, 1) wrinkle crashed too: ``electrogrowth critical ... --energy "(exp(0.5*(I1-3))-1) + I5/2"
--mode 0 1`` printed "internal error: LinAlgError" and no value, exit status 1, while the
value itself is fine (lambda_z,cr = 0.418141270798; collocation agrees to 3e-13).
"""

import json
import warnings

import pytest

from electrogrowth import Material, Tube, critical_value, solve_base_state
from electrogrowth.cli.app import main

FUNG_TEXT = "(exp(0.5*(I1-3))-1) + I5/2"
FUNG = Material("fung", FUNG_TEXT)


@pytest.mark.parametrize("stretch", [0.3, 0.245, 0.21])
def test_homogeneous_state_of_an_exponential_energy(stretch):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        state = solve_base_state(Tube.uniform(2.0, 1.0, stretch=stretch, material=FUNG))
    assert state.lambda_i == pytest.approx(stretch**-0.5, rel=1e-10)


def test_verdict_of_an_exponential_energy_does_not_crash(capsys):
    tube = Tube.uniform(2.2, 1.5, material=FUNG)
    crit = critical_value(tube, 0, 1, "stretch", side="compression")
    assert crit.value == pytest.approx(0.418141270798, rel=1e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        verdict = crit.verdict
    assert verdict.wrinkle is not None and verdict.wrinkle.value == crit.value
    args = ["critical", "--solve-for", "stretch", "--side", "compression"]
    args += ["--outer-radius", "2.2", "--length", "1.5", "--energy", FUNG_TEXT]
    assert main([*args, "--mode", "0", "1", "--json", "--quiet"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["value"] == pytest.approx(crit.value, rel=1e-10)
