"""
The paper's Figure 8 (low resolution)
=====================================

The critical voltage against the axial stretch for Rbar_o = 1.4 and two lengths, with the
mode switches. ``electrogrowth figure 8`` draws it at full resolution; every figure of the
paper is a function in :mod:`electrogrowth.figures` returning its data, its plot and a
few headline numbers that the test suite checks.
"""

from electrogrowth.figures import FIGURES

result = FIGURES[8](quick=True)
for key, value in result.headline.items():
    print(f"{key} = {value:.8g}")
fig = result.figure
