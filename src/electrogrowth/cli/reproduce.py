"""``electrogrowth reproduce``: the paper's Figures 4-10, the 3D patterns of Figs 9B/10B
and an index page (index.md) with the paper's captions and the run's parameters; with
``--gallery``, the worked examples of layered tubes (figures/gallery.py), their 3D patterns at
onset and an index page (gallery.md)."""

from __future__ import annotations

import argparse
import inspect
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from ..atomic import write_text
from ..errors import ParameterError
from ..figures import FIGURES, GALLERY
from ..figures.plots import render_pattern
from ..shapes.mode_shape import mode_shape
from .options import path_arg
from .progress import add_quiet_option, counting, progress_options, stage

#: The paper's captions (quoted; Figure 7's caption in the paper repeats Figure 5's topic,
#: while the text describes critical stretches: we show what the text describes).
CAPTIONS = {
    4: "The effect of the growth factor g and axial stretch lambda_z on the nonlinear"
    " response of inner circumferential stretch lambda_i versus the applied voltage Vbar,"
    " in the case Rbar_o = 2.0.",
    5: "The distribution of residual stress of a tube that subjects to the external electric"
    " field Vbar and axial stretch lambda_z after growth, where Rbar_o = 2.0.",
    6: "Tube of length L = 1.0. (A) Critical axial stretch lambda_z,cr and modes of"
    " instability m_cr, n_cr, when there is no growth (g = 1.0) and no voltage applied"
    " (Vbar = 0.0). (B) Critical voltage Vbar_cr and modes of instability when there is no"
    " growth (g = 1.0) and no axial stretch (lambda_z = 1.0).",
    7: "[Paper: 'Distribution of residual stress after growth subject to an external"
    " electric field Vbar = 0.4, 0.6 and axial stretch lambda_z. The integer values given"
    " in the neighbourhood of each point are the couple n_cr, m_cr.'] Shown, as the text"
    " describes: critical axial stretch in compression and extension against Rbar_o.",
    8: "The effect of axial stretch on the critical voltage with Rbar_o = 1.4 and L = 1.0, 1.5.",
    9: "(A) The influence of the external axial strain on the critical growth factor and the"
    " corresponding wave numbers with applied voltage Vbar = 0.4, 0.6, where Rbar_o = 1.4,"
    " R_i = 1.0, L = 1.0; (B) some typical patterns of (A).",
    10: "(A) The influence of the applied voltage on the critical growth factor and the"
    " corresponding wave numbers with axial stretches lambda_z = 1.0, 1.1, where"
    " Rbar_o = 1.4, R_i = 1.0, L = 1.0; (B) some typical patterns of (A).",
}


def configure_reproduce(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--out",
        type=path_arg,
        default=Path("out/figures"),
        metavar="DIR",
        help="directory for fig<N>.png/.csv, the patterns and index.md (default ./out/figures)",
    )
    parser.add_argument("--quick", action="store_true", help="low resolution (previews and tests)")
    parser.add_argument(
        "--figures",
        type=int,
        nargs="+",
        metavar="N",
        help="only these figure numbers (default: all, 4-10)",
    )
    parser.add_argument(
        "--gallery",
        action="store_true",
        help="the gallery of layered tubes instead of the paper's figures (gallery.md)",
    )
    parser.add_argument(
        "--examples",
        nargs="+",
        metavar="NAME",
        help=f"with --gallery, only these examples (default: all: {', '.join(GALLERY)})",
    )
    parser.add_argument(
        "--workers",
        type=int,
        default=1,
        metavar="N",
        help="with --gallery, solve the tubes of an example on N processes (default 1)",
    )
    add_quiet_option(parser)


def run_reproduce(args) -> int:
    if args.gallery or args.examples:
        return run_gallery(args)
    numbers = args.figures or sorted(FIGURES)
    unknown = sorted(set(numbers) - set(FIGURES))
    if unknown:
        raise ParameterError(
            f"figure {unknown[0]} is not reproduced; choose from {sorted(FIGURES)}"
        )
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    sections = []
    for k, number in enumerate(numbers, 1):
        fn = FIGURES[number]
        t = time.perf_counter()
        with stage(args, f"figure {number} ({k} of {len(numbers)})", done=False):
            result = fn(quick=args.quick, **progress_options(fn, args))
            result.save(out)
            patterns = [_pattern(number, pt, out) for pt in getattr(result, "points", ())]
        seconds = time.perf_counter() - t
        sections.append(_section(number, fn, result, patterns, seconds, args.quick))
        print(f"figure {number}: {out / f'fig{number}.png'} ({seconds:.1f} s)")
    index = out / "index.md"
    write_text(
        index,
        "# The paper's figures, reproduced by electrogrowth\n\n"
        "Each figure: the paper's caption, our plot and data, and the"
        " parameters of this run. Differences from the paper are discussed"
        " in docs/paper-comparison.md.\n\n" + "\n".join(sections),
    )
    print(index)
    return 0


