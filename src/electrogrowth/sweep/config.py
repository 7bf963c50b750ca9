"""A sweep: a grid of tubes, the fixed parameters, the material and what to solve for.

:class:`SweepConfig` validates itself; a mistake raises :class:`ConfigError`, which names
the offending key (sweep/file.py adds the file and line). Read from a TOML file
(sweep/file.py, docs/sweeps.md) with the tables::

    [solve]     for = "growth" | "stretch" | "voltage"       (required)
                side = "compression" | "extension"           (stretch only)
                rtol = 1e-12                                  (1e-14 .. 1e-4)
                koiter = false   also the wrinkle's amplitude equation (not for the force)
    [modes]     m = [0, 12], n = [1, 30], extend = true, top = 5, surface = true,
                prismatic = true, torsional = true            (every ScanOptions field)
    [material]  name = "neo-hookean" | "gent" | "mooney-rivlin", and its parameters;
                or energy = "(I1 - 3)/2 + I5/2" (an energy as text, model/energy_text.py)
    [fixed]     outer_radius, length, growth, stretch, voltage   (numbers)
    [grid]      any of the same names = [v1, v2, ...] or {start, stop, num}
    [run]       chunk = grid points per task (default from the grid size)
    [tube]      file = "bilayer.toml"   a layered tube (model/tube_file.py) instead of
                [material] and the one-layer parameters; then [solve] for is any control
                of it (growth[K].theta, pressure, force, ...; or for = "growth" with
                layer = K, component = "theta") and [fixed] / [grid] take its controls
                and keys (model/layers.py Tube.at: "layers[1].thickness",
                "layers[1].shear_modulus", "growth[1].theta", voltage, pressure, ...).

Both kinds of sweep take one path: the sweep's :func:`reference_tube` (the tube file's
tube, or the paper's tube ``Tube.uniform()`` with the sweep's material) is what every name
and value is checked on, and every point is that tube with the [fixed] values and then the
point's grid values set by ``Tube.at``. The names a sweep of the paper's tube takes are
that tube's ``parameter_keys()``, and it solves for the controls among them (see
:func:`sweep_keys`).

A parameter is either fixed or swept, never both, and never the one solved for; unset
ones take the :meth:`~electrogrowth.Tube.uniform` defaults, except the outer
radius, which must be given (with a tube file: the file's values).
"""

from __future__ import annotations

import dataclasses
import inspect
import json
import math
from typing import Any

import numpy as np

from ..bifurcation.koiter_controls import COVERED as KOITER_COVERED
from ..bifurcation.scan import ScanOptions
from ..errors import ConfigError, ElectrogrowthError, ParameterError
from ..incremental.accuracy import RTOL_RANGE
from ..model.controls import SIDED, SIDES, TUBE_CONTROLS, parse_control
from ..model.energy_text import energy_material
from ..model.layers import Tube
from ..model.materials import BUILTIN, Material, material_by_name
from ..model.toml_input import SWEEP_UNITS, shown, typename, units_hint
from ..model.tube_file import parse_tube
from .unit import ScanSpec

#: The [modes] keys a store has always held, in its order: a sweep stores them always.
ALWAYS_STORED = ("m", "n", "extend", "top")
#: The [modes] keys and the ScanOptions field each sets: every field, named without
#: "_range", so a new scan option is a sweep option too (read as its default's type, stored
#: and compared on resume). The keys beyond ALWAYS_STORED are stored only where they differ
#: from the default, so a sweep that leaves them alone stores what stores always held.
_FIELDS = {f.name.removesuffix("_range"): f.name for f in dataclasses.fields(ScanOptions)}
MODE_KEYS = {key: _FIELDS[key] for key in ALWAYS_STORED} | _FIELDS
#: The most grid points of one sweep: 1e7 points are days of a large cluster, and the store's
#: completion marks of a larger grid are read whole into memory (docs/security.md).
MAX_POINTS = 10_000_000
#: The most mode records (points x top) a sweep's store may hold: refused up front rather
#: than filling the disk and the memory of whoever opens it.
MAX_MODE_RECORDS = 10**8


def reference_tube(tube_text: str | None, material: Material | None = None) -> Tube:
    """The tube a sweep's names and values are checked on and its points start from,
    before the [fixed] values: the [tube] file's tube, or (no file) the paper's tube
    ``Tube.uniform()`` at its defaults with ``material`` (default neo-Hookean)."""
    if tube_text is None:
        return Tube.uniform(material=material)
    return parse_tube(tube_text, source="[tube] file")


