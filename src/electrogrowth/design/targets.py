"""The pattern a design aims at: one mode (m, n), a list of modes, a named set or a
predicate of (m, n)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

from ..errors import ParameterError
from ..incremental.modes import MODE_MAX, check_mode

#: the named sets of modes: m = 0 (axisymmetric), n = 0 (prismatic)
NAMED_SETS = {
    "axisymmetric": lambda m, n: m == 0,
    "prismatic": lambda m, n: n == 0,
}


def _mode(value) -> tuple[int, int]:
    ok = (
        isinstance(value, (tuple, list))
        and len(value) == 2
        and all(not isinstance(v, bool) and isinstance(v, int) and v >= 0 for v in value)
    )
    if not ok:
        raise ParameterError(
            f"target mode {value!r} is invalid; give (m, n) with integers m >= 0, n >= 0"
        )
    if max(value) > MODE_MAX:  # as the command line: no scan reaches it
        raise ParameterError(
            f"target mode {tuple(value)!r} is out of range; m and n go from 0 to {MODE_MAX}"
        )
    try:  # (1, 0), a rigid motion, and (0, 0) are no modes: no scan can ever reach them
        check_mode(*value)
    except ParameterError as exc:
        raise ParameterError(f"target {exc}") from None
    return int(value[0]), int(value[1])


@dataclasses.dataclass(frozen=True)
class Target:
    """A set of modes: ``accepts(m, n)`` and a ``name`` for reports ("(12, 1)",
    "axisymmetric", "[(0, 1), (0, 2)]", or the predicate's name)."""

    name: str
    accepts: Callable[[int, int], bool]
    modes: tuple[tuple[int, int], ...] = ()  # the listed modes, if the target is a list

    def __contains__(self, mode) -> bool:
        # a map's other patterns are names ("surface", "threshold", "failed"), no modes:
        # unpacked into accepts(m, n) a design crashed on a map with a surface region
        if mode is None or isinstance(mode, str):
            return False
        return tuple(mode) != (-1, -1) and bool(self.accepts(*mode))


def check_target(target) -> Target:
    """The Target of ``target``: (m, n), a list of (m, n), "axisymmetric", "prismatic" or a
    callable (m, n) -> bool; ParameterError otherwise."""
    if isinstance(target, Target):
        return target
    if isinstance(target, str):
        if target not in NAMED_SETS:
            raise ParameterError(
                f"target = {target!r} is unknown; give (m, n), a list of modes or one of"
                f" {', '.join(NAMED_SETS)}"
            )
        return Target(target, NAMED_SETS[target])
    if callable(target):
        return Target(getattr(target, "__name__", "predicate"), target)
    if (
        isinstance(target, (tuple, list))
        and len(target) == 2
        and all(isinstance(v, int) and not isinstance(v, bool) for v in target)
    ):
        mode = _mode(target)
        return Target(f"({mode[0]}, {mode[1]})", lambda m, n: (m, n) == mode, (mode,))
    if isinstance(target, tuple) and all(isinstance(v, int) for v in target):
        # (0, 1, 2) is no list of modes ("target mode 0 is invalid" blamed one of its entries)
        raise ParameterError(
            f"target = {target!r} is invalid; give (m, n), two integers, or a list of modes"
        )
    if isinstance(target, (tuple, list, set, frozenset)) and target:
        modes = tuple(sorted({_mode(t) for t in target}))
        text = "[" + ", ".join(f"({m}, {n})" for m, n in modes) + "]"
        return Target(text, lambda m, n: (m, n) in modes, modes)
    raise ParameterError(
        f"target = {target!r} is invalid; give (m, n), a list of modes, a callable (m, n) ->"
        f" bool or one of {', '.join(NAMED_SETS)}"
    )
