"""One Dormand–Prince step of a slip in any regime, a step brought onto an event, and the peak of |u| inside a step.

The slip is integrated with the 8th-order Runge–Kutta pair of Dormand and
Prince (DOP853; the coefficients are SciPy's, :mod:`stickslip.solvers.dop853`),
its step chosen for a relative tolerance ``rtol`` on the velocity, with the
right-hand side of the regime (:func:`rhs`: :mod:`~stickslip.solvers.plane.sliding`
fast and slow, :mod:`~stickslip.solvers.plane.settled` on the slow manifold).
The peak of |u| is located inside a step where u·v changes sign, by a root of
the step's cubic Hermite interpolant and one more step to it
(:func:`interior_peak`).
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers.dop853 import A as _A
from stickslip.solvers.dop853 import B as _B
from stickslip.solvers.dop853 import E3 as _E3
from stickslip.solvers.dop853 import E5 as _E5
from stickslip.solvers.plane.resistance import CURVATURE, MU_FAST, MU_SLOW, RATE
from stickslip.solvers.plane.settled import rhs_settled
from stickslip.solvers.plane.sliding import rhs_sliding
from stickslip.solvers.plane.state import (
    A1, A2, G1, G2, GRAVITY, K1, K2, N_DYNAMIC, N_STATE, NORMAL, NORMAL_RATE, SETTLED, SLOW, TAU, U1, U2, V1, V2)

#: Rows of a step's work array: the 13 stage derivatives, the stage state, and (column 0) the lowest speed of a step
#: on the slow manifold over its stages [m/s].
STAGE, LOWEST = 13, 14
WORK_ROWS = 15
#: Newton iterations that bring a step onto an event (the interval's end in the slow regime, a speed in the settled).
_LANDING_ITERATIONS = 12


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def rhs(y, regime, segment, law, phi, out):
    """The slip's right-hand side into ``out``: d y/dt (FAST, SETTLED) or d y/dσ = s·d y/dt (SLOW).

    The ground acceleration is a₀ + k·τ [m/s²], the normal force per unit mass
    n₀ + ν·τ [m/s²] and the ground velocity g₀ + a₀·τ + k·τ²/2 [m/s]
    (``segment``), τ = y[TAU] the time since the interval's start [s].  In the
    SETTLED regime y[V1] is the speed s, y[V2] is not used, and the direction
    is the slow manifold's (:func:`~stickslip.solvers.plane.settled.rhs_settled`).
    """
    if regime == SETTLED:
        rhs_settled(y, segment, law, phi, out.reshape((1, N_STATE)), 0)
    else:
        rhs_sliding(y, regime == SLOW, segment[A1], segment[A2], segment[K1], segment[K2], segment[NORMAL],
                    segment[NORMAL_RATE], segment[G1], segment[G2], segment[GRAVITY], law[CURVATURE], law[MU_SLOW],
                    law[MU_FAST], law[RATE], out.reshape((1, N_STATE)), 0)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def step(y, f0, h, regime, segment, law, phi, rtol, v_scale, dt, work, y_new, f_new):
    """One DOP853 step of size h from (y, f0 = rhs(y)) into y_new, f_new; returns the scaled error norm.

    Only the states that enter the right-hand side (v, τ, u) are formed at the
    inner stages, side by side; the others are quadratures.  The
    error is measured on v (on s in the SETTLED regime; scale
    rtol·(|v| + v_scale), v_scale [m/s]) and, in the SLOW regime, on τ (scale
    rtol·dt); a norm ≤ 1 accepts the step.
    """
    k = work
    for j in range(N_STATE):
        k[0, j] = f0[j]
    stage = work[STAGE]
    for j in range(N_DYNAMIC, N_STATE):
        stage[j] = y[j]
    a1, a2, k1, k2 = segment[A1], segment[A2], segment[K1], segment[K2]
    n0, nu, g1, g2, gravity = segment[NORMAL], segment[NORMAL_RATE], segment[G1], segment[G2], segment[GRAVITY]
    curvature, mu_slow, mu_fast, rate = law[CURVATURE], law[MU_SLOW], law[MU_FAST], law[RATE]
    slow = regime == SLOW
    lowest = y[V1]
    for i in range(1, 12):
        # the five dynamic states side by side: independent sums the processor overlaps
        sum_0 = 0.0
        sum_1 = 0.0
        sum_2 = 0.0
        sum_3 = 0.0
        sum_4 = 0.0
        for m in range(i):
            weight = _A[i, m]
            sum_0 += weight * k[m, 0]
            sum_1 += weight * k[m, 1]
            sum_2 += weight * k[m, 2]
            sum_3 += weight * k[m, 3]
            sum_4 += weight * k[m, 4]
        stage[0] = y[0] + h * sum_0
        lowest = min(lowest, stage[0])
        stage[1] = y[1] + h * sum_1
        stage[2] = y[2] + h * sum_2
        stage[3] = y[3] + h * sum_3
        stage[4] = y[4] + h * sum_4
        if regime == SETTLED:
            rhs_settled(stage, segment, law, phi, k, i)
        else:
            rhs_sliding(stage, slow, a1, a2, k1, k2, n0, nu, g1, g2, gravity, curvature, mu_slow, mu_fast, rate, k,
                        i)
    for j in range(N_STATE):
        y_new[j] = 0.0
    for m in range(12):
        weight = _B[m]
        for j in range(N_STATE):
            y_new[j] += weight * k[m, j]
    for j in range(N_STATE):
        y_new[j] = y[j] + h * y_new[j]
    work[LOWEST, 0] = min(lowest, y_new[V1])  # on the slow manifold, the speed at the stages
    if regime == SETTLED:
        rhs_settled(y_new, segment, law, phi, k, 12)
    else:
        rhs_sliding(y_new, slow, a1, a2, k1, k2, n0, nu, g1, g2, gravity, curvature, mu_slow, mu_fast, rate, k, 12)
    for j in range(N_STATE):
        f_new[j] = k[12, j]
    speed = max(math.sqrt(y[V1] * y[V1] + y[V2] * y[V2]), math.sqrt(y_new[V1] * y_new[V1] + y_new[V2] * y_new[V2]))
    velocity_scale = rtol * (speed + v_scale)
    e5x = 0.0
    e5y = 0.0
    e3x = 0.0
    e3y = 0.0
    e5t = 0.0
    e3t = 0.0
    for m in range(13):
        e5x += _E5[m] * k[m, V1]
        e5y += _E5[m] * k[m, V2]
        e3x += _E3[m] * k[m, V1]
        e3y += _E3[m] * k[m, V2]
        e5t += _E5[m] * k[m, TAU]
        e3t += _E3[m] * k[m, TAU]
    err5 = (e5x * e5x + e5y * e5y) / (velocity_scale * velocity_scale)
    err3 = (e3x * e3x + e3y * e3y) / (velocity_scale * velocity_scale)
    n_checked = 2
    if regime == SLOW:  # and τ
        err5 += (e5t / (rtol * dt)) ** 2
        err3 += (e3t / (rtol * dt)) ** 2
        n_checked = 3
    if err5 == 0.0 and err3 == 0.0:
        return 0.0
    norm = abs(h) * err5 / math.sqrt((err5 + 0.01 * err3) * n_checked)
    # a step far beyond the method's stability overflows, and its estimate with it (inf, or NaN from inf/inf, which
    # no comparison with 1 refuses): such a step is refused as infinitely wrong
    return norm if norm < math.inf else math.inf


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _hermite(p0, d0, p1, d1, h, u):
    """The cubic Hermite interpolant on [0, h] of end values p0, p1 and slopes d0, d1, and its slope, at u."""
    r = u / h
    r2 = r * r
    r3 = r2 * r
    value = (2 * r3 - 3 * r2 + 1) * p0 + (r3 - 2 * r2 + r) * h * d0 + (-2 * r3 + 3 * r2) * p1 + (r3 - r2) * h * d1
    slope = ((6 * r2 - 6 * r) * p0 + (3 * r2 - 4 * r + 1) * h * d0 + (-6 * r2 + 6 * r) * p1
             + (3 * r2 - 2 * r) * h * d1) / h
    return value, slope


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def interior_peak(y, f0, y_new, f_new, h, regime, segment, law, phi, rtol, v_scale, dt, work, y_try, f_try):
    """The largest |u| [m] inside a step whose u·u̇ falls from positive to negative (0 when it does not)."""
    if y[U1] * f0[U1] + y[U2] * f0[U2] <= 0.0 or y_new[U1] * f_new[U1] + y_new[U2] * f_new[U2] >= 0.0:
        return 0.0
    low = 0.0
    high = h
    for _ in range(60):
        middle = 0.5 * (low + high)
        x1, d1 = _hermite(y[U1], f0[U1], y_new[U1], f_new[U1], h, middle)
        x2, d2 = _hermite(y[U2], f0[U2], y_new[U2], f_new[U2], h, middle)
        if x1 * d1 + x2 * d2 > 0.0:
            low = middle
        else:
            high = middle
    step(y, f0, 0.5 * (low + high), regime, segment, law, phi, rtol, v_scale, dt, work, y_try, f_try)
    return math.sqrt(y_try[U1] * y_try[U1] + y_try[U2] * y_try[U2])


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def land(y, f, h, target, component, regime, segment, law, phi, rtol, v_scale, dt, work, y_new, f_new,
         error):
    """Bring a step of size h that passed ``y_new[component]`` = ``target`` onto it, by safeguarded Newton on h.

    The step sizes that fall short and that pass bracket the root; a Newton
    step outside the bracket is replaced by bisection.  Returns (h, error) of
    the last step tried, which y_new, f_new hold; tolerance 1e-13 of the
    target's scale.
    """
    tolerance = 1e-13 * (abs(target) + (dt if component == TAU else v_scale))
    sign = 1.0 if y_new[component] > target else -1.0  # the side the first step passed to
    short = 0.0
    past = h
    for _ in range(_LANDING_ITERATIONS):
        miss = y_new[component] - target
        if abs(miss) <= tolerance or error > 1.0:
            break
        if sign * miss > 0.0:
            past = h
        else:
            short = h
        slope = f_new[component]
        landed = h - miss / slope if slope != 0.0 else -1.0
        h = landed if short < landed < past else 0.5 * (short + past)
        error = step(y, f, h, regime, segment, law, phi, rtol, v_scale, dt, work, y_new, f_new)
    return h, error
