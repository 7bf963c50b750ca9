"""``make bench``: the suite across the parameter space, the figures, first calls, memory.

For every point of :data:`CASES` a full scan (m <= 30, n <= 40, the prismatic and
torsional families, probes, widening and the exact short-wave limit, as ``scan_modes``
does by default) is timed in this process against

* the peer: the package's own Chebyshev collocation with the same pruning (the same march,
  the same lazily re-evaluated modes). Its time is that of our scan with each kernel
  evaluation replaced by a collocation evaluation: the number of (state, mode)
  evaluations of the scan (loose signs and fine solves counted apart) times the measured
  cost of one collocation evaluation at that point (24 nodes for signs, 40 for solves),
  plus our scan's time outside the kernel (base states, march, short-wave limit), which
  the peer shares. A collocation scan run in full would take hours per point; its
  accuracy is measured: the collocation critical value of the critical mode (40 nodes).
* the baseline (baseline.py): plain SciPy, no pruning, timed on the critical mode of the
  scan (a low mode: among the cheapest for SciPy) and multiplied by the number of wrinkle
  modes.

Errors are against a converged value: the critical mode at rtol 1e-13 (or the short-wave
limit at 1e-13). Then: one critical mode in a warm process, the first critical value in a
fresh process, every paper figure and the whole ``electrogrowth reproduce`` (a child
process under resource accounting: peak memory), and the sweep throughput serial / local
pool / dask LocalCluster (sweep_bench.py). Results go to benchmarks/results.json and the
tables between the markers of BENCHMARKS.md. The layered points (layered_bench.py: a
mucosal bilayer, a thin stiff film, three layers, a pressurised and a force-controlled tube,
the collocation peer run on four) follow; ``--layered`` runs only those (their table
between the layered markers). ``--quick``: three small points, no figures, no sweep
(checks that the script runs).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from electrogrowth import Layer, Tube
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes
from electrogrowth.bifurcation.scan_grid import scan_grid
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.incremental import targets as targets_module
from electrogrowth.incremental.targets import collocation_targets
from electrogrowth.model.materials import gent

sys.path.insert(0, os.path.dirname(__file__))
import baseline  # noqa: E402
import layered_bench  # noqa: E402

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
FULL = ScanOptions((0, 30), (1, 40))
QUICK = ScanOptions((0, 4), (1, 4))
P = Tube.uniform

#: (name, tube, solve_for, side): the paper's box and its hard corners.
CASES = [
    ("thin Rbar_o 1.05, growth, Vbar 0.2", P(1.05, 1.0, voltage=0.2), "growth", None),
    ("thin Rbar_o 1.1, stretch compression", P(1.1, 1.0), "stretch", "compression"),
    ("thin Rbar_o 1.1, voltage", P(1.1, 1.0), "voltage", None),
    ("Fig. 9 tube Rbar_o 1.4, growth, Vbar 0.4", P(1.4, 1.0, voltage=0.4), "growth", None),
    ("short L 0.5, growth, Vbar 0.4", P(1.4, 0.5, voltage=0.4), "growth", None),
    ("slender L 10, stretch compression", P(1.4, 10.0), "stretch", "compression"),
    ("slender L 10, voltage", P(1.4, 10.0), "voltage", None),
    ("thick Rbar_o 2, growth, Vbar 0.3", P(2.0, 1.0, voltage=0.3), "growth", None),
    ("thick Rbar_o 2, voltage (near threshold)", P(2.0, 1.0), "voltage", None),
    (
        "thick Rbar_o 2.5, stretch extension, Vbar 0.3",
        P(2.5, 1.0, voltage=0.3),
        "stretch",
        "extension",
    ),
    (
        "short wave: extension, Vbar 0.4 (surface)",
        P(1.4, 1.0, voltage=0.4),
        "stretch",
        "extension",
    ),
    (
        "Gent J_m 10, growth, Vbar 0.4",
        P(1.4, 1.0, voltage=0.4, material=gent(10.0)),
        "growth",
        None,
    ),
]
QUICK_CASES = [CASES[3], CASES[1], CASES[10]]


class KernelCounter:
    """Counts (state, mode) kernel evaluations, loose (rtol >= 1e-6) and fine, and their
    time, by wrapping the kernel entry points that impedance_targets calls."""

    def __init__(self):
        self.loose = self.fine = 0
        self.seconds = 0.0
        self.saved = {}

    def __enter__(self):
        # rows_*: a target evaluation's modes (incremental/mode_rows.py); target_serial: the
        # retries of failed members; rows_determinant: a root's refinement on det(M2)
        # (incremental/targets.py). All take (batch, ..., tables, rtol, max_steps) with the
        # batch's length first.
        for name in ("rows_parallel", "rows_serial", "target_serial", "rows_determinant"):
            kernel = getattr(targets_module, name)
            self.saved[name] = kernel

            def wrapped(batch, *args, _kernel=kernel):
                t = time.perf_counter()
                out = _kernel(batch, *args)
                self.seconds += time.perf_counter() - t
                if args[-2] >= 1e-6:  # rtol
                    self.loose += len(batch)
                else:
                    self.fine += len(batch)
                return out

            setattr(targets_module, name, wrapped)
        return self

    def __exit__(self, *exc):
        for name, kernel in self.saved.items():
            setattr(targets_module, name, kernel)


def median_time(fn, repeat):
    """Median wall time, median CPU time of this process (all threads), last result."""
    times, cpu, out = [], [], None
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        out = fn()
        times.append(time.perf_counter() - t)
        cpu.append(time.process_time() - c)
    return statistics.median(times), out, statistics.median(cpu)


def converged(params, solve_for, side, res):
    c = res.critical
    if c.kind == "surface":
        return short_wave_limit(params, solve_for, side=side, rtol=1e-13).value
    if c.kind != "bifurcation":
        return c.value
    return resolve(params, c, solve_for, side, 1e-7, rtol=1e-13)


def resolve(params, c, solve_for, side, width, **kw) -> float:
    """The critical value of the scan's critical mode again, bracketed within a relative
    ``width`` of it (``kw``: rtol, method)."""
    w = width * abs(c.value)
    bracket = (c.value - w, c.value + w)
    return critical_value(
        params, c.m, c.n, solve_for, family=c.family, side=side, bracket=bracket, **kw
    ).value


def collocation_cost(params, res, rows, nodes, repeat=3):
    """Seconds per collocation evaluation at the critical state: the median over ``rows``
    of each row's fastest of ``repeat`` evaluations (single timings of a dense SVD varied
    up to 6x between runs on the idle machine)."""
    at = res.critical.params
    state = solve_base_state(at)
    collocation_targets(state, rows[:1], nodes=nodes)
    times = []
    for row in rows:
        best = math.inf
        for _ in range(repeat):
            t = time.perf_counter()
            collocation_targets(state, row[None, :], nodes=nodes)
            best = min(best, time.perf_counter() - t)
        times.append(best)
    return statistics.median(times)


def bench_case(name, params, solve_for, side, options, repeat, peer_accuracy):
    scan = lambda: scan_modes(params, solve_for, side=side, options=options)  # noqa: E731
    scan()  # warm: the stable-sign caches of this tube, as along a curve
    t_eg, res, cpu_eg = median_time(scan, repeat)
    with KernelCounter() as count:
        t_counted = time.perf_counter()
        scan()
        t_counted = time.perf_counter() - t_counted
    ref = converged(params, solve_for, side, res)
    err_eg = abs(res.critical.value - ref) / abs(ref)
    c = res.critical
    grid = scan_grid(res.m_range, res.n_range, options.extend, (True, True))
    pick = grid[np.linspace(0, len(grid) - 1, 5).astype(int)]
    t24 = collocation_cost(params, res, pick, 24)
    t40 = collocation_cost(params, res, pick, 40)
    t_peer = (t_counted - count.seconds) + count.loose * t24 + count.fine * t40
    err_peer = None
    if peer_accuracy and c.kind == "bifurcation":
        col = resolve(params, c, solve_for, side, 1e-6, method="collocation")
        err_peer = abs(col - ref) / abs(ref)
    # baseline: the critical mode (or (0, 1) at a surface optimum); a low mode is among
    # the cheapest for SciPy, so the extrapolation favours the baseline
    modes = [(c.m, c.n) if c.kind == "bifurcation" and c.n > 0 else (0, 1)]
    t_base, err_base = [], None
    for k, (m, n) in enumerate(modes):
        t = time.perf_counter()
        try:
            v = baseline.critical_value(params, m, n, solve_for, side, rtol=1e-8)
        except (RuntimeError, ValueError) as exc:
            print(f"  baseline mode ({m}, {n}) failed: {exc}", file=sys.stderr)
            v = None
        t_base.append(time.perf_counter() - t)
        if k == 0 and v is not None and c.kind == "bifurcation":
            err_base = abs(v - ref) / abs(ref)
    wrinkles = int(np.sum(grid[:, 2] == 0)) if grid.shape[1] > 2 else len(grid)
    t_baseline = float(np.mean(t_base)) * wrinkles
    out = {
        "name": name,
        "tube": params.as_dict() if hasattr(params, "as_dict") else str(params),
        "solve_for": solve_for,
        "side": side,
        "kind": str(c.kind),
        "mode": [c.m, c.n],
        "value": c.value,
        "converged": ref,
        "m_range": list(res.m_range),
        "n_range": list(res.n_range),
        "modes_in_grid": int(len(grid)),
        "kernel_evaluations": {"loose": count.loose, "fine": count.fine},
        "seconds": t_eg,
        "cpu_seconds": cpu_eg,
        "kernel_seconds": count.seconds,
        "peer_seconds": t_peer,
        "peer_seconds_per_evaluation": {"24 nodes": t24, "40 nodes": t40},
        "baseline_seconds": t_baseline,
        "baseline_seconds_per_mode": t_base,
        "error": err_eg,
        "peer_error": err_peer,
        "baseline_error": err_base,
    }
    print(
        f"{name:<48}{t_eg:8.3f}s peer {t_peer:9.1f}s ({t_peer / t_eg:6.0f}x)"
        f" baseline {t_baseline:9.0f}s ({t_baseline / t_eg:7.0f}x)  err {err_eg:.1e}"
        f" peer {err_peer if err_peer is None else f'{err_peer:.1e}'}"
        f" base {err_base if err_base is None else f'{err_base:.1e}'}  {c.kind} ({c.m}, {c.n})",
        flush=True,
    )
    return out


def warm_mode(repeat=30):
    """(median wall, min wall, median CPU) of one critical value in a warm process."""
    p = P(1.4, 1.0, voltage=0.4)
    critical_value(p, 0, 1, "growth")
    wall, _, cpu = median_time(lambda: critical_value(p, 0, 1, "growth"), repeat)
    return wall, wall, cpu


#: a critical value's CPU time against its mode (issue 21: the cost per mode must not grow
#: with m): the thick tube in voltage, and a stiff film outside a thick substrate
MODE_COST = [
    (
        "thick Rbar_o 2, L 1, voltage",
        P(2.0, 1.0),
        "voltage",
        [(2, 1), (40, 0), (400, 0), (2000, 0), (0, 2000), (2000, 2000)],
    ),
    (
        "film mu 100, 0.004 thick, outside R 2, L 5, hoop growth",
        Tube((Layer(2.0), Layer(2.004, shear_modulus=100.0)), length=5.0, stretch=1.0),
        "growth[2].theta",
        [(20, 0), (200, 0), (1000, 0), (2000, 0)],
    ),
]


def mode_cost(repeat=5) -> list:
    """[{tube, mode, value, cpu_seconds}]: the median CPU of ``repeat`` warm calls each."""
    out = []
    for name, tube, control, modes in MODE_COST:
        for m, n in modes:
            critical_value(tube, m, n, control)  # its first call: tables, states
            _, res, cpu = median_time(lambda: critical_value(tube, m, n, control), repeat)  # noqa: B023
            out.append({"tube": name, "mode": [m, n], "value": res.value, "cpu_seconds": cpu})
    return out


FRESH = (
    "import time; t = time.perf_counter(); from electrogrowth import Tube;"
    "from electrogrowth.bifurcation.critical import critical_value;"
    "critical_value(Tube.uniform(1.4, 1.0, voltage=0.4), 0, 1, 'growth');"
    "print(time.perf_counter() - t)"
)


def fresh_process(repeat=3):
    """Wall time of a new interpreter importing the package and computing one critical
    value, the compiled kernels loaded from numba's cache; and of the whole process."""
    inner, outer = [], []
    for _ in range(repeat):
        t = time.perf_counter()
        out = subprocess.run(
            [sys.executable, "-c", FRESH], capture_output=True, text=True, check=True
        ).stdout
        outer.append(time.perf_counter() - t)
        inner.append(float(out.split()[-1]))
    return statistics.median(inner), statistics.median(outer)


