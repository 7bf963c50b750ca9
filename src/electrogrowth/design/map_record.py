"""What a mode map holds (design/mode_map.py): the grid's patterns, the traced boundaries
with their certificates, the triple points; the pattern at any design, regions, JSON and
xarray."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..outcomes import json_number


def label_json(label):
    """A pattern for JSON and text: [m, n] for a mode, else its kind ("surface", ...)."""
    return list(label) if isinstance(label, tuple) else str(label)


def label_of(value):
    """The inverse of :func:`label_json`: (m, n) from [m, n], else the kind as text."""
    if isinstance(value, list) and len(value) == 2 and all(isinstance(v, int) for v in value):
        return (value[0], value[1])
    if isinstance(value, str):
        return value
    raise ValueError(f"pattern {value!r} is invalid; need [m, n] or a kind")


def _float(v) -> float:
    """A stored number: None (written for NaN or infinity) reads back as NaN."""
    return math.nan if v is None else float(v)


@dataclasses.dataclass(frozen=True)
class Certificate:
    """A traced point checked: ``gap`` = |v_P - v_Q| by full solves (NaN against the
    threshold), ``first`` the pattern a full scan finds first there and ``ahead`` = s
    (v_scan - v_P) (< 0: the scan found an earlier pattern); ``ok`` if gap <= 1e-8 and
    nothing scanned comes earlier (both to 1e-8 max(1, |v|))."""

    x: float
    y: float
    gap: float
    first: object
    ahead: float
    ok: bool

    def as_dict(self) -> dict:
        return {
            "x": self.x,
            "y": self.y,
            "gap": json_number(self.gap),
            "first": label_json(self.first),
            "ahead": json_number(self.ahead),
            "ok": self.ok,
        }


@dataclasses.dataclass(frozen=True)
class Boundary:
    """A traced curve on which ``left`` and ``right`` are equally critical (left and right
    of the direction of its points), with the common critical value at each point, how each
    end was reached ("edge", "triple", "closed", "jump", "lost") and its certificates."""

    left: object
    right: object
    x: tuple[float, ...]
    y: tuple[float, ...]
    value: tuple[float, ...]
    ends: tuple[str, str]
    certificates: tuple[Certificate, ...] = ()

    @property
    def certified(self) -> bool:
        return all(c.ok for c in self.certificates)

    def as_dict(self) -> dict:
        return {
            "patterns": [label_json(self.left), label_json(self.right)],
            "x": list(self.x),
            "y": list(self.y),
            "value": [json_number(v) for v in self.value],
            "ends": list(self.ends),
            "certified": self.certified,
            "certificates": [c.as_dict() for c in self.certificates],
        }


@dataclasses.dataclass(frozen=True)
class TriplePoint:
    """Three patterns equally critical at (x, y), at ``value``; ``gap`` the largest
    difference of their three critical values by full solves."""

    patterns: tuple
    x: float
    y: float
    value: float
    gap: float

    def as_dict(self) -> dict:
        return {
            "patterns": [label_json(p) for p in self.patterns],
            "x": self.x,
            "y": self.y,
            "value": self.value,
            "gap": json_number(self.gap),
        }


def _boundary_of(b: dict) -> Boundary:
    certificates = tuple(
        Certificate(
            float(c["x"]),
            float(c["y"]),
            _float(c["gap"]),
            label_of(c["first"]),
            _float(c["ahead"]),
            bool(c["ok"]),
        )
        for c in b["certificates"]
    )
    left, right = (label_of(p) for p in b["patterns"])
    xs, ys, values = (
        tuple(map(f, b[k])) for f, k in ((float, "x"), (float, "y"), (_float, "value"))
    )
    return Boundary(
        left, right, xs, ys, values, (str(b["ends"][0]), str(b["ends"][1])), certificates
    )


def _triple_of(t: dict) -> TriplePoint:
    patterns = tuple(map(label_of, t["patterns"]))
    return TriplePoint(patterns, float(t["x"]), float(t["y"]), float(t["value"]), _float(t["gap"]))


@dataclasses.dataclass(frozen=True)
class ModeMap:
    """Result of :func:`mode_map`: ``keys`` (x, y) over ``box`` ((lo, hi) each), the grid
    ``xs`` x ``ys`` with the pattern first at each node (``labels``: (m, n), "surface",
    "threshold" or "failed") and its critical value, the traced ``boundaries`` and the
    ``triple_points``; ``solves`` single-pattern solves in ``seconds``."""

    keys: tuple[str, str]
    box: tuple[tuple[float, float], tuple[float, float]]
    solve_for: str
    side: str | None
    xs: tuple[float, ...]
    ys: tuple[float, ...]
    labels: tuple[tuple, ...]
    values: np.ndarray
    boundaries: tuple[Boundary, ...]
    triple_points: tuple[TriplePoint, ...]
    solves: int = 0
    seconds: float = 0.0

    def grid_labels(self) -> np.ndarray:
        """The grid's patterns as an object array of shape (len(xs), len(ys))."""
        out = np.empty((len(self.xs), len(self.ys)), object)
        for i, row in enumerate(self.labels):
            for j, lab in enumerate(row):
                out[i, j] = lab
        return out

    def _unit(self, x, y):
        (x0, x1), (y0, y1) = self.box
        return (np.asarray(x, float) - x0) / (x1 - x0), (np.asarray(y, float) - y0) / (y1 - y0)

    def pattern_at(self, x: float, y: float):
        """The pattern first at (x, y): the side of the nearest traced boundary it lies on
        (in a partition of the box the nearest boundary point belongs to the boundary of the
        region holding (x, y)); the nearest grid node's pattern where no boundary exists."""
        return self.raster(np.array([x]), np.array([y]))[0, 0]

    def raster(self, xs, ys) -> np.ndarray:
        """The pattern at each (x, y) of the grid xs x ys (object array, shape (len(xs),
        len(ys))), as :meth:`pattern_at`."""
        X, Y = np.meshgrid(np.asarray(xs, float), np.asarray(ys, float), indexing="ij")
        U, W = self._unit(X, Y)
        out = np.empty(X.shape, object)
        best = np.full(X.shape, np.inf)
        if not self.boundaries:
            gu, gw = self._unit(*np.meshgrid(self.xs, self.ys, indexing="ij"))
            lab = self.grid_labels()
            for idx in np.ndindex(X.shape):
                k = np.argmin((gu - U[idx]) ** 2 + (gw - W[idx]) ** 2)
                out[idx] = lab.ravel()[k]
            return out
        for b in self.boundaries:
            bu, bw = self._unit(b.x, b.y)
            for k in range(len(bu) - 1):
                p = np.array([bu[k], bw[k]])
                e = np.array([bu[k + 1] - bu[k], bw[k + 1] - bw[k]])
                ee = float(e @ e)
                if ee == 0.0:
                    continue
                t = ((U - p[0]) * e[0] + (W - p[1]) * e[1]) / ee
                t = np.clip(t, 0.0, 1.0)
                dx, dy = U - (p[0] + t * e[0]), W - (p[1] + t * e[1])
                dist = dx * dx + dy * dy
                closer = dist < best
                if not closer.any():
                    continue
                side = e[0] * (W - p[1]) - e[1] * (U - p[0])  # > 0: left of the segment
                best = np.where(closer, dist, best)
                for idx in zip(*np.nonzero(closer), strict=True):
                    out[idx] = b.left if side[idx] > 0 else b.right
        return out

    def patterns(self) -> list:
        """The patterns of the grid and of the boundaries, modes first in (m, n) order."""
        found = {lab for row in self.labels for lab in row}
        for b in self.boundaries:
            found |= {b.left, b.right}
        return sorted(found, key=lambda lab: (not isinstance(lab, tuple), str(lab)))

    @classmethod
    def from_dict(cls, record: dict) -> ModeMap:
        """The map written by :meth:`as_dict` (e.g. read back from JSON): a map traced once
        and stored can be drawn, queried and designed in again without tracing it anew.
        Only plain numbers, lists and texts are read (no code); a malformed record raises
        ValueError."""
        try:
            (kx, *bx), (ky, *by) = record["vary"]
            grid = record["grid"]
            boundaries = tuple(_boundary_of(b) for b in record["boundaries"])
            triples = tuple(_triple_of(t) for t in record["triple_points"])
            return cls(
                (str(kx), str(ky)), (tuple(map(float, bx)), tuple(map(float, by))),
                str(record["solve_for"]), record["side"],
                tuple(map(float, grid["x"])), tuple(map(float, grid["y"])),
                tuple(tuple(map(label_of, row)) for row in grid["pattern"]),
                np.array([[_float(v) for v in row] for row in grid["value"]]),
                boundaries, triples, int(record["solves"]), float(record["seconds"]),
            )  # fmt: skip
        except (KeyError, TypeError, ValueError) as exc:
            raise ValueError(f"not a stored mode map: {exc}") from None

    def as_dict(self) -> dict:
        return {
            "vary": [[k, *r] for k, r in zip(self.keys, self.box, strict=True)],
            "solve_for": self.solve_for,
            "side": self.side,
            "grid": {
                "x": list(self.xs),
                "y": list(self.ys),
                "pattern": [[label_json(lab) for lab in row] for row in self.labels],
                "value": [[json_number(float(v)) for v in row] for row in self.values],
            },
            "boundaries": [b.as_dict() for b in self.boundaries],
            "triple_points": [t.as_dict() for t in self.triple_points],
            "solves": self.solves,
            "seconds": self.seconds,
        }

    def to_xarray(self):
        """The grid (dimensions x, y: m, n, kind, critical value), the boundaries' points
        (dimension point, with the boundary index) and the triple points (dimension triple)
        as an ``xarray.Dataset`` (needs xarray, the ``sweep`` extra)."""
        from ..labelled import axis_attrs, xarray

        xr = xarray()
        lab = self.grid_labels()
        m = np.array([[v[0] if isinstance(v, tuple) else -1 for v in row] for row in lab], int)
        n = np.array([[v[1] if isinstance(v, tuple) else -1 for v in row] for row in lab], int)
        kind = np.array(
            [["bifurcation" if isinstance(v, tuple) else v for v in row] for row in lab]
        )
        px, py, pv, pb = [], [], [], []
        for k, b in enumerate(self.boundaries):
            px += b.x
            py += b.y
            pv += b.value
            pb += [k] * len(b.x)
        modes = {"units": "1", "long_name": "(m, n); -1: no finite mode"}
        crit = {"units": "1", "long_name": f"critical {self.solve_for}"}
        sides = [(label_json(b.left), label_json(b.right)) for b in self.boundaries]
        tp = self.triple_points
        # the axes described as a sweep's store describes its own (a key, its symbol, units)
        ax, ay = (axis_attrs(key) for key in self.keys)
        return xr.Dataset(
            {
                "m": (("x", "y"), m, modes),
                "n": (("x", "y"), n, modes),
                "kind": (("x", "y"), kind.astype(str)),
                "value": (("x", "y"), np.asarray(self.values, float), crit),
                "boundary_x": ("point", np.array(px, float), ax),
                "boundary_y": ("point", np.array(py, float), ay),
                "boundary_value": ("point", np.array(pv, float), crit),
                "boundary": ("point", np.array(pb, int)),
                "left": ("boundary_index", [str(s[0]) for s in sides]),
                "right": ("boundary_index", [str(s[1]) for s in sides]),
                "certified": ("boundary_index", [b.certified for b in self.boundaries]),
                "triple_x": ("triple", np.array([t.x for t in tp], float), ax),
                "triple_y": ("triple", np.array([t.y for t in tp], float), ay),
                "triple_value": ("triple", np.array([t.value for t in tp], float), crit),
                "triple_patterns": (
                    "triple",
                    [" ".join(str(label_json(p)) for p in t.patterns) for t in tp],
                ),
            },
            coords={
                "x": ("x", np.array(self.xs, float), ax),
                "y": ("y", np.array(self.ys, float), ay),
            },
            attrs={"keys": " ".join(self.keys), "solve_for": self.solve_for,
                   "side": self.side or ""},
        )  # fmt: skip
