"""The common look of every figure: colours, rc style, the figure factory and the result
record of a reproduced paper figure.

Figures are drawn with the object-oriented API on an Agg canvas: no pyplot, no global state.
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import matplotlib as mpl
import numpy as np
from matplotlib.figure import Figure

from ..atomic import replaced

#: Line colours (colour-blind safe, Okabe-Ito) and the paper-like style of every figure.
COLORS = ("#000000", "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00")
STYLE = {
    "font.size": 9,
    "axes.linewidth": 0.8,
    "lines.linewidth": 1.3,
    "xtick.direction": "in",
    "ytick.direction": "in",
    "legend.frameon": False,
    "axes.formatter.useoffset": False,  # 1.2 not "0.053 + 1.147": a reader reads values
}


@dataclasses.dataclass(frozen=True)
class FigureResult:
    """A reproduced figure: ``table`` rows under ``columns`` (the CSV), the figure, and the
    ``headline`` numbers a test checks."""

    number: int
    columns: tuple[str, ...]
    table: np.ndarray
    figure: Figure
    headline: dict[str, float]

    def save(self, directory: str | Path, *, dpi: int = 200) -> list[Path]:
        """Write fig<N>.png and fig<N>.csv into ``directory`` (created); return the paths."""
        out = Path(directory)
        out.mkdir(parents=True, exist_ok=True)
        png, csv = out / f"fig{self.number}.png", out / f"fig{self.number}.csv"
        # each file whole or not at all: two runs into one folder, or a Ctrl-C, never mix one
        with replaced(png, "wb") as fh:
            self.figure.savefig(fh, dpi=dpi, format="png")
        with replaced(csv) as fh:
            header = ",".join(self.columns)
            np.savetxt(fh, self.table, delimiter=",", header=header, comments="", fmt="%.15g")
        return [png, csv]


def new_figure(width: float, height: float, rows: int, cols: int):
    """An off-screen figure of ``width`` x ``height`` inches with a rows x cols grid of axes
    in the common style (ticks inside, on all four sides)."""
    with mpl.rc_context(STYLE):  # type: ignore[arg-type]  # matplotlib: literal keys
        fig = Figure(figsize=(width, height), layout="constrained")
        axes = fig.subplots(rows, cols, squeeze=False)
    for ax in axes.flat:
        ax.tick_params(direction="in", top=True, right=True, labelsize=8)
    return fig, axes


def wrap(text: str, width_inches: float, fontsize: float = 8.0) -> str:
    """``text`` broken into lines that fit ``width_inches`` at ``fontsize`` points, never
    inside a $math$ span (a line of its own in mathtext), existing line breaks kept."""
    chars = max(20, int(width_inches * 72.0 / (0.55 * fontsize)))
    lines = []
    for line in text.split("\n"):
        words = re.findall(r"(?:\$[^$]*\$|[^\s$])+", line) or [""]
        current = ""
        for word in words:
            joined = f"{current} {word}" if current else word
            if current and _visible(joined) > chars:
                lines.append(current)
                current = word
            else:
                current = joined
        lines.append(current)
    return "\n".join(lines)


def _visible(text: str) -> int:
    """About how many characters ``text`` shows: a mathtext command (\\bar, \\lambda) is
    one glyph or none, braces, ^, _ and $ none."""
    text = re.sub(r"\\(bar|hat|tilde|rm|mathrm|,)\b", "", text)
    text = re.sub(r"\\[A-Za-z]+", "x", text)
    return len(re.sub(r"[${}^_]", "", text))


def wrapped_title(ax, text: str, fontsize: float = 8.0) -> None:
    """Set the title of ``ax`` wrapped to the axes' width, so it never runs off the figure."""
    width = ax.figure.get_figwidth() * ax.get_position().width
    ax.set_title(wrap(text, width, fontsize), fontsize=fontsize)
