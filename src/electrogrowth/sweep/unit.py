"""Parameter sweeps: the critical point of a mode scan at every point of a grid of tubes.

Three layers, each thin over the one below:

* :func:`compute_point` ``(params, spec) -> PointResult`` is the unit of work: one
  :func:`scan.scan_modes`, pure and picklable. A failure is data: a point whose base state
  does not exist or whose root finder does not converge comes back with ``status`` and a
  one-line ``message``, so one bad point never stops a sweep.
* :func:`compute_chunk` runs the points of one task, a block of the grid (a point takes
  from ~0.05 s to seconds, so the few milliseconds a task costs to schedule and to write
  are negligible).
* :func:`~.run.compute_sweep` (run.py) hands the tasks to a pool and writes every result to
  the Zarr store (store.py) as it arrives; a killed sweep resumes where it stopped.

The parallelism is over grid points: every task runs the batch kernel on one thread
(measured on 2 busy cores: 0.06 s a point on one thread, ~1 s on two).
"""

from __future__ import annotations

import dataclasses
import math
import time

from ..bifurcation.critical import CERTIFIED, REFINE
from ..bifurcation.scan import ScanOptions, scan_modes
from ..errors import NoBifurcationFound
from ..interrupts import reraise_interrupt
from ..model.layers import Tube
from ..outcomes import NO_MODE, Kind, Outcome, Status, remedy, status_of, traceback_of


@dataclasses.dataclass(frozen=True)
class ScanSpec:
    """What :func:`~electrogrowth.bifurcation.scan.scan_modes` solves at every point."""

    solve_for: str
    side: str | None = None
    options: ScanOptions = ScanOptions()
    rtol: float = 1e-12
    koiter: bool = False  # also the amplitude equation of the wrinkle (bifurcation/koiter.py)


@dataclasses.dataclass(frozen=True)
class PointResult(Outcome):
    """The outcome at one grid point.

    ``status`` is OK (``kind`` then says what was found: BIFURCATION in mode (m, n),
    THRESHOLD where the axisymmetric state is lost first, or NONE: no instability in
    the range), INACCURATE (found as with OK, but the critical value's error estimate
    exceeds the accuracy asked even after refinement: ``message`` says by how much; see
    :func:`bifurcation.critical_value`), FAILED (an electrogrowth error: no base state, no
    convergence; see ``message`` and ``remedy``) or ERROR (an unexpected exception, a bug:
    please report it; ``traceback`` says where, and is not stored).
    ``runners_up`` holds (m, n, value) of the next modes to bifurcate; (m, n) is NO_MODE
    where no mode is critical. ``kind`` and ``value`` are the linear result's (a wrinkle,
    the short-wave limit or the threshold); the verdict (bifurcation/verdict.py) says what
    comes first once a crease of a face competes: ``verdict`` (its kind),
    ``verdict_value``, ``verdict_face``, the runner-ups ``wrinkle_value``,
    ``crease_value`` (``crease_face``, ``crease_trigger``, ``crease_error``: the
    criterion's accuracy), ``threshold_value``, ``meaning``, and, where the spec asks for
    the amplitude equation (``koiter``), ``branch`` ("supercritical" / "subcritical"; ""
    not computed), ``koiter`` and ``koiter_error`` (NaN: not computed), the second
    harmonic next to onset where there is one (``koiter_resonance_value``, ``_m``, ``_n``:
    NaN and -1 where none) and ``branch_note``: why there is no branch (the case is not
    covered, or "amplitude equation failed: ..." where its solve raised: the point keeps
    its status, the linear result stands). An :class:`~electrogrowth.outcomes.Outcome`:
    ``unwrap()`` raises the failure, ``outcome_dict()`` gives the shared fields.
    """

    status: Status
    value: float = math.nan
    m: int = NO_MODE[0]
    n: int = NO_MODE[1]
    kind: Kind | str = ""
    error_estimate: float = math.nan
    surface_instability: bool = False
    runners_up: tuple[tuple[int, int, float], ...] = ()
    message: str = ""
    seconds: float = math.nan
    remedy: str = ""
    traceback: str = dataclasses.field(default="", repr=False, compare=False)
    verdict: str = ""
    verdict_value: float = math.nan
    verdict_face: str = ""
    wrinkle_value: float = math.nan
    crease_value: float = math.nan
    crease_face: str = ""
    crease_trigger: str = ""
    crease_error: float = math.nan
    threshold_value: float = math.nan
    meaning: str = ""
    branch: str = ""
    koiter: float = math.nan
    koiter_error: float = math.nan
    koiter_resonance_value: float = math.nan
    koiter_resonance_m: int = -1
    koiter_resonance_n: int = -1
    branch_note: str = ""


