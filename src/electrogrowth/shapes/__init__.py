"""What the wrinkle looks like: the mode shape through the wall by either method
(:mod:`.mode_shape`), the 3D wall geometry and its VTK export (:mod:`.wall`). Data only;
drawing is in ``figures``.

May import ``bifurcation``, ``incremental``, ``basestate``, ``model`` and ``errors``.
"""

from .mode_shape import ModeShape, mode_shape
from .wall import export_vtk, wall_mesh, wall_surface

__all__ = ["ModeShape", "mode_shape", "export_vtk", "wall_mesh", "wall_surface"]
