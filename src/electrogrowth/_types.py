"""Named array roles shared by the stages (type hints only)."""

import numpy as np
import numpy.typing as npt

#: A real array (profiles, grids, vectors).
FloatArray = npt.NDArray[np.float64]
