"""
Base state and voltage threshold
================================

The axisymmetric state of a grown, stretched, charged tube (paper Sec. 3.1): the inner
stretch lambda_i against the voltage Vbar, the largest voltage the axisymmetric state can
carry (its threshold), and the residual stresses through the wall.
"""

import matplotlib.pyplot as plt
import numpy as np

from electrogrowth import Tube, solve_base_state, voltage_curve, voltage_threshold

tube = Tube.uniform(outer_radius=2.0, growth=1.1, stretch=1.0, voltage=0.6)
state = solve_base_state(tube)
print(f"lambda_i = {state.lambda_i:.10f}, charge c = {state.charge:.10f}")
threshold, kind, _ = voltage_threshold(tube)
print(f"Vbar threshold = {threshold:.10f} ({kind})")

# %%
# The voltage curve Vbar(lambda_i) rises towards its threshold (an asymptote for the
# neo-Hookean solid); the solved state sits on it.
lam0 = solve_base_state(tube.at("voltage", 0.0)).lambda_i
lam = np.linspace(lam0, 4.0, 200)
fig, ax = plt.subplots(figsize=(5, 3.2), layout="constrained")
ax.plot(voltage_curve(tube, lam), lam, "k-", label=r"$\bar V(\lambda_i)$")
ax.axvline(threshold, ls="--", color="0.5", label="threshold")
ax.plot(tube.voltage, state.lambda_i, "o", color="C3", label="solved state")
ax.set(
    xlabel=r"voltage $\bar V$ (–)", ylabel=r"inner stretch $\lambda_i$ (–)", title="voltage curve"
)
_ = ax.legend()

# %%
# Through-wall profiles: every stress vanishes at Vbar = 0 and g = 1; growth and voltage
# leave a residual stress. ``state.to_xarray()`` gives the same profiles as labelled
# arrays, with units and descriptions (shown below the figure).
profiles = state.to_xarray(101)
fig, ax = plt.subplots(figsize=(5, 3.2), layout="constrained")
for name in ("sigma_rr", "sigma_tt", "sigma_zz"):
    profiles[name].plot(ax=ax, label=profiles[name].attrs["long_name"])
ax.set(xlabel=r"radius $R / R_i$ (–)", ylabel=r"stress / $\mu$ (–)", title="residual stress")
_ = ax.legend(fontsize=7)

# %%
profiles