def _pattern(number: int, point, out: Path) -> tuple[str, Path]:
    path = out / f"fig{number}-{point.name}.png"
    render_pattern(mode_shape((point.params, point.m, point.n)), path=path)
    return point, path


def _section(number, fn, result, patterns, seconds, quick) -> str:
    defaults = {
        k: v.default
        for k, v in inspect.signature(fn).parameters.items()
        if v.default is not inspect.Parameter.empty and k != "quick"
    }
    lines = [
        f"## Figure {number}",
        "",
        f"*Paper:* {CAPTIONS.get(number, '')}",
        "",
        f"![Figure {number}](fig{number}.png)",
        "",
        f"Data: [fig{number}.csv](fig{number}.csv). Parameters: "
        + ", ".join(f"{k} = {v!r}" for k, v in defaults.items() if v is not None)
        + f"{' (quick run)' if quick else ''}; computed in {seconds:.1f} s.",
        "",
    ]
    if result.headline:
        lines += [
            "Headline numbers: "
            + ", ".join(f"{k} = {v:.10g}" for k, v in result.headline.items()),
            "",
        ]
    for point, path in patterns:
        p = point.params
        lines += [
            f"**{point.name}**: (m, n) = ({point.m}, {point.n}), g = {p.growth:.6g},"
            f" lambda_z = {p.stretch:.6g}, Vbar = {p.voltage:.6g}",
            "",
            f"![{point.name}]({path.name})",
            "",
        ]
    return "\n".join(lines)


def run_gallery(args) -> int:
    """Every example of GALLERY (or those of --examples): <name>.png/.csv, the 3D pattern of
    each of its critical points (<name>-<point>.png) and gallery.md."""
    names = args.examples or list(GALLERY)
    unknown = [n for n in names if n not in GALLERY]
    if unknown:
        raise ParameterError(
            f"gallery example {unknown[0]!r} is unknown; choose from {', '.join(GALLERY)}"
        )
    from ..pool import check_workers

    check_workers(args.workers)
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    sections = []
    pool = ProcessPoolExecutor(args.workers) if args.workers > 1 else None
    for k, name in enumerate(names, 1):
        fn = GALLERY[name]
        t = time.perf_counter()
        with stage(args, f"{name} ({k} of {len(names)})", done=False):
            mapper = counting(pool.map if pool else map, args, name)
            result = fn(quick=args.quick, mapper=mapper)
            result.save(out)
            patterns = []
            for label, point in result.points:
                path = out / f"{name}-{label}.png"
                render_pattern(mode_shape(point), path=path)
                patterns.append((label, point, path))
        seconds = time.perf_counter() - t
        sections.append(_gallery_section(fn, result, patterns, seconds, args.quick))
        print(f"{name}: {out / f'{name}.png'} ({seconds:.1f} s)", flush=True)
    if pool:
        pool.shutdown()
    index = out / "gallery.md"
    write_text(
        index,
        "# Gallery: layered, growing, pressurised tubes, computed by electrogrowth\n\n"
        "Each example: what it computes, its plot, its data and the 3D patterns at onset."
        " The discussion is in docs/patterns.md.\n\n" + "\n".join(sections),
    )
    print(index)
    return 0


def _gallery_section(fn, result, patterns, seconds, quick) -> str:
    doc = " ".join((fn.__doc__ or "").split())
    lines = [
        f"## {result.title}",
        "",
        doc,
        "",
        f"![{result.title}]({result.name}.png)",
        "",
        f"Data: [{result.name}.csv]({result.name}.csv){' (quick run)' if quick else ''};"
        f" computed in {seconds:.1f} s.",
        "",
        "| case | x | value | (m, n) | kind |",
        "|---|---|---|---|---|",
    ]
    for row in result.table:
        case, parameter, x, _, value, m, n, _, kind, note = row
        mode = f"({m}, {n})" if m >= 0 else "-"
        lines.append(f"| {case} | {parameter} = {x:g} | {value:.10g} | {mode} | {kind} {note} |")
    lines.append("")
    if result.headline:
        lines += [
            "Headline numbers: "
            + ", ".join(f"{k} = {v:.10g}" for k, v in result.headline.items()),
            "",
        ]
    for label, point, path in patterns:
        lines += [
            f"**{label}**: {point.solve_for} = {point.value:.8g}, (m, n) = ({point.m},"
            f" {point.n}), {point.family}",
            "",
            f"![{label}]({path.name})",
            "",
        ]
    return "\n".join(lines)
