"""
Prismatic modes and the short-wave limit
========================================

As the circumferential wavenumber m grows, the critical value of the prismatic modes
(m, 0) (plane strain, n = 0) tends to the exact short-wave limit m, n -> infinity: a
surface instability of one face, computed from the half-space problem without any scan.
"""

import matplotlib.pyplot as plt

from electrogrowth import Tube, critical_value
from electrogrowth.bifurcation.surface import short_wave_limit

tube = Tube.uniform(outer_radius=1.4, length=1.0, voltage=0.6)
limit = short_wave_limit(tube, "stretch", side="extension")
print(f"short-wave limit: lambda_z = {limit.value:.10f} at the {limit.face} face")

ms = [2, 4, 8, 16, 32]
values = [
    critical_value(tube, m, 0, "stretch", side="extension", family="prismatic").value for m in ms
]
for m, v in zip(ms, values):
    print(f"  prismatic (m, 0) = ({m}, 0): lambda_z,cr = {v:.8f}")

# %%
fig, ax = plt.subplots(figsize=(5, 3.2), layout="constrained")
ax.semilogx(ms, values, "o-", label="prismatic modes (m, 0)", base=2)
ax.axhline(limit.value, ls="--", color="C3", label=f"short-wave limit ({limit.face} face)")
ax.set(
    xlabel="circumferential wave number m",
    ylabel=r"critical stretch $\lambda_{z,\rm cr}$ in extension (–)",
)
_ = ax.legend(fontsize=8)
