"""Reading a TOML input file (a tube file, a sweep file): the text, the TOML, and every
error as one ConfigError naming the file, the line and the key."""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Callable
from pathlib import Path

from ..errors import ConfigError


def read_text(path: str | Path, what: str) -> str:
    """The UTF-8 text of ``path``; ConfigError if it cannot be read (``what``: "tube file")."""
    try:
        return Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise ConfigError(
            (), f"cannot read the {what}: {exc.strerror}", source=str(path)
        ) from None
    except UnicodeDecodeError:
        raise ConfigError((), f"the {what} is not UTF-8 text", source=str(path)) from None


def parse(text: str, source: str, build: Callable, line_of: Callable):
    """``build(raw)`` of the TOML ``text``; its ConfigErrors (and TOML syntax errors) get the
    ``source`` and the line ``line_of(text, key)`` of the offending key."""
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        hit = re.search(r"\(at line (\d+), column \d+\)", msg)
        line = int(hit.group(1)) if hit else text.count("\n") + 1
        reason = re.sub(r"\s*\(at (line \d+, column \d+|end of document)\)", "", msg)
        raise ConfigError((), f"invalid TOML: {reason}", source=source, line=line) from None
    try:
        return build(raw)
    except ConfigError as exc:
        raise ConfigError(
            exc.key, exc.reason, source=source, line=line_of(text, exc.key)
        ) from None


# -- typed values ------------------------------------------------------------------------------


def typename(v) -> str:
    """How a TOML value's type reads in an error message ("an integer", "a table", ...)."""
    return {
        bool: "a boolean",
        int: "an integer",
        float: "a number",
        str: "a string",
        list: "a list",
        dict: "a table",
    }.get(type(v), type(v).__name__)


def finite(v, path: tuple) -> float:
    """``v`` as a finite float, or ConfigError at the key ``path``."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise ConfigError(path, f"expected a number, got {typename(v)} {v!r}")
    if not math.isfinite(v):
        raise ConfigError(path, f"{v!r} is not a finite number")
    return float(v)


def number(table: dict, where: tuple, key: str) -> float:
    """``table[key]`` as a finite float, or ConfigError at ``where + (key,)``."""
    return finite(table[key], where + (key,))
