"""Sweep throughput (points per second): serial, the local process pool and a dask
LocalCluster with 1 and 2 workers, on the same small sweep, each into a fresh Zarr store.

The serial run without a store (compute_chunk in this process) gives the cost of the
points alone; the serial sweep adds chunking and storing. Prints one JSON line at the end
(read by bench.py). ``--quick``: a 4-point sweep, no dask.
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path

from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.model.layers import Tube
from electrogrowth.sweep.file import parse_config
from electrogrowth.sweep.run import compute_sweep
from electrogrowth.sweep.unit import ChunkTask, compute_chunk

SWEEP = """
[solve]
for = "growth"
[modes]
m = [0, 12]
n = [1, 30]
[fixed]
length = 1.0
voltage = 0.4
[grid]
stretch = {{ start = 0.9, stop = 1.3, num = {num} }}
outer_radius = [1.3, 1.4, 1.5]
[run]
chunk = {chunk}
"""


def run(name, config, **kw):
    with tempfile.TemporaryDirectory() as tmp:
        t = time.perf_counter()
        summary = compute_sweep(config, Path(tmp) / "s.zarr", progress=False, **kw)
        seconds = time.perf_counter() - t
    points = sum(summary.counts.values())
    print(f"{name}: {points} points in {seconds:.1f} s", flush=True)
    return {"name": name, "points": points, "seconds": seconds}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    num, chunk = (2, 2) if args.quick else (4, 2)
    config = parse_config(SWEEP.format(num=num, chunk=chunk))
    critical_value(Tube.uniform(1.4, 1.0, voltage=0.4), 0, 1, "growth")
    runs = []
    # the points alone: one task of the whole grid, serial, in this process, no store
    whole = tuple(slice(0, len(values)) for _, values in config.grid)
    task = ChunkTask(
        0, tuple((0, s.stop) for s in whole), tuple(config.points(whole)), config.spec
    )
    t = time.perf_counter()
    compute_chunk(task, threads=None)
    runs.append(
        {
            "name": "points alone (serial, no chunks, no store)",
            "points": len(task.params),
            "seconds": time.perf_counter() - t,
        }
    )
    runs.append(run("serial (1 worker, in process, with store)", config, workers=1))
    runs.append(run("local process pool, 2 workers", config, workers=2))
    if not args.quick:
        from distributed import Client, LocalCluster

        for n in (1, 2):
            with LocalCluster(
                n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None
            ) as cluster:
                t = time.perf_counter()
                with Client(cluster) as client:
                    client.run(critical_value, Tube.uniform(1.4, 1.0), 0, 1, "growth")
                warm = time.perf_counter() - t
                r = run(
                    f"dask LocalCluster, {n} worker(s)",
                    config,
                    scheduler=cluster.scheduler_address,
                )
                r["worker_start_seconds"] = warm
                runs.append(r)
    note = (
        f"Sweep: growth over 3 Rbar_o x {num} lambda_z (Vbar = 0.4, L = 1, m <= 12,"
        f" n <= 30), chunks of {chunk}; load average {os.getloadavg()[0]:.1f} at the end."
    )
    print(json.dumps({"runs": runs, "note": note}))


if __name__ == "__main__":
    main()
