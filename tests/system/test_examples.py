"""Every example of the documentation's gallery (examples/gallery) runs, draws its figure
and prints no error: the scripts cannot rot. Run in this process (matplotlib Agg), so the
compiled kernels are shared with the other tests."""

import runpy
from pathlib import Path

import matplotlib.pyplot as plt
import pytest
from matplotlib.figure import Figure

GALLERY = Path(__file__).resolve().parents[2] / "examples" / "gallery"
SECTIONS = (
    "basics",
    "layered",
    "sweeps",
    "design",
    "postbuckle",
)  # sphinx-gallery's subsections, in order
SCRIPTS = sorted(GALLERY.glob("*/plot_*.py"))
# 7-20 s each: make test-slow runs them (and the documentation build)
SLOW = {"plot_16_stretch_rings_folds", "plot_17_growth_voltage"}


def test_gallery_has_its_examples_in_sections():
    assert 8 <= len(SCRIPTS) <= 20
    assert (GALLERY / "README.txt").is_file()
    assert sorted(s.parent.name for s in SCRIPTS) == sorted(
        s for s in SECTIONS for _ in GALLERY.glob(f"{s}/plot_*.py")
    )
    for section in SECTIONS:  # a subsection needs its header, or sphinx-gallery skips it
        assert (GALLERY / section / "README.txt").is_file()
        assert list((GALLERY / section).glob("plot_*.py")), section
    assert not list(GALLERY.glob("plot_*.py")), "every example belongs to a section"


@pytest.mark.parametrize(
    "script",
    [pytest.param(s, marks=[pytest.mark.slow] if s.stem in SLOW else []) for s in SCRIPTS],
    ids=[s.stem for s in SCRIPTS],
)
def test_example_runs_and_draws(script, monkeypatch, tmp_path):
    if "sweep" in script.stem:
        pytest.importorskip("zarr")
    if "units" in script.stem:
        pytest.importorskip("pint")
    if script.parent.name == "postbuckle":  # the finite-element model's extra
        pytest.importorskip("skfem")
    monkeypatch.chdir(tmp_path)
    plt.close("all")
    names = runpy.run_path(str(script), run_name="__main__")
    figures = plt.get_fignums() or [v for v in names.values() if isinstance(v, Figure)]
    plt.close("all")
    assert figures, f"{script.name} drew no figure"
    doc = script.read_text(encoding="utf-8").split('"""')[1].strip().splitlines()
    assert len(doc) >= 3 and set(doc[1]) == {"="}, "a title underlined with = first"


@pytest.mark.parametrize("script", SCRIPTS, ids=[s.stem for s in SCRIPTS])
def test_no_cell_ends_in_a_stray_repr(script):
    """sphinx-gallery prints the value of a cell's last expression: a cell must not end in
    a call that returns a matplotlib artist (ax.legend(), ax.plot(...)): assign it to _."""
    import ast

    source = script.read_text(encoding="utf-8")
    cells = source.split("\n# %%")
    for cell in cells:
        body = ast.parse(cell.split('"""', 2)[-1] if cell is cells[0] else cell).body
        if body and isinstance(body[-1], ast.Expr) and isinstance(body[-1].value, ast.Call):
            call = body[-1].value
            name = call.func.attr if isinstance(call.func, ast.Attribute) else ""
            assert name not in ("legend", "plot", "set", "colorbar", "set_title", "annotate"), (
                f"{script.name}: a cell ends in .{name}(...), whose repr would be printed"
            )
