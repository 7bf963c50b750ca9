"""What a fresh process imports (issue 25): a command loads only the stack its work needs.

Each case runs the command line's ``main`` in a new interpreter and lists the heavy modules
left in ``sys.modules``: the plotting, labelled-array, unit and sweep extras are imported
only on their commands' paths, and the compiled kernels (numba) only where modes are solved.
No timing is asserted (the machine's load would decide it); BENCHMARKS.md has the times.
"""

from __future__ import annotations

import json
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXTRAS = ("matplotlib", "xarray", "pint", "zarr", "dask", "meshio")

_PROBE = """
import json, sys
from electrogrowth.cli.app import main
status = main(sys.argv[1:])
names = {names!r}
print(json.dumps([status, sorted(n for n in names if n in sys.modules)]))
"""


def _imports(argv: list[str], names: tuple[str, ...]) -> tuple[int, list[str]]:
    """(exit status, the modules of ``names`` imported) of `electrogrowth argv` in a fresh
    process, run from the repository root (the example files' paths)."""
    code = _PROBE.format(names=names)
    done = subprocess.run(
        [sys.executable, "-c", code, *argv], capture_output=True, text=True, cwd=ROOT
    )
    assert done.returncode == 0, done.stderr
    status, imported = json.loads(done.stdout.strip().splitlines()[-1])
    return status, imported


@pytest.mark.parametrize(
    "argv",
    [
        ["state", "--outer-radius", "1.4", "--growth", "1.2", "--voltage", "0.2"],
        ["state", "--outer-radius", "1.4", "--growth", "1.2", "--material", "gent", "--json"],
        ["state", "--tube", "examples/bilayer.toml", "--json"],
    ],
    ids=["neo-hookean", "gent", "bilayer"],
)
def test_state_imports_neither_extras_nor_the_compiled_kernels(argv):
    status, imported = _imports(argv, EXTRAS + ("numba",))
    assert status == 0
    assert imported == []


def test_sweep_command_does_not_import_matplotlib():
    # matplotlib is for `electrogrowth plot` (the phase diagram), not for computing a sweep
    status, imported = _imports(["sweep", "--help"], ("matplotlib",))
    assert status == 0
    assert imported == []


def test_critical_imports_no_extras():
    status, imported = _imports(["critical", "--help"], EXTRAS)
    assert status == 0
    assert imported == []
