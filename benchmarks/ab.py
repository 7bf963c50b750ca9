"""``make bench-ab BASE=<git revision>``: is this checkout slower than BASE on any point?

Timings of two versions run one after the other differ by +-20 % on a shared machine, more
than the changes one wants to see. So the package of BASE (``git archive``) and the working
tree's are copied under two names (the package imports itself only relatively) and run in
**rounds of two fresh processes in alternating order**, each timing every point in CPU time
(all threads; waiting for a busy core does not count) as the median of ``--repeat`` warm
calls. The ratio reported is the median over rounds of head/base, with its quartiles. (Both
versions in one process, timed call by call, was tried first: the second package loaded ran
1.5x slower than alone, whichever it was, an artefact of sharing one process.) Numba compiles
each copy once (its cache is keyed by the file's path).

The points: the scans of ``make bench`` (bench.py CASES, full mode range), two critical modes
of the paper's tube (bench.py's warm mode among them), one of a bilayer, one of the mucosal
bilayer (layered_bench.py's) and a bilayer scan. Both versions must accept the
point; a point one of them cannot compute is listed, not timed. The table goes between the
``ab`` markers of BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import importlib
import io
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
import warnings
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

#: (name, the one-layer tube as Tube.uniform's keywords, control, side): bench.py CASES
UNIFORM = [
    ("thin Rbar_o 1.05, growth, Vbar 0.2", dict(outer_radius=1.05, voltage=0.2), "growth", None),
    ("thin Rbar_o 1.1, stretch compression", dict(outer_radius=1.1), "stretch", "compression"),
    ("thin Rbar_o 1.1, voltage", dict(outer_radius=1.1), "voltage", None),
    (
        "Fig. 9 tube Rbar_o 1.4, growth, Vbar 0.4",
        dict(outer_radius=1.4, voltage=0.4),
        "growth",
        None,
    ),
    (
        "short L 0.5, growth, Vbar 0.4",
        dict(outer_radius=1.4, length=0.5, voltage=0.4),
        "growth",
        None,
    ),
    (
        "slender L 10, stretch compression",
        dict(outer_radius=1.4, length=10.0),
        "stretch",
        "compression",
    ),
    ("slender L 10, voltage", dict(outer_radius=1.4, length=10.0), "voltage", None),
    ("thick Rbar_o 2, growth, Vbar 0.3", dict(outer_radius=2.0, voltage=0.3), "growth", None),
    ("thick Rbar_o 2, voltage (near threshold)", dict(outer_radius=2.0), "voltage", None),
    (
        "thick Rbar_o 2.5, stretch extension, Vbar 0.3",
        dict(outer_radius=2.5, voltage=0.3),
        "stretch",
        "extension",
    ),
    (
        "short wave: extension, Vbar 0.4 (surface)",
        dict(outer_radius=1.4, voltage=0.4),
        "stretch",
        "extension",
    ),
    (
        "Gent J_m 10, growth, Vbar 0.4",
        dict(outer_radius=1.4, voltage=0.4, gent=10.0),
        "growth",
        None,
    ),
]
QUICK = [UNIFORM[3], UNIFORM[1]]


def export(revision: str, into: Path, name: str) -> None:
    """The package ``src/electrogrowth`` of ``revision`` (or of the working tree when
    revision is None) as the top-level package ``name`` under ``into``."""
    target = into / name
    if revision is None:
        shutil.copytree(ROOT / "src" / "electrogrowth", target,
                        ignore=shutil.ignore_patterns("__pycache__"))  # fmt: skip
        return
    data = subprocess.run(
        ["git", "-C", str(ROOT), "archive", revision, "src/electrogrowth"],
        check=True, capture_output=True,
    ).stdout  # fmt: skip
    with tarfile.open(fileobj=io.BytesIO(data)) as tar:
        tar.extractall(into / "_archive", filter="data")
    shutil.move(into / "_archive" / "src" / "electrogrowth", target)


def uniform(eg, **kw):
    """The paper's tube in either version (``TubeParameters`` before ``Tube.uniform``)."""
    make = getattr(eg.Tube, "uniform", None) or eg.TubeParameters
    gent = kw.pop("gent", None)
    if gent is not None:
        kw["material"] = eg.gent(gent)
    return make(**kw)


def points(eg, quick: bool) -> dict:
    """name -> a call computing that point in package ``eg``."""
    full = eg.ScanOptions((0, 4), (1, 4)) if quick else eg.ScanOptions((0, 30), (1, 40))
    out = {}
    for name, kw, solve_for, side in QUICK if quick else UNIFORM:
        tube = uniform(eg, **kw)
        out[f"scan: {name}"] = lambda t=tube, c=solve_for, s=side: eg.scan_modes(
            t, c, side=s, options=full
        )
    paper = uniform(eg, outer_radius=1.4, voltage=0.4)
    out["critical mode (0, 1), growth (bench.py's warm mode)"] = lambda: eg.critical_value(
        paper, 0, 1, "growth"
    )
    out["critical mode (2, 3), stretch in compression"] = lambda: eg.critical_value(
        paper, 2, 3, "stretch", side="compression"
    )
    bilayer = eg.Tube((eg.Layer(1.1, shear_modulus=10.0, growth=1.1), eg.Layer(2.0)), voltage=0.2)
    out["bilayer critical mode (4, 1), growth[1]"] = lambda: eg.critical_value(
        bilayer, 4, 1, "growth[1]"
    )
    mucosa = eg.Tube(
        (eg.Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), eg.Layer(2.0)),
        length=3.0,
        voltage=0.3,
        inner_pressure=0.05,
    )
    out["mucosal bilayer critical mode (4, 1), growth[1].theta"] = lambda: eg.critical_value(
        mucosa, 4, 1, "growth[1].theta"
    )
    few = eg.ScanOptions((0, 8), (1, 4), surface=False)
    out["bilayer scan m <= 8, n <= 4, growth[1]"] = lambda: eg.scan_modes(
        bilayer, "growth[1]", options=few
    )
    return out


