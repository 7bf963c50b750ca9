"""Phase diagram of a sweep: which mode comes first, and at what critical value.

Over two swept parameters the critical value is drawn as a colour map (one cell per grid
point). Cells whose outcome differs (another critical mode (m, n), the threshold where the
axisymmetric state is lost, no instability, a failure) are separated by lines along the
cell edges, and every connected region is labelled. The edge between the threshold region
and the rest, where the axisymmetric state is lost before any wrinkling mode, is drawn
bold and dashed.
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np
from matplotlib import colormaps
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from scipy import ndimage

from ..errors import ParameterError
from ..outcomes import Kind, Status
from .labels import axis_label, symbol_text

THRESHOLD, NONE, FAILED, PENDING = "threshold", "no instability", "failed", "pending"
UNSTABLE = "already unstable"
#: the message of a point whose tube is unstable before the control is applied (march.py)
_UNSTABLE = re.compile(
    r"already unstable in mode \(\d+, \d+\).*? at (?P<name>[\w\[\].+]+) = (?P<x>[^;\s]+)"
)
SURFACE = "surface (m, n -> inf)"
MAX_LABELS = 40


@dataclasses.dataclass(frozen=True)
class Region:
    """A connected set of grid cells with the same outcome; ``label`` is (m, n) or one of
    "threshold", "surface (m, n -> inf)", "no instability", "already unstable at g = 1"
    (or another control and start), "failed", "pending"."""

    label: tuple[int, int] | str
    cells: int
    x: float  # a cell of the region near its centroid, where the label goes
    y: float


def select_plane(ds, x: str, y: str, at: dict | None = None):
    """The dataset on the (y, x) plane; further swept parameters at the nearest ``at``
    value (default their first)."""
    dims = [d for d in ds["critical_value"].dims]
    if len(dims) < 2:
        raise ParameterError(
            f"a phase diagram needs two swept parameters; the store sweeps only {dims[0]}"
        )
    for name, role in ((x, "--x"), (y, "--y")):
        if name not in dims:
            raise ParameterError(
                f"{role} {name!r} is not a swept parameter; the store sweeps {', '.join(dims)}"
            )
    if x == y:
        raise ParameterError(f"--x and --y are both {x!r}; choose two swept parameters")
    at = dict(at or {})
    rest = [d for d in dims if d not in (x, y)]
    for name in at:
        if name not in rest:
            raise ParameterError(
                f"--at {name}: not a further swept parameter (the others"
                f" are {', '.join(rest) or 'none'})"
            )
    plane = ds.sel({d: at[d] for d in rest if d in at}, method="nearest")
    plane = plane.isel({d: 0 for d in rest if d not in at})
    return plane.transpose(y, x, ...)


def outcomes(plane) -> np.ndarray:
    """Per cell: (m, n) of the critical mode, or a string for every other outcome."""
    status = np.asarray(plane["status"].values, dtype=object)
    message = (
        np.asarray(plane["message"].values, dtype=object)
        if "message" in plane
        else np.full(status.shape, "", dtype=object)
    )
    kind = np.asarray(plane["kind"].values, dtype=object)
    m, n = np.asarray(plane["m"].values), np.asarray(plane["n"].values)
    out = np.empty(status.shape, dtype=object)
    for idx in np.ndindex(status.shape):
        if status[idx] in (Status.OK, Status.INACCURATE):  # a value, if not certified
            out[idx] = (
                (int(m[idx]), int(n[idx]))
                if kind[idx] == Kind.BIFURCATION
                else {Kind.THRESHOLD: THRESHOLD, Kind.SURFACE: SURFACE}.get(kind[idx], NONE)
            )
        elif status[idx] == "pending":
            out[idx] = PENDING
        else:
            out[idx] = _failure(str(message[idx]))
    return out


def _failure(message: str) -> str:
    """ "already unstable at g = 1" when the tube is unstable before the control is applied
    (the march's start), else "failed"."""
    if UNSTABLE not in message:
        return FAILED
    found = _UNSTABLE.search(message)
    if found is None:
        return UNSTABLE
    return f"{UNSTABLE} at {symbol_text(found['name'])} = {found['x']}"


def regions(labels: np.ndarray, xs: np.ndarray, ys: np.ndarray) -> list[Region]:
    """The connected regions (4-neighbours) of equal outcome, largest first."""
    found = []
    for value in {v for v in labels.ravel()}:
        mask = np.array([[lab == value for lab in row] for row in labels])
        comp, count = ndimage.label(mask)
        for k in range(1, count + 1):
            jj, ii = np.nonzero(comp == k)
            c = np.argmin((jj - jj.mean()) ** 2 + (ii - ii.mean()) ** 2)
            found.append(Region(value, len(jj), float(xs[ii[c]]), float(ys[jj[c]])))
    return sorted(found, key=lambda r: (-r.cells, str(r.label)))


def boundaries(labels: np.ndarray, xe: np.ndarray, ye: np.ndarray):
    """Cell-edge segments between different outcomes: (others, threshold), the second
    with the threshold region on exactly one side."""
    segs, thr = [], []
    ny, nx = labels.shape
    for j in range(ny):
        for i in range(nx):
            for dj, di in ((0, 1), (1, 0)):
                jb, ib = j + dj, i + di
                if jb >= ny or ib >= nx or labels[j, i] == labels[jb, ib]:
                    continue
                seg = (
                    [(xe[ib], ye[j]), (xe[ib], ye[j + 1])]
                    if di
                    else [(xe[i], ye[jb]), (xe[i + 1], ye[jb])]
                )
                if (labels[j, i] == THRESHOLD) != (labels[jb, ib] == THRESHOLD):
                    thr.append(seg)
                else:
                    segs.append(seg)
    return segs, thr


def cell_edges(centres) -> np.ndarray:
    """Edges of cells centred on sorted ``centres`` (midpoints, ends mirrored)."""
    c = np.asarray(centres, dtype=float)
    if c.size == 1:
        h = 0.05 * max(abs(c[0]), 1.0)
        return np.array([c[0] - h, c[0] + h])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])


