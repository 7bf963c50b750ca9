"""Trace the gut-like bilayer's full mode map and design it for 8, 12 and 16 folds (dev tool).

Run ``PYTHONPATH=src .venv/bin/python tools/gut_fold_designs.py`` to (re)write
``examples/gallery/design/gut_folds.json``, which the gallery page
``plot_14_gut_folds.py`` reads: the map (figures/design_gallery.py ``FULL_BOX``,
``FULL_OPTIONS``) takes tens of minutes to trace and each design several more on a shared
two-core machine, far beyond a page's budget. ``--map FILE`` reuses a map already traced
(a JSON file of ``ModeMap.as_dict()``, or of this tool's output) and only designs.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parents[1]
OUT = HERE / "examples" / "gallery" / "design" / "gut_folds.json"


def main(argv=None) -> int:
    from electrogrowth.design.map_record import ModeMap
    from electrogrowth.figures import design_gallery as gallery

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", type=pathlib.Path, help="a map already traced (JSON)")
    parser.add_argument("--out", type=pathlib.Path, default=OUT)
    parser.add_argument("--map-out", type=pathlib.Path, help="also write the map alone here")
    parser.add_argument("--workers", type=int, default=1, help="processes (default 1)")
    args = parser.parse_args(argv)

    def say(text: str) -> None:
        print(text, file=sys.stderr, flush=True)

    if args.map is None:
        gallery.write_fold_designs(
            args.out, progress=say, workers=args.workers, map_path=args.map_out
        )
        return 0
    record = json.loads(args.map.read_text(encoding="utf-8"))
    record = record.get("map", record)
    mmap = ModeMap.from_dict(record)
    gallery.design_and_write(args.out, mmap, float(record["seconds"]), say, args.workers)
    return 0


if __name__ == "__main__":
    sys.exit(main())
