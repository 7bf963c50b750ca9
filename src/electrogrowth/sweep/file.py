"""Reading a sweep file (TOML, stdlib ``tomllib``) into a :class:`SweepConfig`.

Everything is checked before any work starts. A mistake raises
:class:`sweep_config.ConfigError` naming the file, the line and the key, e.g.
``sweep.toml:18: grid.outer_radius: outer radius Rbar_o = 0.5 is out of range; ...``.
tomllib keeps no positions, so the line is found by scanning the text for the key
(:func:`line_of`). The tables and keys are listed in sweep/config.py and docs/sweeps.md.
"""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import numpy as np

from ..bifurcation.scan import ScanOptions
from ..errors import ConfigError, ParameterError
from ..model import toml_input
from ..model.controls import parse_control
from ..model.layers import Tube
from ..model.toml_input import SWEEP_UNITS, parse, read_text, shown, typename
from ..model.tube_file import parse_tube
from .config import MODE_KEYS, SweepConfig, default_chunk, reference_tube, sweep_keys

#: table -> allowed keys (None: free keys, checked by the table's own rules; [fixed] and
#: [grid] take the names of the sweep's tube, config.sweep_keys)
TABLES = {
    "solve": ("for", "side", "rtol", "layer", "component", "koiter"),
    "modes": tuple(MODE_KEYS),
    "material": None,
    "fixed": None,
    "grid": None,
    "run": ("chunk",),
    "tube": ("file",),
}

# a sweep's numbers: a quantity given as text gets the sweep's remedy, not the tube file's
finite = functools.partial(toml_input.finite, units=SWEEP_UNITS)
number = functools.partial(toml_input.number, units=SWEEP_UNITS)
units_hint = functools.partial(toml_input.units_hint, units=SWEEP_UNITS)


#: The most values a {start, stop, num} range may ask for (a sweep file is read before any
#: check of the whole grid: num = 1e12 would have allocated 8 TB).
MAX_AXIS = 1_000_000


def load_config(path: str | Path) -> SweepConfig:
    """Read and validate a sweep file; raise :class:`ConfigError` naming file and line."""
    return parse_config(read_text(path, "sweep file"), source=str(path))


def parse_config(text: str, *, source: str = "<sweep>") -> SweepConfig:
    """Validate the TOML ``text`` of a sweep file (see the module docstring); a [tube] file
    is read relative to the sweep file's directory."""
    base = Path(source).parent if not source.startswith("<") else Path.cwd()
    build = functools.partial(_from_raw, base=base)
    return parse(text, source, build, line_of, what="sweep file", example="examples/sweep.toml")


def _from_raw(raw: dict, base: Path = Path()) -> SweepConfig:
    """The SweepConfig of a sweep file's tables: of its [tube] file's tube, or of the
    paper's tube (every key not given at its default) with its [material]."""
    _check_tables(raw)
    solve, modes, run = (raw.get(t, {}) for t in ("solve", "modes", "run"))
    if "for" not in solve:
        raise ConfigError(("solve",), "missing key 'for' (growth, stretch or voltage)")
    text, tube = _tube_file(raw, base) if "tube" in raw else (None, reference_tube(None))
    keys = sweep_keys(text, tube)
    for table in ("fixed", "grid"):  # the paper's tube takes its keys; a tube file's, Tube.at
        for key in raw.get(table, {}):
            if keys is not None and key not in keys:
                raise ConfigError((table, key), f"unknown key; [{table}] takes {', '.join(keys)}")
    solve_for = _solve_for(solve, tube if text is not None else None)
    material, energy = _material_table(raw.get("material", {}))
    fixed = {key: number(raw.get("fixed", {}), ("fixed",), key) for key in raw.get("fixed", {})}
    grid = tuple((key, _grid_values(key, value)) for key, value in raw.get("grid", {}).items())
    for key in fixed:
        if key == solve_for:
            raise ConfigError(("fixed", key), f"{key} is what is solved for; remove it")
        if key in dict(grid):
            raise ConfigError(("fixed", key), f"{key} is also swept in [grid]; keep one")
    if solve_for in dict(grid):
        raise ConfigError(
            ("grid", solve_for), f"{solve_for} is what is solved for; it cannot be swept"
        )
    if text is None:  # the paper's tube: the store holds every one of its numbers
        fixed = _with_defaults(tube, fixed, grid, solve_for)
    chunk = _integer(run, ("run",), "chunk") if "chunk" in run else None
    return SweepConfig(
        solve_for=solve_for,
        grid=grid,
        fixed=tuple(fixed.items()),
        material=material,
        energy=energy,
        side=_string(solve, ("solve",), "side") if "side" in solve else None,
        rtol=number(solve, ("solve",), "rtol") if "rtol" in solve else 1e-12,
        scan=_scan_options(modes),
        chunk=chunk if chunk is not None else default_chunk(math.prod(len(v) for _, v in grid)),
        tube=text,
        koiter=_bool(solve, ("solve",), "koiter") if "koiter" in solve else False,
    )


