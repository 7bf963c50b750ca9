"""
A sweep and its phase diagram
=============================

A grid of tubes, each scanned for its critical mode, written to a resumable Zarr store
(the unit of work is one pure function per point; the same file runs on a Dask cluster
with ``electrogrowth sweep --scheduler``). A small grid here; the phase diagram outlines the
regions of each critical mode.
"""

import tempfile
from pathlib import Path

from electrogrowth import compute_sweep
from electrogrowth.figures.phase_diagram import phase_diagram
from electrogrowth.sweep.file import parse_config
from electrogrowth.sweep.store import open_results

config = parse_config(
    """
[solve]
for = "growth"
[modes]
m = [0, 3]
n = [1, 2]
extend = false
[fixed]
length = 1.0
voltage = 0.4
[grid]
outer_radius = [1.3, 1.5, 1.7]
stretch = [0.8, 1.0, 1.2]
"""
)
out = Path(tempfile.mkdtemp()) / "phase.zarr"
summary = compute_sweep(config, out, workers=1, progress=False)
print(summary.text())
results = open_results(out)
results

# %%
# The thinnest, most compressed tube is unstable before it grows at all: its cell says
# "already unstable at g = 1" rather than "failed".
fig = phase_diagram(results, "stretch", "outer_radius")
