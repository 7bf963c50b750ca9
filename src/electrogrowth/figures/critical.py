"""Figures 6-8 of the paper (Sec. 4.3): critical stretch, voltage and growth factor; the
figure record and the curve helpers that Figures 9 and 10 (:mod:`.growth`) share.

Each figure is a pure function ``figure<N>(*, quick=False, ...)`` returning a
:class:`ModeFigure` (a :class:`~.style.FigureResult` that also keeps the computed
:class:`curves.Curve` objects and, for Figs. 9 and 10, the representative points of the
paper's panels B). Every curve comes from :func:`curves.critical_curve`: a mode scan per
grid point, the switches of the critical mode located exactly. Branches are labelled with
their critical mode "(m, n)" (the paper writes "n, m"); dots are switches, open circles the
ends of branches.

The CSV (``fig<N>.csv``) has one row per curve row: the fixed parameters of the curve, the
abscissa, the critical value, m, n and ``kind`` coded as :data:`KIND_CODES`. Figures 9 and
10 also write ``fig<N>_points.csv``: the representative points (critical states and modes)
for rendering 3D patterns.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from ..atomic import replaced
from ..basestate.tube import voltage_threshold
from ..bifurcation.critical import critical_value
from ..bifurcation.curves import Curve, critical_curve
from ..bifurcation.scan import ScanOptions, scan_modes
from ..model.layers import Tube
from ..model.materials import Material, neo_hookean
from ..outcomes import Kind, Status
from .plots import curve_legend, plot_curve
from .style import COLORS, FigureResult, new_figure, wrapped_title

#: kind column of the CSVs.
KIND_CODES = {
    Kind.BIFURCATION: 0,
    Kind.SWITCH: 1,
    Kind.THRESHOLD: 2,
    Status.FAILED: 3,
    Kind.SURFACE: 4,
    Kind.END: 5,
    Status.ERROR: 6,  # an internal error at that point (a bug), never an ordinary failure
}
#: Mode ranges of every scan (extended automatically when the optimum is on an edge). The
#: full figures use the scan's defaults: near the voltage threshold the critical value
#: first rises with m and then falls for m > 12 towards a short-wavelength instability of
#: a face, which the scan's probes beyond the range and its exact short-wave limit catch
#: (the figures used to scan m <= 64 for it, five times the modes, for the same curves).
FULL_MODES, QUICK_MODES = (ScanOptions().m_range, ScanOptions().n_range), ((0, 4), (1, 4))
NUDGE = 1e-6  # relative step inside a curve end where the tube is exactly critical
COLUMNS = ("outer_radius", "length", "growth", "stretch", "voltage")


@dataclasses.dataclass(frozen=True)
class PatternPoint:
    """A representative critical state (paper Figs. 9B, 10B): the tube ``params`` at the
    critical growth factor, wrinkling in mode (m, n)."""

    name: str
    params: Tube
    m: int
    n: int

    def as_dict(self) -> dict:
        p = self.params
        return {"name": self.name, "m": self.m, "n": self.n, **{f: getattr(p, f) for f in COLUMNS}}


@dataclasses.dataclass(frozen=True)
class ModeFigure(FigureResult):
    """A FigureResult with the curves it was drawn from and its representative points."""

    curves: tuple[Curve, ...] = ()
    points: tuple[PatternPoint, ...] = ()

    def save(self, directory: str | Path, *, dpi: int = 200) -> list[Path]:
        """fig<N>.png, fig<N>.csv and, if there are points, fig<N>_points.csv."""
        paths = super().save(directory, dpi=dpi)
        if self.points:
            path = Path(directory) / f"fig{self.number}_points.csv"
            with replaced(path) as fh:
                fh.write("name,m,n," + ",".join(COLUMNS) + "\n")
                for p in self.points:
                    d = p.as_dict()
                    fh.write(
                        ",".join([p.name, str(p.m), str(p.n)] + [repr(d[f]) for f in COLUMNS])
                        + "\n"
                    )
            paths.append(path)
        return paths


def _table(curves: list[Curve]) -> tuple[tuple[str, ...], np.ndarray]:
    """Columns: the five parameters (the curve's abscissa and value in their own columns),
    then m, n, kind code, surface (1: the critical mode is on the edge of the scanned range),
    the scan's m or n -> inf limit (NaN if none), side (-1 compression, 1 extension, 0), and
    which field is the abscissa / the value (COLUMNS index)."""
    rows = []
    for c in curves:
        base = np.array([getattr(c.params, f) for f in COLUMNS], dtype=float)
        block = np.tile(base, (len(c.x), 1))
        block[:, COLUMNS.index(c.along)] = c.x
        block[:, COLUMNS.index(c.solve_for)] = c.value
        codes = np.array([KIND_CODES[k] for k in c.kind], dtype=float)
        side = {None: 0.0, "compression": -1.0, "extension": 1.0}[c.side]
        rows.append(
            np.column_stack(
                [
                    block,
                    c.m,
                    c.n,
                    codes,
                    c.surface.astype(float),
                    c.short_wave_limit,
                    np.full(len(c.x), side),
                    np.full(len(c.x), COLUMNS.index(c.along)),
                    np.full(len(c.x), COLUMNS.index(c.solve_for)),
                ]
            )
        )
    cols = COLUMNS + (
        "m",
        "n",
        "kind",
        "surface",
        "short_wave_limit",
        "side",
        "along_column",
        "critical_column",
    )
    return cols, np.concatenate(rows)


def _modes(quick: bool) -> ScanOptions:
    """The scans of the figures' curves: the default ranges, and the critical mode with two
    runners-up (top = 3), which the curve follows between full scans. A followed point is
    accepted only if every mode of the grid is stable just before it, so following fewer
    competitors costs no accuracy; finding runners-up 3 and 4 took a quarter of a thick
    tube's scan (Figures 7 and 9: 27.7 -> 23.4 s and 11.0 -> 9.2 s, values identical)."""
    return ScanOptions(*(QUICK_MODES if quick else FULL_MODES), top=3)


def _curve(params, solve_for, along, values, quick, side=None, progress=None) -> Curve:
    return critical_curve(
        params, solve_for, along, values, side=side, progress=progress, options=_modes(quick)
    )


def _finite(c: Curve) -> np.ndarray:
    return np.isfinite(c.value)


def _title(ax, text: str):
    wrapped_title(ax, text, 9)


def _grid(c: Curve) -> np.ndarray:
    """The grid rows of a curve (not the located switches and ends)."""
    return ~np.isin(c.kind, (Kind.SWITCH, Kind.END))


# -- Figure 6 -------------------------------------------------------------------------------


def figure6(
    *,
    radii=None,
    length: float = 1.0,
    material: Material | None = None,
    quick: bool = False,
    progress=None,
) -> ModeFigure:
    """Critical stretch (Vbar = 0) and critical voltage (lambda_z = 1) against Rbar_o, g = 1.

    (A) lambda_z,cr in compression at Vbar = 0; (B) Vbar_cr at lambda_z = 1 (paper Fig. 6).
    ``radii``: the Rbar_o grid; default 1.1 .. 1.8 in steps of 0.05, or 1.2, 1.3, 1.4 when
    ``quick``. (Thicker tubes, Rbar_o >~ 1.9, first wrinkle under voltage in a
    short-wavelength mode of large n, whose scan is slow.)

    Returns
    -------
    ModeFigure
        Headline ``lambda_cr_Ro{Rbar_o}``, ``V_cr_Ro{Rbar_o}`` and their modes
        ``m_...``/``n_...`` at every grid Rbar_o.
    """
    material = material or neo_hookean()
    radii = np.asarray(
        radii
        if radii is not None
        else ((1.2, 1.3, 1.4) if quick else np.round(np.arange(1.1, 1.8001, 0.05), 10)),
        float,
    )
    base = Tube.uniform(outer_radius=radii[0], length=length, material=material)
    a = _curve(
        base, "stretch", "outer_radius", radii, quick, side="compression", progress=progress
    )
    b = _curve(base, "voltage", "outer_radius", radii, quick, progress=progress)
    fig, axes = new_figure(7.0, 2.8, 1, 2)
    plot_curve(a, axes[0, 0])
    plot_curve(b, axes[0, 1])
    curve_legend(axes[0, 1])
    _title(axes[0, 0], rf"(A) $g = 1$, $\bar V = 0$, $L = {length:g}$")
    _title(axes[0, 1], rf"(B) $g = 1$, $\lambda_z = 1$, $L = {length:g}$")
    headline = {}
    for name, c in (("lambda_cr", a), ("V_cr", b)):
        grid = _grid(c)
        for x, v, m, n in zip(c.x[grid], c.value[grid], c.m[grid], c.n[grid]):
            headline[f"{name}_Ro{x:g}"] = float(v)
            headline[f"m_{name}_Ro{x:g}"], headline[f"n_{name}_Ro{x:g}"] = float(m), float(n)
    cols, table = _table([a, b])
    return ModeFigure(6, cols, table, fig, headline, (a, b))


# -- Figure 7 -------------------------------------------------------------------------------


def figure7(
    *,
    radii=None,
    voltages=(0.4, 0.6),
    length: float = 1.0,
    material: Material | None = None,
    quick: bool = False,
    progress=None,
) -> ModeFigure:
    """Critical stretch in compression and extension against Rbar_o for Vbar = 0.4, 0.6.

    No growth (g = 1), L = 1 (paper Fig. 7). One column per voltage, extension above,
    compression below; the tube is stable for lambda_z between the two curves. ``radii``
    default 1.2 .. 2.0 in steps of 0.05, or 1.3, 1.4 when ``quick``. Points where the tube
    is unstable already at lambda_z = 1 (Vbar above its critical voltage) are kept as
    failed rows.

    Returns
    -------
    ModeFigure
        Headline ``compression_V{Vbar}_Ro{Rbar_o}`` / ``extension_...`` (lambda_z,cr) and
        their m, n at every grid Rbar_o.
    """
    material = material or neo_hookean()
    radii = np.asarray(
        radii
        if radii is not None
        else ((1.3, 1.4) if quick else np.round(np.arange(1.2, 2.0001, 0.05), 10)),
        float,
    )
    fig, axes = new_figure(7.0, 4.6, 2, len(voltages))
    curves, headline = [], {}
    for col, V in enumerate(voltages):
        for row, side in enumerate(("extension", "compression")):
            ax = axes[row, col]
            p = Tube.uniform(outer_radius=radii[0], length=length, voltage=V, material=material)
            c = _curve(p, "stretch", "outer_radius", radii, quick, side=side, progress=progress)
            plot_curve(c, ax, color=COLORS[row])
            curves.append(c)
            grid = _grid(c)
            for x, v, m, n in zip(c.x[grid], c.value[grid], c.m[grid], c.n[grid]):
                headline[f"{side}_V{V:g}_Ro{x:g}"] = float(v)
                headline[f"m_{side}_V{V:g}_Ro{x:g}"] = float(m)
                headline[f"n_{side}_V{V:g}_Ro{x:g}"] = float(n)
            _title(ax, rf"{side}: $\bar V = {V:g}$, $g = 1$, $L = {length:g}$")
    curve_legend(axes[1, 0])  # a panel with switches: the legend shows their mark
    cols, table = _table(curves)
    return ModeFigure(7, cols, table, fig, headline, tuple(curves))


# -- Figure 8 -------------------------------------------------------------------------------


def figure8(
    *,
    outer_radius: float = 1.4,
    lengths=(1.0, 1.5),
    stretch_max: float = 2.6,
    points: int | None = None,
    material: Material | None = None,
    quick: bool = False,
    progress=None,
) -> ModeFigure:
    """Critical voltage against the axial stretch for Rbar_o = 1.4, L = 1.0 and 1.5, g = 1.

    The lambda_z grid of each L runs from the critical compressive stretch at Vbar = 0
    (where Vbar_cr = 0; moved inside by a relative 1e-6) to ``stretch_max``, plus
    lambda_z = 1 (paper Fig. 8), denser near the start where Vbar_cr rises like a square
    root. ``points`` per curve: default 36; when ``quick`` the grid is just the start, 1.0
    and 1.3. The dotted line is the threshold where the axisymmetric state is lost.

    Returns
    -------
    ModeFigure
        Headline ``V_max_L{L}`` and ``lambda_at_max_L{L}`` (the largest Vbar_cr: at a
        switch, or located to 1e-9 in lambda_z inside a branch), ``lambda_start_L{L}``.
    """
    material = material or neo_hookean()
    points = points or 36
    fig, axes = new_figure(4.2, 3.0, 1, 1)
    ax = axes[0, 0]
    curves, headline = [], {}
    for color, L in zip(COLORS, lengths):
        p = Tube.uniform(outer_radius=outer_radius, length=L, material=material)
        start = scan_modes(p, "stretch", side="compression", options=_modes(quick)).critical.value
        t = np.linspace(0.0, 1.0, points) ** 2  # Vbar_cr ~ sqrt(lambda_z - start) there
        grid = (
            [start * (1 + NUDGE), 1.0, 1.3]
            if quick
            else np.union1d(start * (1 + NUDGE) + (stretch_max - start) * t, [1.0])
        )
        c = _curve(p, "voltage", "stretch", grid, quick, progress=progress)
        plot_curve(c, ax, color=color, label=rf"$L = {L:g}$")
        curves.append(c)
        x_max, v_max = _maximum(c)
        headline[f"V_max_L{L:g}"], headline[f"lambda_at_max_L{L:g}"] = v_max, x_max
        headline[f"lambda_start_L{L:g}"] = float(start)
        ax.plot([x_max], [v_max], "s", color=color, ms=3)
    lz = np.linspace(min(c.x[0] for c in curves), max(c.x[-1] for c in curves), 100)
    thr = [
        voltage_threshold(Tube.uniform(outer_radius=outer_radius, stretch=x, material=material))[0]
        for x in lz
    ]
    ax.plot(lz, thr, ":", color="0.5", lw=0.9, label="threshold")
    ax.set_ylim(0.0, 1.15 * max(headline[f"V_max_L{L:g}"] for L in lengths))
    _title(ax, rf"$\bar R_o = {outer_radius:g}$, $g = 1$")
    curve_legend(ax)
    cols, table = _table(curves)
    return ModeFigure(8, cols, table, fig, headline, tuple(curves))


def _maximum(c: Curve) -> tuple[float, float]:
    """(x, value) of the largest critical value: a switch row as it is; a grid row inside a
    branch refined by maximising that mode's critical value between its neighbours."""
    ok = _finite(c)
    i = int(np.argmax(np.where(ok, c.value, -np.inf)))
    inside = (
        0 < i < len(c.x) - 1
        and c.kind[i] == Kind.BIFURCATION
        and all((c.m[j], c.n[j]) == (c.m[i], c.n[i]) for j in (i - 1, i + 1))
    )
    if not inside:
        return float(c.x[i]), float(c.value[i])
    from scipy.optimize import minimize_scalar

    mode = int(c.m[i]), int(c.n[i])
    at = lambda x: c.params.at(c.along, x)  # noqa: E731
    res = minimize_scalar(
        lambda x: -critical_value(at(x), *mode, c.solve_for, side=c.side).value,
        bounds=(c.x[i - 1], c.x[i + 1]),
        method="bounded",
        options={"xatol": 1e-9},
    )
    return (
        (float(res.x), float(-res.fun))
        if -res.fun >= c.value[i]
        else (float(c.x[i]), float(c.value[i]))
    )
