"""The first pattern over two design variables: a mode map with traced boundaries.

``mode_map`` scans a coarse grid of designs (x, y) (``scan_modes`` at each node: the
pattern that comes first there), then traces every boundary between two patterns as a
curve of the two-pattern condition d_PQ(x, y) = 0 (design/map_trace.py), seeded from the
grid edges whose ends have different patterns, and locates the triple points where the
traced curves meet a third pattern. The boundaries are not interpolated from the grid: each
point is a root of d_PQ to 1e-13 of the box. Each boundary is certified at a sample of
its points by full solves (the two critical values agree) and a full scan (no scanned mode
comes earlier); each triple point by the three critical values. docs/design.md.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import time

import numpy as np

from ..bifurcation.problem import as_problem
from ..bifurcation.scan import ScanOptions
from ..continuation.contour import CONTOUR_STEPS
from ..errors import ParameterError
from ..pool import check_workers, run_tasks
from .map_checks import certificate, sampled, scan_label, scan_node
from .map_record import Boundary, ModeMap, TriplePoint, label_json
from .map_trace import (
    FAILED,
    TRIPLE,
    Values,
    edge_root,
    follow,
    gradient,
    valued,
)
from .sequence import check_vary

MIN_NODES, MAX_NODES = 2, 101
SPLITS = 8  # an edge split at a third pattern found by a scan, at most this deep
ROUNDS = 3  # boundaries traced outwards from new triple points, at most this often


def check_points(points) -> tuple[int, int]:
    if isinstance(points, int) and not isinstance(points, bool):
        points = (points, points)
    ok = (
        isinstance(points, (tuple, list))
        and len(points) == 2
        and all(isinstance(p, int) and not isinstance(p, bool) for p in points)
        and all(MIN_NODES <= p <= MAX_NODES for p in points)
    )
    if not ok:
        raise ParameterError(
            f"points = {points!r} is invalid; give one or two integers from {MIN_NODES} to"
            f" {MAX_NODES} (grid nodes along each variable)"
        )
    return int(points[0]), int(points[1])


def _crosses(poly, a, b) -> bool:
    """Does the polyline (array k x 2) meet the segment ab (endpoints included)?"""
    a, b = np.asarray(a), np.asarray(b)
    for p, q in itertools.pairwise(poly):

        def orient(u, v, w):
            return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

        o1, o2 = orient(p, q, a), orient(p, q, b)
        o3, o4 = orient(a, b, p), orient(a, b, q)
        if o1 * o2 <= 0 and o3 * o4 <= 0 and (o1, o2, o3, o4) != (0, 0, 0, 0):
            return True
    return False


class _Mapper:
    """The state of one map: the values, the grid's labels, the traced curves."""

    def __init__(self, values: Values, grid_u, labels, options, progress, policy):
        self.values, self.grid_u, self.labels = values, grid_u, labels
        self.policy = policy
        self.options, self.progress = options, progress
        self.found: set = set()  # set once the grid is scanned
        self.curves: list[dict] = []
        self.triples: list[tuple] = []

    def say(self, text: str):
        if self.progress is not None:
            self.progress(text)

    def candidates(self, u):
        """The patterns a traced point is checked against: every pattern of the grid, and
        those found first by a scan where no grid node has them (``extra``)."""
        return self.found

    def scan_label(self, u):
        return scan_label(self.values, self.options, u)

    def covered(self, p, q, a, b) -> bool:
        return any(
            {c["left"], c["right"]} == {p, q} and _crosses(c["u"], a, b) for c in self.curves
        )

    def edge(self, p, q, a, b, depth: int = SPLITS):
        """Seed and trace the P|Q boundary crossing the grid edge from a (P) to b (Q)."""
        if self.covered(p, q, a, b):
            return
        r = edge_root(self.values, p, q, a, b)
        crossing = r is not None
        if r is None:  # no crossing of d_PQ: a third pattern between, found by a scan
            if depth <= 0:
                return
            r = 0.5 * (np.asarray(a) + np.asarray(b))
        first, _ = self.scan_label(r)  # the root checked by a scan: a third pattern splits
        if first not in (p, q):
            if first != FAILED and depth > 0:
                self.found.add(first)
                self.edge(p, first, a, r, depth - 1)
                self.edge(first, q, r, b, depth - 1)
            return
        if not crossing or not self.values.agree(p, q, r):
            return  # a jump of one pattern's first critical value, not a crossing
        ab = np.asarray(b, float) - np.asarray(a, float)
        if valued(p) and valued(q):
            g = gradient(self.values.condition(p, q), r)
            t = np.array([-g[1], g[0]]) / math.hypot(*g)
        else:
            t = np.array([-ab[1], ab[0]]) / math.hypot(*ab)
        left = p if np.dot(np.asarray(a) - r, [-t[1], t[0]]) > 0 else q
        self._trace(p, q, left, r, t, None)

    def _trace(self, p, q, left, start, t, start_end):
        self.say(f"tracing the boundary {label_json(p)} | {label_json(q)}")
        fwd = follow(self.values, p, q, start, t, self.candidates, self.policy)
        if start_end is None:
            back = follow(self.values, p, q, start, -t, self.candidates, self.policy)
        else:
            back = ([np.asarray(start)], start_end, None)
        pts = [np.asarray(x) for x in back[0][::-1]]
        for x in fwd[0][1:]:
            if np.linalg.norm(np.asarray(x) - pts[-1]) > 1e-14:
                pts.append(np.asarray(x))
        while len(pts) > 1 and np.linalg.norm(pts[1] - pts[0]) <= 1e-14:
            pts.pop(0)  # an exit at the seed itself (a seed on the box's edge)
        self.curves.append(
            {"left": left, "right": q if left == p else p, "u": np.array(pts),
             "ends": (back[1], fwd[1])}
        )  # fmt: skip
        for found in (back[2], fwd[2]):
            if found is not None:
                self._add_triple(*found)

    def _add_triple(self, labels, u, v):
        for lab, w, _ in self.triples:
            if set(lab) == set(labels) and np.linalg.norm(w - u) < 1e-6:
                return
        self.triples.append((labels, np.asarray(u), v))

    def from_triples(self):
        """Trace the boundaries leaving each triple point that no curve reached yet."""
        done = 0
        for _ in range(ROUNDS):
            todo = self.triples[done:]
            done = len(self.triples)
            if not todo:
                return
            for labels, u, _ in todo:
                for a, b in itertools.combinations(labels, 2):
                    c = next(lab for lab in labels if lab not in (a, b))
                    if self._reached(a, b, u):
                        continue
                    d = self.values.condition(a, b)
                    g = gradient(d, u)
                    t = np.array([-g[1], g[0]]) / math.hypot(*g)
                    probe = np.clip(u + 1e-3 * t, 0, 1)
                    if self.values.condition(a, c)(probe) > 0:  # c first that way
                        t = -t
                    left = b if np.dot(g, [-t[1], t[0]]) > 0 else a
                    self._trace(a, b, left, u, t, TRIPLE)

    def _reached(self, a, b, u) -> bool:
        return any(
            {c["left"], c["right"]} == {a, b}
            and min(np.linalg.norm(c["u"][0] - u), np.linalg.norm(c["u"][-1] - u)) < 1e-7
            for c in self.curves
        )