def child(package: str, quick: bool, only: str | None, repeat: int) -> None:
    """In a child process: each point of ``package`` warmed, then its median CPU time
    over ``repeat`` calls, as JSON on stdout (or the reason it cannot be computed)."""
    eg = importlib.import_module(package)
    out = {}
    for name, fn in points(eg, quick).items():
        if only is not None and only not in name:
            continue
        try:
            fn()
            times = []
            for _ in range(repeat):
                t = time.process_time()
                fn()
                times.append(time.process_time() - t)
            out[name] = statistics.median(times)
        except Exception as exc:  # a point one version cannot compute is listed
            out[name] = f"not timed: {type(exc).__name__}: {exc}".replace("|", "/")[:120]
    print(json.dumps(out))


def rounds(tmp: Path, args) -> dict:
    """name -> list of (base s, head s), one pair per round; the two versions run in
    alternating order, each round in fresh processes."""
    pairs: dict = {}
    for r in range(args.rounds):
        got = {}
        for package in ("eg_base", "eg_head") if r % 2 == 0 else ("eg_head", "eg_base"):
            cmd = [sys.executable, __file__, "--child", package, "--repeat", str(args.repeat)]
            cmd += ["--quick"] * args.quick + (["--only", args.only] if args.only else [])
            env = dict(os.environ, PYTHONPATH=str(tmp))
            done = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True)
            got[package] = json.loads(done.stdout)
        for name, head in got["eg_head"].items():
            pairs.setdefault(name, []).append((got["eg_base"].get(name), head))
        print(f"round {r + 1} of {args.rounds}:", json.dumps(got), file=sys.stderr, flush=True)
    return pairs


def summary(pairs: list) -> tuple | str:
    """(median base s, median head s, median of head/base over rounds, its quartiles)."""
    for b, h in pairs:
        if isinstance(b, str) or isinstance(h, str) or b is None:
            return b if isinstance(b, str) else str(h)
    tb, th = [b for b, _ in pairs], [h for _, h in pairs]
    ratios = sorted(h / b for b, h in pairs)
    q = statistics.quantiles(ratios, n=4) if len(ratios) > 1 else ratios * 3
    return statistics.median(tb), statistics.median(th), statistics.median(ratios), q[0], q[2]


def table(base_rev: str, head: str, rows: list, repeat: int) -> str:
    load = os.getloadavg()[0]
    lines = [
        f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} on"
        f" {os.cpu_count()} cores, {platform.machine()}, Python {platform.python_version()};"
        f" base `{base_rev}`, head `{head}`; {repeat} rounds of fresh processes; load average"
        f" {load:.1f} at the end (the machine is shared; rounds alternate the order).",
        "",
        "| point | base (median CPU) | head (median CPU) | head/base, median of rounds"
        " | quartiles |",
        "|---|---:|---:|---:|---:|",
    ]
    for name, res in rows:
        if isinstance(res, str):
            lines.append(f"| {name} | {res} | | | |")
            continue
        tb, th, r, q1, q3 = res
        lines.append(f"| {name} | {tb * 1e3:.1f} ms | {th * 1e3:.1f} ms | {r:.3f} |"
                     f" {q1:.3f} - {q3:.3f} |")  # fmt: skip
    return "\n".join(lines)


def write_markdown(path: Path, text: str) -> None:
    doc = path.read_text()
    begin, end = "<!-- ab:begin -->", "<!-- ab:end -->"
    block = f"{begin}\n{text}\n{end}"
    if begin in doc:
        doc = re.sub(re.escape(begin) + ".*?" + re.escape(end), lambda _: block, doc, flags=re.S)
    else:
        title = "## A/B against a base revision (`make bench-ab`)"
        doc = doc.rstrip("\n") + f"\n\n{title}\n\n{block}\n"
    path.write_text(doc)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("base", nargs="?", help="the git revision to compare with (a tag, a hash)")
    ap.add_argument("--rounds", type=int, default=7, help="process pairs (default 7)")
    ap.add_argument("--repeat", type=int, default=5, help="calls timed per process (default 5)")
    ap.add_argument("--quick", action="store_true", help="two small scans (checks it runs)")
    ap.add_argument("--only", metavar="TEXT", help="only the points whose name contains TEXT")
    ap.add_argument("--markdown", type=Path, default=ROOT / "BENCHMARKS.md")
    ap.add_argument("--no-markdown", action="store_true", help="print the table only")
    ap.add_argument("--child", metavar="PACKAGE", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    warnings.simplefilter("ignore")
    if args.child:
        return child(args.child, args.quick, args.only, args.repeat)
    if args.base is None:
        ap.error("the base revision is required (e.g. make bench-ab BASE=v0.3)")
    head = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip()  # fmt: skip
    with tempfile.TemporaryDirectory() as tmp:
        export(args.base, Path(tmp), "eg_base")
        export(None, Path(tmp), "eg_head")
        pairs = rounds(Path(tmp), args)
    rows = [(name, summary(p)) for name, p in pairs.items()]
    text = table(args.base, head + "+" if _dirty() else head, rows, args.rounds)
    print(text)
    if not args.no_markdown:
        write_markdown(args.markdown, text)


def _dirty() -> bool:
    out = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "src"],
                         capture_output=True, text=True).stdout  # fmt: skip
    return bool(out.strip())


if __name__ == "__main__":
    main()