def sweep_keys(tube_text: str | None, tube: Tube) -> tuple[str, ...] | None:
    """The names [fixed] and [grid] take: a sweep without a [tube] file is of the paper's
    tube and takes its ``parameter_keys()`` only (any other key, a layer's modulus, a
    pressure, one growth component, would make it another tube than the paper's); a tube
    file's sweep takes every control and key ``Tube.at`` accepts (None: ask the tube)."""
    return tube.parameter_keys() if tube_text is None else None


@dataclasses.dataclass(frozen=True)
class SweepConfig:
    """A validated sweep: the grid, the fixed parameters, the material and the scan options.

    ``grid`` keeps the file's order (it is the order of the dataset's dimensions); its
    values are sorted and distinct. ``fixed`` holds every other tube parameter except the
    one solved for, defaults filled in.
    """

    solve_for: str
    grid: tuple[tuple[str, tuple[float, ...]], ...]
    fixed: tuple[tuple[str, float], ...]
    material: tuple[str, tuple[tuple[str, float], ...]] = ("neo-hookean", ())
    side: str | None = None
    rtol: float = 1e-12
    scan: ScanOptions = ScanOptions()
    chunk: int = 1
    tube: str | None = None  # the TOML text of a layered tube file, if the sweep has one
    energy: str = ""  # an energy as text (model/energy_text.py) in place of ``material``
    koiter: bool = False  # also the amplitude equation of each point's wrinkle (branch)

    def __post_init__(self):
        _validate(self)

    @property
    def dims(self) -> tuple[str, ...]:
        return tuple(name for name, _ in self.grid)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(values) for _, values in self.grid)

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    @property
    def spec(self) -> ScanSpec:
        """The options of every point's mode scan. A side of a control that has none (a
        tube file's sweep accepts one, for the stores written so far) is left out: the scan
        refuses it (model/controls.check_side), and it never changed a point."""
        side = self.side if parse_control(self.solve_for).kind in SIDED else None
        return ScanSpec(self.solve_for, side, self.scan, self.rtol, self.koiter)

    def build_material(self):
        if self.energy:
            return energy_material(self.energy)
        name, params = self.material
        return material_by_name(name, **dict(params))

    def reference(self, material: Material | None = None) -> Tube:
        """The tube before the [fixed] values (:func:`reference_tube`; ``material``, when
        given, is this sweep's, already built)."""
        if self.tube is None and material is None:
            material = self.build_material()
        return reference_tube(self.tube, material)

    def points(self, index_slices, material: Material | None = None) -> list[Tube]:
        """The tubes of a block of the grid (tuple of slices), in C order: the reference
        tube with the [fixed] values, then each point's grid values, set by ``Tube.at``."""
        axes = [values[s] for (_, values), s in zip(self.grid, index_slices)]
        base = self.reference(material)
        for name, value in self.fixed:
            base = base.at(name, value)
        out = []
        for combo in np.ndindex(*(len(a) for a in axes)):
            tube = base
            for name, axis, i in zip(self.dims, axes, combo):
                tube = tube.at(name, axis[i])
            out.append(tube)
        return out

    def to_dict(self) -> dict:
        """A JSON-ready dict (stored in the dataset attributes; see :meth:`from_dict`)."""
        return {
            "solve": {
                "for": self.solve_for,
                "side": self.side,
                "rtol": self.rtol,
                **({"koiter": True} if self.koiter else {}),  # stores before it stay equal
            },
            "modes": _modes_dict(self.scan),
            "material": (
                {"energy": self.energy}
                if self.energy
                else {"name": self.material[0], **dict(self.material[1])}
            ),
            "fixed": dict(self.fixed),
            "grid": {name: list(values) for name, values in self.grid},
            "run": {"chunk": self.chunk},
            **({} if self.tube is None else {"tube": {"text": self.tube}}),
        }

    def to_json(self) -> str:
        return json.dumps(self.to_dict())

    @classmethod
    def from_dict(cls, d: dict) -> SweepConfig:
        mat = dict(d["material"])
        energy = mat.pop("energy", "")
        return cls(
            solve_for=d["solve"]["for"],
            side=d["solve"]["side"],
            rtol=d["solve"]["rtol"],
            grid=tuple((k, tuple(v)) for k, v in d["grid"].items()),
            fixed=tuple(d["fixed"].items()),
            material=(mat.pop("name", "neo-hookean"), tuple(mat.items())),
            energy=energy,
            scan=_modes_options(d["modes"]),
            chunk=d["run"]["chunk"],
            tube=d["tube"]["text"] if "tube" in d else None,
            koiter=d["solve"].get("koiter", False),  # a store written before it: not asked
        )


