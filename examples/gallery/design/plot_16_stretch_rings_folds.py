"""
Axial stretch selects rings or folds
====================================

The gut-like bilayer again (a stiff inner layer R = 1 .. 1.1 of shear modulus mu_1 = 10
growing in the hoop direction, F_g = diag(1, g_theta, 1), inside a soft ungrown substrate
1.1 .. 2 of mu_2 = 1; L = 1, no voltage; units mu_2 = R_i = 1), now held at an axial
stretch lambda_z below 1. Which pattern comes first as the growth g_theta rises: axial
rings (0, n), axially modulated folds (m, 1) or plain longitudinal folds (m, 0)? The
pattern sequence along lambda_z (``mode_sequence``) answers with the switch positions,
each the root of v_A(lambda_z) = v_B(lambda_z) for two fixed modes (Brent's method).

Coarsened for the page: 4 grid values of lambda_z on [0.94, 1] and modes m = 0 .. 12,
n = 0 .. 2 (a wider window, m to 13 and n to 3, gives the same sequence); the narrow
intervals between grid points are found by splitting the brackets, not by more points.
"""

from electrogrowth import ScanOptions, mode_sequence
from electrogrowth.figures.design import label_branches
from electrogrowth.figures.design_gallery import gut_bilayer
from electrogrowth.figures.plots import plot_curve

HOOP = "growth[1].theta"
options = ScanOptions((0, 12), (1, 2), top=3, extend=False, surface=False)
seq = mode_sequence(
    gut_bilayer(0.1, 10.0), HOOP, ("stretch", 0.94, 1.0), options=options, points=4
)
for iv in seq.intervals:
    print(f"lambda_z {iv.lo:.8f} .. {iv.hi:.8f}: (m, n) = {iv.mode}")
for s in seq.switches:
    print(
        f"switch at lambda_z = {s.x:.10f}: {s.mode_before} -> {s.mode_after},"
        f" g_theta,cr = {s.value:.10f}"
    )

# %%
# Compressed axially the stiff layer forms rings, (0, 2); released, it forms longitudinal
# folds, (11, 0), with a window of axially modulated folds (9, 1) between, and near
# lambda_z = 0.959 two slivers, (1, 2) and (8, 1), each narrower than 1e-3 (see the
# intervals printed above; their labels are set apart, each with a line to its branch).
# The lines join the computed points: the grid values and the located switches. The last
# switch sits at g_theta,cr = 1.7120162..., the critical growth of the (11, 0) folds at
# lambda_z = 1: for neo-Hookean layers growing in the hoop direction the plane-strain
# problem at any lambda_z is the one at lambda_z = 1 rescaled (docs/patterns.md), so the
# prismatic branch is flat in lambda_z and the axial compression only lowers the
# competitors.
#
# The trend met: in the chick and human gut, the growing lining first folds into
# longitudinal ridges when the circular smooth muscle restricts its circumferential
# expansion, and into zigzags once the longitudinal muscle also restricts it axially
# (Shyer et al. 2013, Science 342, 212). Here too the (m, 0) ridges give way to axially
# modulated patterns when the axial compression is added. The comparison is qualitative:
# a linear onset in a short (L = 1) tube, not their finite-element growth model, and the
# (m, 1) mode is one axial half-wave, not a zigzag.
ax = plot_curve(seq.curve, annotate=False)
_ = label_branches(ax, seq.curve)  # the slivers' labels set apart, each pointing at its branch
ax.set_title("gut-like bilayer along the axial stretch: first pattern (m, n)", fontsize=9)
fig = ax.figure
