"""
One critical mode, certified by two methods
===========================================

The critical growth factor g_cr of the axisymmetric mode (m, n) = (0, 1) of the paper's
headline tube (Rbar_o = 1.4, L = 1, lambda_z = 1, Vbar = 0.4), found by the compiled
surface-impedance (Riccati) method and certified by an independent Chebyshev collocation.
"""

import matplotlib.pyplot as plt

from electrogrowth import Tube, critical_value, mode_shape

tube = Tube.uniform(outer_radius=1.4, length=1.0, stretch=1.0, voltage=0.4)
impedance = critical_value(tube, 0, 1, "growth")
collocation = critical_value(tube, 0, 1, "growth", method="collocation")
print(
    f"impedance:   g_cr = {impedance.value:.12f} (error estimate {impedance.error_estimate:.1e})"
)
print(f"collocation: g_cr = {collocation.value:.12f}")
print(f"relative difference {abs(impedance.value / collocation.value - 1):.1e}")

# %%
# The mode shape through the wall at onset: the incremental displacements U_r, U_theta,
# U_z and the potential Phi, normalised to a largest displacement of 1.
shape = mode_shape(impedance, points=81)
fig, ax = plt.subplots(figsize=(5, 3.2), layout="constrained")
for name, label in (
    ("U_r", "$U_r$"),
    ("U_th", r"$U_\theta$"),
    ("U_z", "$U_z$"),
    ("Phi", r"$\Phi$"),
):
    ax.plot(shape.r, getattr(shape, name), label=label)
ax.set(
    xlabel=r"current radius $r / R_i$ (–)",
    ylabel="amplitude (largest displacement 1)",
    title=f"mode (0, 1) at g_cr = {impedance.value:.6f}",
)
_ = ax.legend()
impedance
