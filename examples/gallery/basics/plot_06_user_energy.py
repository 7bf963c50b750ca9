"""
Your own energy
===============

A material is its energy Omega(I1, I2, I4, I5, I6) (paper eq. 8); stresses, the field and
the 23 incremental moduli follow from it. Here a Mooney-Rivlin solid whose permittivity
changes with the stretch (an I6 term), written as a string as the command line takes it
(``--energy``), against the ideal neo-Hookean dielectric.
"""

import matplotlib.pyplot as plt
import numpy as np

from electrogrowth import Tube, critical_value, neo_hookean
from electrogrowth.model.energy_text import energy_material

mine = energy_material("0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2 + 0.05*(I6 - I4)")
print(mine.energy)

voltages = np.linspace(0.0, 0.5, 3)
curves = {}
for material in (neo_hookean(), mine):
    curves[material.name] = [
        critical_value(Tube.uniform(1.4, 1.0, voltage=v, material=material), 0, 1, "growth").value
        for v in voltages
    ]

# %%
# The critical growth of mode (0, 1) falls with the voltage for both; the softer
# electrostrictive material wrinkles earlier.
fig, ax = plt.subplots(figsize=(5, 3.2), layout="constrained")
for name, values in curves.items():
    ax.plot(voltages, values, "o-", label=name)
ax.set(xlabel=r"voltage $\bar V$ (–)", ylabel=r"critical growth $g_{\rm cr}$ of mode (0, 1) (–)")
_ = ax.legend(fontsize=7)
