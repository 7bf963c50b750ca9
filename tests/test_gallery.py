"""Every example of the documentation's gallery (examples/gallery) runs, draws its figure
and prints no error: the scripts cannot rot. Run in this process (matplotlib Agg), so the
compiled kernels are shared with the other tests."""

import runpy
from pathlib import Path

import matplotlib.pyplot as plt
import pytest
from matplotlib.figure import Figure

GALLERY = Path(__file__).resolve().parents[1] / "examples" / "gallery"
SCRIPTS = sorted(GALLERY.glob("plot_*.py"))


def test_gallery_has_its_examples():
    assert 8 <= len(SCRIPTS) <= 12
    assert (GALLERY / "README.txt").is_file()


@pytest.mark.parametrize("script", SCRIPTS, ids=[s.stem for s in SCRIPTS])
def test_example_runs_and_draws(script, monkeypatch, tmp_path):
    if "sweep" in script.stem:
        pytest.importorskip("zarr")
    if "units" in script.stem:
        pytest.importorskip("pint")
    monkeypatch.chdir(tmp_path)
    plt.close("all")
    names = runpy.run_path(str(script), run_name="__main__")
    figures = plt.get_fignums() or [v for v in names.values() if isinstance(v, Figure)]
    plt.close("all")
    assert figures, f"{script.name} drew no figure"
    doc = script.read_text(encoding="utf-8").split('"""')[1].strip().splitlines()
    assert len(doc) >= 3 and set(doc[1]) == {"="}, "a title underlined with = first"