def reproduce(quick: bool):
    """The whole ``electrogrowth reproduce`` in a child: its time, each figure's time, the
    child's peak memory."""
    exe = Path(sys.executable).with_name("electrogrowth")
    with tempfile.TemporaryDirectory() as tmp:
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        before = usage.ru_maxrss
        cpu = usage.ru_utime + usage.ru_stime
        t = time.perf_counter()
        cmd = [str(exe), "reproduce", "--out", tmp] + (["--quick"] if quick else [])
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        seconds = time.perf_counter() - t
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        peak = usage.ru_maxrss
        cpu = usage.ru_utime + usage.ru_stime - cpu
    figures = {
        int(m.group(1)): float(m.group(2))
        for m in re.finditer(r"figure (\d+): .* \(([\d.]+) s\)", out)
    }
    return seconds, figures, max(peak, before) / 1024, cpu


def sweep_throughput(quick: bool):
    cmd = [sys.executable, str(HERE / "sweep_bench.py")] + (["--quick"] if quick else [])
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def tables(results) -> str:
    lines = [
        f"Measured {results['date']} on {results['machine']}; {results['note']}",
        "",
        "| point | result | modes | electrogrowth (CPU) | peer (collocation) | ratio | baseline"
        " (SciPy) | ratio | error | peer error | baseline error |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    fmt = lambda e: "" if e is None else f"{e:.0e}"  # noqa: E731
    for r in results["scans"]:
        what = (
            f"{r['kind']} ({r['mode'][0]}, {r['mode'][1]})"
            if r["kind"] == "bifurcation"
            else r["kind"]
        )
        lines.append(
            f"| {r['name']} | {what} {r['value']:.6g} | {r['modes_in_grid']} |"
            f" {r['seconds']:.3f} s ({r.get('cpu_seconds', math.nan):.3f} s) |"
            f" {r['peer_seconds']:.0f} s |"
            f" {r['peer_seconds'] / r['seconds']:.0f}x | {r['baseline_seconds']:.0f} s |"
            f" {r['baseline_seconds'] / r['seconds']:.0f}x | {fmt(r['error'])} |"
            f" {fmt(r['peer_error'])} | {fmt(r['baseline_error'])} |"
        )
    for f in results.get("failed", []):
        lines.append(f"| {f['name']} | failed: {f['error']} | | | | | | | | | |")
    s = [r["seconds"] for r in results["scans"]]
    c = [r.get("cpu_seconds", math.nan) for r in results["scans"]]
    lines += [
        "",
        f"Scans: wall median {statistics.median(s):.3f} s, max {max(s):.3f} s; CPU median"
        f" {statistics.median(c):.3f} s, max {max(c):.3f} s. At the surface points the"
        " baseline's time is its march of mode (0, 1) (it has no short-wave limit).",
        "",
    ]
    o = results["other"]
    lines += [
        "| case | time |",
        "|---|---:|",
        f"| one critical mode, warm process (median of 30) | {1e3 * o['warm_mode'][0]:.2f} ms"
        f" (CPU {1e3 * o['warm_mode'][2]:.2f} ms) |",
        f"| fresh process: import + first critical value | {o['fresh'][0]:.2f} s"
        f" (whole process {o['fresh'][1]:.2f} s) |",
    ]
    for row in o.get("mode_cost", []):
        m, n = row["mode"]
        lines.append(
            f"| critical ({m}, {n}), {row['tube']}, warm (CPU, median of 5)"
            f" | {1e3 * row['cpu_seconds']:.1f} ms |"
        )
    if "reproduce" in o:
        rep = o["reproduce"]
        for number, sec in sorted(rep["figures"].items(), key=lambda kv: int(kv[0])):
            lines.append(f"| Figure {number} | {sec:.1f} s |")
        lines.append(
            f"| `electrogrowth reproduce` (all, patterns, index) | {rep['seconds']:.1f} s |"
        )
        lines.append(f"| peak memory of `reproduce` (max RSS) | {rep['max_rss_mb']:.0f} MB |")
    lines.append(f"| peak memory of this benchmark process | {o['max_rss_mb']:.0f} MB |")
    if "sweep" in o:
        sw = o["sweep"]
        lines += ["", "| sweep driver | points/s | seconds | speed-up |", "|---|---:|---:|---:|"]
        base = sw["runs"][0]["seconds"]
        for run in sw["runs"]:
            lines.append(
                f"| {run['name']} | {run['points'] / run['seconds']:.2f} | {run['seconds']:.1f}"
                f" | {base / run['seconds']:.2f} |"
            )
        lines.append("")
        lines.append(sw["note"])
    return "\n".join(lines)


def write_markdown(text: str, path: Path, which: str = "bench") -> None:
    begin, end = f"<!-- {which}:begin -->", f"<!-- {which}:end -->"
    doc = path.read_text()
    if begin in doc and end in doc:
        doc = doc[: doc.index(begin) + len(begin)] + "\n" + text + "\n" + doc[doc.index(end) :]
    else:
        doc += f"\n{begin}\n{text}\n{end}\n"
    path.write_text(doc)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="three small points, no figures")
    ap.add_argument("--layered", action="store_true", help="only the layered points")
    ap.add_argument("--out", type=Path, default=HERE / "results.json")
    ap.add_argument("--markdown", type=Path, default=ROOT / "BENCHMARKS.md")
    args = ap.parse_args(argv)
    load = os.getloadavg()[0]
    results = {
        "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "machine": f"{os.cpu_count()} cores, {platform.machine()}, Python"
        f" {platform.python_version()}",
        "note": f"load average {load:.1f} at the start (the machine is shared); quick"
        if args.quick
        else f"load average {load:.1f} at the start (the machine is shared)",
        "quick": args.quick,
    }
    critical_value(P(1.4, 1.0, voltage=0.4), 0, 1, "growth")  # load the compiled kernels
    if args.layered:
        results["layered"] = layered(results, args)
        return
    options, cases = (QUICK, QUICK_CASES) if args.quick else (FULL, CASES)
    other = {}
    results["other"] = other

    def save():
        other["max_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        results["load_average_end"] = os.getloadavg()[0]
        args.out.write_text(json.dumps(results, indent=1, default=str))

    results["scans"] = []
    for case in cases:
        try:
            results["scans"].append(bench_case(*case, options, 1 if args.quick else 3, True))
        except Exception as exc:  # noqa: BLE001 -- a failing point is a result too
            results.setdefault("failed", []).append(
                {"name": case[0], "error": f"{type(exc).__name__}: {exc}"}
            )
            print(f"{case[0]}: FAILED {type(exc).__name__}: {exc}", flush=True)
        save()
    other["warm_mode"] = warm_mode()
    other["fresh"] = fresh_process(1 if args.quick else 3)
    print(f"warm mode {1e3 * other['warm_mode'][0]:.2f} ms, fresh {other['fresh']}", flush=True)
    if not args.quick:
        other["mode_cost"] = mode_cost()
    save()
    if not args.quick:
        other["sweep"] = sweep_throughput(False)
        save()
        seconds, figures, rss, cpu = reproduce(False)
        other["reproduce"] = {
            "seconds": seconds,
            "cpu_seconds": cpu,
            "figures": figures,
            "max_rss_mb": rss,
        }
        print(f"reproduce {seconds:.1f} s {figures} {rss:.0f} MB", flush=True)
    save()
    text = tables(results)
    print(text)
    if not args.quick:
        write_markdown(text, args.markdown)
        layered(results, args)


def layered(results, args) -> list:
    """The layered points (layered_bench.py), their results in ``layered`` of the results
    file (of results_layered.json with ``--layered``) and their table in BENCHMARKS.md."""
    rows = results.setdefault("layered", [])
    out = args.out.with_name("results_layered.json") if args.layered else args.out
    for case in layered_bench.LAYERED_CASES:
        try:
            rows.append(layered_bench.bench_layered(*case))
        except Exception as exc:  # noqa: BLE001 -- a failing point is a result too
            rows.append({"name": case[0], "failed": f"{type(exc).__name__}: {exc}"})
        results["load_average_end"] = os.getloadavg()[0]
        out.write_text(json.dumps(results, indent=1, default=str))
    done = [r for r in rows if "failed" not in r]
    text = "\n".join(
        [
            f"Measured {results['date']} on {results['machine']}; {results['note']}, load"
            f" average {results['load_average_end']:.1f} at the end",
            "",
            layered_bench.layered_table(done),
        ]
        + [f"\n{r['name']}: failed: {r['failed']}" for r in rows if "failed" in r]
    )
    print(text)
    if not args.quick:
        write_markdown(text, args.markdown, "layered")
    return rows


if __name__ == "__main__":
    main()
