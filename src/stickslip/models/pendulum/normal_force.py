"""The normal force on a slider under the vertical ground motion, and the intervals where it lifts off.

Per unit mass, with the vertical ground acceleration a_v(t) [m/s²] positive
up and linear between samples, the surface pushes the slider with

    N/m = g + a_v(t)   [m/s²],

linear between samples too.  This neglects the slider's own vertical
acceleration relative to the ground (on a concave surface of radius R, the
second derivative of its rise h = u²/(2R), (u̇² + u·ü)/R, of which u̇²/R is the
centripetal part): the standard design model of the friction pendulum.
Where g + a_v ≤ 0 the surface would have to pull on the slider: it lifts off,
with neither friction nor the surface's restoring force, and touches down
again where g + a_v turns positive.  Its own flight (its vertical motion
after lift-off, which would land it later than that) is not followed.
"""

from __future__ import annotations

import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.errors import StickslipError


def normal_acceleration(vertical, samples: int, g: float) -> np.ndarray:
    """N/m = g + a_v [m/s²] at the samples, from the vertical ground acceleration ``vertical`` [m/s², positive up].

    ``vertical`` ``None`` is no vertical motion (N/m = g).  It must be a finite
    1-D array of ``samples`` values, as many as the horizontal record's.
    """
    g = checked_positive(g, "gravity g [m/s2]")
    if vertical is None:
        return np.full(samples, g)
    vertical = checked_acceleration(vertical, "vertical acceleration")
    if vertical.size != samples:
        raise StickslipError(f"vertical acceleration: {vertical.size} samples, but the horizontal record has "
                             f"{samples}; give records of the same length (or pad the shorter)")
    return g + vertical


def liftoff_intervals(vertical, dt: float, g: float) -> np.ndarray:
    """The intervals of lift-off, where g + a_v(t) ≤ 0: shape (k, 2), start and end times [s].

    ``vertical`` [m/s², positive up] is linear between samples spaced ``dt``
    [s], so each interval's ends are linear crossings of −g (or the record's
    ends).  Intervals are maximal and of positive length: a sample that only
    touches −g is no lift-off.
    """
    dt = checked_positive(dt, "time step dt [s]")
    normal = normal_acceleration(vertical, np.size(vertical), g)
    off = normal <= 0.0
    intervals = []
    start = 0.0 if off[0] else None
    for i in range(normal.size - 1):
        n0, n1 = normal[i], normal[i + 1]
        if start is None and n1 <= 0.0 < n0:  # lifts off inside the interval, or touches −g at its end
            start = (i + n0 / (n0 - n1)) * dt
        elif start is not None and n0 <= 0.0 < n1:  # touches down inside the interval
            end = (i + n0 / (n0 - n1)) * dt
            if end > start:
                intervals.append((start, end))
            start = None
    if start is not None and (normal.size - 1) * dt > start:
        intervals.append((start, (normal.size - 1) * dt))
    return np.array(intervals, dtype=float).reshape(-1, 2)
