"""
A critical curve with mode switches
===================================

The critical axial compression of a charged tube (Vbar = 0.3, L = 1) as the wall
thickens: thin tubes buckle with lobes around (m = 3, 2, 1), thick ones axisymmetrically
(m = 0). Between grid points whose critical modes differ, the switch is located exactly.
"""

from electrogrowth import ScanOptions, Tube, critical_curve
from electrogrowth.figures.plots import plot_curve

tube = Tube.uniform(outer_radius=1.4, length=1.0, voltage=0.3)
curve = critical_curve(
    tube,
    "stretch",
    "outer_radius",
    [1.1, 1.2, 1.3, 1.6, 2.0],
    side="compression",
    options=ScanOptions(m_range=(0, 4), n_range=(1, 3), top=2),
)
for s in curve.switches + curve.ends:
    print(
        f"{s.kind} at Rbar_o = {s.x:.8f}: {s.mode_before} -> {s.mode_after},"
        f" lambda_z,cr = {s.value:.8f}"
    )

# %%
# Branches are labelled with their critical mode (m, n) (the paper writes "n, m"); dots
# mark the located switches, open circles the ends of branches, if any.
ax = plot_curve(curve)
ax.set_title("in compression", fontsize=9)
fig = ax.figure
curve
