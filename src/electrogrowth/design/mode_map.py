"""The first pattern over two design variables: a mode map with traced boundaries.

``mode_map`` scans a coarse grid of designs (x, y) (``scan_modes`` at each node: the
pattern that comes first there), then traces every boundary between two patterns as a
curve of the two-pattern condition d_PQ(x, y) = 0 (design/map_trace.py), seeded from the
grid edges whose ends have different patterns, and locates the triple points where the
traced curves meet a third pattern (design/map_boundaries.py: each seed's trace a task of a
pool). The boundaries are not interpolated from the grid: each
point is a root of d_PQ to 1e-13 of the box. Each boundary is certified at a sample of
its points by full solves (the two critical values agree) and a full scan (no scanned mode
comes earlier); each triple point by the three critical values. docs/design.md.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import math
import time

import numpy as np

from ..bifurcation.problem import as_problem
from ..bifurcation.scan import ScanOptions
from ..continuation.contour import CONTOUR_STEPS
from ..errors import ParameterError
from ..pool import check_workers, local_processes, run_tasks
from .map_boundaries import trace_boundaries
from .map_checks import certificate, sampled, scan_node
from .map_record import Boundary, ModeMap, TriplePoint
from .map_trace import FAILED, Values, valued
from .sequence import check_vary, shared_variable

MIN_NODES, MAX_NODES = 2, 101


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


def _run(fn, tasks, pool, name):
    workers, scheduler, processes = pool
    lost = "; the map is not finished: run it again (fewer workers, or workers=1)"
    return run_tasks(
        fn, tasks, workers=workers, scheduler=scheduler, name=name, lost=lost,
        processes=processes,
    )  # fmt: skip


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
        Processes that scan the grid's nodes, trace the boundaries from different seeds
        (each trace is serial: each step needs the last) and certify the boundaries' points
        (default 1: this process). The map is the same, to the last bit, for any number of
        workers (design/map_boundaries.py); ``solves`` counts the work the map needed, not
        traces run ahead and found redundant.
    scheduler : str, optional
        Address of a dask.distributed scheduler (``tcp://host:8786``) to send those tasks
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
    same = shared_variable(tube, vx[0], vy[0])
    if same is not None:
        raise ParameterError(
            f"the two design variables {vx[0]!r} and {vy[0]!r} both set {same} of this tube;"
            " choose two keys"
        )
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
    policy = dataclasses.replace(
        CONTOUR_STEPS, largest=float(max_step), first=min(CONTOUR_STEPS.first, max_step)
    )
    problem = as_problem(tube, solve_for, side=side, rtol=rtol, options=options)
    values = Values(
        problem.tube, problem.control, (vx[0], vy[0]), (vx[1:], vy[1:]), problem.side,
        problem.rtol,
    )  # fmt: skip
    us, ws = np.linspace(0, 1, nx), np.linspace(0, 1, ny)
    say = progress if progress is not None else (lambda text: None)
    with local_processes(workers, scheduler) as processes:
        run = functools.partial(_run, pool=(workers, scheduler, processes))
        labels, crit, seeds = _grid(values, problem.options, us, ws, run, say)
        width = workers if scheduler is None else len(seeds) or 1  # a cluster: all at once
        curves, found_triples, _, traced = trace_boundaries(
            values, sorted({lab for lab in labels.ravel() if lab != FAILED}, key=str),
            problem.options, policy, seeds, functools.partial(run, name="trace"), width, say,
        )  # fmt: skip
        values.solves += traced
        boundaries = _certified(values, problem.options, curves, certify, run, say)
    triples = []
    for labs, u, v in found_triples:
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


def _grid(values, options, us, ws, run, say):
    """The coarse map: the pattern first at each node and its value (kept in the values'
    cache), and the seeds (p, q, a, b) of its edges whose ends differ, in a fixed order."""
    nx, ny = len(us), len(ws)
    grid_u = np.stack(np.meshgrid(us, ws, indexing="ij"), axis=-1)
    labels = np.empty((nx, ny), object)
    crit = np.full((nx, ny), math.nan)
    nodes = list(itertools.product(range(nx), range(ny)))
    tasks = [(values, options, grid_u[ij]) for ij in nodes]
    for done, (k, (label, value)) in enumerate(run(scan_node, tasks, name="scan"), 1):
        say(f"scan {done} of {nx * ny}")
        labels[nodes[k]], crit[nodes[k]] = label, value
        if valued(label) and math.isfinite(value):
            values.cache[(label, *map(float, grid_u[nodes[k]]), True)] = value
    edges = [((i, j), (i + 1, j)) for i in range(nx - 1) for j in range(ny)]
    edges += [((i, j), (i, j + 1)) for i in range(nx) for j in range(ny - 1)]
    seeds = [
        (labels[a], labels[b], tuple(grid_u[a]), tuple(grid_u[b]))
        for a, b in edges
        if labels[a] != labels[b]
        and FAILED not in (labels[a], labels[b])
        and (valued(labels[a]) or valued(labels[b]))
    ]
    return labels, crit, seeds


def _certified(values, options, curves, certify, run, say) -> list[Boundary]:
    """The traced curves as boundaries, ``certify`` points of each checked (a pool's
    tasks: full solves and a full scan)."""
    where = [(k, i) for k, c in enumerate(curves) for i in sampled(c, certify)]
    tasks = [(values, options, curves[k]["left"], curves[k]["right"], curves[k]["u"][i])
             for k, i in where]  # fmt: skip
    certificates: list[list] = [[] for _ in curves]
    for done, (t, (cert, count)) in enumerate(run(certificate, tasks, name="certify"), 1):
        say(f"certifying point {done} of {len(tasks)}")
        certificates[where[t][0]].append((where[t][1], cert))
        values.solves += count
    boundaries = []
    for k, c in enumerate(curves):
        xy = np.array([values.xy(u) for u in c["u"]])
        boundaries.append(
            Boundary(
                c["left"], c["right"], tuple(xy[:, 0]), tuple(xy[:, 1]), c["value"], c["ends"],
                tuple(cert for _, cert in sorted(certificates[k], key=lambda ic: ic[0])),
            )
        )  # fmt: skip
    return boundaries
