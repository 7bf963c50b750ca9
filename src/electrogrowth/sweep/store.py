"""The Zarr store of a sweep: a labelled xarray Dataset, written one task at a time.

Layout: one dimension per swept parameter (in the order of the sweep file), its values as
the coordinate; the fixed parameters as scalar coordinates; the sweep file in the
attributes (``sweep_config``, normalised JSON, compared on resume; ``sweep_file``, the
text as written). Variables per grid point: ``critical_value``, ``m``, ``n``, ``kind``,
``error_estimate``, ``surface_instability``, ``status``, ``message``, ``seconds``, the
runners-up over a ``rank`` dimension, and ``run``.

Never corrupt, and resumable:

* the store is built in a temporary directory and renamed into place, so a store at the
  path always has all its arrays;
* the Zarr chunks are exactly the task blocks: a task writes whole chunks of its own,
  never a chunk holding another task's results;
* Zarr writes every chunk file atomically (temp file + rename), and a task's ``run``
  block, its completion mark, is written after all its data. ``run`` > 0 is the number of
  the invocation that computed the point; a block without it is recomputed on resume;
* only the process running the sweep writes, under an exclusive lock (``flock``).
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import uuid
import warnings
from importlib.metadata import version
from pathlib import Path

import numpy as np
import xarray as xr
import zarr

from ..errors import Remedy, SweepError
from ..labelled import axis_attrs
from ..outcomes import Kind, Status
from .config import SweepConfig, differences
from .schema import MARK, POINT_VARIABLES, RUNNER_VARIABLES, label, units
from .unit import BRANCH_FAILED, ChunkResult


def block_shape(shape: tuple[int, ...], points: int) -> tuple[int, ...]:
    """A block of about ``points`` grid points: whole trailing axes first."""
    block, rest = [1] * len(shape), points
    for d in reversed(range(len(shape))):
        block[d] = max(1, min(shape[d], rest))
        if block[d] < shape[d]:
            break
        rest //= shape[d]
    return tuple(block)


def grid_blocks(shape: tuple[int, ...], block: tuple[int, ...]) -> list[tuple[slice, ...]]:
    """The blocks tiling the grid, in C order of the block grid (the chunk numbers)."""
    counts = [math.ceil(s / b) for s, b in zip(shape, block)]
    return [
        tuple(slice(i * b, min((i + 1) * b, s)) for i, b, s in zip(idx, block, shape))
        for idx in np.ndindex(*counts)
    ]


class SweepStore:
    """An open sweep store (see :func:`open_store`)."""

    def __init__(self, path: Path, config: SweepConfig):
        self.path, self.config = path, config
        self.group = zarr.open_group(str(path), mode="r+")
        self.block = block_shape(config.shape, config.chunk)
        self.blocks = grid_blocks(config.shape, self.block)
        self.ranks = config.scan.top - 1

    @contextlib.contextmanager
    def locked(self):
        """Hold an exclusive lock on the store (released even if the process is killed)."""
        try:
            import fcntl
        except ImportError:  # not POSIX: no lock
            yield
            return
        fd = os.open(self.path, os.O_RDONLY)
        try:
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                raise SweepError(
                    f"{self.path} is being written by another running sweep; wait for it to finish"
                ) from None
            yield
        finally:
            os.close(fd)

    def _run(self) -> np.ndarray:
        return np.asarray(self.group["run"][...])

    def pending_chunks(self) -> list[int]:
        """Numbers of the chunks without a completion mark."""
        run = self._run()
        return [i for i, b in enumerate(self.blocks) if not (run[b] > 0).all()]

    def next_run(self) -> int:
        return int(self._run().max(initial=0)) + 1

    def write_chunk(self, result: ChunkResult, run: int) -> None:
        """Write a task's results, then its completion mark."""
        where = self.blocks[result.index]
        if tuple((s.start, s.stop) for s in where) != tuple(result.block):
            raise SweepError(
                f"chunk {result.index} came back for block {result.block}, not {where}"
            )
        shape = tuple(s.stop - s.start for s in where)
        pts = result.points
        for name, (dtype, _, _) in POINT_VARIABLES.items():
            if name not in self.group:  # a store begun before the variable was added
                continue
            field = "value" if name == "critical_value" else name
            column = [getattr(p, field) for p in pts]
            if dtype is object:  # enums stored as their plain values
                column = [str(v) for v in column]
            values = np.array(column, dtype=dtype)
            self.group[name][where] = values.reshape(shape)
        if self.ranks:
            for name, (dtype, fill, _) in RUNNER_VARIABLES.items():
                col = {"runner_up_m": 0, "runner_up_n": 1, "runner_up_value": 2}[name]
                values = np.full((len(pts), self.ranks), fill, dtype=dtype)
                for i, p in enumerate(pts):
                    for r, mode in enumerate(p.runners_up[: self.ranks]):
                        values[i, r] = mode[col]
                self.group[name][where] = values.reshape(shape + (self.ranks,))
        self.group[MARK[0]][where] = np.full(shape, run, dtype=MARK[1])

    def counts(self) -> dict:
        """Number of points by outcome: bifurcation, surface, threshold, none, inaccurate
        (a value not certified, whatever its kind), failed, error, pending."""
        status = np.asarray(self.group["status"][...], dtype=object)
        kind = np.asarray(self.group["kind"][...], dtype=object)
        outcome = np.where(status == Status.OK, kind, status)
        return {
            k: int((outcome == k).sum())
            for k in (
                Kind.BIFURCATION,
                Kind.SURFACE,
                Kind.THRESHOLD,
                Kind.NONE,
                Status.INACCURATE,
                Status.FAILED,
                Status.ERROR,
                "pending",
            )
        }

    def verdicts(self) -> dict:
        """What comes first at the computed points ("first": verdict kind -> count) and, for
        a sweep asking for the amplitude equation, the branches ("branch": supercritical,
        subcritical, "not covered", "failed" -> count); empty for what a store written
        before these variables lacks."""
        out: dict = {}
        status = np.asarray(self.group["status"][...], dtype=object)
        done = (status == Status.OK) | (status == Status.INACCURATE)
        if "verdict" in self.group:
            verdict = np.asarray(self.group["verdict"][...], dtype=object)[done]
            out["first"] = _tally(v for v in verdict if v)
        if self.config.koiter and "branch_note" in self.group:
            branch = np.asarray(self.group["branch"][...], dtype=object)[done]
            note = np.asarray(self.group["branch_note"][...], dtype=object)[done]
            out["branch"] = _tally(
                b or ("failed" if n.startswith(BRANCH_FAILED) else "not covered")
                for b, n in zip(branch, note)
            )
        return out


