"""
A layered tube: base state
==========================

A thin stiff inner layer growing in the hoop direction on a soft outer layer, inflated and
charged. Each layer has its own energy, shear modulus, permittivity and growth tensor
F_g = diag(g_r, g_theta, g_z); the base state is continuous in traction across the
interface, its hoop stress is not. (The wrinkling of layered tubes is the next step of the
package.)
"""

import matplotlib.pyplot as plt

from electrogrowth import Layer, Tube, solve_base_state

tube = Tube(
    [Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)],
    length=3.0,
    voltage=0.3,
    inner_pressure=0.05,
)
state = solve_base_state(tube)
print(f"lambda_i = {state.lambda_i:.8f}, interface radius r = {state.radii[0]:.8f}")
profiles = state.to_xarray(120)

# %%
fig, ax = plt.subplots(figsize=(5, 3.2), layout="constrained")
for name in ("sigma_rr", "sigma_tt", "sigma_zz"):
    ax.plot(profiles["R"], profiles[name], label=name)
ax.axvline(1.1, color="0.6", lw=0.8)
ax.set(xlabel=r"radius $R / R_i$ (–)", ylabel=r"stress / $\mu$ of the outer layer (–)")
_ = ax.legend(fontsize=8)
profiles
