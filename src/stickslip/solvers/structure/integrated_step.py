"""The friction-linked structure's right-hand side in each regime and one DOP853 step of it: numba kernels.

The state ``y`` of a structure of n degrees of freedom per direction (indices
from :func:`layout`): x (n × 2, row-major) [m], the held velocity h (n × 2)
[m/s], the slip velocity w (2) [m/s] (on the slow manifold, SETTLED, w[0] is
the speed and w[1] is not used; in its last straight stretch, STOPPING, w[0] is
the speed along ``segment``'s aim), τ [s] from the sample interval's start, and
the quadratures E_ζ, E_df, E_I, W_v [J] and the sliding path [m].  The
equations are :mod:`~stickslip.solvers.structure.interface`'s; the regimes
:mod:`~stickslip.solvers.structure.integrated`'s.

``segment`` (:data:`SEGMENT_SIZE` floats) holds one sample interval: a (2)
[m/s²], its slope (2) [m/s³], N [N] and its slope [N/s], the ground velocity
(2) [m/s] at the start, and the unit vector a straight stop holds.  ``law`` (:data:`LAW_SIZE` floats): μ_slow, μ_fast,
rate [s/m], 1/R [1/m], μ̃ [1/kg], dᵀι [1], N₀ [N].  ``vectors`` (6 × n): the
masses [kg], g = M⁻¹d, d, ι, dᵀM⁻¹C, dᵀM⁻¹K; ``matrices`` (4 × n × n): M⁻¹C,
M⁻¹K, C, K.

numba renews a kernel's cache when the kernel's own file changes, not when a
module it calls does (the friction law of
:mod:`stickslip.solvers.plane.resistance`): after editing that one, delete
this module's cached kernels and those of
:mod:`~stickslip.solvers.structure.integrated_events` (``*.nbi``, ``*.nbc`` in its ``__pycache__``).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.solvers.dop853 import A as _A
from stickslip.solvers.dop853 import B as _B
from stickslip.solvers.dop853 import E3 as _E3
from stickslip.solvers.dop853 import E5 as _E5
from stickslip.solvers.plane.resistance import friction_coefficient

#: What the interface does (and the regime of a step's right-hand side): holds, slides off the slow manifold
#: (FAST in time, SLOW in the Sundman variable σ, dt = s·dσ), slides on it, flies (N ≤ 0), or slides the last
#: of a slip in a straight line to its stop.
STICK, FAST, SLOW, SETTLED, FLIGHT, STOPPING = range(6)
#: ``segment``: a₁, a₂ [m/s²], their slopes [m/s³], N [N], its slope [N/s], the ground velocity [m/s], the
#: direction of a straight stop (STOPPING) [1].
A1, A2, K1, K2, NORMAL, NORMAL_RATE, G1, G2, AIM1, AIM2 = range(10)
SEGMENT_SIZE = 10
#: ``law``: μ_slow, μ_fast, rate [s/m], 1/R [1/m], μ̃ [1/kg], dᵀι, N₀ [N].
MU_SLOW, MU_FAST, RATE, CURVATURE, MOBILITY, GROUND_SHARE, STATIC_NORMAL = range(7)
LAW_SIZE = 7
#: ``vectors`` rows and ``matrices`` layers.
MASSES, SLIP_MODE, DIRECTION, INFLUENCE, DAMPING_ROW, STIFFNESS_ROW = range(6)
MASS_DAMPING, MASS_STIFFNESS, DAMPING, STIFFNESS = range(4)
#: The quadratures after τ, in order.
VISCOUS, DISSIPATED, INPUT, VERTICAL, PATH = range(1, 6)


@numba.njit(cache=True)
def layout(n):
    """(start of h, start of w, index of τ, state size) for n degrees of freedom per direction."""
    return 2 * n, 4 * n, 4 * n + 2, 4 * n + 8


@numba.njit(cache=True, error_model="numpy")
def driving(y, segment, law, vectors, n, normal):
    """β [m/s²] (a pair): the interface's driving acceleration at y with the normal force ``normal`` [N]."""
    return (_driving_along(y, segment, law, vectors, n, normal, 0),
            _driving_along(y, segment, law, vectors, n, normal, 1))


@numba.njit(cache=True, error_model="numpy")
def _driving_along(y, segment, law, vectors, n, normal, k):
    """β's component k [m/s²] at y with the normal force ``normal`` [N]."""
    held, _, tau_index, _ = layout(n)
    tau = y[tau_index]
    stiffness = law[MOBILITY] * normal * law[CURVATURE]
    total = law[GROUND_SHARE] * (segment[A1 + k] + segment[K1 + k] * tau)
    for i in range(n):
        x = y[2 * i + k]
        total += (vectors[DAMPING_ROW, i] * y[held + 2 * i + k] + vectors[STIFFNESS_ROW, i] * x
                  + stiffness * vectors[DIRECTION, i] * x)
    return total