def compute_point(params: Tube, spec: ScanSpec) -> PointResult:
    """The critical point of ``spec.solve_for`` at one tube; never raises.

    Examples
    --------
    >>> from electrogrowth import Tube
    >>> r = compute_point(Tube.uniform(1.4, voltage=50.0), ScanSpec("growth"))
    >>> r.status.value, r.message.split(":")[0], r.remedy.split(" (")[0]
    ('failed', 'BaseStateError', 'lower the voltage below the threshold')
    """
    start = time.perf_counter()
    took = lambda: time.perf_counter() - start  # noqa: E731
    try:
        res = scan_modes(
            params, spec.solve_for, side=spec.side, options=spec.options, rtol=spec.rtol
        )
        verdict = res.verdict
        note = ""
        if spec.koiter:
            verdict, note = branch_of(verdict, params, spec.solve_for, spec.side)
        fields = verdict_fields(verdict) | {"branch_note": note}
    except NoBifurcationFound as exc:
        return PointResult(Status.OK, kind=Kind.NONE, message=str(exc), seconds=took())
    except Exception as exc:  # noqa: BLE001 - failures are data
        reraise_interrupt(exc)  # Ctrl-C inside the compiled kernel is no failed point
        status = status_of(exc)
        prefix = "" if status is Status.FAILED else "internal error: "
        return PointResult(
            status,
            message=f"{prefix}{type(exc).__name__}: {exc}",
            seconds=took(),
            remedy=remedy(exc),
            traceback=traceback_of(exc),
        )
    c = res.critical
    inaccurate = c.status == Status.INACCURATE
    return PointResult(
        Status.INACCURATE if inaccurate else Status.OK,
        value=float(c.value),
        m=int(c.m),
        n=int(c.n),
        kind=c.kind,
        error_estimate=float(c.error_estimate),
        surface_instability=res.surface_instability,
        runners_up=tuple((int(r.m), int(r.n), float(r.value)) for r in res.runners_up),
        message=_inaccurate_message(c, spec.rtol) if inaccurate else "",
        seconds=took(),
        **fields,
    )


#: how branch_note begins where the amplitude equation raised (store.py counts them)
BRANCH_FAILED = "amplitude equation failed"


def branch_of(verdict, params: Tube, solve_for: str, side: str | None = None):
    """(verdict with its branch, "") where the amplitude equation covers the point, else
    (verdict, why not); a failure of the expansion is data too: (verdict, its message)."""
    from ..bifurcation.koiter import with_branch  # scipy's dense algebra: only when asked

    try:
        out, note = with_branch(verdict, params, solve_for, side)
    except Exception as exc:  # noqa: BLE001 - failures are data; the linear result stands
        reraise_interrupt(exc)
        return verdict, f"{BRANCH_FAILED}: {type(exc).__name__}: {exc}"
    return out, note or ""


def verdict_fields(v) -> dict:
    """The verdict's fields of a PointResult (NaN and "" where a kind was not found)."""
    val = lambda r: math.nan if r is None else float(r.value)  # noqa: E731
    c = v.crease
    return {
        "verdict": str(v.kind),
        "verdict_value": float(v.value),
        "verdict_face": v.face or "",
        "wrinkle_value": val(v.wrinkle),
        "crease_value": val(c),
        "crease_face": "" if c is None else c.face or "",
        "crease_trigger": "" if c is None else c.trigger or "",
        "crease_error": math.nan if c is None else float(c.error_estimate),
        "threshold_value": val(v.threshold),
        "meaning": v.meaning,
        "branch": v.branch or "",
        "koiter": math.nan if v.koiter is None else float(v.koiter),
        "koiter_error": math.nan if v.koiter_error is None else float(v.koiter_error),
        **_resonance_fields(v.koiter_resonance),
    }


def _resonance_fields(resonance: dict | None) -> dict:
    """The second harmonic next to onset (koiter_resonance.Resonance as a dict), or none."""
    r = resonance or {"value": math.nan, "m": -1, "n": -1}
    return {
        "koiter_resonance_value": float(r["value"]),
        "koiter_resonance_m": int(r["m"]),
        "koiter_resonance_n": int(r["n"]),
    }


def _inaccurate_message(c, rtol: float) -> str:
    """Why a critical value is not certified (bifurcation/critical.py's rule)."""
    return (
        f"inaccurate: error estimate {c.error_estimate:.1e} exceeds {CERTIFIED:g} rtol"
        f" |value| (rtol = {rtol:g}) even at rtol / {REFINE:g}"
    )


@dataclasses.dataclass(frozen=True)
class ChunkTask:
    """One task: the block ``block`` (a (start, stop) per dimension) of the grid, chunk
    number ``index``, its tubes in C order."""

    index: int
    block: tuple[tuple[int, int], ...]
    params: tuple[Tube, ...]
    spec: ScanSpec


@dataclasses.dataclass(frozen=True)
class ChunkResult:
    index: int
    block: tuple[tuple[int, int], ...]
    points: tuple[PointResult, ...]


def compute_chunk(task: ChunkTask, threads: int | None = 1) -> ChunkResult:
    """Every point of a task.

    ``threads`` caps the compiled kernel's threads while the task runs (numba's
    ``set_num_threads``, for the calling thread only; None leaves numba's setting). A
    sweep's parallelism is over grid points, so its workers run the kernel on one thread
    each: threads of the batch kernel inside each worker would only contend for the cores.
    """
    if threads is None:
        return ChunkResult(
            task.index, task.block, tuple(compute_point(p, task.spec) for p in task.params)
        )
    import numba

    before = numba.get_num_threads()
    numba.set_num_threads(max(1, min(threads, numba.config.NUMBA_NUM_THREADS)))
    try:
        return compute_chunk(task, None)
    finally:
        numba.set_num_threads(before)
