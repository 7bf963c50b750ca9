"""
A layered tube's critical curve
===============================

A thin stiff inner layer (shear modulus ten times the outer layer's) grows in the hoop
direction inside a soft, ungrown tube (radii 1, 1 + h, 2): the critical hoop growth of the
inner layer as its thickness h grows from 0.08 to 0.12; the number of folds m falls. The
axis labels name the control in words ("growth g_θ of layer 1"); the branches carry their
critical mode (m, n).
"""

from electrogrowth import Layer, ScanOptions, Tube, critical_curve
from electrogrowth.figures.plots import plot_curve

tube = Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)))
curve = critical_curve(
    tube,
    "growth[1].theta",
    "layers[1].thickness",
    [0.08, 0.1, 0.12],
    options=ScanOptions(m_range=(0, 8), n_range=(1, 2)),
)
for x, v, m, n in zip(curve.x, curve.value, curve.m, curve.n):
    print(f"h = {x:.3f}: g_theta,cr = {v:.6f} in mode (m, n) = ({m}, {n})")

# %%
ax = plot_curve(curve)
ax.set_title("hoop growth of a stiff inner layer", fontsize=9)
fig = ax.figure
