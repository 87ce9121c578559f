"""The Dormand–Prince 8(5,3) pair (DOP853): SciPy's tableau as contiguous arrays, and its step-size control, for numba.

12 stages; the 13th (the first of the next step) enters the error estimate.
The kernels that integrate a slip to a tolerance take both from here: the
planar block's (:mod:`stickslip.models.planar.kernel`) and the pendulum's
(:mod:`stickslip.models.pendulum.integrated`).
"""

from __future__ import annotations

import numba
import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _dop853

#: Stage coefficients a_ij [1], 12 × 12.
A = np.ascontiguousarray(_dop853.A[:12, :12])
#: Weights b_i of the 8th-order solution [1].
B = np.ascontiguousarray(_dop853.B)
#: Weights of the 3rd- and 5th-order error estimates [1].
E3 = np.ascontiguousarray(_dop853.E3)
E5 = np.ascontiguousarray(_dop853.E5)


@numba.njit(cache=True)
def next_step(h, error):
    """The step after one of size h [s] with scaled error ``error`` [1] (factor 0.2 to 10, safety 0.9)."""
    if error == 0.0:
        return 10.0 * h
    return h * min(10.0, max(0.2, 0.9 * error ** (-1.0 / 8.0)))
