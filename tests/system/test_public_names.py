"""Every name a package face lists in ``__all__`` is importable from it (a star import
of any stage works)."""

import importlib

import pytest

PACKAGES = [
    "electrogrowth",
    "electrogrowth.model",
    "electrogrowth.continuation",
    "electrogrowth.basestate",
    "electrogrowth.incremental",
    "electrogrowth.bifurcation",
    "electrogrowth.design",
    "electrogrowth.shapes",
    "electrogrowth.sweep",
    "electrogrowth.figures",
]


@pytest.mark.parametrize("name", PACKAGES)
def test_every_listed_name_is_there(name):
    module = importlib.import_module(name)
    missing = [n for n in getattr(module, "__all__", ()) if not hasattr(module, n)]
    assert not missing, f"{name} lists {missing} in __all__ but has no such attribute"
