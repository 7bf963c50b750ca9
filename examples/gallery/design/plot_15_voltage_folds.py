"""
Fold number set by voltage
==========================

An electro-active version of the gut-like bilayer: a stiff inner layer (R = 1 .. 1.1,
mu_1/mu_2 = 10) grows in the hoop direction (F_g = diag(1, g_theta, 1)) inside a soft
ungrown substrate (1.1 .. 2, mu_2 = 1), L = 1, lambda_z = 1, with a voltage across the
whole wall, Vbar = V sqrt(eps/mu) / (R_o - R_i) (units mu_2 = eps = R_i = 1). At each
voltage the first pattern is the one with the lowest critical hoop growth g_theta; along
Vbar the pattern sequence (``mode_sequence``) gives the intervals of one fold number and
the switches between them, each the root of v_A(Vbar) = v_B(Vbar) for two fixed modes
(Brent's method, to 1e-13).

Coarsened for the page: 3 grid voltages on [0, 0.4] and modes m = 9 .. 15 with n = 0
(prismatic folds) and n = 1 only (the full scans of the patterns gallery, m from 0 and n
to 16, find the same (11, 0) at Vbar = 0 and (13, 0) at 0.4). The page "Growth-voltage
map" draws this bilayer's map over a wider voltage range.
"""

from electrogrowth import ScanOptions, mode_sequence
from electrogrowth.figures.design_gallery import gut_bilayer
from electrogrowth.figures.plots import plot_curve

HOOP = "growth[1].theta"
options = ScanOptions((9, 15), (1, 1), top=3, extend=False, surface=False)
seq = mode_sequence(gut_bilayer(0.1, 10.0), HOOP, ("voltage", 0.0, 0.4), options=options, points=3)
for iv in seq.intervals:
    print(f"Vbar {iv.lo:.8f} .. {iv.hi:.8f}: (m, n) = {iv.mode}")
for s in seq.switches:
    print(
        f"switch at Vbar = {s.x:.10f}: {s.mode_before} -> {s.mode_after},"
        f" g_theta,cr = {s.value:.10f}"
    )

# %%
# The first pattern's critical hoop growth along the voltage, each branch labelled (m, n),
# the switches as dots; the lines join the computed points (the grid voltages and the
# switches). The voltage delays the folds (g_theta,cr rises) and makes them finer: the
# fold number steps up by one at each switch.
#
# What the literature says: for a dielectric film bonded to a substrate under a field
# alone, the film's thickness, modulus and surface energy set whether it creases or
# wrinkles and at which wavelength (Wang and Zhao 2013, Phys. Rev. E 88, 042403). We found
# no published fold number of a growing tube under voltage to compare with, so the rise of
# m with Vbar here is a prediction of the model, not a check against data.
ax = plot_curve(seq.curve)
ax.set_title("gut-like bilayer under voltage: first folds (m, n)", fontsize=9)
fig = ax.figure
