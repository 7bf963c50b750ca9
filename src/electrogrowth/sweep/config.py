"""A sweep: a grid of tubes, the fixed parameters, the material and what to solve for.

:class:`SweepConfig` validates itself; a mistake raises :class:`ConfigError`, which names
the offending key (sweep/file.py adds the file and line). Read from a TOML file
(sweep/file.py, docs/sweeps.md) with the tables::

    [solve]     for = "growth" | "stretch" | "voltage"       (required)
                side = "compression" | "extension"           (stretch only)
                rtol = 1e-12                                  (1e-14 .. 1e-4)
    [modes]     m = [0, 12], n = [1, 30], extend = true, top = 5
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

A parameter is either fixed or swept, never both, and never the one solved for; unset
ones take the :meth:`~electrogrowth.Tube.uniform` defaults, except the outer
radius, which must be given (with a tube file: the file's values).
"""

from __future__ import annotations

import dataclasses
import inspect
import json
import math

import numpy as np

from ..bifurcation.scan import ScanOptions
from ..errors import ConfigError, ElectrogrowthError, ParameterError
from ..incremental.accuracy import RTOL_RANGE
from ..model.energy_text import energy_material
from ..model.layers import Tube
from ..model.materials import BUILTIN, material_by_name
from ..model.params import CONTROLS, SIDES
from ..model.tube_file import parse_tube
from .unit import ScanSpec

#: The numbers of the paper's tube (Tube.uniform) a sweep can fix or vary.
SWEEPABLE = ("outer_radius", "length", "growth", "stretch", "voltage")
#: The most grid points of one sweep: 1e7 points are days of a large cluster, and the store's
#: completion marks of a larger grid are read whole into memory (docs/security.md).
MAX_POINTS = 10_000_000
#: The most mode records (points x top) a sweep's store may hold: refused up front rather
#: than filling the disk and the memory of whoever opens it.
MAX_MODE_RECORDS = 10**8


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

    def __post_init__(self):
        if self.tube is not None:
            _validate_tube(self)
        else:
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
        """The options of every point's mode scan."""
        return ScanSpec(self.solve_for, self.side, self.scan, self.rtol)

    def build_material(self):
        if self.energy:
            return energy_material(self.energy)
        name, params = self.material
        return material_by_name(name, **dict(params))

    def points(self, index_slices, material=None) -> list[Tube]:
        """The tubes of a block of the grid (tuple of slices), in C order."""
        axes = [values[s] for (_, values), s in zip(self.grid, index_slices)]
        fixed = dict(self.fixed)
        base = None if self.tube is None else _fixed_tube(self)
        material = material or (self.build_material() if base is None else None)
        out = []
        for combo in np.ndindex(*(len(a) for a in axes)):
            swept = {name: axes[d][i] for d, (name, i) in enumerate(zip(self.dims, combo))}
            if base is None:
                out.append(Tube.uniform(**fixed, **swept, material=material))
                continue
            tube = base
            for name, value in swept.items():
                tube = tube.at(name, value)
            out.append(tube)
        return out

    def to_dict(self) -> dict:
        """A JSON-ready dict (stored in the dataset attributes; see :meth:`from_dict`)."""
        return {
            "solve": {"for": self.solve_for, "side": self.side, "rtol": self.rtol},
            "modes": {
                "m": list(self.scan.m_range),
                "n": list(self.scan.n_range),
                "extend": self.scan.extend,
                "top": self.scan.top,
            },
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
            scan=ScanOptions(
                tuple(d["modes"]["m"]),
                tuple(d["modes"]["n"]),
                d["modes"]["top"],
                d["modes"]["extend"],
            ),
            chunk=d["run"]["chunk"],
            tube=d["tube"]["text"] if "tube" in d else None,
        )


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
    if c.solve_for not in CONTROLS:
        raise ConfigError(
            ("solve", "for"), f"{c.solve_for!r} is unknown; choose growth, stretch or voltage"
        )
    if c.side is not None and c.solve_for != "stretch":
        raise ConfigError(("solve", "side"), 'side applies only to for = "stretch"')
    _check_run(c)
    if not c.grid:
        raise ConfigError(
            ("grid",), f"nothing to sweep; give at least one of {', '.join(SWEEPABLE)} in [grid]"
        )
    for table, names in (("grid", c.dims), ("fixed", [name for name, _ in c.fixed])):
        for name in names:
            if name not in SWEEPABLE:
                raise ConfigError(
                    (table, name), f"unknown parameter; use any of {', '.join(SWEEPABLE)}"
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
    material = _energy(c.energy) if c.energy else _material(c.material)
    # Tube.uniform checks each field on its own and its defaults are valid, so every
    # value is checked alone: the error then names the entry that is wrong.
    for name, value in c.fixed:
        _tube(name, value, ("fixed", name), material)
    for name, values in c.grid:
        for v in values:
            _tube(name, v, ("grid", name), material)


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


def _fixed_tube(c: SweepConfig) -> Tube:
    """The sweep's tube file with its [fixed] values applied."""
    tube = parse_tube(c.tube or "", source="[tube] file")
    for name, value in c.fixed:
        tube = tube.at(name, value)
    return tube


def _validate_tube(c: SweepConfig) -> None:
    """The checks of :func:`_validate` for a sweep of a layered tube: the control is one of
    the tube's, every fixed and swept name is a control or key of it and every value valid."""
    try:
        tube = parse_tube(c.tube or "", source="[tube] file")
    except ConfigError as exc:
        raise ConfigError(("tube", "file"), str(exc)) from None
    try:
        solve_for = str(tube.check_control(c.solve_for))
    except ParameterError as exc:
        raise ConfigError(("solve", "for"), str(exc)) from None
    if solve_for != c.solve_for:
        raise ConfigError(("solve", "for"), f"write it as {solve_for!r}")
    _check_run(c)
    if not c.grid:
        raise ConfigError(("grid",), "nothing to sweep; give a control or key of the tube")
    for table, items in (("fixed", [(k, (v,)) for k, v in c.fixed]), ("grid", c.grid)):
        for name, values in items:
            if name == solve_for:
                raise ConfigError((table, name), f"{name} is what is solved for")
            if table == "fixed" and name in c.dims:
                raise ConfigError((table, name), f"{name} is also swept in [grid]; keep one")
            for v in values:
                try:
                    tube.at(name, v)
                except ParameterError as exc:
                    raise ConfigError((table, name), str(exc)) from None
    for name, values in c.grid:
        if not values or list(values) != sorted(set(values)):
            raise ConfigError(("grid", name), "need distinct values in increasing order")


def _tube(name, value, where, material):
    try:
        Tube.uniform(**{name: value}, material=material)
    except ParameterError as exc:
        raise ConfigError(where, str(exc)) from None
    except TypeError:
        raise ConfigError(where, f"unknown parameter; use any of {', '.join(SWEEPABLE)}") from None


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