def _modes_dict(scan: ScanOptions) -> dict:
    """The [modes] table of ``scan``, keyed by name: the first four always, the others
    where they differ from the default (MODE_KEYS)."""
    default = ScanOptions()
    out = {}
    for key, field in MODE_KEYS.items():
        value = getattr(scan, field)
        if key in ALWAYS_STORED or value != getattr(default, field):
            out[key] = list(value) if isinstance(value, tuple) else value
    return out


def _modes_options(modes: dict) -> ScanOptions:
    """ScanOptions from a stored [modes] table, by name; a key it lacks (a store written
    before that option was stored) takes today's default, an unknown key is refused."""
    for key in modes:
        if key not in MODE_KEYS:
            raise ValueError(f"modes.{key} is not a scan option; known: {', '.join(MODE_KEYS)}")
    given: dict[str, Any] = {
        field: tuple(modes[key]) if field.endswith("_range") else modes[key]
        for key, field in MODE_KEYS.items()
        if key in modes
    }
    return ScanOptions(**given)


def differences(a: SweepConfig, b: SweepConfig) -> list[str]:
    """Dotted keys at which two configurations differ (empty when they are the same)."""
    da, db = a.to_dict(), b.to_dict()
    out = []
    for table in da:
        keys = list(dict.fromkeys([*da[table], *db[table]]))
        out += [f"{table}.{k}" for k in keys if da[table].get(k) != db[table].get(k)]
    if not out and a.dims != b.dims:
        out.append("grid (the order of the swept parameters)")
    return out


