"""The verdict in a sweep's store: every added variable is written and read back, the
crease value at the closed form of the homogeneous tube (docs/derivation-crease.md)."""

import math

import numpy as np
import pytest

pytest.importorskip("xarray")
pytest.importorskip("zarr")

from electrogrowth.sweep.file import parse_config  # noqa: E402
from electrogrowth.sweep.run import compute_sweep  # noqa: E402
from electrogrowth.sweep.schema import POINT_VARIABLES  # noqa: E402
from electrogrowth.sweep.store import open_results  # noqa: E402

SWEEP = """\
[solve]
for = "stretch"
side = "compression"
[modes]
m = [0, 2]
n = [1, 2]
extend = false
[fixed]
length = 1.0
[grid]
outer_radius = [1.6, 1.8]
"""
ADDED = (
    "verdict",
    "verdict_value",
    "verdict_face",
    "wrinkle_value",
    "crease_value",
    "crease_face",
    "crease_trigger",
    "crease_error",
    "threshold_value",
    "meaning",
    "branch",
    "koiter",
)


def test_the_store_holds_the_verdict(tmp_path):
    assert set(ADDED) <= set(POINT_VARIABLES)
    config = parse_config(SWEEP, source=str(tmp_path / "s.toml"))
    compute_sweep(config, tmp_path / "out.zarr", workers=1)
    ds = open_results(tmp_path / "out.zarr")
    for name in ADDED:
        assert name in ds, name
    crease = 2.4 ** (-2 / 3)
    assert [str(v) for v in ds["verdict"].values] == ["bifurcation", "crease"]
    assert [str(v) for v in ds["kind"].values] == ["bifurcation", "bifurcation"]  # linear
    assert np.allclose(ds["crease_value"].values, crease, rtol=1e-12, atol=0)
    assert np.array_equal(ds["wrinkle_value"].values, ds["critical_value"].values)
    assert ds["verdict_value"].values[0] == ds["critical_value"].values[0]
    assert ds["verdict_value"].values[1] == pytest.approx(crease, rel=1e-12)
    assert [str(v) for v in ds["crease_trigger"].values] == ["axial", "axial"]
    assert all(math.isnan(v) for v in ds["threshold_value"].values)
    assert all(math.isnan(v) for v in ds["koiter"].values)
    assert [str(v) for v in ds["branch"].values] == ["", ""]
    assert "creases" in str(ds["meaning"].values[1])
