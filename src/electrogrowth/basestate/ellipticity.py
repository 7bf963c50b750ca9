"""Strong ellipticity of a state, read off its shear moduli along the coordinate axes.

A wave with normal e_p and polarisation e_i (i != p; the field D along e_1 = r) is resisted
by the shear modulus A_pipi, less the field's share where the normal is the field's
direction (an incremental D' lies across the normal, so Gamma_1iq D'_q with q = i):

    gamma_12 = A1212 - G122^2 / K22,  gamma_13 = A1313 - G133^2 / K33,
    A2121, A3131, A2323, A3232.

Strong ellipticity needs all six > 0 (they are its acoustic tensor's diagonal along the
axes); where one vanishes a mode's roots come densely and no target is meaningful
(bifurcation/torsion_onset.py: gamma_12 and A3232 are the torsional problem's). With no
field, A_ijij = l_i^2 (tau_i - tau_j) / (l_i^2 - l_j^2) is the Baker-Ericksen quotient, so
A1212 <= 0 means the hoop-radial stress difference falls as the wall opens: at the
unloaded homogeneous state (l_1 = l_2 = lambda_e^(-1/2), lambda_e = lambda_z / g_z) that is
a function of lambda_e alone, Mooney-Rivlin's (c_1 + c_2 lambda_e^2) l_1^2 (docs
derivation-base-state.md, Sec. 6).
"""

from __future__ import annotations

import math

import numpy as np

from ..brent import brentq
from ..errors import BaseStateError, Remedy
from ..model.materials import Material, shorten
from ..model.moduli import MODULI_INDEX

#: the six shear moduli of :func:`shear_moduli`, in its order
SHEAR_NAMES = ("gamma_12", "gamma_13", "A2121", "A3131", "A2323", "A3232")

#: a shear modulus below this share of its layer's is lost beyond rounding (the moduli's
#: ~1e-15; a state at a located onset, x_e to ~1e-13, reads A1313 = -8.9e-16 and stays)
LOST = -1e-9

_I = {name: MODULI_INDEX[name] for name in ("A1212", "A1313", "A2121", "A3131", "A2323")}
_I |= {name: MODULI_INDEX[name] for name in ("A3232", "G122", "G133", "K22", "K33")}


def shear_moduli(moduli: np.ndarray) -> np.ndarray:
    """The six shear moduli (SHEAR_NAMES) of moduli arrays (last axis MODULI_NAMES)."""
    m = np.asarray(moduli, float)

    def take(name):
        return m[..., _I[name]]

    return np.stack(
        [
            take("A1212") - take("G122") ** 2 / take("K22"),
            take("A1313") - take("G133") ** 2 / take("K33"),
            take("A2121"),
            take("A3131"),
            take("A2323"),
            take("A3232"),
        ],
        axis=-1,
    )


def wall_shear(state, per_layer: int = 17) -> np.ndarray:
    """The six shear moduli at ``per_layer`` points through each layer of a solved state
    (both faces, each on the layer's own side), each over its layer's small-strain shear
    modulus: shape (points, 6); the layer of row j is ``j // per_layer``."""
    radii, rows = state.tube.radii, []
    for layer, a, b in zip(state.tube.layers, radii, radii[1:]):
        R = np.linspace(a, b, per_layer)
        inner = state.moduli(R[:1], side="outer")  # the layer's own side of its faces
        outer = state.moduli(R[-1:], side="inner")
        mod = np.concatenate([inner, state.moduli(R[1:-1]), outer])
        rows.append(shear_moduli(mod) / layer.initial_moduli[0])
    return np.concatenate(rows)


def softest(state, per_layer: int = 17) -> str:
    """The softest of the six shear moduli through a state's wall, in words (which, in which
    layer, over its small-strain shear modulus), for a message."""
    shear = wall_shear(state, per_layer)
    j, k = np.unravel_index(np.argmin(shear), shear.shape)
    return f"{SHEAR_NAMES[k]} of layer {j // per_layer + 1} at {shear[j, k]:.2g} of its own"


def in_plane_shear(material: Material, stretch: float) -> float:
    """gamma_12 (= A2121 there) of the energy at its unloaded homogeneous state of elastic
    axial stretch ``stretch``, over its small-strain shear modulus."""
    l_in = 1.0 / math.sqrt(stretch)
    moduli = material.moduli(l_in, l_in, stretch, 0.0)
    return float(shear_moduli(moduli)[..., 0]) / material.initial_moduli()[0]


def elliptic_limit(material: Material, stretch: float) -> float:
    """The elastic axial stretch between 1 (where every energy of the package is elliptic)
    and ``stretch``, where :func:`in_plane_shear` is <= 0, at which it vanishes."""
    a, b = sorted((1.0, stretch))
    return brentq(lambda s: in_plane_shear(material, s), a, b, xtol=1e-14, rtol=1e-14)


def check_in_plane(material: Material, stretch: float, where: str) -> None:
    """BaseStateError where the energy has lost strong ellipticity in the r-theta plane at
    the unloaded homogeneous state of elastic axial stretch ``stretch`` (``where`` names
    the layer): the traction's residual then falls as the wall opens, so no unloaded state
    is followed, whatever the load. The user's stretch is past the energy's valid range."""
    low = in_plane_shear(material, stretch)
    if not low <= 0:  # elliptic, or not computed (stresses past a double: named elsewhere)
        return
    limit = elliptic_limit(material, stretch)
    side = "below" if stretch > 1.0 else "above"
    err = BaseStateError(
        f"{where}: the energy {shorten(material.name)!r} is not strongly elliptic at the"
        f" elastic axial stretch lambda_z / g_z = {stretch:.6g}: its in-plane shear modulus"
        f" at the unloaded state is {low:.3g} of its small-strain one, so the wall's"
        f" hoop/radial response stops rising as it opens and no state is followed; it is"
        f" elliptic {side} lambda_z / g_z = {limit:.10g}"
    )
    err.remedy = Remedy(
        f"use a stretch with lambda_z / g_z {side} {limit:.6g}, inside the energy's"
        " strongly elliptic range"
    )
    raise err


#: a shear modulus below this share of its layer's at the end of a march's states is the
#: reason they end: loss of ellipticity located by the march's bisection (to ~1e-13 of
#: the control, so the modulus reads ~1e-12), not merely a soft wall
VANISHED = 1e-6


def why_lost(state) -> str:
    """'' or why the states end at ``state`` (the last one a march solved): a shear modulus
    vanishing there, which no other threshold does (a voltage's limit point keeps them)."""
    if wall_shear(state).min() >= VANISHED:
        return ""
    return f"the energy loses strong ellipticity, {softest(state)}"
