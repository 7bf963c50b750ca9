"""The post-buckled branch: equilibria followed in the fold amplitude.

The amplitude a = (u_R(1, 0) - u_R(1, pi / m)) / 2, half the difference of the inner face's
radial displacement at the two rays (the coefficient of cos(m Theta) up to third-order
harmonics; in a sector of k half wavelengths the mean of the k half wavelengths' values,
the same number on a branch of the mode's own period), is prescribed and the control is
an unknown: each point solves

    residual(x; c) - xi f = 0,   a(x) = a_k

by Newton's method on the bordered system [[K, dR/dc], [a^T, 0]] (dR/dc by central
differences of the residual in the control). Prescribing the amplitude passes the limit
points of the control (a snap-through of a subcritical onset) and the bifurcation point
itself (the border removes the null direction), as a displacement-controlled arc length.
``xi = 0`` gives the perfect bifurcated branch (started from the onset state plus a times
the critical mode); ``xi > 0`` the path of the tube with a load imperfection f = M z in the
shape of the critical mode z.
"""

from __future__ import annotations

import dataclasses
import signal
from collections.abc import Callable

import numpy as np
import scipy.sparse as sps
import scipy.sparse.linalg as spla

from ..errors import ConvergenceError, ParameterError
from ..interrupts import Interrupted
from .harmonics import ELEMENT_SCALE, element_scale_fraction
from .newton import MAX_ITERATIONS, RESIDUAL_TOL, fe_error
from .onset import lowest_eigenvalue
from .stability import classify

#: relative step of the central difference dR/dc
DC = 1e-6
#: a failed amplitude step is halved at most this many times
HALVINGS = 3


@dataclasses.dataclass
class BranchPoint:
    """One equilibrium: control value, amplitude, energy, unknowns."""

    control: float
    amplitude: float
    energy: float
    x: np.ndarray
    #: the lowest eigenvalue of the tangent at fixed control (< 0: unstable), when computed
    eigenvalue: float = float("nan")
    #: its eigenvector's fraction outside the mode's family, and the period of its pattern
    #: in wavelengths of the mode (1: the mode's family; 2: period doubling; 0: not computed)
    subharmonic: float = float("nan")
    pattern: int = 0
    #: its share in patterns the mesh does not resolve (harmonics.element_scale_fraction)
    element_scale: float = float("nan")

    @property
    def unresolved(self) -> bool:
        """Whether the lowest eigenvalue is negative in a pattern of the elements' size: the
        mesh's artefact, which leaves the tube's stability at this point unknown."""
        return self.eigenvalue < 0 and self.element_scale > ELEMENT_SCALE


def with_stability(section, point: BranchPoint) -> BranchPoint:
    """``point`` with its lowest eigenvalue and the pattern of its eigenvector."""
    point.eigenvalue, z = lowest_eigenvalue(section, point.x, vector=True)
    point.subharmonic, point.pattern = classify(section, z)
    point.element_scale = element_scale_fraction(section, z)
    return point


def amplitude_vector(section, face: str = "inner") -> np.ndarray:
    """The functional a(x) = a . x: half the difference of ``face``'s radial displacement at
    the two ends of a half wavelength (Y = j h and (j + 1) h, h = extent / periods), with
    the sign (-1)^j, averaged over the half wavelengths j of the sector."""
    dofs, y = section.face_dofs(face)
    k = section.periods
    ends = [int(np.argmin(np.abs(y - j * section.extent / k))) for j in range(k + 1)]
    a = np.zeros(section.basis.N)
    for j in range(k):
        sign = 0.5 * (-1) ** j / k
        a[dofs[ends[j]]] += sign
        a[dofs[ends[j + 1]]] -= sign
    return a


