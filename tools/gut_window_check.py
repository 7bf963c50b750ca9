"""Which modes ever come first in the gut-like bilayer's map box (dev tool).

Full scans (``--m-max``, ``--n-max``, short waves probed, the exact short-wave limit, the
prismatic and torsional modes) at the nodes of a grid over the map's box and at the triple
points and certificate points of a stored map (``gut_folds.json``): the mode first and the
runners-up (m, n, family, critical value) at each. Its output (JSON lines) is the evidence that the
window of figures/design_gallery.py ``FULL_OPTIONS`` is complete for ``FULL_BOX``.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys
import time

HERE = pathlib.Path(__file__).resolve().parents[1]
MAP = HERE / "examples" / "gallery" / "design" / "gut_folds.json"


def points(record: dict, nodes: int) -> list[tuple[str, float, float]]:
    """The nodes of a ``nodes`` x ``nodes`` grid over the map's box, then the stored map's
    triple points and certificate points."""
    (_, x0, x1), (_, y0, y1) = record["vary"]
    grid = [i / (nodes - 1) for i in range(nodes)]
    out = [("node", x0 + a * (x1 - x0), y0 + b * (y1 - y0)) for a in grid for b in grid]
    out += [("triple", t["x"], t["y"]) for t in record["triple_points"]]
    for b in record["boundaries"]:
        out += [("certificate", c["x"], c["y"]) for c in b["certificates"]]
    return out


def main(argv=None) -> int:
    from electrogrowth import ScanOptions, scan_modes
    from electrogrowth.design.map_checks import label_of
    from electrogrowth.figures.design_gallery import CONTROL, FULL_BOX, gut_bilayer

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", type=pathlib.Path, default=MAP)
    parser.add_argument("--m-max", type=int, default=24)
    parser.add_argument("--n-max", type=int, default=30)
    parser.add_argument("--nodes", type=int, default=9, help="grid nodes a variable")
    parser.add_argument("--only", choices=("node", "triple", "certificate"))
    args = parser.parse_args(argv)
    record = json.loads(args.map.read_text(encoding="utf-8"))
    options = ScanOptions((0, args.m_max), (1, args.n_max), top=8)
    (kx, *_), (ky, *_) = FULL_BOX
    for kind, x, y in points(record.get("map", record), args.nodes):
        if args.only and kind != args.only:
            continue
        start = time.perf_counter()
        tube = gut_bilayer().at(kx, x).at(ky, y)
        res = scan_modes(tube, CONTROL, options=options)
        ranked = [res.critical, *res.runners_up]
        line = {
            "kind": kind, "x": x, "y": y, "first": str(label_of(res)),
            "value": res.critical.value,
            "ranked": [[c.m, c.n, c.family, c.value] for c in ranked if c.m is not None],
            "seconds": round(time.perf_counter() - start, 1),
        }  # fmt: skip
        print(json.dumps(line), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
