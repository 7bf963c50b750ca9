"""
Growth-voltage map: the voltage selects the fold number
=======================================================

The electro-active gut-like bilayer of the previous pages (a stiff inner layer R = 1 .. 1.1
of shear modulus mu_1 = 10 growing in the hoop direction, F_g = diag(1, g_theta, 1), inside
a soft ungrown substrate 1.1 .. 2 of mu_2 = 1; L = 1, lambda_z = 1; units mu_2 = eps =
R_i = 1) with a voltage across the whole wall, Vbar = V sqrt(eps/mu) / (R_o - R_i). At a
voltage Vbar the tube stays axisymmetric while g_theta is below the first critical growth
g_cr(Vbar) = min over (m, n) of g_mn(Vbar), and wrinkles in the minimising mode when it
grows past it. So in the (Vbar, g_theta) plane the onset curve separates the smooth tube
below from one region per first mode above, bounded by the switch voltages where two modes
are equally critical (``growth_voltage_map``: the mode sequence along Vbar, each switch the
root of g_A(Vbar) = g_B(Vbar) for two fixed modes by Brent's method, to 1e-13).

Coarsened for the page: 4 grid voltages on [0, 0.6] (the narrow intervals between them
are found by splitting the brackets, not by more points) and the full mode window m = 0 ..
20, n = 0 .. 3 (a window m = 9 .. 15, enough up to Vbar = 0.4, misses the (m, 1) modes of
few waves that take over beyond 0.47: at Vbar = 0.6 it reports (9, 1) at g_theta = 2.211
where (1, 1) comes at 2.013).
"""

from electrogrowth import ScanOptions
from electrogrowth.design.growth_voltage import growth_voltage_map
from electrogrowth.figures.design import plot_growth_voltage
from electrogrowth.figures.design_gallery import gut_bilayer

HOOP = "growth[1].theta"
gv = growth_voltage_map(
    gut_bilayer(0.1, 10.0), HOOP, (0.0, 0.6), options=ScanOptions((0, 20), (1, 3)), points=4
)
for r in gv.regions:
    print(f"Vbar {r.lo:.8f} .. {r.hi:.8f}: (m, n) = {r.mode}")
for s in gv.switches:
    print(
        f"switch at Vbar = {s.x:.10f}: {s.mode_before} -> {s.mode_after},"
        f" g_theta,cr = {s.value:.10f}"
    )

# %%
# Below the onset curve the tube stays smooth; growing through it, it folds in the mode of
# the region above. Up to Vbar = 0.469 the voltage delays the folds and makes them finer,
# prismatic (11, 0) -> (12, 0) -> (13, 0), as on the page "Fold number set by voltage".
# Beyond it the onset curve turns down and the pattern changes kind: folds modulated along
# the axis, (m, 1) with one axial half-wave, whose fold number falls as the voltage rises,
# (10, 1), a sliver of (4, 1), (3, 1), (2, 1), then (1, 1) near Vbar = 0.6. So a voltage
# programme can both refine the longitudinal folds and switch them to a few axially
# modulated lobes.
#
# What the literature says: we found no published growth-voltage diagram of a growing
# tube to compare with. Voltage is known to tune the non-axisymmetric (prismatic) modes of
# an electro-active tube's small vibrations (Zhu, Wu, Destrade et al. 2024,
# arXiv:2406.13483) and, for a dielectric film on a substrate, to set crease or wrinkle
# and the wavelength (Wang and Zhao 2013, Phys. Rev. E 88, 042403); the fold sequence here
# is a prediction of the model, not a check against data.
ax = plot_growth_voltage(gv)
fig = ax.figure
