"""The harmonics of a finite-element field along the sector (or the meridian's window): the
one that carries a face's displacement (the pattern of an onset), and the share in patterns
shorter than the mesh resolves (an element-sized mode, not the tube's). Functions of a
model and a field alone: onset.py and stability.py both ask them.
"""

from __future__ import annotations

import numpy as np
import scipy.fft as sfft


def face_harmonic(model, z: np.ndarray) -> tuple[int, float]:
    """(i, share): the harmonic cos(i pi Y / extent) that carries most of the radial
    displacement of ``z`` on the face where it is largest, and its share of that face's
    squared amplitude (0 when ``z`` leaves both faces still). The onset of a Theta- (Z-)
    invariant state on a uniform mesh has one harmonic alone, i = ``periods`` for the
    mode itself (k half wavelengths in the sector)."""
    best = (0, 0.0, 0.0)  # (i, share, norm)
    for face in ("inner", "outer"):
        dofs, _ = model.face_dofs(face)  # vertices, equally spaced along Y
        # the cosine coefficients (DCT-I) and their shares of the trapezoidal squared norm
        # (Parseval: the end terms weigh half)
        c = sfft.dct(z[dofs], type=1)
        energy = c * c
        energy[[0, -1]] /= 2
        norm = float(energy.sum())
        if norm > best[2]:
            i = int(np.argmax(energy))
            best = (i, float(energy[i] / norm), norm)
    return best[0], best[1]


def element_scale_fraction(model, z: np.ndarray) -> float:
    """The share of ``z``'s squared nodal values (u_R and u_Y at every Q2 node, row by row
    along the sector or window, mirrored into one period) in harmonics cos(i pi Y / extent)
    with i > N / 2, N the elements along it: patterns whose half wavelength is shorter than
    two elements, which the mesh does not resolve. The Q2 / discontinuous-P1 pair loses
    stability under finite compression in such patterns at loads that fall as the mesh is
    refined (Auricchio, Beirao da Veiga, Lovadina and Reali 2005; probe 12a D1: a uniform
    tube on (8) x 16 at -485 in harmonic 16 of 16 at g = 1.4, where the continuum is
    stable to 1.956), so such an eigenvector says nothing about the continuum's stability.
    All Q2 nodes, not the vertices alone: a pattern can alternate between midside nodes."""
    energy = 0.0
    for name, parity in (("u^1^1", 1.0), ("u^2^1", -1.0)):  # u_R even, u_Y odd at the ends
        dofs = model.basis.get_dofs(elements=True).all(name)
        R, Y = model.basis.doflocs[:, dofs]
        # rows of constant R, each along Y (R rounded: a midside node's R can differ from
        # its row's vertices' in the last bit, which would reorder the row)
        order = np.lexsort((Y, np.round(R, 10)))
        f = z[dofs[order]].reshape(-1, 2 * model.size.hoop + 1)
        f = np.concatenate([f, parity * f[:, -2:0:-1]], axis=1)
        energy = energy + (np.abs(np.fft.rfft(f, axis=-1)) ** 2).sum(axis=0)
    total = float(np.sum(energy))
    if total == 0.0:
        return 0.0
    unresolved = np.arange(len(energy)) > model.size.hoop / 2
    return float(energy[unresolved].sum() / total)


#: the element-scale share above which an eigenvector is the mesh's, not the tube's
ELEMENT_SCALE = 0.5


def is_element_scale(model, z: np.ndarray) -> bool:
    """Whether most of ``z`` lies in patterns the mesh does not resolve
    (:func:`element_scale_fraction`)."""
    return element_scale_fraction(model, z) > ELEMENT_SCALE
