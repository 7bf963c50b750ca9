"""Every example of README.md and docs/*.md runs as written and gives the output it quotes.

* every ```python block runs (README's with top-level imports only);
* every line of a ```sh block (or of a bare ``` block) that starts with ``electrogrowth``
  runs as ``python -m electrogrowth`` would (``cli.main``, the function it calls) and
  succeeds;
* every value a block quotes in a comment (a number with four or more decimals, or
  ``# True``) is in :data:`QUOTED`, and the run gives it to the digits quoted.

They run in one scratch directory holding a copy of ``examples/``, as a reader in a clone
would. The long ones are marked slow (:data:`SLOW`, with their reasons); the rest take
about a minute of the default run.
"""

from __future__ import annotations

import re
import shlex
import shutil
from pathlib import Path

import pytest

from electrogrowth.cli.app import main

ROOT = Path(__file__).resolve().parents[2]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(r"^```([\w-]*)[^\n]*\n(.*?)^```", flags=re.S | re.M)


def _fenced(languages: tuple[str, ...]) -> list[tuple[str, int, str]]:
    """(document, line of the fence, code) of every fenced block in ``languages``."""
    found = []
    for doc in DOCS:
        text = doc.read_text(encoding="utf-8")
        for match in FENCE.finditer(text):
            if match.group(1) in languages:
                line = text.count("\n", 0, match.start()) + 1
                found.append((str(doc.relative_to(ROOT)), line, match.group(2)))
    return found


def _commands(code: str) -> list[str]:
    """The ``electrogrowth`` command lines of a shell block, continuations joined."""
    joined = re.sub(r"\\\n\s*", " ", code)
    return [line.strip() for line in joined.splitlines() if line.startswith("electrogrowth ")]


PYTHON = _fenced(("python",))
COMMANDS = [
    (doc, line, command)
    for doc, line, code in _fenced(("sh", "bash", ""))
    for command in _commands(code)
]

#: Why a block or command is slow (a substring of it -> reason); they run with -m slow. The
#: times are of one run of the slow set on the shared two-core machine under a load of 7-9.
SLOW = {
    'method="collocation"': "the collocation solve of a mode (18-22 s)",
    "results.zarr": "computes (195 s) or reads the 55-point sweep of examples/sweep.toml",
    "--certify": "the collocation solve of the mode (28 s one layer, 59 s bilayer)",
    "reproduce --out": "every figure of the paper (240 s)",
    "figure 9": "two critical curves (32-51 s)",
    "--points 60": "a 60-point curve (53 s)",
    "--points 17": "a 17-point curve with modes up to m = 64 (37 s)",
    "curve --tube": "a layered curve with its switches located (26 s)",
    "Material(": "a new energy: its moduli are derived and compiled (11-33 s)",
    "--energy": "the same new energy, when the block above has not compiled it",
    "postbuckle --tube": "a finite-element onset and branch (the fe extra; 40 s)",
    "postbuckle(tube": "a finite-element onset and branch (the fe extra; 40 s)",
    "--solve-for pressure": "a layered scan for the pressure up to m = 16, n = 8 (30 s)",
    "--vary length 0.95 1.05": "a mode map over two variables, boundaries traced (40 s)",
}
#: Commands not run at all, with the reason.
SKIP = {
    "--workers 2   # all examples": "the whole gallery takes 10-30 min; its quick form runs",
    "--scheduler tcp://head": "needs a dask cluster (tests/sweep/test_run.py runs one in-process)",
}

#: Quoted output -> the expression (in the namespace of its block, run up to the quote)
#: that gives it.
QUOTED = {
    "g_cr = 1.26611156226": "c.value",
    "g_theta,cr = 2.0404425747": 'critical_value(tube, 12, 1, "growth[1].theta").value',
    "True: the same tube as a file": 'load_tube("examples/bilayer.toml") == tube',
    "crease at lambda_z = 0.557861": "v.value if v.kind == 'crease' else None",
    "c_2 = 6.18497": "k.coefficient",
}
QUOTE = re.compile(r"#[^\n]*?=\s*-?\d+\.\d{4,}|#\s*(?:True|False)\b")


def _marks(text: str):
    reasons = [reason for key, reason in SLOW.items() if key in text]
    return [pytest.mark.slow] if reasons else []