def _run(fn, tasks, pool, name):
    workers, scheduler = pool
    lost = "; the map is not finished: run it again (fewer workers, or workers=1)"
    return run_tasks(fn, tasks, workers=workers, scheduler=scheduler, name=name, lost=lost)


def mode_map(
    tube,
    solve_for: str,
    vary: tuple[tuple[str, float, float], tuple[str, float, float]],
    *,
    side: str | None = None,
    options: ScanOptions = ScanOptions(),
    points: int | tuple[int, int] = 5,
    certify: int = 3,
    rtol: float = 1e-12,
    max_step: float = CONTOUR_STEPS.largest,
    workers: int = 1,
    scheduler: str | None = None,
    progress=None,
) -> ModeMap:
    """The first pattern over two design variables, its boundaries traced as curves.

    Parameters
    ----------
    tube : Tube
        The tube; ``solve_for`` is the unknown, the two keys of ``vary`` are overridden.
    solve_for : str
        The control whose critical value decides which pattern comes first (as in
        :func:`scan_modes`; ``side`` for the stretch, pressure and force).
    vary : ((key_x, lo, hi), (key_y, lo, hi))
        The two design variables (any keys ``tube.at`` accepts, not the unknown) and ranges.
    options : ScanOptions
        The modes each scan of the grid and of the certificates examines.
    points : int or (int, int)
        Grid nodes along x and y (2 to 101): the coarse map the boundaries are seeded from.
        A region that no node lands in and that no traced boundary meets can be missed.
    certify : int
        Points of each boundary checked by full solves and a full scan (0: none).
    rtol : float
        Accuracy of every critical value (default 1e-12).
    max_step : float
        The longest step along a boundary, as a fraction of the box's sides (default 0.08,
        from 0.01 to 0.5): every traced point is a root whatever the step; longer steps
        give fewer points (a coarser polyline between them) for boundaries that barely bend.
    workers : int
        Processes that scan the grid's nodes and certify the boundaries' points (default 1:
        this process). The tracing itself runs here: each step needs the last. The map is
        the same for any number of workers.
    scheduler : str, optional
        Address of a dask.distributed scheduler (``tcp://host:8786``) to send those scans
        to instead (``workers`` is then ignored; the ``sweep`` extra).
    progress : callable str -> None, optional
        Called with a line per stage (the grid's scans, each traced boundary).

    Returns
    -------
    ModeMap
        The grid's patterns and critical values, the boundaries (polylines with the
        pattern on each side, their ends: edge, triple, closed, jump, lost, and their
        certificates) and the triple points.

    Examples
    --------
    >>> from electrogrowth import ScanOptions, Tube
    >>> mm = mode_map(Tube.uniform(), "stretch", (("outer_radius", 1.2, 1.3),
    ...               ("length", 0.95, 1.05)), side="compression", points=2, certify=0,
    ...               options=ScanOptions((0, 1), (1, 1)))
    >>> [(b.left, b.right) for b in mm.boundaries]  # scans widen past m = 1 where needed
    [((1, 1), (0, 1)), ((2, 1), (1, 1))]
    """
    t0 = time.perf_counter()
    vx = check_vary(vary[0], tube, solve_for) if len(vary) == 2 else None
    if vx is None:
        raise ParameterError(f"vary = {vary!r} is invalid; give two (key, lo, hi)")
    vy = check_vary(vary[1], tube, solve_for)
    if vx[0] == vy[0]:
        raise ParameterError(f"the two design variables are both {vx[0]!r}; choose two keys")
    tube.at(vx[0], vx[1]).at(vy[0], vy[1])
    nx, ny = check_points(points)
    if isinstance(certify, bool) or not isinstance(certify, int) or certify < 0:
        raise ParameterError(f"certify = {certify!r} is invalid; need an integer >= 0")
    if (
        isinstance(max_step, bool)
        or not isinstance(max_step, (int, float))
        or not (0.01 <= max_step <= 0.5)
    ):
        raise ParameterError(f"max_step = {max_step!r} is out of range; valid range: 0.01 to 0.5")
    check_workers(workers, "workers =")
    pool = (workers, scheduler)
    in_process = workers == 1 and scheduler is None
    policy = dataclasses.replace(
        CONTOUR_STEPS, largest=float(max_step), first=min(CONTOUR_STEPS.first, max_step)
    )
    problem = as_problem(tube, solve_for, side=side, rtol=rtol, options=options)
    values = Values(
        problem.tube, problem.control, (vx[0], vy[0]), (vx[1:], vy[1:]), problem.side,
        problem.rtol,
    )  # fmt: skip
    us, ws = np.linspace(0, 1, nx), np.linspace(0, 1, ny)
    grid_u = np.stack(np.meshgrid(us, ws, indexing="ij"), axis=-1)
    labels = np.empty((nx, ny), object)
    crit = np.full((nx, ny), math.nan)
    mapper = _Mapper(values, grid_u, labels, problem.options, progress, policy)
    nodes = list(itertools.product(range(nx), range(ny)))
    tasks = [(values, problem.options, grid_u[ij]) for ij in nodes]
    for done, (k, (label, value)) in enumerate(_run(scan_node, tasks, pool, "scan"), 1):
        mapper.say(f"scan {done} of {nx * ny}")
        labels[nodes[k]], crit[nodes[k]] = label, value
        if valued(label) and math.isfinite(value):
            values.cache[(label, *map(float, grid_u[nodes[k]]), True)] = value
    mapper.found = {lab for lab in labels.ravel() if lab != FAILED}
    edges = [((i, j), (i + 1, j)) for i in range(nx - 1) for j in range(ny)]
    edges += [((i, j), (i, j + 1)) for i in range(nx) for j in range(ny - 1)]
    for a, b in edges:
        p, q = labels[a], labels[b]
        if p == q or FAILED in (p, q) or not (valued(p) or valued(q)):
            continue
        mapper.edge(p, q, grid_u[a], grid_u[b])
    mapper.from_triples()
    where = [(k, i) for k, c in enumerate(mapper.curves) for i in sampled(c, certify)]
    curves = mapper.curves
    tasks = [(values, problem.options, curves[k]["left"], curves[k]["right"], curves[k]["u"][i])
             for k, i in where]  # fmt: skip
    certificates: list[list] = [[] for _ in mapper.curves]
    for done, (t, (cert, solves)) in enumerate(_run(certificate, tasks, pool, "certify"), 1):
        mapper.say(f"certifying point {done} of {len(tasks)}")
        certificates[where[t][0]].append((where[t][1], cert))
        if not in_process:  # a worker's solves, on a copy of values
            values.solves += solves
    boundaries = []
    for k, c in enumerate(mapper.curves):
        xy = np.array([values.xy(u) for u in c["u"]])
        common = [values.value(c["left"] if valued(c["left"]) else c["right"], u) for u in c["u"]]
        boundaries.append(
            Boundary(
                c["left"], c["right"], tuple(xy[:, 0]), tuple(xy[:, 1]),
                tuple(math.nan if v is None else v for v in common), c["ends"],
                tuple(cert for _, cert in sorted(certificates[k], key=lambda ic: ic[0])),
            )
        )  # fmt: skip
    triples = []
    for labs, u, v in mapper.triples:
        vals = [values.value(lab, u, hinted=False) for lab in labs]
        gap = (
            max(abs(a - b) for a, b in itertools.combinations(vals, 2))
            if None not in vals
            else math.inf
        )
        triples.append(TriplePoint(tuple(labs), *values.xy(u), v, gap))
    return ModeMap(
        (vx[0], vy[0]),
        (vx[1:], vy[1:]),
        values.solve_for,
        values.side,
        tuple(vx[1] + us * (vx[2] - vx[1])),
        tuple(vy[1] + ws * (vy[2] - vy[1])),
        tuple(tuple(row) for row in labels),
        crit,
        tuple(boundaries),
        tuple(triples),
        values.solves,
        time.perf_counter() - t0,
    )
