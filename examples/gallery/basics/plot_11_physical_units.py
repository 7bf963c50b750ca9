"""
Physical units in and out
=========================

The package computes in units mu = eps = R_i = 1. A tube of 2 mm inner radius, 2.8 mm outer
radius, 10 mm long, of a silicone with mu = 100 kPa and relative permittivity 4.7 becomes
Rbar_o = 1.4, L = 5, and a voltage V becomes Vbar = V / (R_o - R_i) sqrt(eps / mu)
(pint, the ``units`` extra). Results come back in kV, kPa, mm and N. On the command line::

    electrogrowth critical --solve-for voltage --inner-radius 2mm --outer-radius 2.8mm \\
        --length 10mm --shear-modulus 100kPa --permittivity 4.7 --growth 1.1 --mode 0 1
"""

import matplotlib.pyplot as plt
import numpy as np

from electrogrowth import critical_value, tube_from_quantities

tube, scales = tube_from_quantities(
    "2 mm", "2.8 mm", length="10 mm", shear_modulus="100 kPa", permittivity=4.7, growth=1.1
)
print(tube)
crit = critical_value(tube, 0, 1, "voltage")
print(f"Vbar_cr = {crit.value:.8f}  ->  V_cr = {scales.voltage(crit.value):.4f~P}")

# %%
# The critical voltage in kV as the growth proceeds.
growths = np.linspace(1.0, 1.2, 5)
kv = [
    scales.voltage(critical_value(tube.at("growth", g), 0, 1, "voltage").value).magnitude
    for g in growths
]
fig, ax = plt.subplots(figsize=(5, 3.2), layout="constrained")
ax.plot(growths, kv, "o-")
_ = ax.set(xlabel="growth factor g (–)", ylabel="critical voltage (kV)")
