"""Closed forms over one sample interval, where the ground acceleration is linear in time.

The first stop of a slip whose velocity is a quadratic in time, and the input
energy of a block stuck to the ground.  Plain Python written for numba's
nopython mode, importing nothing of numba: each solver compiles them beside its
own kernels (:mod:`stickslip.models.rigid.events` runs them as plain Python for
short records too; :mod:`stickslip.solvers.plane` compiles them for the block in
the plane).
"""

from __future__ import annotations

import math


def first_stop_time(c0, c1, c2):
    """Smallest τ > 0 with c0 + c1·τ + c2·τ² = 0, or +inf if there is none.

    The polynomial is s·ẋ(τ) (speed in the sliding direction [m/s]) with
    c0 = s·ẋ(0) ≥ 0 [m/s], c1 [m/s²], c2 [m/s³].  A root at τ = 0 (c0 = 0, the
    start of a slip) does not count.  Roots are computed as q/c2 and c0/q with
    q = −(c1 + sgn(c1)·√disc)/2, which avoids cancellation.
    """
    if c2 == 0.0:
        if c1 < 0.0:
            return -c0 / c1
        return math.inf
    disc = c1 * c1 - 4.0 * c2 * c0
    if disc < 0.0:
        return math.inf
    q = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
    if q == 0.0:
        return math.inf
    root = math.inf
    near = q / c2
    if near > 0.0:
        root = near
    far = c0 / q
    if 0.0 < far < root:
        root = far
    return root


def stick_input_energy(a, slope, vg, tau):
    """∫₀^τ a(σ)·u̇_g(σ) dσ [J/kg] for a(σ) = a + slope·σ [m/s²], u̇_g(σ) = vg + a·σ + slope·σ²/2 [m/s]."""
    return tau * (a * vg + tau * (0.5 * (a * a + slope * vg) + tau * (0.5 * a * slope + 0.125 * slope * slope * tau)))
