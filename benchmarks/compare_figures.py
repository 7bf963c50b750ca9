"""Compare a regenerated figure directory with the committed docs/figures: per CSV the row
count, the largest relative difference of every numeric column (NaN = NaN), and the rows
whose mode or kind differ.

    python benchmarks/compare_figures.py out/figures [docs/figures]
"""

from __future__ import annotations

import csv
import math
import sys
from pathlib import Path


def rows(path: Path) -> tuple[list[str], list[list[str]]]:
    with path.open() as fh:
        data = list(csv.reader(fh))
    return data[0], data[1:]


def number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def compare(new: Path, old: Path) -> bool:
    same = True
    for old_csv in sorted(old.glob("fig*.csv")):
        new_csv = new / old_csv.name
        if not new_csv.exists():
            print(f"{old_csv.name}: missing in {new}")
            same = False
            continue
        head, a = rows(new_csv)
        head_old, b = rows(old_csv)
        if head != head_old or len(a) != len(b):
            print(
                f"{old_csv.name}: {len(a)} rows vs {len(b)} committed (columns equal: "
                f"{head == head_old})"
            )
            same = False
            continue
        worst, modes = {}, []
        for i, (ra, rb) in enumerate(zip(a, b)):
            for name, x, y in zip(head, ra, rb):
                u, v = number(x), number(y)
                if u is None or v is None:
                    if x != y:
                        modes.append((i, name, x, y))
                    continue
                if math.isnan(u) and math.isnan(v):
                    continue
                if math.isnan(u) != math.isnan(v):
                    modes.append((i, name, x, y))
                    continue
                d = abs(u - v) / max(abs(v), 1e-300) if v else abs(u)
                worst[name] = max(worst.get(name, 0.0), d)
                if name in ("m", "n", "kind", "surface") and u != v:
                    modes.append((i, name, x, y))
        big = {k: f"{v:.1e}" for k, v in worst.items() if v > 0}
        print(f"{old_csv.name}: {len(a)} rows; max relative difference {big or 0}")
        for i, name, x, y in modes[:10]:
            print(f"   row {i + 2}: {name} = {x} (committed {y})")
        same = same and not modes
    return same


if __name__ == "__main__":
    new = Path(sys.argv[1])
    old = Path(sys.argv[2]) if len(sys.argv) > 2 else Path(__file__).parents[1] / "docs/figures"
    sys.exit(0 if compare(new, old) else 1)
