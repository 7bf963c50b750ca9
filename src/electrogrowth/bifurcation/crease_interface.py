"""The crease at a bonded interface: which interfaces of a layered tube can crease, on which
side, and how far a soft neighbour moves the onset (docs/derivation-crease.md section 8).

A bonded interface is not a free face: the neighbour follows every motion of the face, and
two identical layers in the same state have no interface at all (nothing can crease
there). In the opposite limit, a neighbour of vanishing modulus offers no resistance and
the face of the stiffer layer is a free face. Between the two no onset criterion is
published. The package takes the limit as far as it is near:

* an interface is a crease candidate only where the softer of its two layers has at most
  SOFT_NEIGHBOUR (0.1, to a relative 1e-12: the same at any unit of the moduli) times the
  small-strain shear modulus of the stiffer one (the layer's shear_modulus times its
  energy's own, Layer.initial_moduli) ("bonded to a much softer layer");
* the face of the *stiffer* layer creases, folding into the stiffer layer (the soft
  neighbour is drawn into the fold); the soft layer's face is bonded to a body that is at
  least ten times stiffer and is left out, as a face bonded to a rigid body would be;
* the criterion is the free face's (crease.py: lambda_r / lambda_in-face = 2.4, on the
  stiffer layer's elastic stretches at the interface); an interface is no electrode, so
  the electro-creasing field criterion is not applied there;
* the neighbour delays the onset. How much is measured on the linear analogue, Biot's
  interfacial wrinkle of two bonded neo-Hookean half-spaces in the same state (the
  package's own half-space solver, surface.py: :func:`interfacial_biot_ratio`); the
  relative rise of its ratio over the free face's 3.383 (crease.py neighbour_delay) is
  added to the criterion's accuracy in the error estimate. The value itself is the free
  face's: an early bound.
"""

from __future__ import annotations

import dataclasses
import functools
import math

from ..errors import ElectrogrowthError
from ..model.layer import Layer
from ..model.layers import Tube
from ..outcomes import Kind
from .surface import ray_limit

#: the largest modulus ratio mu_soft / mu_stiff at which an interface is taken as a free
#: face of its stiffer layer: an order of magnitude. At 0.1 the linear analogue is delayed
#: by 20 % (neighbour_delay), which the error estimate carries.
SOFT_NEIGHBOUR = 0.1
#: the relative tolerance of that comparison: the ratio of two moduli is rounded, so a tube
#: whose every modulus is scaled by c (no load carries a modulus: the same state) may
#: round to just above 0.1 where the unscaled one is exactly 0.1 (0.07 / 0.7 =
#: 0.10000000000000002); ratios within a few ulps of the threshold are on it, and a tube's
#: crease onset does not depend on the unit of its moduli (probe 8b D10)
SOFT_NEIGHBOUR_RTOL = 1e-12


@dataclasses.dataclass(frozen=True)
class Interface:
    """A crease candidate: interface ``index`` (between layers index and index + 1,
    1-based), at the undeformed radius ``radius``; the layer that folds (``layer``, on
    ``side`` "inner" or "outer" of the interface) and the neighbour's modulus as a
    fraction of the folding layer's (``neighbour`` <= SOFT_NEIGHBOUR)."""

    index: int
    radius: float
    layer: int
    side: str
    neighbour: float

    @property
    def name(self) -> str:
        """The surface's name, as the half-space solver's: "interface-K"."""
        return f"interface-{self.index}"

    @property
    def label(self) -> str:
        """In words: "interface 1|2 (R = 1.5), layer 1 folds"."""
        k = self.index
        return f"interface {k}|{k + 1} (R = {self.radius:.4g}), layer {self.layer} folds"


def interfaces(tube: Tube) -> tuple[Interface, ...]:
    """The interfaces of ``tube`` that may crease: those whose softer layer has at most
    SOFT_NEIGHBOUR times the stiffer one's small-strain shear modulus (none for a uniform
    tube). The modulus is ``Layer.initial_moduli``'s, shear_modulus times the energy's own:
    an energy text carrying its modulus (check_units=False) is the built-in layer with it."""
    out = []
    for k in range(1, len(tube.layers)):
        below, above = tube.layers[k - 1], tube.layers[k]
        mu_below, mu_above = below.initial_moduli[0], above.initial_moduli[0]
        if mu_below >= mu_above:
            layer, side, ratio = k, "inner", mu_above / mu_below
        else:
            layer, side, ratio = k + 1, "outer", mu_below / mu_above
        if soft_enough(ratio):
            out.append(Interface(k, float(below.outer_radius), layer, side, ratio))
    return tuple(out)


def soft_enough(ratio: float) -> bool:
    """Is a neighbour ``ratio`` times as stiff much softer (at most SOFT_NEIGHBOUR, within
    SOFT_NEIGHBOUR_RTOL: scale-invariant, the mucosa's 10 | 1 is on the threshold at any
    unit)?

    >>> soft_enough(0.1), soft_enough(0.07 / 0.7), soft_enough(0.1000001)
    (True, True, False)
    """
    return ratio <= SOFT_NEIGHBOUR * (1.0 + SOFT_NEIGHBOUR_RTOL)


def label(tube: Tube, face: str | None) -> str:
    """A face's name in words: "inner face", "outer face" or the interface's label."""
    for i in interfaces(tube):
        if i.name == face:
            return i.label
    return f"{face} face"


@functools.lru_cache(maxsize=256)
def interfacial_biot_ratio(neighbour: float) -> float:
    """Biot's ratio lambda_r / lambda_z of the interfacial wrinkle of two bonded
    neo-Hookean solids, the softer ``neighbour`` times as stiff, in the same homogeneous
    state (an ungrown two-layer tube compressed axially, waves along z; surface.py's
    half-space solver at the interface). BIOT_RATIO as neighbour -> 0, inf at 1 (one
    solid); NaN if the solver fails. crease.py's neighbour_delay compares it with the
    free face's."""
    tube = Tube((Layer(1.5), Layer(2.0, shear_modulus=neighbour)), length=1.0)
    try:
        limit = ray_limit(tube, 0, 1, "stretch", side="compression", faces="interface-1")
    except ElectrogrowthError:
        return math.nan
    return limit.value**-1.5 if limit.kind == Kind.SURFACE else math.inf
