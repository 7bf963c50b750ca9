"""The amplitude equation at onset: the Koiter coefficient of a wrinkle and whether its
branch is super- or subcritical (docs/derivation-koiter.md).

Covered so far: the flat film on a half-space (koiter_film.py: both incompressible
neo-Hookean, plane strain, uniaxial compression of the film alone or of the whole bilayer),
the limit of a thin stiff film on a thick tube; and a tube's prismatic modes (m, 0) and
axisymmetric modes (0, n) (koiter_tube.py: layers of any strain energy, growth constant or graded,
axial stretch prescribed, or the axial force when unloaded, koiter_force.py; a radial
voltage on ideal dielectrics; follower pressures on the faces, koiter_loads.py) in a
growth control, the voltage, the axial stretch or the inner pressure
(koiter_controls.py), and the wrinkles (m, n), m, n >= 1, of the same tubes in the same
controls (koiter_wall.py): c = c_c + c_2 eps^2 with eps = max |u_r| / R_i, supercritical
when c_2 has the sign of the control's direction (> 0 for a growth). Other cases raise a
one-line
:class:`~electrogrowth.errors.ParameterError`.
"""

from __future__ import annotations

import dataclasses

from ..errors import (
    BaseStateError,
    ConvergenceError,
    NoBifurcationFound,
    ParameterError,
    Remedy,
)
from ..model.layers import Tube
from .koiter_controls import branch as branch_of
from .koiter_controls import check_control
from .koiter_film import (
    FilmOnHalfSpace,
    _coefficient,
    critical_mode,
    expansion,
    sign_change_ratio,
)
from .koiter_loads import loaded_expansion
from .koiter_resonance import Resonance, nearest_resonance
from .koiter_tube import (
    TubeExpansion,
    axial_wavenumber,
    axisymmetric_expansion,
    tube_expansion,
)
from .koiter_wall import wrinkle_expansion
from .verdict import Verdict

#: a tube's node counts: three, since the coefficient's rounding (~5e-8 relative on a film's
#: fold) makes one difference of two a single, possibly small, sample
RESOLUTIONS = (18, 24, 32)

__all__ = [
    "FilmOnHalfSpace",
    "KoiterResult",
    "TubeExpansion",
    "axisymmetric_expansion",
    "critical_mode",
    "expansion",
    "koiter_coefficient",
    "sign_change_ratio",
    "tube_expansion",
    "with_branch",
]


@dataclasses.dataclass(frozen=True)
class KoiterResult:
    """The amplitude equation c = c_c + coefficient * eps^2 of one mode, c the control.

    Flat film: c = lambda, the compressive stretch; eps = K_c w (w the amplitude of the
    vertical displacement of the free face, K_c the reference wavenumber, both in film
    thicknesses); ``wavenumber`` K_c. Tube: c the control; eps = max_R |u_r| / R_i
    of the mode (R_i = 1, the undeformed inner radius); ``wavenumber`` m of a prismatic
    mode (m, 0), the reference axial wavenumber K = n pi / L of an axisymmetric one (0, n)
    or of a wrinkle (m, n) (max |u_r| at cos(m Theta) cos(K Z) = 1). ``branch`` is
    "supercritical" when the branch exists beyond onset, in the direction
    the control moves to reach it (lambda_2 < 0 for the compressive stretch, > 0 for
    growth), else "subcritical"; ``error_estimate`` for the flat film the change of the
    coefficient from a resolution 3/4 as fine (spectral convergence: it bounds the error of
    the finer); for a tube the coefficient is the finest of RESOLUTIONS and the estimate the
    spread over them plus the largest change of one when the steps of A''s central
    differences are halved or shifted (the rounding the node count does not see)."""

    coefficient: float
    critical_value: float
    wavenumber: float
    branch: str
    error_estimate: float
    normalisation: str = "eps = K_c w, w the amplitude of the free face's deflection"
    #: a tube's second harmonic bifurcating within koiter_resonance.WINDOW of onset (c_2
    #: has a pole where one does at onset), or None
    resonance: Resonance | None = None

    def as_dict(self) -> dict:
        return dataclasses.asdict(self)


