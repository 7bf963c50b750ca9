"""Beyond onset: the post-buckled cross-section (prismatic modes (m, 0)) or meridian
(axisymmetric modes (0, n)) of a tube by finite elements (the ``fe`` extra, scikit-fem). The
models (wall.py: the mesh, unknowns and assembly they share; section.py and meridian.py:
their kinematics and pressures; energy.py: the density and its derivatives), the
unperturbed path (newton.py), the onset (onset.py), the branch (branch.py), the shapes
(shape.py) and the entry point :func:`postbuckle` (api.py).

Its names are imported on first use, so that the shapes and the figures of a result load
without the finite-element library.
"""

from __future__ import annotations

import importlib

__all__ = ["PostbuckleResult", "postbuckle"]


def __getattr__(name: str):
    if name in __all__:
        return getattr(importlib.import_module(".api", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