def _id(doc: str, line: int, extra: str = "") -> str:
    return f"{doc}:{line}{extra}"


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    """A scratch directory holding a copy of examples/, as a clone would."""
    path = tmp_path_factory.mktemp("docs")
    shutil.copytree(ROOT / "examples", path / "examples")
    return path


@pytest.fixture(scope="module")
def sweep_store(workdir):
    """results.zarr of examples/sweep.toml in workdir, which the plotting examples read."""
    with pytest.MonkeyPatch.context() as mp:
        mp.chdir(workdir)
        assert main(["sweep", "examples/sweep.toml", "--out", "results.zarr", "--quiet"]) == 0
    return workdir / "results.zarr"


def _run_python(code: str, where: str) -> dict:
    namespace: dict = {"__name__": "__docs__"}
    exec(compile(code, where, "exec"), namespace)
    return namespace


def test_the_documents_have_examples():
    docs = {doc for doc, _, _ in PYTHON + COMMANDS}
    assert {"README.md", "docs/getting-started.md", "docs/sweeps.md"} <= docs
    assert len(PYTHON) >= 6 and len(COMMANDS) >= 20


@pytest.mark.parametrize(
    "doc, line, code",
    [pytest.param(*b, marks=_marks(b[2]), id=_id(b[0], b[1])) for b in PYTHON],
)
def test_python_block_runs(doc, line, code, workdir, monkeypatch, request):
    if doc == "README.md":  # the README shows the public surface only
        for row in code.splitlines():
            if row.startswith(("from electrogrowth", "import electrogrowth")):
                assert row.startswith("from electrogrowth import "), row
    if "results.zarr" in code:
        request.getfixturevalue("sweep_store")
    monkeypatch.chdir(workdir)
    _run_python(code, f"{doc}:{line}")


@pytest.mark.parametrize(
    "doc, line, command",
    [
        pytest.param(*c, marks=_marks(c[2]), id=_id(c[0], c[1], " " + c[2][14:50]))
        for c in COMMANDS
    ],
)
def test_command_runs(doc, line, command, workdir, monkeypatch, capsys, request):
    for key, reason in SKIP.items():
        if key in command:
            pytest.skip(reason)
    if command.startswith("electrogrowth plot results.zarr"):
        request.getfixturevalue("sweep_store")
    monkeypatch.chdir(workdir)
    argv = shlex.split(command, comments=True)[1:]
    status = main(argv)
    out, err = capsys.readouterr()
    assert status == 0, f"{command}\n{err}"
    assert out.strip(), command  # every command reports what it did


def _quotes() -> list[tuple[str, int, str, int, str]]:
    """(document, fence line, code, line index, quoted text) of every quote in a block."""
    found = []
    for doc, line, code in PYTHON:
        for index, row in enumerate(code.splitlines()):
            if QUOTE.search(row):
                found.append((doc, line, code, index, row))
    return found


def test_every_quoted_value_is_checked():
    for doc, line, _, index, row in _quotes():
        assert any(key in row for key in QUOTED), f"{doc}:{line + 1 + index}: {row.strip()}"


@pytest.mark.parametrize(
    "doc, line, code, index, row",
    [pytest.param(*q, id=_id(q[0], q[1] + 1 + q[3])) for q in _quotes()],
)
def test_quoted_value_is_the_computed_one(doc, line, code, index, row, workdir, monkeypatch):
    """The block runs up to the quoting line (the quick part before a slow solve), then the
    quoted expression must give the quoted value to the digits shown."""
    key = next(k for k in QUOTED if k in row)
    rows = code.splitlines()
    end = index + 1
    while True:  # up to the end of the statement the quote belongs to
        try:
            prefix = compile("\n".join(rows[:end]), f"{doc}:{line}", "exec")
            break
        except SyntaxError:
            end += 1
            assert end <= len(rows), row
    monkeypatch.chdir(workdir)
    namespace: dict = {"__name__": "__docs__"}
    exec(prefix, namespace)
    got = eval(QUOTED[key], namespace)  # noqa: S307 -- our own test table, not data
    number = re.search(r"-?\d+\.(\d{4,})", key)
    if number is None:
        assert got is (key.split(":")[0] == "True"), key
        return
    quoted, decimals = float(number.group(0)), len(number.group(1))
    assert abs(got - quoted) <= 0.5 * 10.0**-decimals, (key, got)
