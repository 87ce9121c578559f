"""The Dormand–Prince 8(5,3) tableau (DOP853), SciPy's, as contiguous arrays for numba kernels.

12 stages; the 13th (the first of the next step) enters the error estimate.
The kernels that integrate a slip to a tolerance take it from here: the
planar block's (:mod:`stickslip.models.planar.kernel`) and the pendulum's
(:mod:`stickslip.models.pendulum.integrated`).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _dop853

#: Stage coefficients a_ij [1], 12 × 12.
A = np.ascontiguousarray(_dop853.A[:12, :12])
#: Weights b_i of the 8th-order solution [1].
B = np.ascontiguousarray(_dop853.B)
#: Weights of the 3rd- and 5th-order error estimates [1].
E3 = np.ascontiguousarray(_dop853.E3)
E5 = np.ascontiguousarray(_dop853.E5)
