"""
The wrinkled tube in 3D
=======================

The mode shape at onset drawn on the tube, coloured by the radial displacement u_r, like
the paper's Figs. 9B and 10B. A prismatic or non-axisymmetric mode gives lobes around.
"""

from electrogrowth import Tube, critical_value, mode_shape
from electrogrowth.figures.plots import render_pattern

tube = Tube.uniform(outer_radius=1.4, length=1.0, stretch=1.0, voltage=0.4)
crit = critical_value(tube, 3, 1, "growth")
print(f"mode (3, 1): g_cr = {crit.value:.10f}")
shape = mode_shape(crit, points=41)

# %%
# The exported wall is the same as ``electrogrowth pattern --vtk`` writes for ParaView.
fig = render_pattern(shape, amplitude=0.08, n_theta=90, n_z=40)

# %%
# The same wall to turn around: drag to rotate, wheel to zoom. The page is one HTML file
# with an inline WebGL viewer (nothing is loaded from the network), written by
# ``electrogrowth.figures.viewer.write_pattern_html(shape, "pattern.html", amplitude=0.08)``.
#
# .. raw:: html
#
#    <iframe src="../../_static/pattern-3d.html" title="the wrinkled tube in 3D"
#     style="width: 100%; height: 520px; border: 1px solid #ddd"></iframe>
