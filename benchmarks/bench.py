"""``make bench``: electrogrowth against the plain SciPy baseline, same inputs, one process.

Prints, per case, both times, their ratio and each result's error against a converged
value. The baseline (benchmarks/baseline.py) is too slow for full scans; there it is timed
on a subsample of modes and extrapolated per mode, which the table says.
"""

from __future__ import annotations

import dataclasses
import os
import resource
import subprocess
import sys
import time

import numpy as np

from electrogrowth import TubeParameters
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes

sys.path.insert(0, os.path.dirname(__file__))
import baseline  # noqa: E402

POINT = TubeParameters(outer_radius=1.4, length=1.0, stretch=1.0, voltage=0.4)
FULL = dict(options=ScanOptions((0, 30), (1, 40), extend=False))
SAMPLE = [(0, 1), (4, 1), (3, 7)]  # baseline subsample of the scan (g_cr 1.27 .. 2.25)


def timed(fn, *args, repeat=1, **kwargs):
    best, out = np.inf, None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn(*args, **kwargs)
        best = min(best, time.perf_counter() - t)
    return best, out


def baseline_tolerance(ref: float, m: int, n: int) -> tuple[float, float, float]:
    """Loosest solve_ivp rtol whose critical g matches the converged value to 1e-8."""
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
        t, g = timed(baseline.critical_growth, POINT, m, n, rtol=rtol)
        if abs(g - ref) <= 1e-8 * ref:
            return rtol, t, g
    raise RuntimeError("baseline never reached 1e-8")


def row(name, t_base, t_eg, err_base, err_eg, note=""):
    ratio = t_base / t_eg
    print(
        f"{name:<34}{t_base:>12.3f}{t_eg:>10.3f}{ratio:>10.0f}x{err_base:>11.1e}"
        f"{err_eg:>11.1e}  {note}"
    )
    return ratio


def main() -> None:
    print(f"electrogrowth benchmark, {os.cpu_count()} cores, {time.strftime('%Y-%m-%d')}")
    critical_value(POINT, 0, 1, "growth")  # compile / load the cached kernel
    print(f"{'case':<34}{'baseline s':>12}{'eg s':>10}{'ratio':>11}{'err base':>11}{'err eg':>11}")
    tolerances = []
    for m, n in ((0, 1), (3, 7)):
        ref = critical_value(POINT, m, n, "growth", rtol=1e-13)
        cert = critical_value(
            POINT,
            m,
            n,
            "growth",
            method="collocation",
            bracket=(ref.value * (1 - 1e-6), ref.value * (1 + 1e-6)),
        )
        rtol, t_base, g_base = baseline_tolerance(ref.value, m, n)
        tolerances.append(rtol)
        t_eg, one = timed(critical_value, POINT, m, n, "growth", repeat=3)
        row(
            f"one mode: g_cr of ({m}, {n})",
            t_base,
            t_eg,
            abs(g_base - ref.value) / ref.value,
            abs(one.value - ref.value) / ref.value,
            f"converged {ref.value:.13g} (collocation {cert.value:.13g}); baseline rtol {rtol:g}",
        )
        if (m, n) == (0, 1):
            ref01 = ref
    rtol = min(tolerances)
    per_mode = []
    for m, n in SAMPLE:
        t, _ = timed(baseline.critical_growth, POINT, m, n, rtol=rtol)
        per_mode.append(t)
    n_modes = 31 * 40
    t_base_scan = float(np.mean(per_mode)) * n_modes
    t_scan, scan = timed(scan_modes, POINT, "growth", repeat=3, **FULL)
    row(
        "full scan m 0..30, n 1..40",
        t_base_scan,
        t_scan,
        np.nan,
        abs(scan.critical.value - ref01.value) / ref01.value,
        f"baseline: {len(SAMPLE)} modes timed, x{n_modes} extrapolated",
    )

    t_fig9, points = figure9_time()
    row(
        "Figure 9: 2 x 40 full scans",
        t_base_scan * points,
        t_fig9,
        np.nan,
        np.nan,
        "baseline extrapolated per mode",
    )
    scaling()
    first_call_cost()


def figure9_time() -> tuple[float, int]:
    """Critical g along lambda_z for Vbar = 0.4, 0.6: 40 points each, full scans."""
    total, count = 0.0, 0
    for volt in (0.4, 0.6):
        p = dataclasses.replace(POINT, voltage=volt)
        lo = scan_modes(p, "stretch", side="compression", **FULL).critical.value
        hi = scan_modes(p, "stretch", side="extension", **FULL).critical.value
        for lz in np.linspace(lo, hi, 42)[1:-1]:
            t, _ = timed(scan_modes, dataclasses.replace(p, stretch=float(lz)), "growth", **FULL)
            total += t
            count += 1
    return total, count


def scaling() -> None:
    """Scan cost against the number of modes, and memory over many scans."""
    print("\nscan cost vs number of modes (same point):")
    for mm, nn in ((7, 10), (15, 20), (30, 40)):
        t, _ = timed(
            scan_modes,
            POINT,
            "growth",
            repeat=2,
            options=ScanOptions((0, mm), (1, nn), extend=False),
        )
        k = (mm + 1) * nn
        print(f"  {k:>5} modes: {t:.3f} s, {1e3 * t / k:.3f} ms per mode")
    rss = []
    for i, lz in enumerate(np.linspace(0.95, 1.3, 30)):
        scan_modes(
            dataclasses.replace(POINT, stretch=float(lz)),
            "growth",
            options=ScanOptions((0, 8), (1, 10), extend=False),
        )
        if i % 10 == 9:
            rss.append(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
    print("max RSS after 10, 20, 30 scans along a curve: " + ", ".join(f"{r:.0f} MB" for r in rss))


def first_call_cost() -> None:
    """Wall time of a fresh process computing one critical value (kernel from cache)."""
    code = (
        "import time; t=time.time(); from electrogrowth import TubeParameters;"
        "from electrogrowth.bifurcation.critical import critical_value;"
        "critical_value(TubeParameters(1.4, 1.0, voltage=0.4), 0, 1, 'growth');"
        "print(time.time()-t)"
    )
    t = float(
        subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, check=True
        ).stdout
    )
    print(f"\nfresh process, import + one critical value (compiled kernel cached): {t:.2f} s")


if __name__ == "__main__":
    main()
