"""Every plot: the paper's figures 4-10 and their registry, curves, mode shapes, 3D patterns
and phase diagrams.

The only stage that imports matplotlib. It may import every computing stage (model,
basestate, incremental, bifurcation, shapes) and, for phase diagrams, the sweep's data
layout; nothing below it imports it. ``FIGURES`` is the one registry of the paper's
figures: number -> function(*, quick) returning a :class:`~.style.FigureResult` (the first
line of its docstring is its help text). To add a figure, write the function in a module of
this package and add it here. ``GALLERY`` is the registry of the worked examples of layered
tubes (figures/gallery.py, docs/patterns.md): name -> function(*, quick) returning a
:class:`~.gallery.GalleryFigure`.
"""

from collections.abc import Callable

from .base_state import figure4, figure5
from .critical import figure6, figure7, figure8
from .gallery import mucosal_folding, one_layer_growth, pressurised_dielectric
from .gallery_base import GalleryFigure
from .growth import figure9, figure10
from .style import FigureResult

FIGURES: dict[int, Callable[..., FigureResult]] = {
    4: figure4,
    5: figure5,
    6: figure6,
    7: figure7,
    8: figure8,
    9: figure9,
    10: figure10,
}

GALLERY: dict[str, Callable[..., GalleryFigure]] = {
    "mucosal_folding": mucosal_folding,
    "one_layer_growth": one_layer_growth,
    "pressurised_dielectric": pressurised_dielectric,
}