@numba.njit(cache=True, error_model="numpy")
def evaluate(y, regime, segment, law, vectors, matrices, n, f, absolute, friction, slip_velocity):
    """dy/dt (dy/dσ in SLOW) into ``f``; ẍ_abs (n × 2) [m/s²], F (2) [N] and w (2) [m/s] into the others.

    STICK: w = 0 and F the force that holds the interface, −β/μ̃; SETTLED: w = s·(−β/|β|); STOPPING:
    w = s·(the segment's aim); FLIGHT: N = 0, F = 0.
    """
    held, slip, tau_index, size = layout(n)
    tau = y[tau_index]
    normal = 0.0 if regime == FLIGHT else max(segment[NORMAL] + segment[NORMAL_RATE] * tau, 0.0)
    mobility = law[MOBILITY]
    beta = driving(y, segment, law, vectors, n, normal) if regime == STICK or regime == SETTLED else (0.0, 0.0)
    speed = 0.0
    aim = (0.0, 0.0)
    if regime == STICK:
        slip_velocity[0] = 0.0
        slip_velocity[1] = 0.0
        friction[0] = -beta[0] / mobility
        friction[1] = -beta[1] / mobility
    elif regime == SETTLED or regime == STOPPING:
        speed = y[slip]
        if regime == STOPPING:
            aim = (segment[AIM1], segment[AIM2])
        else:
            size_beta = math.sqrt(beta[0] * beta[0] + beta[1] * beta[1])
            aim = (-beta[0] / size_beta, -beta[1] / size_beta) if size_beta > 0.0 else (0.0, 0.0)
        coefficient = friction_coefficient(speed, law[MU_SLOW], law[MU_FAST], law[RATE]) * normal
        for k in range(2):
            slip_velocity[k] = speed * aim[k]
            friction[k] = coefficient * aim[k]
    else:
        slip_velocity[0] = y[slip]
        slip_velocity[1] = y[slip + 1]
        speed = math.sqrt(slip_velocity[0] ** 2 + slip_velocity[1] ** 2)
        if regime == FLIGHT or speed == 0.0:
            friction[0] = 0.0
            friction[1] = 0.0
        else:
            coefficient = friction_coefficient(speed, law[MU_SLOW], law[MU_FAST], law[RATE]) * normal / speed
            friction[0] = coefficient * slip_velocity[0]
            friction[1] = coefficient * slip_velocity[1]
    viscous = 0.0
    input_rate = 0.0
    vertical = 0.0
    for k in range(2):
        ground = segment[A1 + k] + segment[K1 + k] * tau
        ground_velocity = segment[G1 + k] + tau * (segment[A1 + k] + 0.5 * segment[K1 + k] * tau)
        slip_displacement = 0.0
        for i in range(n):
            slip_displacement += vectors[DIRECTION, i] * y[2 * i + k]
        restoring = normal * law[CURVATURE] * slip_displacement
        projected = 0.0
        slip_rate = 0.0
        inertia = 0.0
        for i in range(n):
            free = -restoring * vectors[SLIP_MODE, i] - vectors[INFLUENCE, i] * ground
            damping_force = 0.0
            for j in range(n):
                velocity = y[held + 2 * j + k] + vectors[SLIP_MODE, j] * slip_velocity[k] / mobility
                free -= matrices[MASS_DAMPING, i, j] * velocity + matrices[MASS_STIFFNESS, i, j] * y[2 * j + k]
                damping_force += matrices[DAMPING, i, j] * velocity
            velocity = y[held + 2 * i + k] + vectors[SLIP_MODE, i] * slip_velocity[k] / mobility
            viscous += velocity * damping_force
            f[held + 2 * i + k] = free
            projected += vectors[DIRECTION, i] * free
            acceleration = free - vectors[SLIP_MODE, i] * friction[k]
            slip_rate += vectors[DIRECTION, i] * acceleration
            absolute[i, k] = acceleration + vectors[INFLUENCE, i] * ground
            inertia += vectors[MASSES, i] * absolute[i, k]
            f[2 * i + k] = velocity
        for i in range(n):
            f[held + 2 * i + k] -= vectors[SLIP_MODE, i] * projected / mobility
        input_rate += inertia * ground_velocity
        vertical -= (normal - law[STATIC_NORMAL]) * law[CURVATURE] * slip_displacement * slip_velocity[k]
        f[slip + k] = slip_rate  # the slip's acceleration
    if regime == STICK:
        f[slip] = 0.0
        f[slip + 1] = 0.0
    elif regime == SETTLED or regime == STOPPING:  # the speed's rate: the slip's acceleration along its aim
        f[slip] = f[slip] * aim[0] + f[slip + 1] * aim[1]
        f[slip + 1] = 0.0
    f[tau_index] = 1.0
    f[tau_index + VISCOUS] = viscous
    f[tau_index + DISSIPATED] = friction[0] * slip_velocity[0] + friction[1] * slip_velocity[1]
    f[tau_index + INPUT] = input_rate
    f[tau_index + VERTICAL] = vertical
    f[tau_index + PATH] = speed
    if regime == SLOW:
        for j in range(size):
            f[j] *= speed


