"""Layered tubes found failing by probing (round 6a, 2026-12-05): each test failed on
c79d58f and says what is right.

The unloaded (and force-free) state of a tube with a soft Gent layer: its search started
lambda_z at the area-weighted mean g_z and solved the force balance at every r_i from that
fixed guess, through the layer's lock; a guess within rounding of the root stepped 2 %
into the lock. Now the guess weights the layers by their stiffness, lambda_z is continued
from r_i to r_i, a step into a lock is halved back towards the root, and a core locked
when unloaded that its inner pressure holds open is found at that pressure directly
(basestate/thresholds._start, branches._short_of_edge, plies.start_guess)."""

import os
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

from electrogrowth import (
    Layer,
    Material,
    Tube,
    critical_value,
    gent,
    solve_base_state,
    threshold,
)
from electrogrowth.errors import BaseStateError, ParameterError

SRC = Path(__file__).resolve().parents[2] / "src"

FOUR_LAYERS = """
length = 3.0
stretch = 1.0
voltage = 0.1
outer_pressure = 0.01
[[layers]]
outer_radius = 1.05
shear_modulus = 20.0
growth = [1.0, 1.1, 1.05]
[[layers]]
outer_radius = 1.3
material = "gent"
jm = 50
shear_modulus = 2.0
[[layers]]
outer_radius = 1.8
material = "mooney-rivlin"
alpha = 0.3
shear_modulus = 0.5
[[layers]]
outer_radius = 2.5
shear_modulus = 0.05
"""


def _cli(tmp_path, *args):
    f = tmp_path / "t4.toml"
    f.write_text(FOUR_LAYERS)
    env = dict(os.environ, PYTHONPATH=str(SRC))
    return subprocess.run(
        [sys.executable, "-m", "electrogrowth", *[a.replace("FILE", str(f)) for a in args]],
        capture_output=True,
        text=True,
        env=env,
        timeout=300,
    )


def test_layer_zero_is_refused_not_read_as_layer_one(tmp_path):
    # cli/tube_input.py:control_of uses `args.layer or 1`, so --layer 0 solves for layer 1
    # (exit 0, "g[1],cr = 1.31283439342"); Python's "growth[0]" is refused.
    with pytest.raises(ParameterError):
        Tube([Layer(1.5), Layer(2.0)]).check_control("growth[0]")
    p = _cli(
        tmp_path,
        "critical",
        "--quiet",
        "--tube",
        "FILE",
        "--solve-for",
        "growth",
        "--layer",
        "0",
        "--mode",
        "1",
        "1",
    )
    assert p.returncode == 2, p.stdout
    assert "layer" in p.stderr and "0" in p.stderr


def test_huge_voltage_on_a_layered_tube_is_one_line_not_an_internal_error(tmp_path):
    # basestate/layered.py:solve_layered_state squares tube.voltage as a Python float:
    # OverflowError (34, 'Numerical result out of range') for Vbar >= ~1.3e154; the CLI
    # prints "internal error: OverflowError", exit 1. A one-layer tube says "at or above
    # the threshold", exit 2.
    t = Tube([Layer(1.5), Layer(2.0)], length=2.0, voltage=1e160)
    with pytest.raises(BaseStateError):
        solve_base_state(t)
    p = _cli(tmp_path, "state", "--tube", "FILE", "--voltage", "1e160")
    assert p.returncode == 2, p.stderr
    assert "internal error" not in p.stderr


