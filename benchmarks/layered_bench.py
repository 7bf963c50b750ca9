"""The layered points of ``make bench`` (bench.py ``--layered`` runs only these).

At each point:

* **our scan**: ``scan_modes`` with its defaults (m <= 12, n <= 30, both families, probes,
  widening, the coarse-to-fine search of m beyond 64, the exact short-wave limit), the
  median of ``repeat`` runs after one warm-up (wall and CPU);
* **the march head to head**: the same mode march (bifurcation/march.py
  ``first_bifurcations``: the same steps, pruning and lazily re-evaluated modes) over the
  same grid (m <= 4, n <= 4 with the prismatic and torsional families), once with our
  impedance targets and once with the package's Chebyshev collocation (the peer), **run**,
  not modelled: signs at the scan's tolerance (1e-5; 40 nodes for collocation), roots at
  1e-12 (collocation: 40 nodes or the nodes that resolve the mode), the stable signs of the
  grid on the unloaded tube included in both times. Its ratio is the peer's time over ours.
* errors against a converged value: the critical mode of the march at rtol 1e-13.

The thin film is too costly for the peer's march (its modes need hundreds of nodes), so
there the peer is only its critical value of the scan's critical mode (accuracy).
"""

from __future__ import annotations

import statistics
import sys
import time

import numpy as np

from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.march import first_bifurcations, unloaded_signs
from electrogrowth.bifurcation.problem import as_problem
from electrogrowth.bifurcation.scan import scan_modes
from electrogrowth.bifurcation.scan_grid import scan_grid
from electrogrowth.incremental.accuracy import SCAN_SIGNS, SCAN_STABLE_SIGNS
from electrogrowth.incremental.targets import (
    CollocationTarget,
    ImpedanceTarget,
    collocation_stable_signs,
)
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.materials import gent, mooney_rivlin

#: the head-to-head grid: m <= 4, n <= 4, prismatic and torsional families (32 modes: a
#: collocation evaluation costs 0.1-1 s on the shared machine)
GRID = scan_grid((0, 4), (1, 4), False, (True, True))

MUCOSA = Tube(
    (Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)),
    length=3.0,
    voltage=0.3,
    inner_pressure=0.05,
)
FILM = Tube((Layer(1.002, growth=1.0), Layer(3.0, shear_modulus=1e-3)), length=1.0)
STACK = Tube(
    (
        Layer(1.05, shear_modulus=20.0, growth=(1.0, 1.15, 1.0)),
        Layer(1.3, shear_modulus=2.0, material=mooney_rivlin(0.3)),
        Layer(1.8, shear_modulus=0.5, growth=1.05, material=gent(30.0)),
    ),
    length=2.0,
    voltage=0.2,
)
PRESSURISED = Tube(
    (Layer(1.2, shear_modulus=5.0, growth=(1.0, 1.1, 1.0)), Layer(1.6)),
    length=2.0,
    voltage=0.1,
    outer_pressure=0.02,
)
FORCE = Tube(
    (Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)),
    length=3.0,
    axial_force=0.0,
    voltage=0.2,
    closed_ends=True,
    inner_pressure=0.03,
)

#: (name, tube, solve_for, side, run the peer's march)
LAYERED_CASES = [
    ("mucosal bilayer (mu 10 on 1, hoop growth, P_i 0.05, Vbar 0.3)", MUCOSA,
     "growth[1].theta", None, True),
    ("thin stiff film (h = 0.002, mu 1 on 1e-3, R_o 3), hoop growth", FILM,
     "growth[1].theta", None, False),
    ("three layers (mu 20 / 2 MR / 0.5 Gent), hoop growth, Vbar 0.2", STACK,
     "growth[1].theta", None, True),
    ("pressurised bilayer (mu 5 on 1, Vbar 0.1, P_o 0.02), inner pressure", PRESSURISED,
     "pressure", None, True),
    ("force-controlled bilayer (free closed ends, P_i 0.03), voltage", FORCE,
     "voltage", None, True),
]  # fmt: skip


def _timed(fn):
    t, c = time.perf_counter(), time.process_time()
    out = fn()
    return time.perf_counter() - t, time.process_time() - c, out


def march(tube, solve_for, side, method: str):
    """The mode march over GRID with ``method``'s targets, stable signs included, on the
    side the scan takes (the control's default side when ``side`` is None)."""
    side = as_problem(tube, solve_for, side=side).side
    if method == "impedance":
        loose, fine = ImpedanceTarget(SCAN_SIGNS), ImpedanceTarget(1e-12)
        signs = unloaded_signs(tube, GRID, ImpedanceTarget(SCAN_STABLE_SIGNS))
    else:
        loose, fine = CollocationTarget(SCAN_SIGNS), CollocationTarget(1e-12)
        signs = collocation_stable_signs(tube, GRID)
    res = first_bifurcations(
        tube, solve_for, side, GRID, loose, brent_targets=fine, stable_signs=signs
    )
    return res.found[0] if res.found else None


