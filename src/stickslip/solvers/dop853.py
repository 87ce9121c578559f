"""The Dormand–Prince 8(5,3) pair (DOP853): SciPy's tableau as contiguous arrays, and its step-size control, for numba.

12 stages; the 13th (the first of the next step) enters the error estimate.
The kernels that integrate a slip to a tolerance take both from here: the
block's in the plane (:mod:`stickslip.solvers.plane`) and the pendulum's
(:mod:`stickslip.models.pendulum.integrated`).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numba
import numpy as np
import scipy


def _scipy_dop853_coefficients():
    """SciPy's module of the Dormand–Prince 8(5,3) coefficients, ``scipy.integrate._ivp.dop853_coefficients``, run
    from its file: imported by name, it would import the whole of :mod:`scipy.integrate` first (half a second of
    the start of ``stickslip solve --pair``).  The file imports numpy only."""
    path = Path(scipy.__file__).parent / "integrate" / "_ivp" / "dop853_coefficients.py"
    spec = importlib.util.spec_from_file_location("scipy.integrate._ivp.dop853_coefficients", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


_dop853 = _scipy_dop853_coefficients()

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