class AmplitudeBranch:
    """Newton on (x, c) at a prescribed amplitude, for ``section`` of ``tube`` along
    ``control``; ``imperfection`` a force vector (zero on the prescribed unknowns) or None;
    ``eigenvalues``: each point's lowest eigenvalue at fixed control (its stability)."""

    def __init__(
        self, section, tube, control: str, imperfection=None, *, eigenvalues=False, face="inner"
    ):
        self.section, self.tube, self.control = section, tube, control
        self.eigenvalues, self.ended = eigenvalues, ""
        self.a = amplitude_vector(section, face)
        self.f = None if imperfection is None else imperfection

    def _set(self, c: float) -> None:
        self.section.set_tube(self.tube.at(self.control, c))

    def _residual(self, x, c):
        try:
            self._set(c)
        except ParameterError as exc:  # a Newton step left the control's range
            message = f"a Newton step left the control's range: {exc}"
            raise fe_error(ConvergenceError, message) from None
        x = self.section.with_fixed(x)
        r = self.section.residual(x)
        if self.f is not None:
            r = r - self.f
        return x, self.section.restrict(r)

    def solve(self, x, c, amplitude: float) -> tuple[np.ndarray, float, int]:
        """The equilibrium at ``amplitude`` from the guess (x, c)."""
        s = self.section
        a = s.restrict(self.a)  # the amplitude's row on the solvers' unknowns
        for it in range(MAX_ITERATIONS + 1):
            x, r = self._residual(x, c)
            g = self.a @ x - amplitude
            norm = max(np.abs(r).max(), abs(g))
            if norm < RESIDUAL_TOL:
                return x, c, it
            if not np.isfinite(norm):
                break
            h = DC * max(1.0, abs(c))
            _, rp = self._residual(x, c + h)
            _, rm = self._residual(x, c - h)
            dr = (rp - rm) / (2 * h)
            x, _ = self._residual(x, c)  # the section back at c (and its prescribed values)
            K = s.reduced(s.tangent(x))
            A = sps.bmat(
                [[K, sps.csc_matrix(dr[:, None])], [sps.csr_matrix(a[None, :]), None]]
            ).tocsc()
            step = spla.spsolve(A, -np.concatenate([r, [g]]))
            x = x + s.expand(step[:-1])
            c += step[-1]
        raise fe_error(
            ConvergenceError,
            f"the branch point at amplitude {amplitude:.4g} did not converge (residual"
            f" {norm:.3g}, even in steps of 1/{2**HALVINGS} of the amplitude step)",
        )

    def _guess(self, last, prev, amp, direction):
        if prev is None:
            d = direction if direction is not None else np.zeros_like(last.x)
            return last.x + (amp - last.amplitude) * d, last.control
        t = (amp - last.amplitude) / (last.amplitude - prev.amplitude)
        return last.x + t * (last.x - prev.x), last.control + t * (last.control - prev.control)

    def _advance(self, points: list, amp: float, direction) -> None:
        """Append the point at ``amp`` to ``points``, through intermediate amplitudes (the
        step halved, at most HALVINGS times in all) when Newton fails there."""
        targets, halvings = [amp], 0
        while targets:
            last = points[-1]
            prev = points[-2] if len(points) > 1 else None
            x0, c0 = self._guess(last, prev, targets[-1], direction)
            try:
                x, c, _ = self.solve(x0, c0, targets[-1])
            except ConvergenceError:
                if halvings >= HALVINGS:
                    raise
                halvings += 1
                targets.append(0.5 * (last.amplitude + targets[-1]))
                continue
            point = BranchPoint(c, targets.pop(), self.section.energy(x), x)
            if self.eigenvalues:
                with_stability(self.section, point)
            points.append(point)

    def follow(
        self,
        start: BranchPoint,
        amplitudes,
        *,
        direction: np.ndarray | None = None,
        stop: Callable[[BranchPoint], bool] | None = None,
        progress: Callable[[BranchPoint], None] | None = None,
        keep_going: bool = False,
    ) -> list[BranchPoint]:
        """The points at ``amplitudes`` (increasing), from ``start``: the first guess is the
        start plus (a - a_0) ``direction`` (the critical mode), then secant predictions; a
        step where Newton fails is halved (the intermediate points are kept). With
        ``keep_going`` a step that still fails ends the branch there: the points so far are
        returned and ``self.ended`` says why (else ConvergenceError).
        Stops early (returning what it has) when ``stop(point)`` is true; a Ctrl-C raises
        Interrupted carrying the finished points as ``partial``."""
        points = [start]
        self.ended = ""
        for amp in amplitudes:
            try:
                self._advance(points, float(amp), direction)
            except ConvergenceError as exc:
                if not keep_going:
                    raise
                self.ended = (
                    f"the branch ends at amplitude {points[-1].amplitude:.4g}: {exc} (a limit"
                    " point of the amplitude, a secondary bifurcation, or too coarse a mesh)"
                )
                break
            except KeyboardInterrupt as exc:
                signum = getattr(exc, "signum", signal.SIGINT)
                raise Interrupted(signum, partial=points[1:]) from exc
            if progress is not None:
                progress(points[-1])
            if stop is not None and stop(points[-1]):
                break
        return points[1:]
