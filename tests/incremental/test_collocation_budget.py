"""Collocation's memory budget (probe 12b, D5).

Collocation sizes its nodes from the mode's decay through the wall (resolving_nodes), with
no bound: (0, 1000) of Tube.uniform(100, length=1) needs 2681 nodes, whose nodal maps alone
are a 4.8 GiB (3, 3, 2681, 13403) complex array. The process was OOM-killed on a 24 GB
machine (exit 137), or under a memory limit ended "internal error: MemoryError", also for
``--certify`` of a valid impedance value. Now the arrays' bytes are derived from their
shapes and a mode beyond MEMORY_BUDGET is refused (CollocationTooLarge, a
ConvergenceError) before any array of the nodes' size exists; certify says "not
certified: ..." and the value stands.

No test here allocates more than a few MB: the large cases run with the nodal maps
replaced by a guard that fails on a large grid, or in a process under a memory limit.
"""

import subprocess
import sys
import textwrap
import tracemalloc

import numpy as np
import pytest

from electrogrowth import Layer, Tube, certify, critical_value, solve_base_state
from electrogrowth.errors import CollocationTooLarge, ConvergenceError
from electrogrowth.incremental import collocation
from electrogrowth.incremental.collocation import MEMORY_BUDGET, collocation_bytes
from electrogrowth.incremental.targets import collocation_targets, resolving_nodes

THICK = Tube.uniform(100, length=1.0)


@pytest.fixture
def no_large_arrays(monkeypatch):
    """Every layer's nodal maps built on at most 300 nodes (a few hundred MB), else fail
    instead of allocating: the old code went on to ask for 4.8 GiB here."""
    fluxes = collocation._fluxes

    def guarded(state, grid, m, layer=0):
        assert grid.r.size <= 300, f"collocation built the maps of {grid.r.size} nodes"
        return fluxes(state, grid, m, layer)

    monkeypatch.setattr(collocation, "_fluxes", guarded)


@pytest.mark.parametrize(
    "tube",
    [
        Tube.uniform(2.0, length=1.0),
        Tube([Layer(1.1, shear_modulus=10.0), Layer(2.0)], length=1.0),
    ],
    ids=["one layer", "two layers"],
)
def test_the_bytes_bound_the_measured_peak(tube):
    """collocation_bytes, derived from the arrays' shapes, is an upper bound within 5 % of
    the peak tracemalloc sees (numpy's and LAPACK's arrays) for one target evaluation."""
    state = solve_base_state(tube)
    collocation_targets(state, [[2, 1]], nodes=20)  # warm: imports and caches
    tracemalloc.start()
    try:
        collocation_targets(state, [[2, 1]], nodes=80)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    bound = collocation_bytes(80, len(tube.layers))
    assert peak <= bound <= 1.05 * peak


def test_the_budget_keeps_a_four_layer_film_to_the_mode_cap():
    """The budget admits the nodes of the shortest prismatic wave a scan reaches, (2000, 0)
    of a film on a substrate to R = 3 (q = m ln 3) at rtol 1e-12, for four layers."""
    nodes = resolving_nodes(solve_base_state(Tube.uniform(3.0, length=1.0)), 2000, 0, 1e-12)
    assert collocation_bytes(nodes, 4) <= MEMORY_BUDGET


def test_a_short_wave_of_a_thick_tube_is_refused_before_its_arrays(no_large_arrays):
    """The probe's case: a named ConvergenceError saying how many nodes the mode needs,
    with a remedy naming the impedance method and the short-wave limit (was: a 4.8 GiB
    allocation, OOM-killed)."""
    with pytest.raises(CollocationTooLarge) as err:
        critical_value(THICK, 0, 1000, "growth", method="collocation")
    assert isinstance(err.value, ConvergenceError)
    assert "2681 nodes a layer for mode (m, n) = (0, 1000)" in str(err.value)
    assert "beyond its budget" in str(err.value)
    assert "--method impedance" in err.value.remedy
    assert "short-wave limit" in err.value.remedy


def test_certify_refuses_to_certify_rather_than_crash(no_large_arrays):
    """certify of the valid impedance value (2.2535427) cannot run collocation there: it says
    "not certified: ...", which the command line prints with the value (exit 3)."""
    crit = critical_value(THICK, 0, 1000, "growth")
    assert crit.value == pytest.approx(2.2535427, abs=1e-7)
    with pytest.raises(ConvergenceError, match=r"^not certified: collocation would need"):
        certify(THICK, crit)


def test_under_a_memory_limit_no_memory_error():
    """In a process limited to 2 GB of address space (the old code asked numpy for 4.8 GiB
    there and ended "internal error: MemoryError", without one it was OOM-killed)."""
    code = textwrap.dedent(
        """
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))
        from electrogrowth import Tube, critical_value
        from electrogrowth.errors import ConvergenceError
        try:
            critical_value(Tube.uniform(100, length=1.0), 0, 1000, "growth", method="collocation")
        except ConvergenceError as exc:
            print(type(exc).__name__)
        """
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert "MemoryError" not in r.stderr
    assert r.stdout.strip() == "CollocationTooLarge"


def test_cli_certify_prints_the_value_and_exits_3(tmp_path):
    """``critical --outer-radius 100 --length 1 --mode 0 1000 --certify`` prints the
    impedance value, "NOT certified: collocation would need ...", and exits 3 (was: killed,
    or "internal error: MemoryError", exit 1), under a memory limit for safety."""
    code = textwrap.dedent(
        """
        import resource, sys
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))
        from electrogrowth.cli import main
        sys.exit(main(["critical", "--solve-for", "growth", "--outer-radius", "100",
                       "--length", "1", "--mode", "0", "1000", "--certify"]))
        """
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert r.returncode == 3, r.stderr
    assert "g_cr = 2.2535426" in r.stdout
    assert "NOT certified: collocation would need 2681 nodes" in r.stdout


def test_a_failed_kernel_mode_beyond_the_budget_names_both_failures(no_large_arrays, monkeypatch):
    """Where the kernel fails for a mode (also at tighter tolerances) it goes to collocation
    (targets._retry); beyond the budget the error names the kernel's failure and
    collocation's nodes, and sends the user to neither method (the kernel's failures are
    made here: the kernel integrates this mode)."""
    from electrogrowth.incremental import targets
    from electrogrowth.incremental.impedance import STEP_UNDERFLOW

    def failed(state, modes, *args):  # (targets, status codes): every integration underflows
        return np.full(len(modes), np.nan), np.full(len(modes), STEP_UNDERFLOW)

    monkeypatch.setattr(targets, "_serial", failed)
    state = solve_base_state(THICK.at("growth", 2.25))
    with pytest.raises(CollocationTooLarge) as err:
        targets._retry(state, np.array([[0.0, 1000.0]]), np.array([STEP_UNDERFLOW]), 1e-12, 100)
    text = str(err.value)
    assert text.startswith("impedance integration failed for mode (m, n) = (0, 1000)")
    assert "step size underflow, also at tighter tolerances, and collocation would need" in text
    assert err.value.remedy.startswith("neither method resolves this mode here")
