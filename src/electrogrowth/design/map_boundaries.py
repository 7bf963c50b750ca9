"""The boundaries of a mode map traced as independent tasks, kept in a fixed order.

A boundary is traced from a seed: a grid edge whose ends have different patterns
(:func:`trace_edge`: the root of d_PQ on the edge, split where a scan finds a third
pattern, then the curve both ways) or a triple point and two of its three patterns
(:func:`trace_branch`: the curve leaving the point). A task is a pure function of its
inputs: it starts from the grid's values alone (no critical value or bracket carried over
from another task, patterns compared in a fixed order) and returns its curves, each with
the seed it grew from, the common critical value along it and the triple points it met.

:func:`trace_boundaries` takes the tasks' results in the order of the seeds and keeps a
curve unless one kept before it already crosses its seed (the same boundary reached from
two seeds). A pool may run tasks ahead of that order; a trace run ahead is wasted when an
earlier seed's curve turns out to cross its seed, so a batch takes seeds of different
pattern pairs, the next ``width`` in order. Whatever ran the tasks, and however many at
once, the kept curves are the same to the last bit. docs/design.md, "Where a map runs".
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np

from .map_checks import CERTIFIED, scan_label
from .map_record import label_json
from .map_trace import FAILED, TRIPLE, edge_root, follow, gradient, valued

SPLITS = 8  # an edge split at a third pattern found by a scan, at most this deep
ROUNDS = 3  # boundaries traced outwards from new triple points, at most this often


def crosses(poly, a, b) -> bool:
    """Does the polyline (array k x 2) meet the segment ab (endpoints included)?"""
    a, b = np.asarray(a), np.asarray(b)

    def orient(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    for p, q in itertools.pairwise(poly):
        o1, o2 = orient(p, q, a), orient(p, q, b)
        o3, o4 = orient(a, b, p), orient(a, b, q)
        if o1 * o2 <= 0 and o3 * o4 <= 0 and (o1, o2, o3, o4) != (0, 0, 0, 0):
            return True
    return False


def covered(curves, p, q, a, b) -> bool:
    """Is the edge ab crossed by a P|Q curve of ``curves``?"""
    return any({c["left"], c["right"]} == {p, q} and crosses(c["u"], a, b) for c in curves)


def reached(curves, a, b, u) -> bool:
    """Does an A|B curve of ``curves`` end at u?"""
    return any(
        {c["left"], c["right"]} == {a, b}
        and min(np.linalg.norm(c["u"][0] - u), np.linalg.norm(c["u"][-1] - u)) < 1e-7
        for c in curves
    )


@dataclasses.dataclass(frozen=True)
class Setting:
    """What every trace of one map shares: the values (holding the grid's, pickled to a
    worker), the patterns a traced point is compared with, in order, the scans' options and
    the step policy."""

    values: object
    found: tuple
    options: object
    policy: object


@dataclasses.dataclass(frozen=True)
class Piece:
    """A task's result: its curves (dicts: left, right, u, ends, value, seed, triples),
    the patterns its scans found that ``found`` lacked, and its single-pattern solves."""

    curves: tuple
    found: tuple
    solves: int


class _Tracer:
    """One task's state: its own copy of the values and its curves."""

    def __init__(self, setting: Setting):
        self.values = setting.values.fresh()
        self.found = list(setting.found)
        self.options, self.policy = setting.options, setting.policy
        self.curves: list[dict] = []

    def candidates(self, u):
        return self.found

    def check(self, u, v):
        """A pattern a full scan finds earlier than v at u (a triple point, or where a curve
        ends), else None; a mode no task had seen joins the compared ones (the curve is
        taken again to it)."""
        first, w = scan_label(self.values, self.options, u)
        late = not (valued(first) and math.isfinite(w))
        if late or self.values.sense * (w - v) >= -CERTIFIED * max(1.0, abs(v)):
            return None
        if first not in self.found:
            self.found.append(first)
        return first

    def piece(self, known) -> Piece:
        new = tuple(lab for lab in self.found if lab not in known)
        return Piece(tuple(self.curves), new, self.values.solves)

    def edge(self, p, q, a, b, depth: int = SPLITS):
        """Seed and trace the P|Q boundary crossing the grid edge from a (P) to b (Q)."""
        if covered(self.curves, p, q, a, b):
            return
        r = edge_root(self.values, p, q, a, b)
        crossing = r is not None
        if r is None:  # no crossing of d_PQ: a third pattern between, found by a scan
            if depth <= 0:
                return
            r = 0.5 * (np.asarray(a) + np.asarray(b))
        first, _ = scan_label(self.values, self.options, r)  # a third pattern splits
        if first not in (p, q):
            if first != FAILED and depth > 0:
                if first not in self.found:
                    self.found.append(first)
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
        self.trace(p, q, left, r, t, None, ("edge", p, q, tuple(a), tuple(b)))

    def branch(self, labels, u, a, b):
        """Trace the A|B boundary leaving the triple point u of ``labels`` (away from the
        side where the third pattern comes first)."""
        c = next(lab for lab in labels if lab not in (a, b))
        d = self.values.condition(a, b)
        g = gradient(d, u)
        t = np.array([-g[1], g[0]]) / math.hypot(*g)
        probe = np.clip(u + 1e-3 * t, 0, 1)
        if self.values.condition(a, c)(probe) > 0:  # c first that way
            t = -t
        left = b if np.dot(g, [-t[1], t[0]]) > 0 else a
        self.trace(a, b, left, u, t, TRIPLE, ("branch", a, b, tuple(u)))

    def trace(self, p, q, left, start, t, start_end, seed):
        values = self.values
        fwd = follow(values, p, q, start, t, self.candidates, self.policy, self.check)
        if start_end is None:
            back = follow(values, p, q, start, -t, self.candidates, self.policy, self.check)
        else:
            back = ([np.asarray(start)], start_end, None)
        pts = [np.asarray(x) for x in back[0][::-1]]
        for x in fwd[0][1:]:
            if np.linalg.norm(np.asarray(x) - pts[-1]) > 1e-14:
                pts.append(np.asarray(x))
        while len(pts) > 1 and np.linalg.norm(pts[1] - pts[0]) <= 1e-14:
            pts.pop(0)  # an exit at the seed itself (a seed on the box's edge)
        common = [values.value(p if valued(p) else q, u) for u in pts]
        self.curves.append(
            {"left": left, "right": q if left == p else p, "u": np.array(pts),
             "ends": (back[1], fwd[1]), "seed": seed,
             "value": tuple(math.nan if v is None else v for v in common),
             "triples": tuple(x for x in (back[2], fwd[2]) if x is not None)}
        )  # fmt: skip