def _check_tables(raw: dict) -> None:
    """Every table is known and a table, every key of a table with fixed keys is one."""
    for table, value in raw.items():
        if table not in TABLES:
            raise ConfigError(
                (table,),
                f"unknown key; the sweep file has the tables"
                f" {', '.join(f'[{t}]' for t in TABLES)}",
            )
        if not isinstance(value, dict):
            raise ConfigError((table,), f"expected a table [{table}], got {typename(value)}")
        allowed = TABLES[table]
        for key in value:
            if allowed is not None and key not in allowed:
                raise ConfigError(
                    (table, key), f"unknown key; [{table}] takes {', '.join(allowed)}"
                )


def _tube_file(raw: dict, base: Path) -> tuple[str, Tube]:
    """The text and tube of the [tube] file (relative to the sweep file's folder), which
    replaces [material]."""
    if "material" in raw:
        raise ConfigError(("material",), "the materials come from the [tube] file; remove it")
    if "file" not in raw["tube"]:
        raise ConfigError(("tube",), "missing key 'file' (the tube file, relative to this file)")
    path = base / _string(raw["tube"], ("tube",), "file")
    try:
        text = read_text(path, "tube file")
        return text, parse_tube(text, source=str(path))
    except ConfigError as exc:
        raise ConfigError(("tube", "file"), str(exc)) from None


def _solve_for(solve: dict, tube: Tube | None) -> str:
    """[solve] for, with a tube file's layer and component folded into the control's name
    as that tube writes it; the paper's tube (``tube`` None) takes the name as written,
    which SweepConfig checks against its controls."""
    name = _string(solve, ("solve",), "for")
    if tube is None:
        for key in ("layer", "component"):
            if key in solve:
                raise ConfigError(("solve", key), "applies only to a sweep with a [tube] file")
        return name
    layer = _integer(solve, ("solve",), "layer") if "layer" in solve else None
    comp = _string(solve, ("solve",), "component") if "component" in solve else None
    try:
        return str(tube.check_control(parse_control(name, layer, comp)))
    except ParameterError as exc:
        raise ConfigError(("solve", "for"), str(exc)) from None


def _material_table(mat: dict) -> tuple[tuple[str, tuple[tuple[str, float], ...]], str]:
    """[material]: (name, parameters) and the energy text ("" unless given)."""
    mat = dict(mat)
    energy = _string(mat, ("material",), "energy") if "energy" in mat else ""
    mat.pop("energy", None)
    if energy and mat:
        raise ConfigError(
            ("material", "energy"), "give either energy or a name and its parameters, not both"
        )
    name = _string(mat, ("material",), "name") if "name" in mat else "neo-hookean"
    mat.pop("name", None)
    return (name, tuple((key, number(mat, ("material",), key)) for key in mat)), energy


def _with_defaults(tube: Tube, fixed: dict, grid: tuple, solve_for: str) -> dict:
    """Every key of the paper's tube neither swept nor solved for: given, or the default
    (``tube`` is Tube.uniform() at its defaults); the outer radius has none."""
    if "outer_radius" not in fixed and "outer_radius" not in dict(grid):
        raise ConfigError(
            ("fixed",),
            "missing outer_radius (Rbar_o > 1): give it in [fixed] or sweep it in [grid]",
        )
    return {
        key: fixed.get(key, tube.value_of(key))
        for key in tube.parameter_keys()
        if key != solve_for and key not in dict(grid)
    }


def _scan_options(modes: dict) -> ScanOptions:
    """The [modes] table as ScanOptions, its defaults where a key is absent; an invalid
    entry is a ConfigError naming it. Each key is read as its default's type: a range is
    two integers, a switch true or false, a count an integer."""
    default, given = ScanOptions(), {}
    for key, field in MODE_KEYS.items():
        if key in modes:
            like = getattr(default, field)
            if isinstance(like, tuple):
                given[field] = _int_pair(modes, key)
            else:
                read = _bool if isinstance(like, bool) else _integer
                given[field] = read(modes, ("modes",), key)
    keys = {field: key for key, field in MODE_KEYS.items()}
    for field, value in given.items():  # one at a time: the error names the entry
        try:
            ScanOptions(**{field: value})
        except ParameterError as exc:
            raise ConfigError(("modes", keys[field]), str(exc)) from None
    return ScanOptions(**given)


