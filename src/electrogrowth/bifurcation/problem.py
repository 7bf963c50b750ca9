"""A bifurcation problem, built once: the tube, the control solved for, its side, the
accuracy and the scan options.

:func:`~.critical.critical_value`, :func:`~.scan.scan_modes`,
:func:`~.surface.short_wave_limit`, :func:`~.curves.critical_curve` and
:func:`~.certify.certify` take a :class:`Problem` as their first argument, or the tube with
the same pieces as keywords (``critical_value(tube, m, n, "growth", rtol=1e-10)``), from which
they build one. The problem checks itself once (the control against the tube, the side, the
accuracy) and hands out the tube at a control value (:meth:`Problem.at`) and the named target
of a method (:meth:`Problem.targets`), which is what every march evaluates.
"""

from __future__ import annotations

import dataclasses

from ..errors import ParameterError
from ..incremental.accuracy import Accuracy, check_rtol
from ..incremental.targets import Target, targets_for
from ..model.controls import check_side
from ..model.layers import Tube
from .options import ScanOptions

#: the default accuracy of every entry point (incremental/accuracy.py)
DEFAULT_RTOL = 1e-12


@dataclasses.dataclass(frozen=True)
class Problem:
    """Where a tube first wrinkles as one control varies: the inputs shared by every stage.

    Parameters
    ----------
    tube : Tube
        The tube; the value of ``control`` in it is ignored (it is the unknown).
    control : str
        The control solved for, as ``solve_for`` of :func:`critical_value` ("growth",
        "stretch", "voltage", "growth[K]", "pressure", "force", ...; model/controls.py),
        checked against the tube and stored by its canonical name.
    side : {"compression", "extension"}, optional
        The direction of the march for the stretch, the pressure and the force (default
        its ControlKind's default_side, model/controls.py: compression, extension, compression).
    accuracy : Accuracy or float
        The accuracy policy (incremental/accuracy.py) from one rtol in RTOL_RANGE (1e-14 to
        1e-4); a number is taken as that rtol.
    options : ScanOptions
        The modes a scan examines and how much it reports.

    Raises
    ------
    ParameterError
        One line naming the bad value: an unknown control or one the tube cannot take, an
        unknown side, an rtol out of range, options that are not ScanOptions.

    Examples
    --------
    >>> from electrogrowth import Problem, Tube
    >>> problem = Problem(Tube.uniform(outer_radius=1.4, length=1.0), "stretch")
    >>> problem.side
    'compression'
    >>> problem.at(0.9).stretch
    0.9
    """

    tube: Tube
    control: str
    side: str | None = None
    accuracy: Accuracy = Accuracy(DEFAULT_RTOL)
    options: ScanOptions = ScanOptions()

    def __post_init__(self):
        if not isinstance(self.tube, Tube):
            raise ParameterError(f"tube = {self.tube!r} is not a Tube")
        control = str(self.tube.check_control(self.control))
        object.__setattr__(self, "control", control)
        object.__setattr__(self, "side", check_side(control, self.side))
        accuracy = self.accuracy
        if not isinstance(accuracy, Accuracy):
            accuracy = Accuracy(accuracy)
        rtol = accuracy.rtol
        if isinstance(rtol, bool) or not isinstance(rtol, (int, float)):
            raise ParameterError(f"rtol = {rtol!r} is not a number; valid range: 1e-14 to 1e-4")
        check_rtol(rtol)
        object.__setattr__(self, "accuracy", accuracy)
        if not isinstance(self.options, ScanOptions):
            raise ParameterError(f"options = {self.options!r} is not a ScanOptions")

    @property
    def rtol(self) -> float:
        """The one tolerance the accuracy derives from."""
        return self.accuracy.rtol

    def at(self, value: float) -> Tube:
        """The tube with the control set to ``value``."""
        return self.tube.at(self.control, value)

    def targets(self, method: str = "impedance", rtol: float | None = None) -> Target:
        """The named target f(state, modes) of ``method`` ("impedance" or "collocation") at
        ``rtol`` (default the accuracy's ``fine`` tolerance, the user's rtol)."""
        return targets_for(method, self.accuracy.fine if rtol is None else rtol)


def as_problem(
    first,
    control: str | None = None,
    *,
    side: str | None = None,
    rtol: float | None = None,
    options: ScanOptions | None = None,
) -> Problem:
    """``first`` if it is a Problem (then the other arguments must be left out: they are
    the problem's), else the Problem of the tube ``first`` and the keywords (an entry
    point's keyword form)."""
    if isinstance(first, Problem):
        given = [
            name
            for name, value in (
                ("solve_for", control),
                ("side", side),
                ("rtol", rtol),
                ("options", options),
            )
            if value is not None
        ]
        if given:
            raise ParameterError(
                f"{', '.join(given)} given with a Problem; set them in the Problem instead"
            )
        return first
    if control is None:
        raise ParameterError("solve_for is missing: pass a Problem, or a Tube and solve_for")
    return Problem(
        first,
        control,
        side,
        Accuracy(DEFAULT_RTOL if rtol is None else rtol),
        ScanOptions() if options is None else options,
    )
