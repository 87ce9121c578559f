"""A block held by friction in the plane: when it breaks away, and whole intervals and blocks of samples proven stuck.

A block held at u sticks while the force needed to hold it, |b| with
b = a + κ·n·u (:func:`~stickslip.solvers.plane.resistance.driving`), stays
within μ(0)·n, and breaks away along −b/|b| where |b| rises past it.  With a
and n linear in a sample interval, |b|² − (μ(0)·n)² is a quadratic in time
(:func:`hold_quadratic`), whose first up-crossing is the breakaway.  A stick
costs almost nothing: μ-independent prefix sums of the stick's input energy
and, per block of :data:`BLOCK` samples, the bounds of a and n prove whole
blocks stuck (:func:`prepare_record`, :func:`block_sticks`), as the 1-D kernel
does.
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers import closed_forms
from stickslip.solvers.plane.resistance import CURVATURE, MU_SLOW, driving
from stickslip.solvers.plane.state import NORMAL, NORMAL_RATE

#: Samples per block whose bounds on a and n let a stick skip ahead.
BLOCK = 32
#: Columns of a record's block bounds: max |a|² [m²/s⁴], min and max of a₁ and a₂ [m/s²], min and max of n [m/s²].
AMAX2, A1MIN, A1MAX, A2MIN, A2MAX, NMIN, NMAX = range(7)

#: ∫a·u̇_g dt [J/kg] of a block stuck over part of an interval
#: (:func:`stickslip.solvers.closed_forms.stick_input_energy`).
stick_input_energy = numba.njit(cache=True)(closed_forms.stick_input_energy)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def hold_quadratic(segment, law, u1, u2, tau):
    """The coefficients (c₀, c₁, c₂) of |b|² − (μ(0)·n)² [m²/s⁴] in τ' = τ − ``tau`` for a block held at u [m].

    b = a + κ·n·u and n are linear in time, so the excess of the force needed
    to hold the block over the friction limit is a quadratic; it is convex
    without the vertical motion.
    """
    bx, by, rx, ry, normal = driving(segment, law, tau, u1, u2)
    hold = law[MU_SLOW] * normal
    hold_rate = law[MU_SLOW] * segment[NORMAL_RATE]
    return (bx * bx + by * by - hold * hold, 2.0 * (bx * rx + by * ry - hold * hold_rate),
            rx * rx + ry * ry - hold_rate * hold_rate)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def breakaway_time(segment, law, u1, u2, tau, stalled):
    """The first τ' ≥ 0 after τ at which the block held at u breaks away (|b| exceeds μ(0)·n), or +inf.

    The excess q(τ') = c₀ + c₁·τ' + c₂·τ'² (:func:`hold_quadratic`) is at
    most 0 now; its first up-crossing is the root −2c₀/(c₁ + √disc) where it
    rises now (c₁ ≥ 0), the larger root where it falls but is convex, and none
    where it falls and is concave.  ``stalled``: the block was just found not
    to slide at τ although q is not below 0 (to round-off, not rising); then
    the next crossing after τ is sought.
    """
    c0, c1, c2 = hold_quadratic(segment, law, u1, u2, tau)
    if stalled:
        c0 = min(c0, 0.0)
    elif c0 > 0.0:
        return 0.0
    disc = c1 * c1 - 4.0 * c2 * c0
    if c1 >= 0.0:
        if disc < 0.0:
            return math.inf
        denominator = c1 + math.sqrt(disc)
        if denominator > 0.0:
            return -2.0 * c0 / denominator
        return 0.0 if c2 > 0.0 else math.inf
    if c2 <= 0.0:
        return math.inf
    return (-c1 + math.sqrt(max(disc, 0.0))) / (2.0 * c2)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def interval_sticks(segment, law, u1, u2, dt):
    """Whether a block held at u [m] stays stuck over the whole interval [0, dt] [s] (n > 0, |b| ≤ μ(0)·n)."""
    if segment[NORMAL] <= 0.0 or segment[NORMAL] + segment[NORMAL_RATE] * dt <= 0.0:
        return False
    c0, c1, c2 = hold_quadratic(segment, law, u1, u2, 0.0)
    if c0 > 0.0 or c0 + dt * (c1 + dt * c2) > 0.0:
        return False
    if c2 < 0.0:
        vertex = -c1 / (2.0 * c2)
        if 0.0 < vertex < dt and c0 + vertex * (c1 + vertex * c2) > 0.0:
            return False
    return True


@numba.njit(cache=True, error_model="numpy")
def prepare_record(first, second, normal, gravity, dt, velocity, stick_energy, bounds):
    """Fill one record's friction-independent arrays.

    ``velocity`` (n, 2) [m/s]: the ground velocity at the samples (trapezoid
    sums, exact for a linear between samples); ``stick_energy`` [J/kg]: prefix
    sums of the input energy of a block that sticks over whole intervals;
    ``bounds`` (blocks, 7): per :data:`BLOCK` samples (and the next block's
    first), max |a|², min and max of a₁, a₂ and of n [m/s², m²/s⁴].  ``normal``
    is n = g + a_v at the samples, or empty for n = ``gravity`` throughout.
    """
    n = first.size
    velocity[0, 0] = 0.0
    velocity[0, 1] = 0.0
    stick_energy[0] = 0.0
    for i in range(n - 1):
        slope_1 = (first[i + 1] - first[i]) / dt
        slope_2 = (second[i + 1] - second[i]) / dt
        stick_energy[i + 1] = (stick_energy[i] + stick_input_energy(first[i], slope_1, velocity[i, 0], dt)
                               + stick_input_energy(second[i], slope_2, velocity[i, 1], dt))
        velocity[i + 1, 0] = velocity[i, 0] + 0.5 * dt * (first[i] + first[i + 1])
        velocity[i + 1, 1] = velocity[i, 1] + 0.5 * dt * (second[i] + second[i + 1])
    for block in range(bounds.shape[0]):
        low = block * BLOCK
        high = min(low + BLOCK, n - 1)
        bounds[block, AMAX2] = 0.0
        bounds[block, A1MIN] = first[low]
        bounds[block, A1MAX] = first[low]
        bounds[block, A2MIN] = second[low]
        bounds[block, A2MAX] = second[low]
        level = normal[low] if normal.size > 0 else gravity
        bounds[block, NMIN] = level
        bounds[block, NMAX] = level
        for k in range(low, high + 1):
            bounds[block, AMAX2] = max(bounds[block, AMAX2], first[k] * first[k] + second[k] * second[k])
            bounds[block, A1MIN] = min(bounds[block, A1MIN], first[k])
            bounds[block, A1MAX] = max(bounds[block, A1MAX], first[k])
            bounds[block, A2MIN] = min(bounds[block, A2MIN], second[k])
            bounds[block, A2MAX] = max(bounds[block, A2MAX], second[k])
            if normal.size > 0:
                bounds[block, NMIN] = min(bounds[block, NMIN], normal[k])
                bounds[block, NMAX] = max(bounds[block, NMAX], normal[k])


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def n_blocks(samples):
    """The number of blocks of :data:`BLOCK` sample intervals in a record of ``samples`` samples."""
    return max(1, (samples - 2) // BLOCK + 1)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def block_sticks(bounds, block, law, u1, u2):
    """Whether a block held at u [m] certainly sticks over the block of samples ``block`` of ``bounds``.

    |b| = |a + κ·n·u| is convex in (a, n), so its largest value over the
    samples' bounding box in a and range of n is at a corner; it must stay
    within μ(0)·min n, with min n > 0.
    """
    lowest = bounds[block, NMIN]
    if lowest <= 0.0:
        return False
    limit = law[MU_SLOW] * lowest
    limit2 = limit * limit
    curvature = law[CURVATURE]
    if curvature == 0.0 or (u1 == 0.0 and u2 == 0.0):
        return bounds[block, AMAX2] <= limit2
    for corner in range(8):
        a1 = bounds[block, A1MAX] if corner & 1 else bounds[block, A1MIN]
        a2 = bounds[block, A2MAX] if corner & 2 else bounds[block, A2MIN]
        level = bounds[block, NMAX] if corner & 4 else bounds[block, NMIN]
        b1 = a1 + curvature * level * u1
        b2 = a2 + curvature * level * u2
        if b1 * b1 + b2 * b2 > limit2:
            return False
    return True


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def stuck_peak(first, second, bounds, low, high):
    """max |a| [m/s²] over the samples ``low`` to ``high`` (a stretch of whole blocks after ``low``'s own block).

    The samples of ``low``'s block from ``low`` on one by one, the whole blocks after it from their bounds.
    """
    boundary = min((low // BLOCK + 1) * BLOCK, high)
    largest2 = 0.0
    for k in range(low, boundary + 1):
        largest2 = max(largest2, first[k] * first[k] + second[k] * second[k])
    for block in range(boundary // BLOCK, (high - 1) // BLOCK + 1):
        if block * BLOCK >= boundary and block * BLOCK < high:
            largest2 = max(largest2, bounds[block, AMAX2])
    return math.sqrt(largest2)
