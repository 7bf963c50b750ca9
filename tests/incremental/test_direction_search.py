"""The worst wave direction of a half-space, compiled (incremental/direction_search.py), is
its twin's to the last bit (bifurcation.directions.worst_direction_numpy: a NumPy grid and
SciPy's bounded minimiser): on the faces of solved tubes across growth, stretch, voltage,
radius and energy (Hypothesis), on interfaces made of two such faces, and on perturbed
expansions whose decaying split fails or is not strongly elliptic in some directions (the
NaN and infinite paths), for both signs, the fine and coarse grids and the grid alone."""

from __future__ import annotations

import math

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from electrogrowth import Tube  # noqa: E402
from electrogrowth.basestate.tube import solve_base_state  # noqa: E402
from electrogrowth.bifurcation.directions import (  # noqa: E402
    Resolution,
    sampler,
    worst_direction,
    worst_direction_numpy,
)
from electrogrowth.errors import ElectrogrowthError  # noqa: E402
from electrogrowth.incremental.halfspace import (  # noqa: E402
    FaceProblem,
    InterfaceProblem,
    surface_problem,
)
from electrogrowth.model.materials import gent, mooney_rivlin, neo_hookean  # noqa: E402

SETTINGS = settings(
    max_examples=25,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
#: the resolutions the short-wave limit uses (surface.py: fine, coarse) and the grid alone
RESOLUTIONS = ((25, 1e-10), (13, 1e-7), (25, None))


def _same(problem, sign) -> None:
    for grid, tol in RESOLUTIONS:
        got = worst_direction(problem, sign, grid=grid, psi_tol=tol)
        want = worst_direction_numpy(problem, sign, grid=grid, psi_tol=tol)
        assert np.array(got).tobytes() == np.array(want, float).tobytes(), (grid, tol)


tubes = st.builds(
    dict,
    outer=st.floats(1.02, 3.0),
    growth=st.floats(0.6, 3.0),
    stretch=st.floats(0.5, 2.0),
    voltage=st.floats(0.0, 0.8),
    material=st.sampled_from([neo_hookean(), mooney_rivlin(0.3), gent(10.0)]),
)


def _state(t):
    tube = Tube.uniform(
        t["outer"], 1.0, growth=t["growth"], stretch=t["stretch"], voltage=t["voltage"],
        material=t["material"],
    )  # fmt: skip
    try:
        return solve_base_state(tube)
    except ElectrogrowthError:
        assume(False)


@SETTINGS
@given(t=tubes, sign=st.sampled_from([1.0, -1.0]))
def test_faces_of_solved_tubes(t, sign):
    state = _state(t)
    for face in ("inner", "outer"):
        _same(surface_problem(state, face), sign)


@SETTINGS
@given(below=tubes, above=tubes, sign=st.sampled_from([1.0, -1.0]))
def test_interfaces_of_two_faces(below, above, sign):
    b, a = (
        FaceProblem.from_state(_state(below), "outer"),
        FaceProblem.from_state(_state(above), "inner"),
    )
    _same(InterfaceProblem("interface-1", b.expansion, a.expansion), sign)


@SETTINGS
@given(
    t=tubes,
    seed=st.integers(0, 2**32 - 1),
    size=st.sampled_from([1e-3, 0.1, 0.3, 1.0, 10.0]),
    pressure=st.sampled_from([0.0, 0.3, -0.5]),
)
def test_perturbed_expansions(t, seed, size, pressure):
    """Noise on a face's expansion: the split fails, or loses strong ellipticity, in some
    directions (NaN from the grid; +inf inside the minimiser), in others not."""
    face = FaceProblem.from_state(_state(t), "inner")
    noise = np.random.default_rng(seed).normal(size=face.expansion.shape)
    E = face.expansion * (1.0 + size * noise)
    for inner in ("inner", "outer"):
        _same(FaceProblem(inner, E, pressure=pressure), 1.0)


def test_the_march_sampler_refines_as_the_twin_does():
    """The sampler's one call (refined only where the grid minimum is at most refine_below)
    is the twin's two calls: the grid, then the refinement where it is not above."""
    state = solve_base_state(Tube.uniform(1.4, 1.0, voltage=0.4, stretch=1.6))
    signs = {"inner": 1.0, "outer": 1.0}
    for below in (math.inf, 0.05, -math.inf):
        got = sampler(("inner", "outer"), signs, Resolution(25, 1e-10, 1e-12), None, below)
        sample = got(state)
        best = math.inf, None, None
        for face in ("inner", "outer"):
            problem = surface_problem(state, face)
            v, psi = worst_direction_numpy(problem, 1.0, psi_tol=None)
            if not v > below:
                v, psi = worst_direction_numpy(problem, 1.0)
            if v < best[0] - 1e-13:
                best = v, face, psi
        assert (sample.value, sample.face, sample.psi) == best
