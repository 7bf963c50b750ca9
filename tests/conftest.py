"""Shared fixtures. Plots are drawn off-screen (MPLBACKEND=Agg) before anything imports
matplotlib."""

import os

os.environ["MPLBACKEND"] = "Agg"
# Small dense matrices only: BLAS threads just contend with numba's on 2 cores.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from electrogrowth.model.layers import Tube  # noqa: E402
from electrogrowth.model.materials import gent, neo_hookean  # noqa: E402

from .tubes import TUBES  # noqa: E402


@pytest.fixture
def neo():
    """The ideal neo-Hookean dielectric, Omega = (I1 - 3)/2 + I5/2."""
    return neo_hookean()


@pytest.fixture
def gent_mat():
    """The ideal Gent dielectric with the VHB value jm = 97.2."""
    return gent(97.2)


@pytest.fixture
def rng():
    """A seeded generator: every run draws the same 'random' points."""
    return np.random.default_rng(20240611)


@pytest.fixture(params=list(TUBES))
def tubes(request) -> Tube:
    """Every kind of tube in turn (uniform, two-layer, graded, pressurised,
    force-controlled): one physics test, run over all of them."""
    return TUBES[request.param]
