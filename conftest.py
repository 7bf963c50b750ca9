"""The docstring examples of modules that need an optional extra are collected only when it
is installed (pytest --doctest-modules imports every module of src/electrogrowth)."""

import importlib.util

collect_ignore_glob = []
if importlib.util.find_spec("skfem") is None:  # the fe extra (scikit-fem)
    collect_ignore_glob += [
        "src/electrogrowth/postbuckle/api.py",
        "src/electrogrowth/postbuckle/section.py",
    ]
