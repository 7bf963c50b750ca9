"""Grids of tubes: the TOML sweep file (:mod:`.file`) and its validated configuration
(:mod:`.config`), the pure unit of work, one scan per point (:mod:`.unit`), the resumable Zarr
store (:mod:`.store`, needs the ``sweep`` extra: xarray, zarr) and the drivers on a process
pool or a Dask cluster (:mod:`.run`).

May import ``bifurcation`` and everything below it; ``store`` is imported only where a store
is opened, so the package works without the extra.
"""

from .config import SweepConfig
from .file import load_config
from .run import compute_sweep
from .unit import PointResult, ScanSpec, compute_point

__all__ = [
    "SweepConfig",
    "load_config",
    "compute_sweep",
    "PointResult",
    "ScanSpec",
    "compute_point",
]