def koiter_coefficient(
    problem, mode=None, control: str = "stretch", *, side: str | None = None
) -> KoiterResult:
    """The Koiter coefficient of a critical mode (docs/derivation-koiter.md): the control
    on the bifurcated branch is c = c_c + c_2 eps^2 (``KoiterResult`` says which eps),
    from the mode phi, the second-order correction psi (harmonics 0 and 2) of
    A(c_c) psi = -C[phi, phi, .] / 2 and

        c_2 = (2 A(c_c)[psi, psi] - 4 E4(phi)) / A'(c_c)[phi, phi],

    E4 the quartic part of the energy (non-zero for the axisymmetric family, whose
    incompressibility constraint is cubic in the displacement, and under a voltage).

    Parameters
    ----------
    problem : FilmOnHalfSpace or Tube
        A flat film on a half-space, or a tube (layers of any strain energy with constant
        or graded growth, the axial stretch prescribed (or the axial force, without a voltage or a
        pressure); follower pressures on the faces; a radial voltage on ideal
        dielectrics).
    mode : None or (m, 0) or (0, n) or (m, n)
        The film: None (K_c maximises lambda_c). A tube: a prismatic mode (m, 0), m >= 2,
        an axisymmetric mode (0, n), n >= 1 (axial wavenumber n pi / L in the
        reference length), or a wrinkle (m, n), m, n >= 1.
    control : str
        The film: "stretch", the compressive stretch lambda. A tube: a growth control
        ("growth", "growth[K]", "growth[K].theta", ...), "voltage", "stretch" or
        "pressure" (koiter_controls.py lists what each family covers).
    side : None or "compression" or "extension"
        A tube's sided control (the stretch): the side its critical value is sought on and
        the branch's direction (default the control's own, model/controls.py).

    Returns
    -------
    KoiterResult

    Raises
    ------
    ParameterError
        For any other problem, mode or control (one line naming what is covered).
    NoBifurcationFound
        When no wrinkle of finite wavelength is critical (mu_f / mu_s too small).

    >>> r = koiter_coefficient(FilmOnHalfSpace(5.0, nodes=12, substrate_nodes=16))
    >>> r.branch
    'supercritical'
    """
    if isinstance(problem, Tube):
        return _tube_result(problem, mode, control, side)
    if not isinstance(problem, FilmOnHalfSpace):
        raise ParameterError(
            f"the amplitude equation covers a flat film on a half-space (FilmOnHalfSpace) "
            f"and a tube's prismatic and axisymmetric modes so far, not {type(problem).__name__}"
        )
    if mode is not None or control != "stretch":
        raise ParameterError(
            f"mode = {mode!r}, control = {control!r}: only the critical wrinkle under the "
            "compressive stretch is covered (mode=None, control='stretch')"
        )
    fine, lam, Kc = _coefficient(problem)
    coarse = _coefficient(problem.refined(0.75))[0]
    return KoiterResult(
        coefficient=fine,
        critical_value=float(lam),
        wavenumber=Kc,
        branch="supercritical" if fine < 0 else "subcritical",
        error_estimate=abs(fine - coarse),
    )


#: where a tube's expansion does not converge: the linear value stands; the branch itself
#: comes from the post-buckling model
NOT_EXPANDED = Remedy(
    "the critical value stands (run without --koiter); a prismatic (m, 0) or axisymmetric"
    " (0, n) branch can be followed with `electrogrowth postbuckle`",
    python="the critical value stands (critical_value); a prismatic (m, 0) or axisymmetric"
    " (0, n) branch can be followed with electrogrowth.postbuckle.postbuckle",
)


def _tube_result(tube: Tube, mode, control: str, side: str | None = None) -> KoiterResult:
    """The tube's case of :func:`koiter_coefficient`, with its one-line refusals."""
    family = _tube_family(mode)
    check_control(family, control)
    why = _tube_not_covered(tube, family, control)
    if why:
        raise ParameterError(f"the tube's amplitude equation needs {why}")
    if family == "prismatic":
        wavenumber = float(mode[0])
    else:  # the axial wavenumber K = n pi / L (a wrinkle's m is in its mode)
        wavenumber = axial_wavenumber(tube, int(mode[1]))
    try:
        runs = [_expansion(tube, mode, control, nodes, side) for nodes in RESOLUTIONS]
    except ConvergenceError as exc:  # not an rtol or a method: this function takes neither
        if "remedy" not in vars(exc):  # the class's own, not a deeper error's
            exc.remedy = NOT_EXPANDED
        raise
    fine = runs[-1]
    return KoiterResult(
        coefficient=fine.coefficient,
        critical_value=fine.control_value,
        wavenumber=wavenumber,
        branch=branch_of(fine.coefficient, control, side),
        error_estimate=_spread(runs),
        normalisation="eps = max_R |u_r| / R_i of the mode (R_i = 1)",
        resonance=nearest_resonance(tube, mode, control, side, fine.control_value),
    )


