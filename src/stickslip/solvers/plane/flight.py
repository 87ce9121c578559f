"""Flight: a block lifted off the surface where the normal force n = g + a_v is not positive, in closed form.

Where n ≤ 0 the block lifts off the surface: no friction, no restoring force,
v̇ = −a, and it lands where n rises past 0, with its velocity
(:func:`~stickslip.solvers.plane.interval.advance_interval` finds where n
crosses zero in a sample interval).
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers.plane.resistance import CURVATURE
from stickslip.solvers.plane.state import A1, A2, GRAVITY, K1, K2, TAU, U1, U2, V1, V2, VERTICAL


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def fly(y, segment, law, end, totals):
    """Advance a block off the surface (n ≤ 0: v̇ = −a) from y[TAU] to ``end`` [s], in closed form.

    No force acts on it: its absolute velocity u̇_g + v is constant, so E_I,
    E_df and the path do not change, and W_v (N = 0: −κ·(0 − g)·u·v) takes
    the change of E_p = ½·g·κ·|u|².  The largest |u| on the way
    (|u|² is a polynomial) goes into totals[2].
    """
    start = y[TAU]
    span = end - start
    if span <= 0.0:
        return
    ax = segment[A1] + segment[K1] * start
    ay = segment[A2] + segment[K2] * start
    kx = segment[K1]
    ky = segment[K2]
    u1, u2, v1, v2 = y[U1], y[U2], y[V1], y[V2]

    def position(t):
        return (u1 + t * (v1 - t * (0.5 * ax + kx * t / 6.0)), u2 + t * (v2 - t * (0.5 * ay + ky * t / 6.0)),
                v1 - t * (ax + 0.5 * kx * t), v2 - t * (ay + 0.5 * ky * t))

    pieces = 16
    previous = 0.0
    x1, x2, w1, w2 = position(0.0)
    before = x1 * w1 + x2 * w2
    for piece in range(1, pieces + 1):
        t = span * piece / pieces
        x1, x2, w1, w2 = position(t)
        after = x1 * w1 + x2 * w2
        totals[2] = max(totals[2], math.sqrt(x1 * x1 + x2 * x2))
        if before > 0.0 >= after:  # |u| has a maximum inside the piece
            low = previous
            high = t
            for _ in range(60):
                middle = 0.5 * (low + high)
                z1, z2, q1, q2 = position(middle)
                if z1 * q1 + z2 * q2 > 0.0:
                    low = middle
                else:
                    high = middle
            z1, z2, q1, q2 = position(0.5 * (low + high))
            totals[2] = max(totals[2], math.sqrt(z1 * z1 + z2 * z2))
        before = after
        previous = t
    y[VERTICAL] -= 0.5 * segment[GRAVITY] * law[CURVATURE] * (u1 * u1 + u2 * u2)
    y[U1], y[U2], y[V1], y[V2] = position(span)
    y[VERTICAL] += 0.5 * segment[GRAVITY] * law[CURVATURE] * (y[U1] * y[U1] + y[U2] * y[U2])
    y[TAU] = end
    totals[3] += span
