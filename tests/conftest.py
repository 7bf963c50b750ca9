"""Shared fixtures. Plots are drawn off-screen (MPLBACKEND=Agg) before anything imports
matplotlib."""

import os

os.environ["MPLBACKEND"] = "Agg"
# Small dense matrices only: BLAS threads just contend with numba's on 2 cores.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from electrogrowth.model.layers import Layer, LinearGrowth, Tube  # noqa: E402
from electrogrowth.model.materials import gent, mooney_rivlin, neo_hookean  # noqa: E402

#: one tube of every kind, for physics that holds for any tube (the ``tubes`` fixture)
TUBES = {
    "uniform": Tube.uniform(1.5, 2.0, growth=1.1, stretch=1.05, voltage=0.3),
    "two-layer": Tube(
        (Layer(1.2, shear_modulus=4.0, growth=(1.0, 1.15, 1.0)), Layer(1.8, gent(50.0))),
        length=2.0,
        voltage=0.2,
    ),
    "graded": Tube(
        (Layer(1.6, mooney_rivlin(0.3), growth=LinearGrowth(1.0, 1.6, (1.0, 1.12, 1.0), 1.0)),),
        length=2.0,
        stretch=1.02,
    ),
    "pressurised": Tube((Layer(1.5),), length=2.0, inner_pressure=0.08, outer_pressure=0.02),
    "force-controlled": Tube(
        (Layer(1.3, shear_modulus=3.0), Layer(1.7, permittivity=2.0)),
        length=2.0,
        axial_force=-0.5,
        voltage=0.1,
    ),
}


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