def _spread(runs) -> float:
    """The coefficients' spread over the resolutions, plus the largest change of one of them
    with A''s difference steps: the rounding of A(c) and of the correction's solve makes c_2
    wander with the node count and from one process to another (BLAS threads), by up to
    5e-8 relative on a film's fold, and one difference of two resolutions could be small by
    luck (18 against 24 nodes: 1.2e-9 where 24 against 32 gave 6.2e-8)."""
    values = [run.coefficient for run in runs]
    return max(values) - min(values) + max(run.derivative_error for run in runs)


def _expansion(tube: Tube, mode, control: str, nodes: int, side: str | None) -> TubeExpansion:
    """The expansion of ``mode``: with the faces' load when the tube is pressurised or the
    pressure is the control (koiter_loads.py), else the wall's alone (koiter_tube.py)."""
    loaded = tube.inner_pressure != 0 or tube.outer_pressure != 0 or control == "pressure"
    if mode[0] != 0 and mode[1] != 0 and not loaded:  # an unloaded wrinkle, charged or not
        return wrinkle_expansion(tube, mode, control, nodes=nodes, side=side)
    charged = mode[1] != 0 and (tube.voltage != 0 or control == "voltage")
    if loaded or charged:  # the axisymmetric family's potential lives there too
        return loaded_expansion(tube, mode, control, nodes=nodes, side=side)
    if mode[1] == 0:
        return tube_expansion(tube, mode[0], control, nodes=nodes, side=side)
    return axisymmetric_expansion(tube, mode[1], control, nodes=nodes, side=side)


def _tube_family(mode) -> str:
    """ "prismatic" for (m, 0), m >= 2, "axisymmetric" for (0, n), n >= 1, "wrinkle" for
    (m, n), m, n >= 1, else the one-line ParameterError naming what is covered."""
    if isinstance(mode, tuple) and len(mode) == 2:
        m, n = mode
        if n == 0 and m >= 2:
            return "prismatic"
        if m == 0 and n >= 1:
            return "axisymmetric"
        if m >= 1 and n >= 1:
            return "wrinkle"
    raise ParameterError(
        f"mode = {mode!r}: the tube's amplitude equation covers prismatic modes (m, 0), "
        "m >= 2, axisymmetric modes (0, n), n >= 1, and wrinkles (m, n), m, n >= 1"
    )


def _tube_not_covered(tube: Tube, family: str, control: str) -> str:
    """What the tube lacks for the expansion, in words ("" when covered)."""
    loaded = tube.voltage != 0 or tube.inner_pressure != 0 or tube.outer_pressure != 0
    if tube.control == "force" and (loaded or control in ("voltage", "pressure")):
        # the force's conjugate would carry the field's and the ends' pressure load too
        return "the axial stretch prescribed under a voltage or a pressure (not the axial force)"
    return _energy_not_covered(tube, control)


def _energy_not_covered(tube: Tube, control: str) -> str:
    """Any strain energy is covered (its derivatives to fourth order); under a voltage
    only an ideal dielectric's, Omega = W(I1, I2) + I5 / 2, whose electric part is the
    one the dielectric forms hold."""
    if tube.voltage == 0 and control != "voltage":
        return ""
    for ply in tube.layers:
        if not ply.material.is_ideal_dielectric():
            return (
                "ideal dielectric layers under a voltage, Omega = W(I1, I2) + I5/2 "
                f"(not {ply.material.name})"
            )
    return ""


def with_branch(
    verdict: Verdict, tube: Tube, solve_for: str, side: str | None = None
) -> tuple[Verdict, str | None]:
    """``verdict`` with its slot ``branch``/``koiter``/``koiter_error`` filled from the
    amplitude equation of its wrinkle, and None; or unchanged with the one-line reason it
    is not computed (no wrinkle, or a case the expansion does not cover yet). The meaning
    gains what the branch means for a user: folds that grow gradually, or a jump at
    onset."""
    w = verdict.wrinkle
    if w is None or w.m is None or w.n is None:
        return verdict, "no wrinkle was found, so there is no amplitude equation"
    try:
        k = koiter_coefficient(tube, (int(w.m), int(w.n)), solve_for, side=side)
    except (ParameterError, NoBifurcationFound, ConvergenceError, BaseStateError) as exc:
        return verdict, str(exc)
    words = {
        "supercritical": "supercritical: the folds grow gradually past onset",
        "subcritical": "subcritical: the tube jumps to large folds at onset",
    }
    meaning = f"{verdict.meaning}; the wrinkle is {words[k.branch]}"
    if k.resonance is not None:
        meaning += f", but {k.resonance.words(solve_for)}"
    out = dataclasses.replace(
        verdict,
        branch=k.branch,
        koiter=k.coefficient,
        koiter_error=k.error_estimate,
        koiter_resonance=None if k.resonance is None else dataclasses.asdict(k.resonance),
        meaning=meaning,
    )
    return out, None
