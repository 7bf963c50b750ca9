"""
Base state and voltage threshold
================================

The axisymmetric state of a grown, stretched, charged tube (paper Sec. 3.1): the inner
stretch lambda_i against the voltage Vbar, the largest voltage the axisymmetric state can
carry (its threshold), and the residual stresses through the wall.
"""

import matplotlib.pyplot as plt
import numpy as np

from electrogrowth import TubeParameters, solve_base_state, voltage_curve, voltage_threshold

tube = TubeParameters(outer_radius=2.0, growth=1.1, stretch=1.0, voltage=0.6)
state = solve_base_state(tube)
print(f"lambda_i = {state.lambda_i:.10f}, charge c = {state.charge:.10f}")
threshold, kind, _ = voltage_threshold(tube)
print(f"Vbar threshold = {threshold:.10f} ({kind})")

# %%
# The voltage curve Vbar(lambda_i) rises towards its threshold (an asymptote for the
# neo-Hookean solid); the solved state sits on it.
lam0 = solve_base_state(tube.at("voltage", 0.0)).lambda_i
lam = np.linspace(lam0, 4.0, 200)
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(8, 3.2), layout="constrained")
ax1.plot(voltage_curve(tube, lam), lam, "k-")
ax1.axvline(threshold, ls="--", color="0.5", label="threshold")
ax1.plot(tube.voltage, state.lambda_i, "o", color="C3", label="solved state")
ax1.set(xlabel=r"$\bar V$", ylabel=r"$\lambda_i$", title="voltage curve")
ax1.legend()

# %%
# Through-wall profiles: every stress vanishes at Vbar = 0 and g = 1; growth and voltage
# leave a residual stress. ``state.to_xarray()`` gives the same profiles as labelled
# arrays, with units and descriptions.
profiles = state.to_xarray(101)
for name in ("sigma_rr", "sigma_tt", "sigma_zz"):
    profiles[name].plot(ax=ax2, label=profiles[name].attrs["long_name"])
ax2.set(xlabel="R / R_i", ylabel=r"stress / $\mu$", title="residual stress")
ax2.legend(fontsize=7)
profiles