def trace_edge(task) -> Piece:
    """The boundaries seeded on one grid edge (a pool's task: setting, (p, q, a, b))."""
    setting, (p, q, a, b) = task
    tracer = _Tracer(setting)
    tracer.edge(p, q, a, b)
    return tracer.piece(setting.found)


def trace_branch(task) -> Piece:
    """The boundary leaving a triple point (a pool's task: setting, (labels, u, a, b))."""
    setting, (labels, u, a, b) = task
    tracer = _Tracer(setting)
    tracer.branch(labels, u, a, b)
    return tracer.piece(setting.found)


def _in_order(fn, setting, seeds, pair, skip, run, width):
    """Yield ``(seed, fn((setting, seed)))`` for each seed not skipped at its turn, in
    order; ``skip`` is asked again at each turn, after the caller kept what came before.
    Batches run the next seed with up to ``width`` - 1 later ones of other pairs."""
    done: dict = {}
    for i, seed in enumerate(seeds):
        if skip(seed):
            continue
        if i not in done:
            batch, pairs = [i], {pair(seed)}
            for j in range(i + 1, len(seeds)):
                if len(batch) >= width:
                    break
                if j not in done and pair(seeds[j]) not in pairs and not skip(seeds[j]):
                    batch.append(j)
                    pairs.add(pair(seeds[j]))
            for k, piece in run(fn, [(setting, seeds[j]) for j in batch]):
                done[batch[k]] = piece
        yield seed, done.pop(i)


def _pair(p, q) -> frozenset:
    return frozenset((p, q))


def trace_boundaries(values, found, options, policy, edges, run, width, say=None):
    """Every boundary of a map: traced from the grid ``edges`` [(p, q, a, b)] in order,
    then outwards from the triple points found (``ROUNDS`` times at most).

    ``run(fn, tasks)`` yields (index, result) in any order (a pool); ``width`` tasks at
    most are run at once. Returns (curves, triples [(labels, u, value)], found, solves):
    ``solves`` counts the kept tasks' solves only (the same for any ``width``).
    """
    found = list(found)
    kept: list[dict] = []
    triples: list[tuple] = []
    solves = 0

    def keep(piece, check_seeds):
        nonlocal solves
        solves += piece.solves
        for c in piece.curves:
            if check_seeds and covered(kept, *c["seed"][1:]):
                continue  # traced before from another seed
            kept.append(c)
            if say is not None:
                say(f"traced the boundary {label_json(c['left'])} | {label_json(c['right'])}")
            for labels, u, v in c["triples"]:
                if not any(
                    set(lab) == set(labels) and np.linalg.norm(w - u) < 1e-6
                    for lab, w, _ in triples
                ):
                    triples.append((labels, np.asarray(u), v))
        found.extend(lab for lab in piece.found if lab not in found)

    setting = Setting(values, tuple(found), options, policy)
    for _, piece in _in_order(
        trace_edge, setting, edges, lambda s: _pair(*s[:2]),
        lambda s: covered(kept, *s), run, width,
    ):  # fmt: skip
        keep(piece, True)
    done = 0
    for _ in range(ROUNDS):
        todo, done = triples[done:], len(triples)
        pairs = [(labels, u, itertools.combinations(labels, 2)) for labels, u, _ in todo]
        branches = [(labels, u, a, b) for labels, u, two in pairs for a, b in two]
        setting = Setting(values, tuple(found), options, policy)
        for _, piece in _in_order(
            trace_branch, setting, branches, lambda s: _pair(*s[2:]),
            lambda s: reached(kept, s[2], s[3], s[1]), run, width,
        ):  # fmt: skip
            keep(piece, False)
    return kept, triples, found, solves
