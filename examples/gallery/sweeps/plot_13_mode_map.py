"""
A mode map over two design variables
====================================

Which pattern comes first as two design variables change: an uncharged, ungrown tube of
one neo-Hookean layer compressed axially, over its outer radius R_o and length L. A coarse
2 x 2 grid of mode scans seeds the boundaries between patterns; each boundary is then
traced as a curve on which its two modes buckle at the same stretch (not interpolated from
the grid), and certified by full solves and scans. Then the inverse question: the design
with the widest margin for the Euler-like mode (1, 1), marked by the star.
"""

from electrogrowth import ScanOptions, Tube, mode_map, prescribe_map
from electrogrowth.figures.design import plot_map

options = ScanOptions((0, 2), (1, 1), extend=False)
mmap = mode_map(
    Tube.uniform(),
    "stretch",
    (("outer_radius", 1.18, 1.3), ("length", 0.9, 1.3)),
    side="compression",
    options=options,
    points=2,
    certify=1,
)
for b in mmap.boundaries:
    print(
        f"{b.left} | {b.right}: {len(b.x)} points from R_o = {b.x[0]:.8f}, L = {b.y[0]:.4f}"
        f" to R_o = {b.x[-1]:.8f}, L = {b.y[-1]:.4f}; certified: {b.certified}"
    )

# %%
design = prescribe_map(Tube.uniform(), (1, 1), mmap, options=options)
print(
    f"best design for (1, 1): R_o = {design.x:.6f}, L = {design.y:.6f}, margin"
    f" {design.margin:.4f} against {design.next_mode}"
)
ax = plot_map(design)
fig = ax.figure
