"""Compute the post-buckling gallery's branches (dev tool).

Run ``PYTHONPATH=src .venv/bin/python tools/postbuckle_gallery.py [mucosa] [dielectric]``
to (re)write ``examples/gallery/postbuckle/<case>.json``, which the pages
``plot_18_mucosal_folding.py`` and ``plot_19_dielectric_rings.py`` read: each branch
(figures/postbuckle_gallery.py ``CASES``) takes minutes on a shared two-core machine,
beyond a page's budget. ``--doc-image`` redraws the documentation's strip
(docs/images/postbuckle-folding.png) from the stored mucosa.json.
"""

from __future__ import annotations

import argparse
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parents[1]
OUT = HERE / "examples" / "gallery" / "postbuckle"
IMAGE = HERE / "docs" / "images" / "postbuckle-folding.png"


def main(argv=None) -> int:
    from electrogrowth.figures import postbuckle_gallery as gallery
    from electrogrowth.figures.postbuckle_gallery import CASES, write_case

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cases", nargs="*", help=f"of {', '.join(CASES)} (default: all)")
    parser.add_argument("--out", type=pathlib.Path, default=OUT, help="the folder")
    parser.add_argument(
        "--doc-image",
        action="store_true",
        help=f"only redraw {IMAGE.relative_to(HERE)} from the stored mucosa.json",
    )
    args = parser.parse_args(argv)
    if args.doc_image:
        record = gallery.read_case(args.out / "mucosa.json")
        gallery.plot_strip(record).savefig(IMAGE, dpi=150)
        return 0
    unknown = sorted(set(args.cases) - set(CASES))
    if unknown:
        parser.error(f"unknown case {unknown[0]!r}; valid: {', '.join(CASES)}")
    for name in args.cases or CASES:
        record = write_case(
            name, args.out / f"{name}.json", lambda text: print(text, file=sys.stderr, flush=True)
        )
        print(f"{name}: {record['seconds']} s, onset {record['onset_fe']:.8g}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
