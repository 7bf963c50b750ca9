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


#: What a critical value of the paper's tube in Python does not use: the crease and its
#: verdict (read only when ``.verdict`` is), the scan, curves and short-wave limit, the
#: layered solver, the collocation method, the later stages, the TOML reader, the extras,
#: sympy (a user's --energy text only) and SciPy's solvers.
UNUSED_BY_ONE_VALUE = (
    "electrogrowth.bifurcation.crease",
    "electrogrowth.bifurcation.verdict",
    "electrogrowth.bifurcation.scan",
    "electrogrowth.bifurcation.scan_grid",
    "electrogrowth.bifurcation.scan_record",
    "electrogrowth.bifurcation.curves",
    "electrogrowth.bifurcation.surface",
    "electrogrowth.bifurcation.certify",
    "electrogrowth.basestate.layered",
    "electrogrowth.basestate.layered_state",
    "electrogrowth.incremental.collocation",
    "electrogrowth.design",
    "electrogrowth.postbuckle",
    "electrogrowth.shapes",
    "electrogrowth.figures",
    "electrogrowth.sweep",
    "electrogrowth.model.tube_file",
    "sympy",
    "scipy.optimize",
    "scipy.integrate",
) + EXTRAS

_ONE_VALUE = """
import json, sys
from electrogrowth import Tube, critical_value
crit = critical_value(Tube.uniform(1.4, 1.0, voltage=0.4), 0, 1, "growth")
before = set(sys.modules)
crit.verdict  # the crease competitor: imported now, when it is read
names = {names!r}
print(json.dumps([crit.value, sorted(n for n in names if n in before),
                  "electrogrowth.bifurcation.crease" in sys.modules]))
"""


def test_a_critical_value_imports_only_what_it_uses():
    # the path to the paper's first value (issue 21): the package faces import their names
    # on first use, so critical.py does not bring the crease, the scan or the curves along
    code = _ONE_VALUE.format(names=UNUSED_BY_ONE_VALUE)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    value, imported, crease_after = json.loads(done.stdout.strip().splitlines()[-1])
    assert imported == []
    assert crease_after  # the verdict still works, importing the crease when asked
    assert value > 1.0  # a growth factor was computed


def test_lazy_package_faces_keep_their_names():
    # `from package import name`, dir() and submodules still work on the lazy faces
    import electrogrowth
    import electrogrowth.bifurcation as bifurcation
    import electrogrowth.incremental as incremental
    import electrogrowth.model as model

    for face in (electrogrowth, bifurcation, incremental, model):
        names = set(dir(face))
        assert set(face.__all__) <= names
        for name in face.__all__:
            assert getattr(face, name) is not None
    from electrogrowth.bifurcation import critical, critical_value

    assert critical.critical_value is critical_value
    with pytest.raises(AttributeError, match="no_such_name"):
        bifurcation.no_such_name  # noqa: B018


@pytest.mark.parametrize(
    "argv",
    [
        ["critical", "--outer-radius", "-1", "--mode", "0", "1", "--solve-for", "growth"],
        ["critical", "--outer-radius", "1.4", "--mode", "0", "-1", "--solve-for", "growth"],
        ["critical", "--outer-radius", "1.4", "--solve-for", "growth", "--method", "fast"],
    ],
    ids=["bad-radius", "bad-mode", "bad-method"],
)
def test_a_bad_argument_is_named_before_the_solvers_load(argv):
    # the options (modes, families, methods, scan caps) are read from incremental/modes.py
    # and bifurcation/options.py, and cli/critical.py imports its solvers once the input
    # is checked: a mistyped command answers without loading numba
    status, imported = _imports(argv, ("numba", "scipy", "electrogrowth.bifurcation.critical"))
    assert status == 2
    assert imported == []