def _tally(values) -> dict:
    """value -> count, in order of first appearance."""
    out: dict = {}
    for v in values:
        out[str(v)] = out.get(str(v), 0) + 1
    return out


def open_store(out: str | Path, config: SweepConfig, *, source_text: str = "") -> SweepStore:
    """Open the store of ``config`` at ``out``, creating it if it does not exist.

    Raises
    ------
    SweepError
        ``out`` exists and is not a sweep store, or holds a different sweep.
    """
    out = Path(out)
    if not out.exists():
        try:
            _create(out, config, source_text)
        except OSError as exc:
            if not out.exists():  # else: another process created it first
                raise SweepError(f"cannot create {out}: {exc.strerror or exc}") from None
    check_same_sweep(out, config)
    return SweepStore(out, config)


def read_config(path: str | Path) -> SweepConfig:
    """The sweep stored at ``path``."""
    path = Path(path)
    try:  # only Zarr v3, as written here (v2 arrays may declare object codecs such as pickle)
        text = zarr.open_group(str(path), mode="r", zarr_format=3).attrs.get("sweep_config")
    except (zarr.errors.BaseZarrError, ValueError, OSError):
        text = None
    if text is None:  # (the remedy, to write to another store, is SweepError's)
        raise SweepError(f"{path} is not an electrogrowth sweep store")
    try:  # JSON, and a SweepConfig validates itself: its energy and tube texts are parsed
        return SweepConfig.from_dict(json.loads(text))  # by the whitelist grammars, never run
    except (KeyError, TypeError, ValueError, AttributeError, RecursionError) as exc:
        raise SweepError(f"{path} holds an unreadable sweep configuration: {exc}") from None


def check_same_sweep(out: Path, config: SweepConfig) -> None:
    """Refuse to resume ``out`` with another configuration; nothing is written."""
    stored = read_config(out)
    if stored.to_json() != config.to_json():
        diff = ", ".join(differences(stored, config))
        raise SweepError(
            f"{out} holds a different sweep (it differs in {diff}); resuming it"
            " with this file would mix two sweeps: use another --out, or delete"
            f" {out} to start over"
        )


