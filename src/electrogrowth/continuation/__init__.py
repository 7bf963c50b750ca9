"""The one path-follower: steps along a control, predictors, events and their location.

Below the base state on the ladder (it imports only errors.py): the mode march and the
short-wave march (bifurcation/), the loading branches of a layered wall (basestate/) and
curve following (bifurcation/curves.py) all step, predict and locate with it.

- :mod:`.path`: :class:`~.path.Point`, the :class:`~.path.Path` protocol,
  :class:`~.path.StepPolicy`, :class:`~.path.Stepper`, :class:`~.path.GeometricGrid`.
- :mod:`.predict`: :class:`~.predict.EventWatch`, :func:`~.predict.secant_bracket`.
- :mod:`.events`: sign changes, dips, :func:`~.events.brent` with named tolerances,
  :func:`~.events.bisect`, :func:`~.events.threshold_between`,
  :func:`~.events.first_roots`.
"""

from .events import Tolerance, bisect, brent, dip_bracket, threshold_between
from .path import ControlPath, GeometricGrid, Path, Point, Stepper, StepPolicy
from .predict import EventWatch, secant_bracket

__all__ = [
    "ControlPath",
    "EventWatch",
    "GeometricGrid",
    "Path",
    "Point",
    "StepPolicy",
    "Stepper",
    "Tolerance",
    "bisect",
    "brent",
    "dip_bracket",
    "secant_bracket",
    "threshold_between",
]