def converged(tube, solve_for, side, m, n, family, value):
    w = 1e-7 * abs(value)
    return critical_value(
        tube,
        m,
        n,
        solve_for,
        family=family,
        side=side,
        bracket=(value - w, value + w),
        rtol=1e-13,
    ).value


def bench_layered(name, tube, solve_for, side, peer: bool, repeat: int = 3) -> dict:
    scan = lambda: scan_modes(tube, solve_for, side=side)  # noqa: E731
    scan()
    runs = [_timed(scan) for _ in range(repeat)]
    t_scan, cpu_scan = statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)
    c = runs[-1][2].critical
    out = {
        "name": name,
        "layers": len(tube.layers),
        "solve_for": solve_for,
        "kind": str(c.kind),
        "mode": [c.m, c.n],
        "family": str(c.family),
        "value": c.value,
        "scan_seconds": t_scan,
        "scan_cpu_seconds": cpu_scan,
    }
    if c.kind == "bifurcation":
        ref = converged(tube, solve_for, side, c.m, c.n, c.family, c.value)
        out["converged"] = ref
        out["scan_error"] = abs(c.value - ref) / abs(ref)
    if peer:
        march(tube, solve_for, side, "impedance")  # warm
        ours = [_timed(lambda: march(tube, solve_for, side, "impedance")) for _ in range(repeat)]
        t_ours = statistics.median(r[0] for r in ours)
        mv = ours[-1][2]
        t_peer, cpu_peer, pv = _timed(lambda: march(tube, solve_for, side, "collocation"))
        ref = converged(tube, solve_for, side, mv.m, mv.n, mv.family, mv.value)
        out["march"] = {
            "modes": int(len(GRID)),
            "mode": [mv.m, mv.n],
            "family": mv.family,
            "seconds": t_ours,
            "cpu_seconds": statistics.median(r[1] for r in ours),
            "peer_seconds": t_peer,
            "peer_cpu_seconds": cpu_peer,
            "peer_mode": None if pv is None else [pv.m, pv.n],
            "error": abs(mv.value - ref) / abs(ref),
            "peer_error": None if pv is None else abs(pv.value - ref) / abs(ref),
        }
    elif c.kind == "bifurcation":  # the peer's accuracy on the critical mode only
        t, _, v = _timed(
            lambda: critical_value(
                tube,
                c.m,
                c.n,
                solve_for,
                family=c.family,
                side=side,
                method="collocation",
                bracket=(c.value * (1 - 1e-6), c.value * (1 + 1e-6)),
            )
        )
        out["peer_critical"] = {"seconds": t, "error": abs(v.value - ref) / abs(ref)}
    print(f"{name}: {out}", file=sys.stderr, flush=True)
    return out


def layered_table(rows) -> str:
    fmt = lambda e: "" if e is None else f"{e:.0e}"  # noqa: E731
    lines = [
        "| layered point | result of the scan | scan (CPU) | error | march head to head:"
        " modes, mode found, ours (CPU) | peer (collocation, run) (CPU) | ratio (CPU) | error |"
        " peer error |",
        "|---|---|---:|---:|---|---:|---:|---:|---:|",
    ]
    for r in rows:
        what = f"{r['kind']} ({r['mode'][0]}, {r['mode'][1]}) {r['family']} {r['value']:.10g}"
        head = (
            f"| {r['name']} | {what} | {r['scan_seconds']:.2f} s ({r['scan_cpu_seconds']:.2f}"
            f" s) | {fmt(r.get('scan_error'))} |"
        )
        if "march" in r:
            m = r["march"]
            lines.append(
                f"{head} {m['modes']}, ({m['mode'][0]}, {m['mode'][1]}): {m['seconds']:.2f} s"
                f" ({m['cpu_seconds']:.2f} s) | {m['peer_seconds']:.0f} s"
                f" ({m['peer_cpu_seconds']:.0f} s) | {m['peer_seconds'] / m['seconds']:.0f}x"
                f" ({m['peer_cpu_seconds'] / m['cpu_seconds']:.0f}x) | {fmt(m['error'])} |"
                f" {fmt(m['peer_error'])} |"
            )
        else:
            p = r.get("peer_critical", {})
            lines.append(
                f"{head} not run (the critical mode alone by collocation:"
                f" {p.get('seconds', np.nan):.0f} s) | | | | {fmt(p.get('error'))} |"
            )
    return "\n".join(lines)