def logarithmic(centres) -> bool:
    """Is an axis of these grid values read on a log scale? Positive values spanning
    LOG_SPAN or more whose steps grow (a geometric grid: moduli, thicknesses over decades);
    on a linear axis the low rows' cells and labels collapse together."""
    c = np.asarray(centres, dtype=float)
    if c.size < 3 or not np.all(c > 0) or c[-1] < LOG_SPAN * c[0]:
        return False
    steps = np.diff(c)
    return bool(steps[-1] > 2.0 * steps[0])


#: the smallest ratio of an axis's largest to its smallest value read on a log scale
LOG_SPAN = 100.0


def axis_edges(centres) -> tuple[np.ndarray, bool]:
    """(cell edges, log scale?) of an axis: midpoints in log x on a log axis."""
    if logarithmic(centres):
        return np.exp(cell_edges(np.log(np.asarray(centres, dtype=float)))), True
    return cell_edges(centres), False


def _plain(text) -> str:
    """A text read from a store, shown as it is: matplotlib would parse ``$...$`` in it as
    mathtext, and a store from someone else may hold any text (a malformed one ended the
    plot with an internal error)."""
    return str(text).replace("$", r"\$")


def _label_text(label) -> str:
    return f"m={label[0]}, n={label[1]}" if isinstance(label, tuple) else label


def _axis_label(coord, name=None) -> str:
    """Words, symbol and unit of a swept parameter (``name``: the solved-for control, for
    the colour bar of the critical value), never a code name in math italics."""
    if name is not None:
        return axis_label(name, critical=True)
    if coord.name in coord.coords or coord.name in coord.dims:
        return axis_label(str(coord.name))
    return _plain(coord.attrs.get("long_name", coord.name))


def phase_diagram(ds, x: str, y: str, *, at: dict | None = None) -> Figure:
    """The phase diagram of a sweep dataset (see :func:`sweep_store.open_results`).

    Parameters
    ----------
    ds : xarray.Dataset
        A sweep's results.
    x, y : str
        The swept parameters on the horizontal and vertical axes.
    at : dict, optional
        Values of further swept parameters (nearest grid value; default the first).

    Returns
    -------
    matplotlib.figure.Figure
        The colour map of the critical value with the mode regions outlined and labelled
        (m, n) and the threshold boundary dashed.
    """
    plane = select_plane(ds, x, y, at)
    xs, ys = plane[x].values, plane[y].values
    (xe, xlog), (ye, ylog) = axis_edges(xs), axis_edges(ys)
    labels = outcomes(plane)
    value = np.ma.masked_invalid(np.asarray(plane["critical_value"].values, dtype=float))
    fig = Figure(figsize=(7.5, 5.5), layout="constrained")
    ax = fig.add_subplot()
    cmap = colormaps["viridis"].with_extremes(bad="0.85")  # no value: light grey
    mesh = ax.pcolormesh(xe, ye, value, cmap=cmap, shading="flat")
    fig.colorbar(
        mesh, ax=ax, label=_axis_label(plane["critical_value"], ds.attrs.get("solve_for"))
    )
    segs, thr = boundaries(labels, xe, ye)
    ax.add_collection(LineCollection(segs, colors="k", linewidths=0.9))
    ax.add_collection(LineCollection(thr, colors="tab:red", linewidths=2.6, linestyles="--"))
    for r in regions(labels, xs, ys)[:MAX_LABELS]:
        ax.annotate(
            _label_text(r.label),
            (r.x, r.y),
            ha="center",
            va="center",
            fontsize=8,
            bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "none", "alpha": 0.75},
        )
    ax.set(
        xscale="log" if xlog else "linear",
        yscale="log" if ylog else "linear",
        xlim=(xe[0], xe[-1]),
        ylim=(ye[0], ye[-1]),
        xlabel=_axis_label(plane[x]),
        ylabel=_axis_label(plane[y]),
    )
    fixed = [
        f"{_plain(plane[c].attrs.get('symbol', c))} = {float(plane[c]):g}"
        for c in plane.coords
        if plane[c].ndim == 0 and c != "rank"
    ]
    ax.set_title(
        _plain(ds.attrs.get("title", "electrogrowth sweep"))
        + (f"\n{', '.join(fixed)}" if fixed else ""),
        fontsize=10,
    )
    keys = [
        (len(segs) > 0, Line2D([], [], color="k", lw=0.9, label="critical mode changes")),
        (
            len(thr) > 0,
            Line2D(
                [],
                [],
                color="tab:red",
                lw=2.6,
                ls="--",
                label="axisymmetric state lost (threshold)",
            ),
        ),
        (
            bool(np.ma.getmaskarray(value).any()),
            Patch(
                color="0.85", label="no value: failed, already unstable, no instability, pending"
            ),
        ),
    ]
    handles = [h for present, h in keys if present]
    if handles:
        fig.legend(
            handles=handles,
            loc="outside lower center",
            ncols=min(len(handles), 2),  # three in a row were cut at the figure's sides
            fontsize=8,
            frameon=False,
        )
    return fig
