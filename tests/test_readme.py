"""The README's Python examples run as written, with top-level imports only."""

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
BLOCKS = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)


def test_readme_has_python_examples():
    assert len(BLOCKS) >= 2


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_block_runs(index):
    code = BLOCKS[index]
    for line in code.splitlines():  # the public surface only
        if line.startswith(("from electrogrowth", "import electrogrowth")):
            assert line.startswith("from electrogrowth import "), line
    namespace: dict = {}
    exec(compile(code, f"README.md block {index}", "exec"), namespace)


def test_readme_headline_value():
    """The value the README quotes for the headline tube is the computed one."""
    from electrogrowth import TubeParameters, critical_value

    c = critical_value(TubeParameters(outer_radius=1.4, length=1.0, voltage=0.4), 0, 1, "growth")
    assert "g_cr = 1.26611156226" in README.read_text(encoding="utf-8")
    assert abs(c.value - 1.26611156226) < 1e-10


def test_readme_layered_value():
    """The value the README quotes for its bilayer is the computed one."""
    from electrogrowth import Layer, Tube, critical_value

    tube = Tube(
        [Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)],
        length=3.0,
        voltage=0.3,
        inner_pressure=0.05,
    )
    assert "g_theta,cr = 2.02499586028" in README.read_text(encoding="utf-8")
    assert abs(critical_value(tube, 12, 1, "growth[1].theta").value - 2.02499586028) < 1e-10