def default_chunk(size: int) -> int:
    """Grid points per task: one for small sweeps, up to 32 for large ones, which still
    leaves at least 64 tasks to spread over the workers. A task costs a few milliseconds
    to schedule and to write (about 15 Zarr chunk files), and a point takes 0.05 s to
    seconds."""
    return max(1, min(32, size // 64))


# -- semantic checks (also run when a config is rebuilt from a store's attributes) -----------


def _validate(c: SweepConfig) -> None:
    """Every check of a sweep, of the paper's tube or of a tube file alike: the names and
    values are checked on the reference tube (each value alone, set by ``Tube.at``)."""
    tube = _reference(c)
    keys = sweep_keys(c.tube, tube)
    _check_solve(c, tube, keys)
    _check_koiter(c)
    _check_run(c)
    if not c.grid:
        what = f"at least one of {', '.join(keys)}" if keys else "a control or key of the tube"
        raise ConfigError(("grid",), f"nothing to sweep; give {what} in [grid]")
    fixed = [(name, (value,)) for name, value in c.fixed]
    for table, items in (("grid", c.grid), ("fixed", fixed)):
        for name, _ in items:
            if keys is not None and name not in keys:
                raise ConfigError(
                    (table, name), f"unknown parameter; use any of {', '.join(keys)}"
                )
            if name == c.solve_for:
                raise ConfigError(
                    (table, name), f"{name} is what is solved for; it cannot be given"
                )
            if table == "fixed" and name in c.dims:
                raise ConfigError((table, name), f"{name} is also swept in [grid]; keep one")
    for name, values in c.grid:
        if not values or list(values) != sorted(set(values)):
            raise ConfigError(("grid", name), "need distinct values in increasing order")
    # Each value is checked alone on the reference tube, whose other values are valid, so
    # the error names the entry that is wrong.
    for table, items in (("fixed", fixed), ("grid", c.grid)):
        for name, values in items:
            for value in values:
                _check_value(tube, name, value, (table, name))


def _reference(c: SweepConfig) -> Tube:
    """The reference tube of ``c``, a mistake in the tube file or the material a
    ConfigError naming it."""
    if c.tube is not None:
        try:
            return reference_tube(c.tube)
        except ConfigError as exc:
            raise ConfigError(("tube", "file"), str(exc)) from None
    return reference_tube(None, _energy(c.energy) if c.energy else _material(c.material))


def _check_solve(c: SweepConfig, tube: Tube, keys: tuple[str, ...] | None) -> None:
    """What is solved for is a control of the tube, written as the tube names it. The
    paper's tube solves for the controls among its keys, and of those only the stretch
    takes a side; a tube file's sweep takes a side for any control, as the stores written
    so far may (a stricter rule would make them unreadable)."""
    if keys is not None:
        controls = [k for k in keys if k in TUBE_CONTROLS]
        if c.solve_for not in controls:
            raise ConfigError(
                ("solve", "for"), f"{c.solve_for!r} is unknown; choose {_or(controls)}"
            )
        sided = [f'"{k}"' for k in controls if k in SIDED]
        if c.side is not None and f'"{c.solve_for}"' not in sided:
            raise ConfigError(("solve", "side"), f"side applies only to for = {_or(sided)}")
    try:
        name = str(tube.check_control(c.solve_for))
    except ParameterError as exc:
        raise ConfigError(("solve", "for"), str(exc)) from None
    if name != c.solve_for:
        raise ConfigError(("solve", "for"), f"write it as {name!r}")


def _check_koiter(c: SweepConfig) -> None:
    """koiter = true asks for the amplitude equation, which covers some controls only
    (bifurcation/koiter_controls.py): any other control would give no branch at any point."""
    if not isinstance(c.koiter, bool):
        raise ConfigError(
            ("solve", "koiter"), f"expected a boolean, got {typename(c.koiter)} {shown(c.koiter)}"
        )
    covered = sorted({kind for kinds in KOITER_COVERED.values() for kind in kinds})
    if c.koiter and parse_control(c.solve_for).kind not in covered:
        raise ConfigError(
            ("solve", "koiter"),
            f"the amplitude equation covers {', '.join(covered)} so far, not for ="
            f" {c.solve_for!r}; remove koiter or solve for one of those",
        )


def _check_value(tube: Tube, name: str, value, where: tuple[str, ...]) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        got = f"{typename(value)} {shown(value)}{units_hint(value, SWEEP_UNITS)}"
        raise ConfigError(where, f"expected a number, got {got}")
    try:
        tube.at(name, value)
    except ParameterError as exc:
        raise ConfigError(where, str(exc)) from None


def _or(names) -> str:
    """'a, b or c'."""
    names = list(names)
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} or {names[-1]}"


def _check_run(c: SweepConfig) -> None:
    """The side's name, rtol and chunk: the checks every sweep shares."""
    if c.side is not None and c.side not in SIDES:
        raise ConfigError(
            ("solve", "side"), f"{c.side!r} is unknown; choose compression or extension"
        )
    if not RTOL_RANGE[0] <= c.rtol <= RTOL_RANGE[1]:
        raise ConfigError(
            ("solve", "rtol"), f"rtol = {c.rtol!r} is out of range; valid range: 1e-14 to 1e-4"
        )
    if c.chunk < 1:
        raise ConfigError(("run", "chunk"), f"chunk = {c.chunk} is invalid; need >= 1")
    if c.size > MAX_POINTS:
        raise ConfigError(
            ("grid",),
            f"{c.size:.3g} grid points, more than the limit {MAX_POINTS:.0e}; split the sweep",
        )
    if c.size * c.scan.top > MAX_MODE_RECORDS:
        raise ConfigError(
            ("modes", "top"),
            f"top = {c.scan.top} modes at each of {c.size:,} points is"
            f" {c.size * c.scan.top:,} mode records; the store holds at most"
            f" {MAX_MODE_RECORDS:.0e}: lower top or the grid",
        )


def _energy(text: str):
    try:
        return energy_material(text)
    except ElectrogrowthError as exc:
        raise ConfigError(("material", "energy"), str(exc)) from None


def _material(material):
    name, params = material
    if name not in BUILTIN:
        raise ConfigError(
            ("material", "name"), f"unknown material {name!r}; choose one of {', '.join(BUILTIN)}"
        )
    accepted = list(inspect.signature(BUILTIN[name]).parameters)
    for key, _ in params:
        if key not in accepted:
            takes = f"takes {', '.join(accepted)}" if accepted else "takes no parameters"
            raise ConfigError(("material", key), f"unknown key; material {name!r} {takes}")
    try:
        return material_by_name(name, **dict(params))
    except ElectrogrowthError as exc:
        key = ("material", params[0][0]) if params else ("material", "name")
        raise ConfigError(key, str(exc)) from None