@numba.njit(cache=True, error_model="numpy")
def step(y, f0, h, regime, segment, law, vectors, matrices, n, rtol, floor, dt, work, y_new, f_new):
    """One DOP853 step of size h ([s], or σ in SLOW) from (y, f0) into y_new, f_new; returns the scaled error.

    The error is measured on the velocities: h (scale rtol·(the largest |h| + ``floor``) [m/s]) and the slip
    w (scale rtol·(|w| + ``floor``): a slow slip is followed to its stop as the block's is), and, in SLOW, on τ
    (scale rtol·dt); a norm ≤ 1 accepts the step.  ``work`` has 14 rows of the state's size.
    """
    held, slip, tau_index, size = layout(n)
    absolute = np.empty((n, 2))
    friction = np.empty(2)
    slip_velocity = np.empty(2)
    for j in range(size):
        work[0, j] = f0[j]
    stage = work[13]
    for i in range(1, 12):  # each sum over the stages in order, its zero terms left out
        stage[:] = 0.0
        for m in range(i):
            if _A[i, m] != 0.0:
                for j in range(size):
                    stage[j] += _A[i, m] * work[m, j]
        for j in range(size):
            stage[j] = y[j] + h * stage[j]
        evaluate(stage, regime, segment, law, vectors, matrices, n, work[i], absolute, friction, slip_velocity)
    y_new[:] = 0.0
    for m in range(12):
        if _B[m] != 0.0:
            for j in range(size):
                y_new[j] += _B[m] * work[m, j]
    for j in range(size):
        y_new[j] = y[j] + h * y_new[j]
    evaluate(y_new, regime, segment, law, vectors, matrices, n, work[12], absolute, friction, slip_velocity)
    for j in range(size):
        f_new[j] = work[12, j]
    largest = 0.0
    for j in range(held, slip):
        largest = max(largest, abs(y[j]), abs(y_new[j]))
    held_scale = rtol * (largest + floor)
    slip_scale = rtol * (max(math.sqrt(y[slip] ** 2 + y[slip + 1] ** 2),
                             math.sqrt(y_new[slip] ** 2 + y_new[slip + 1] ** 2)) + floor)
    err5 = 0.0
    err3 = 0.0
    count = tau_index - held
    for j in range(held, tau_index):
        e5 = 0.0
        e3 = 0.0
        for m in range(13):
            if _E5[m] != 0.0:
                e5 += _E5[m] * work[m, j]
            if _E3[m] != 0.0:
                e3 += _E3[m] * work[m, j]
        scale = held_scale if j < slip else slip_scale
        err5 += (e5 / scale) ** 2
        err3 += (e3 / scale) ** 2
    if regime == SLOW:
        e5 = 0.0
        e3 = 0.0
        for m in range(13):
            e5 += _E5[m] * work[m, tau_index]
            e3 += _E3[m] * work[m, tau_index]
        err5 += (e5 / (rtol * dt)) ** 2
        err3 += (e3 / (rtol * dt)) ** 2
        count += 1
    if err5 == 0.0 and err3 == 0.0:
        return 0.0
    norm = abs(h) * err5 / math.sqrt((err5 + 0.01 * err3) * count)
    return norm if norm < math.inf else math.inf


@numba.njit(cache=True, error_model="numpy")
def driving_rate(y, f, segment, law, vectors, n):
    """β̇ [m/s³] (a pair) while the interface holds, with f = dy/dt in STICK at y."""
    return (_driving_rate_along(y, f, segment, law, vectors, n, 0),
            _driving_rate_along(y, f, segment, law, vectors, n, 1))


@numba.njit(cache=True, error_model="numpy")
def _driving_rate_along(y, f, segment, law, vectors, n, k):
    """β̇'s component k [m/s³] while the interface holds, with f = dy/dt in STICK at y."""
    held, _, tau_index, _ = layout(n)
    tau = y[tau_index]
    normal = segment[NORMAL] + segment[NORMAL_RATE] * tau
    normal_rate = segment[NORMAL_RATE] if normal > 0.0 else 0.0
    normal = max(normal, 0.0)
    total = law[GROUND_SHARE] * segment[K1 + k]
    for i in range(n):
        total += (vectors[DAMPING_ROW, i] * f[held + 2 * i + k] + vectors[STIFFNESS_ROW, i] * f[2 * i + k]
                  + law[MOBILITY] * law[CURVATURE] * vectors[DIRECTION, i]
                  * (normal_rate * y[2 * i + k] + normal * f[2 * i + k]))
    return total
