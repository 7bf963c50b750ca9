"""Beyond onset: the post-buckled cross-section of a tube by finite elements (the ``fe``
extra, scikit-fem). The model (section.py: mesh, unknowns, energy; energy.py: the density and
its derivatives), the unperturbed path (newton.py), the onset (onset.py), the branch
(branch.py), the shapes (shape.py) and the entry point :func:`postbuckle` (api.py)."""

from .api import PostbuckleResult, postbuckle

__all__ = ["PostbuckleResult", "postbuckle"]