def test_layered_voltage_threshold_prints_no_numpy_warnings():
    # a Fung-type layer at stretch 3: the voltage threshold's branch evaluates the stress
    # past the energy's finite range (model/_chain_rule.py, basestate/plies.py:integrals)
    # without np.errstate: 4 RuntimeWarnings; the one-layer tube prints none.
    fung = Material("fung", "(exp(0.5*(I1-3))-1) + I5/2")
    t = Tube([Layer(1.2, shear_modulus=0.01, material=fung), Layer(2.0)], length=2.0, stretch=3.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        threshold(t, "voltage")


def test_free_ends_state_of_an_axially_growing_stiff_skin_on_a_gent_layer_is_found():
    # a skin 1000 times as stiff growing axially (g_z = 2.1) on a soft Gent layer (J_m 8),
    # free ends: "no unloaded state (V = 0, P_i = P_o) found" (BaseStateError; CLI exit 2
    # blaming the load). The state exists: the stretch-controlled tube's axial force changes
    # sign between lambda_z = 2.09 (-25.95) and 2.0999 (+0.399), lambda_i ~ 2.209, the Gent
    # layer at ~79 % of its lock; with a neo-Hookean layer the same free state is found
    # (lambda_z 2.09986). Likely root: basestate/plies.py:start_guess takes lambda_z as the
    # AREA-weighted mean g_z (~1.08 here) instead of a stiffness-weighted one (~2.1), and
    # basestate/thresholds.py:_start's march from that guess runs into the Gent lock.
    layers = (
        Layer(2.9, shear_modulus=0.01, material=gent(8)),
        Layer(3.0, shear_modulus=1000.0, growth=(1.0, 1.0, 2.1)),
    )
    lo = solve_base_state(Tube(layers, length=4.0, stretch=2.09)).axial_force
    hi = solve_base_state(Tube(layers, length=4.0, stretch=2.0999)).axial_force
    assert lo < 0 < hi
    st = solve_base_state(Tube(layers, length=4.0, axial_force=0.0))
    assert 2.09 < st.stretch < 2.0999


CORE = dict(length=3.0, inner_pressure=0.3, closed_ends=True, voltage=0.1)


def _core_layers():
    return (
        Layer(1.2, shear_modulus=0.1, material=gent(5)),
        Layer(1.8, material=gent(50)),
        Layer(2.0, shear_modulus=30.0),
    )


@pytest.mark.slow  # ~60 s: the march of (0, 1) to growth 6
def test_growing_gent_core_under_force_control_bifurcates_in_no_mode_0_1():
    # critical_value(tube, 0, 1, "growth[1]") ended in a bare ValueError from brent, then
    # (fix22a) in a "threshold" at 2.0502 or 1.9595 from run to run: cold solves past ~1.9
    # failed or succeeded by where their walk's steps fell (branches._balance: NaN for a
    # lambda_z guess past the core's lock), the continued ones were all refused (Newton's
    # start past the lock), and the check of a state stalled at its noise (~3e-12) around
    # rtol. The state is not lost there: an independent radial balance (mpmath, the core's
    # distance to its lock as unknown) follows it through growth[1] = 1.8 .. 3.3, the core's
    # inner face within 1.06e-3 (at 2.2) to 4.6e-3 of its lock, no fold, no lock; its states
    # at 1.95, 1.96, 2.06 and 1.92 continued are checked in tests/basestate/test_gent_core.py.
    from electrogrowth.errors import NoBifurcationFound

    tc = Tube(_core_layers(), axial_force=0.2, **CORE)
    with pytest.raises(NoBifurcationFound, match="between 1 and 6"):
        critical_value(tc, 0, 1, "growth[1]")
    st = solve_base_state(tc.at("growth[1]", 2.2))
    assert st.r_i == pytest.approx(1.450825084693174, rel=1e-10)
    assert st.stretch == pytest.approx(1.239629751053730, rel=1e-10)


def test_growing_gent_core_force_controlled_state_exists_past_1_4337():
    # solve_base_state at growth[1] = 1.44: "no unloaded state (V = 0, P_i = P_o) found"
    # (BaseStateError; states are found up to 1.4336 with lambda_i smooth, 0.80209, no
    # turning point). The state exists: the stretch-controlled tube's end force crosses the
    # prescribed 0.2 between lambda_z = 1.011 (-0.0149) and 1.02 (2.091).
    ts = Tube(_core_layers(), stretch=1.0, **CORE)
    lo = solve_base_state(ts.at("growth[1]", 1.44).at("stretch", 1.011)).end_force
    hi = solve_base_state(ts.at("growth[1]", 1.44).at("stretch", 1.02)).end_force
    assert lo < 0.2 < hi
    tc = Tube(_core_layers(), axial_force=0.2, **CORE)
    st = solve_base_state(tc.at("growth[1]", 1.44))
    assert 1.011 < st.stretch < 1.02