#: what a reader of a path that holds no sweep store can do
READ_REMEDY = Remedy(
    "give a store written by electrogrowth sweep FILE --out STORE",
    python="give a store written by compute_sweep(config, out=...)",
)


def open_results(path: str | Path) -> xr.Dataset:
    """The dataset of a sweep store, loaded into memory (points not yet computed have
    status "pending" and NaN values). A path that holds no store is refused with advice
    for a reader (a sweep writing it gets SweepError's own)."""
    try:
        read_config(path)
    except SweepError as exc:
        exc.remedy = READ_REMEDY
        raise
    try:
        with xr.open_zarr(str(path), chunks=None, zarr_format=3) as ds:
            return ds.load()
    except (zarr.errors.BaseZarrError, OSError, RuntimeError, ValueError, KeyError) as exc:
        reason = " ".join(str(exc).split())[:200]  # a damaged array or chunk: the store's fault
        raise SweepError(f"{path} cannot be read: {type(exc).__name__}: {reason}") from None


def _create(out: Path, config: SweepConfig, source_text: str) -> None:
    """Build the store in a temporary directory, then rename it into place. xarray writes
    the coordinates and attributes; the data arrays are created with zarr directly, as
    metadata only: their fill value is the "not computed" value, so no chunk is written
    until a task's results arrive (xarray would write every chunk of a template)."""
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(f".{out.name}.tmp-{uuid.uuid4().hex[:8]}")
    dims, shape = config.dims, config.shape
    block = block_shape(shape, config.chunk)
    ranks = config.scan.top - 1
    scalars = " ".join(name for name, _ in config.fixed)
    what = label(config.solve_for)[0]
    arrays = [(name, dims, block, spec) for name, spec in POINT_VARIABLES.items()]
    if ranks:
        arrays += [
            (name, dims + ("rank",), block + (ranks,), spec)
            for name, spec in RUNNER_VARIABLES.items()
        ]
    arrays.append((MARK[0], dims, block, MARK[1:]))
    try:
        _coordinates(config, source_text).to_zarr(
            str(tmp), mode="w-", zarr_format=3, consolidated=False
        )
        group = zarr.open_group(str(tmp), mode="r+")
        for name, adims, chunks, (dtype, fill, text) in arrays:
            attrs = {
                "description": text,
                "units": units(name, config.solve_for),
                **({"coordinates": scalars} if scalars else {}),
            }
            if name == "critical_value":
                attrs.update(long_name=f"critical {what}", symbol=label(config.solve_for)[1])
            group.create_array(
                name,
                shape=tuple(shape) + chunks[len(dims) :],
                chunks=chunks,
                dtype=str if dtype is object else dtype,
                fill_value=fill,
                dimension_names=adims,
                attributes=attrs,
            )
        with warnings.catch_warnings():  # "consolidated metadata is not in the v3 spec"
            warnings.simplefilter("ignore", category=UserWarning)
            zarr.consolidate_metadata(str(tmp))
        os.rename(tmp, out)
    except BaseException:
        import shutil

        shutil.rmtree(tmp, ignore_errors=True)
        raise


def _coordinates(config: SweepConfig, source_text: str) -> xr.Dataset:
    """The grid values, the fixed parameters (scalar coordinates) and the attributes."""
    coords = {name: (name, np.array(values), _coord_attrs(name)) for name, values in config.grid}
    coords.update({name: ((), value, _coord_attrs(name)) for name, value in config.fixed})
    if config.scan.top > 1:
        coords["rank"] = (
            "rank",
            np.arange(1, config.scan.top),
            {
                "description": "1 = the mode that bifurcates next after the critical one",
                "units": "1",
            },
        )
    what = label(config.solve_for)[0]
    material = config.build_material().name
    attrs = {
        "title": f"electrogrowth sweep: critical {what} ({material})",
        "solve_for": config.solve_for,
        "side": config.side or "",
        "material": material,
        "electrogrowth_version": version("electrogrowth"),
        "sweep_config": config.to_json(),
        "sweep_file": source_text,
    }
    return xr.Dataset(coords=coords, attrs=attrs)


def _coord_attrs(name: str) -> dict:
    return axis_attrs(name)
