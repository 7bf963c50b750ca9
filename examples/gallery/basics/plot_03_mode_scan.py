"""
Which mode comes first: a mode scan
===================================

``scan_modes`` marches the control parameter for every mode (m, n) at once and reports the
first to bifurcate with its runners-up. Here the critical voltage of a thick, long tube,
and a map of each mode's own critical voltage over a small (m, n) grid.
"""

import matplotlib.pyplot as plt
import numpy as np

from electrogrowth import ScanOptions, Tube, critical_value, scan_modes

tube = Tube.uniform(outer_radius=1.4, length=3.0, stretch=1.2)
scan = scan_modes(tube, "voltage", options=ScanOptions(m_range=(0, 4), n_range=(1, 4), top=4))
c = scan.critical
print(f"Vbar_cr = {c.value:.10f} in mode (m, n) = ({c.m}, {c.n}); runners-up:")
for r in scan.runners_up:
    print(f"  ({r.m}, {r.n}) at {r.value:.8f}")

# %%
# Each mode's critical voltage on its own (a small grid; the scan found the minimum).
ms, ns = np.arange(0, 4), np.arange(1, 4)
vcr = np.array([[critical_value(tube, m, n, "voltage").value for n in ns] for m in ms])
fig, ax = plt.subplots(figsize=(4.5, 3.4), layout="constrained")
mesh = ax.pcolormesh(ns, ms, vcr, shading="nearest", cmap="viridis")
fig.colorbar(mesh, label=r"$\bar V_{cr}$ of the mode")
ax.plot(c.n, c.m, "r*", ms=14, label="critical")
ax.set(xlabel="n (axial half-waves)", ylabel="m (circumferential)", xticks=ns, yticks=ms)
_ = ax.legend(loc="upper right")
scan.to_xarray()