def _grid_values(key: str, value) -> tuple[float, ...]:
    where = ("grid", key)
    if isinstance(value, dict):
        for k in value:
            if k not in ("start", "stop", "num"):
                raise ConfigError(where + (k,), "unknown key; a range takes start, stop, num")
        for k in ("start", "stop", "num"):
            if k not in value:
                raise ConfigError(where, f"a range needs start, stop and num; {k} is missing")
        start, stop = number(value, where, "start"), number(value, where, "stop")
        num = _integer(value, where, "num")
        if num < 1:
            raise ConfigError(
                where + ("num",), f"num = {shown(num)} gives an empty grid; need num >= 1"
            )
        if num > MAX_AXIS:
            raise ConfigError(
                where + ("num",),
                f"num = {shown(num)} is out of range; need 1 <= num <= {MAX_AXIS}",
            )
        values = [float(v) for v in np.linspace(start, stop, num)]
    elif isinstance(value, list):
        if not value:
            raise ConfigError(where, "empty grid; give at least one value")
        values = []
        for i, v in enumerate(value):
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise ConfigError(
                    where,
                    f"value {i + 1} is {typename(v)} {shown(v)}, not a number{units_hint(v)}",
                )
            values.append(finite(v, where))
    else:
        raise ConfigError(
            where,
            f"expected a list of numbers or a range {{start, stop,"
            f" num}}, got {typename(value)} {shown(value)}{units_hint(value)}",
        )
    ordered = sorted(values)
    for a, b in zip(ordered, ordered[1:]):
        if a == b:
            raise ConfigError(where, f"the value {a!r} appears twice")
    return tuple(ordered)


# -- types -----------------------------------------------------------------------------------


def _string(table, where, key):
    v = table[key]
    if not isinstance(v, str):
        raise ConfigError(where + (key,), f"expected a string, got {typename(v)} {shown(v)}")
    return v


def _integer(table, where, key):
    v = table[key]
    if isinstance(v, bool) or not isinstance(v, int):
        raise ConfigError(where + (key,), f"expected an integer, got {typename(v)} {shown(v)}")
    return v


def _bool(table, where, key):
    v = table[key]
    if not isinstance(v, bool):
        raise ConfigError(where + (key,), f"expected true or false, got {typename(v)} {shown(v)}")
    return v


def _int_pair(table, key):
    v = table[key]
    if (
        not isinstance(v, list)
        or len(v) != 2
        or any(isinstance(x, bool) or not isinstance(x, int) for x in v)
    ):
        raise ConfigError(
            ("modes", key),
            f"expected an inclusive range [{key}_min, {key}_max] of two integers, got {shown(v)}",
        )
    return (v[0], v[1])


# -- line numbers ----------------------------------------------------------------------------

_HEADER = re.compile(r"^\s*\[\s*([^\[\]]+?)\s*\]")
_KEY = re.compile(
    r"""^\s*((?:[A-Za-z0-9_-]+|"[^"]*"|'[^']*')"""
    r"""(?:\s*\.\s*(?:[A-Za-z0-9_-]+|"[^"]*"|'[^']*'))*)\s*="""
)


_PART = re.compile(r"""[A-Za-z0-9_-]+|"[^"]*"|'[^']*'""")


def _split_key(text: str) -> tuple[str, ...]:
    """The parts of a dotted TOML key; a quoted part keeps its dots ("layers[2].mu")."""
    return tuple(p.strip("\"'") for p in _PART.findall(text))


def line_of(text: str, key: tuple[str, ...]) -> int | None:
    """The line of ``key`` (a dotted path) in TOML ``text``, or of its nearest ancestor.

    tomllib keeps no positions, so this scans the text: it follows the ``[table]`` headers
    and finds ``name =`` lines; a key inside an inline table or array is reported at the
    line of the entry that holds it. None when not even the table appears.
    """
    if not key:
        return None
    table: tuple[str, ...] = ()
    best, depth = None, 0
    for lineno, line in enumerate(text.splitlines(), 1):
        head = _HEADER.match(line)
        if head:
            table = _split_key(head.group(1))
            if key[: len(table)] == table and len(table) > depth:
                best, depth = lineno, len(table)
            continue
        found = _KEY.match(line)
        if found:
            path = table + _split_key(found.group(1))
            n = min(len(path), len(key))
            if path[:n] == key[:n] and n > depth and path[: len(table)] == key[: len(table)]:
                best, depth = lineno, n
    return best
