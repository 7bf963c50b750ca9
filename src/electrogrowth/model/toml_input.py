"""Reading a TOML input file (a tube file, a sweep file): the text, the TOML, and every
error as one ConfigError naming the file, the line and the key."""

from __future__ import annotations

import json
import math
import re
import stat
import tomllib
from collections.abc import Callable
from pathlib import Path

from ..errors import ConfigError

#: The largest tube or sweep file read (a real one is a few hundred bytes).
MAX_FILE_BYTES = 1_000_000


def read_text(path: str | Path, what: str) -> str:
    """The UTF-8 text of ``path`` (a leading byte-order mark dropped, line ends made "\\n");
    ConfigError if it cannot be read (``what``: "tube file").

    Only a regular file of at most :data:`MAX_FILE_BYTES` is read: a path naming a
    directory, a device (``/dev/zero`` never ends) or a pipe is refused before reading.
    """
    path = Path(path)
    try:
        info = path.stat()
        if not stat.S_ISREG(info.st_mode):
            kind = "a directory" if stat.S_ISDIR(info.st_mode) else "not a regular file"
            raise ConfigError((), f"the {what} is {kind}; give a TOML file", source=str(path))
        if info.st_size > MAX_FILE_BYTES:
            raise ConfigError(
                (),
                f"the {what} has {info.st_size} bytes, more than the limit {MAX_FILE_BYTES}",
                source=str(path),
            )
        with path.open("rb") as fh:
            data = fh.read(MAX_FILE_BYTES + 1)  # the file may have grown since stat
    except OSError as exc:
        raise ConfigError(
            (), f"cannot read the {what}: {exc.strerror}", source=str(path)
        ) from None
    if len(data) > MAX_FILE_BYTES:
        raise ConfigError((), f"the {what} grew beyond {MAX_FILE_BYTES} bytes", source=str(path))
    try:  # utf-8-sig: a leading byte-order mark (Windows editors' "UTF-8 with BOM") dropped
        return data.decode("utf-8-sig").replace("\r\n", "\n").replace("\r", "\n")
    except UnicodeDecodeError:
        raise ConfigError((), f"the {what} is not UTF-8 text", source=str(path)) from None


def parse(text: str, source: str, build: Callable, line_of: Callable, *, what: str = "file",
          example: str = ""):  # fmt: skip
    """``build(raw)`` of the TOML ``text``; its ConfigErrors (and TOML syntax errors) get the
    ``source`` and the line ``line_of(text, key)`` of the offending key. A JSON text (``what``:
    "tube file") is told that the file is TOML, as ``example`` is."""
    try:
        raw = tomllib.loads(text)
    except RecursionError:
        raise ConfigError((), "invalid TOML: nested too deeply", source=source) from None
    except ValueError as exc:
        if not isinstance(exc, tomllib.TOMLDecodeError):  # Python's limit on int("...")
            raise ConfigError(
                (), "invalid TOML: an integer of more than 4300 digits", source=source
            ) from None
        msg = str(exc)
        hit = re.search(r"\(at line (\d+), column \d+\)", msg)
        line = int(hit.group(1)) if hit else text.count("\n") + 1
        reason = re.sub(r"\s*\(at (line \d+, column \d+|end of document)\)", "", msg)
        if _is_json(text, source):  # "Invalid statement" alone did not say TOML was wanted
            like = f", as {example}" if example else ""
            reason += f"; this is JSON, and a {what} is TOML: key = value lines and [tables]{like}"
        raise ConfigError((), f"invalid TOML: {reason}", source=source, line=line) from None
    try:
        return build(raw)
    except ConfigError as exc:
        raise ConfigError(
            exc.key, exc.reason, source=source, line=line_of(text, exc.key)
        ) from None


def _is_json(text: str, source: str) -> bool:
    """The text of a JSON object or array, or a file named .json (the TOML reader failed)."""
    if source.lower().endswith(".json"):
        return True
    try:
        return isinstance(json.loads(text), (dict, list))
    except ValueError:  # not JSON either (a JSON number or string is no tube: TOML's error)
        return False


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


#: where a tube file's physical values go: the commands that read it take physical units
TUBE_UNITS = (
    "give physical units on the command line (e.g. --voltage 3kV with --inner-radius,"
    " --shear-modulus and --permittivity), or the value in those units"
)
#: a sweep takes no physical units (its command has no such options, check round 29 D7)
SWEEP_UNITS = (
    "convert the value to those units (a length / R_i, a modulus or pressure / mu, a"
    " permittivity / eps, a voltage to Vbar = V / (R_o - R_i) sqrt(eps / mu)); a sweep"
    " takes no physical units"
)


def finite(v, path: tuple, units: str = TUBE_UNITS) -> float:
    """``v`` as a finite float, or ConfigError at the key ``path`` (``units``: the remedy
    of a quantity given as text, :func:`units_hint`)."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        got = f"{typename(v)} {shown(v)}{units_hint(v, units)}"
        raise ConfigError(path, f"expected a number, got {got}")
    try:
        value = float(v)
    except OverflowError:  # an integer beyond the largest double
        value = math.inf
    if not math.isfinite(value):
        raise ConfigError(path, f"{shown(v)} is not a finite number (largest double 1.8e308)")
    return value


#: a string that reads as a quantity: a number and a unit ("3 kV", "2.8mm")
_QUANTITY = re.compile(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*[A-Za-z\u00b5\u03bc]")


def units_hint(v, units: str = TUBE_UNITS) -> str:
    """For a quantity given where a file wants a number ("3 kV"): where units go, as the
    file's kind says (``units``: TUBE_UNITS or SWEEP_UNITS)."""
    if not (isinstance(v, str) and _QUANTITY.match(v)):
        return ""
    return f"; files hold non-dimensional values (mu = eps = R_i = 1): {units}"


def shown(v, limit: int = 60) -> str:
    """``repr(v)`` cut to ``limit`` characters, for an error message."""
    text = repr(v)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def number(table: dict, where: tuple, key: str, units: str = TUBE_UNITS) -> float:
    """``table[key]`` as a finite float, or ConfigError at ``where + (key,)``."""
    return finite(table[key], where + (key,), units)
