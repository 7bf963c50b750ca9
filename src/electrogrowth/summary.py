"""One-screen summaries of results for Jupyter (the ``_repr_html_`` of the result classes).

A small HTML table per result: what was solved, the value with the digits its error
estimate supports, the mode, the tube. Shared by every stage: imports no stage, reads the
results by their attributes.
"""

from __future__ import annotations

import html
import math

SYMBOL = {"growth": "g_cr", "stretch": "λ_z,cr", "voltage": "V̄_cr"}


def _digits(value: float, error: float | None) -> str:
    """The value with the digits an absolute error estimate supports (3 to 12)."""
    if error is None or not math.isfinite(error) or error <= 0 or value == 0:
        return f"{value:.12g}"
    if not math.isfinite(value):
        return str(value)
    n = math.floor(math.log10(abs(value))) - math.floor(math.log10(error)) + 1
    return f"{value:.{max(3, min(12, n))}g}"


def table(title: str, rows: list[tuple[str, object]]) -> str:
    """An HTML table: a caption and (label, value) rows."""
    body = "".join(
        f"<tr><th style='text-align:left'>{html.escape(str(k))}</th>"
        f"<td style='text-align:left'>{html.escape(str(v))}</td></tr>"
        for k, v in rows
    )
    return (
        f"<table><caption style='text-align:left'><b>{html.escape(title)}</b></caption>"
        f"{body}</table>"
    )


#: the symbols of a tube's numbers (Tube.record) in one-line texts
SYMBOLS = {
    "outer_radius": "Rbar_o",
    "length": "L",
    "growth": "g",
    "stretch": "λ_z",
    "voltage": "V̄",
    "layer_outer_radii": "R_k",
    "axial_force": "N",
    "inner_pressure": "P_i",
    "outer_pressure": "P_o",
}


def tube_text(tube, symbols: dict = SYMBOLS, skip=(), tex: bool = False) -> str:
    """One line: the tube's numbers (:meth:`Tube.record`) as "symbol = value" (each in
    $...$ with ``tex``), its material(s) last; ``skip``: keys left out (e.g. a curve's own
    variables)."""
    rec = tube.record()
    names = rec.pop("material", None) or " / ".join(rec.pop("materials", ()))
    shown = lambda v: ", ".join(f"{x:g}" for x in v) if isinstance(v, list) else f"{v:.6g}"  # noqa: E731
    wrap = (lambda t: f"${t}$") if tex else (lambda t: t)  # noqa: E731
    parts = [
        wrap(f"{symbols.get(k, k.replace('_', ' '))} = {shown(v)}")
        for k, v in rec.items()
        if v is not None and k not in skip
    ]
    return ", ".join(parts + [names])


def _tube(params) -> str:
    return tube_text(params)


def critical_rows(c) -> list[tuple[str, object]]:
    rows = [(SYMBOL.get(c.solve_for, c.solve_for), _digits(c.value, c.error_estimate))]
    rows.append(("error estimate", f"{c.error_estimate:.1e} ({c.method})"))
    rows.append(("kind", str(c.kind)))
    if str(c.kind) == "bifurcation":
        rows.append(("mode (m, n)", f"({c.m}, {c.n}), {c.family}"))
    if getattr(c, "face", None):
        rows.append(("face", c.face))
    if c.side:
        rows.append(("side", c.side))
    rows.append(("tube", _tube(c.params)))
    return rows


def critical_html(c) -> str:
    rows = critical_rows(c)
    rows.insert(-1, ("verdict", c.verdict.meaning))
    return table(f"CriticalPoint: critical {c.solve_for}", rows)


def scan_html(result) -> str:
    rows = critical_rows(result.critical)
    rows.insert(-1, ("scanned m, n", f"{list(result.m_range)}, {list(result.n_range)}"))
    if result.short_wave_limit is not None:
        rows.insert(-1, ("short-wave limit", f"{result.short_wave_limit:.10g}"))
    for r in result.runners_up:
        rows.insert(-1, (f"next ({r.m}, {r.n})", _digits(r.value, r.error_estimate)))
    rows.insert(-1, ("verdict", result.verdict.meaning))
    return table(f"ScanResult: critical {result.critical.solve_for} over the modes", rows)


def curve_html(curve) -> str:
    x = list(curve.x)
    rows = [
        (curve.along, f"{min(x):.6g} .. {max(x):.6g}, {len(x)} rows" if x else "empty"),
        ("branches (m, n)", ", ".join(str(mode) for mode, _ in curve.branches())),
        ("switches", len(curve.switches)),
    ]
    rows += [
        (f"switch at {curve.along} = {s.x:.8g}", f"{s.mode_before} -> {s.mode_after}")
        for s in curve.switches
    ]
    rows += [
        (f"branch ends at {curve.along} = {s.x:.8g}", f"{s.mode_before} -> {s.mode_after}")
        for s in curve.ends
    ]
    failed = sum(1 for k in curve.kind if str(k) == "failed")
    if failed:
        rows.append(("failed points", failed))
    rows.append(("tube", _tube(curve.params)))
    return table(f"Curve: critical {curve.solve_for} along {curve.along}", rows)


def base_state_html(state) -> str:
    thr = state.voltage_threshold
    rows = [
        ("λ_i = r_i / R_i", f"{state.lambda_i:.10g}"),
        ("λ_o = r_o / R_o", f"{state.lambda_o:.10g}"),
        ("charge c (D_r = c / r)", f"{state.charge:.10g}"),
        ("V̄ threshold", f"{thr:.10g} ({state.threshold_kind})"),
        ("axial force N / (μ R_i²)", f"{state.axial_force:.10g}"),
        ("tube", _tube(state.tube)),
    ]
    return table("BaseState", rows)
