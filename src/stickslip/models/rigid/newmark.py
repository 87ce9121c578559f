"""The paper's Algorithm 1: Newmark average acceleration with a stick/slip flag.

The block of the paper's Eq. 1 (ẍ + ü_g + sgn(ẋ)·μ·g = 0 while sliding,
ẍ = 0 while sticking) is integrated with Newmark's method, γ = 1/2, β = 1/4,
on a uniform grid of step ``time_step`` [s]. The record is linear between its
samples and is interpolated linearly onto that grid, as the paper does
(§5.2.1: Δt = 0.001 s, "linear interpolation was used for in-between record
values").

Ground velocity u̇_g [m/s] and displacement u_g [m] are the exact integrals of
the piecewise-linear acceleration on that grid (trapezoid for u̇_g, the cubic
u_{i+1} = u_i + Δt·u̇_i + Δt²·(2·ü_i + ü_{i+1})/6 for u_g), starting from rest
(:func:`stickslip.records.process.integrate_linear_acceleration`).

Energies per unit mass [J/kg] follow the paper's discrete Eqs. 17–21, with a
right-end rectangle rule over each step:

* ΔE_df = −ü_{i+1}·ẋ_{i+1}·Δt (Eq. 18, the friction force −m·ü times ẋ),
* ΔE_I = ü_{i+1}·u̇_g,i+1·Δt (Eq. 20),
* E_k = ½·u̇² (Eq. 17 with the square that the printed equation drops).

The balance E_k + E_df = E_I therefore holds only to the rectangle rule's
accuracy, O(Δt) — not to round-off as in the ``exact`` solver.

Two readings of the printed algorithm are offered (``reading=``):

``"literal"``
    Algorithm 1 line by line. Each step first updates x by Eq. 12 (predictor
    with sgn(ẋ_i), sgn(0) = 0) and ẋ by Eq. 9. Then

    * stick (U_i = 0): if |ü_g,i+1| − μ·g < a_t the block stays stuck, else it
      breaks away (U_{i+1} = 1); either way ẍ_{i+1} = 0. x_{i+1} and ẋ_{i+1}
      keep the Eq. 12 / Eq. 9 values (the algorithm does not reset them), so
      the block *drifts* relative to the base while "stuck":
      ẋ_{i+1} = ẋ_i − Δt/2·(ü_g,i+1 + sgn(ẋ_i)·μ·g);
    * slip (U_i = 1): if |ẋ_i| > v_t (the velocity at the *start* of the step)
      the block keeps sliding and ẍ_{i+1} follows Eq. 8; otherwise it sticks,
      ẍ_{i+1} = 0;
    * the initial relative acceleration is ẍ_0 = −ü_g,0 (sgn(0) = 0), U_0 = 0.

    Right after a breakaway ẋ is only the stick drift, whose size is set by
    Δt·ü_g/2, so at small Δt it is below v_t and the next step sticks the
    block again: the literal reading does not converge as Δt → 0 (see
    docs/newmark.md for numbers).

``"converging"`` (default)
    The closest reading that converges to the ``exact`` solver:

    * stick: x is held, ẋ = 0, ẍ = 0 (the block moves with the base);
    * breakaway: the paper's test |ü_g| − μ·g ≥ a_t, checked at t_{i+1}; the
      crossing time of |ü_g| = μ·g + a_t is located inside the step (ü_g is
      linear there) and the block slides from it in the direction
      s = −sgn(ü_g,i+1), not sgn(ẋ_i) (which is 0);
    * slip: Eqs. 12, 9 and 8 with sgn(ẋ_i) replaced by the slide direction s;
      the slide ends when ẋ changes sign within the step (not when
      |ẋ_i| ≤ v_t): the stop is located by linear interpolation of ẋ; at the
      stop the block sticks if |ü_g| − μ·g < a_t there, else it reverses and
      slides the rest of the step the other way.

    The velocity tolerance v_t is not used by this reading: a stop test
    |ẋ| ≤ v_t ends each slide early by an amount that does not shrink with Δt.
    The observed convergence of E_df towards ``exact`` is second order
    (docs/newmark.md).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.errors import StickslipError
from stickslip.limits import HISTORY_BYTES_PER_POINT, check_memory
from stickslip.records.process import integrate_linear_acceleration, resample
from stickslip.records.record import Record
from stickslip.models.rigid import RIGID
from stickslip.models.rigid.history import SolverHistory
from stickslip.checks import checked_acceleration, checked_positive
from stickslip.models.rigid.resistance import Resistance

#: The readings of Algorithm 1 that :func:`solve_history` accepts.
READINGS = ("converging", "literal")

#: Default tolerances as fractions of PGA and PGV (the paper's §2.2.2).
ACCELERATION_TOLERANCE_FRACTION = 1e-5
VELOCITY_TOLERANCE_FRACTION = 1e-2


def solve_history(acceleration: np.ndarray, dt: float, mu: float, g: float, **options) -> SolverHistory:
    """:func:`sliding_history` for friction ratio ``mu`` [-] under gravity ``g`` [m/s²]; the same ``options``."""
    return sliding_history(acceleration, dt, Resistance.friction(mu, g), **options)


def sliding_history(
    acceleration: np.ndarray,
    dt: float,
    resistance: Resistance,
    *,
    time_step: float = 0.001,
    reading: str = "converging",
    acceleration_tolerance: float | None = None,
    velocity_tolerance: float | None = None,
) -> SolverHistory:
    """Integrate the block on a moving base with the paper's Algorithm 1.

    Parameters
    ----------
    acceleration:
        Ground acceleration ü_g [m/s²], uniformly sampled, linear between samples.
    dt:
        Sampling step of ``acceleration`` [s].
    resistance:
        A flat surface's friction (:meth:`Resistance.friction`): the block breaks
        away when |ü_g| exceeds μ·g.  Algorithm 1 has no other variant.
    time_step:
        Integration step Δt [s] (the paper: 0.001 s), at most ``dt``; the record is
        interpolated linearly onto t = 0, Δt, 2Δt, … ≤ (npts − 1)·dt
        (:func:`stickslip.records.process.resample`).  A step whose histories
        would exceed :func:`stickslip.limits.memory_limit` is refused.
    reading:
        ``"converging"`` (default) or ``"literal"``, see the module docstring.
    acceleration_tolerance:
        a_t [m/s²]; default 1e-5·PGA.
    velocity_tolerance:
        v_t [m/s]; default 1e-2·PGV, PGV from the ground velocity on the
        integration grid. Used by the literal reading only.

    Returns
    -------
    SolverHistory
        Per unit mass, on the integration grid.
    """
    if reading not in READINGS:
        raise StickslipError(f"newmark: unknown reading {reading!r}; expected one of {', '.join(READINGS)}")
    RIGID.scheme("newmark").check_resistance(resistance)
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    time_step = checked_positive(time_step, "newmark time_step [s]")
    if time_step > dt * (1.0 + 1e-9):
        raise StickslipError(
            f"newmark time_step [s] must not exceed the record's time step: time_step = {time_step:g} s, "
            f"record dt = {dt:g} s (a larger step would skip samples)"
        )
    friction = resistance.negative
    steps = math.floor((acceleration.size - 1) * dt / time_step) + 1
    check_memory(
        steps * HISTORY_BYTES_PER_POINT,
        f"newmark with time_step {time_step:g} s over {(acceleration.size - 1) * dt:g} s ({steps:,} steps)",
    )
    ground_acceleration = resample(Record(acceleration, dt), time_step).acceleration
    time = np.arange(ground_acceleration.size) * time_step
    ground_velocity, ground_displacement = integrate_linear_acceleration(ground_acceleration, time_step)
    if acceleration_tolerance is None:
        acceleration_tolerance = ACCELERATION_TOLERANCE_FRACTION * float(np.max(np.abs(ground_acceleration)))
    if velocity_tolerance is None:
        velocity_tolerance = VELOCITY_TOLERANCE_FRACTION * float(np.max(np.abs(ground_velocity)))
    acceleration_tolerance = _checked_tolerance(acceleration_tolerance, "acceleration_tolerance a_t [m/s2]")
    velocity_tolerance = _checked_tolerance(velocity_tolerance, "velocity_tolerance v_t [m/s]")
    if reading == "literal":
        outputs = _literal_kernel(
            ground_acceleration, ground_velocity, time_step, friction, acceleration_tolerance, velocity_tolerance
        )
    else:
        outputs = _converging_kernel(ground_acceleration, ground_velocity, time_step, friction, acceleration_tolerance)
    return SolverHistory.from_kernel_outputs(time, ground_acceleration, ground_velocity, ground_displacement, outputs)


def _checked_tolerance(value: float, name: str) -> float:
    value = float(value)
    if not (np.isfinite(value) and value >= 0.0):
        raise StickslipError(f"newmark: {name} must be a non-negative finite number, got {value!r}")
    return value


@numba.njit(cache=True)
def _sign(value: float) -> float:
    if value > 0.0:
        return 1.0
    if value < 0.0:
        return -1.0
    return 0.0


@numba.njit(cache=True)
def _zero_histories(n):
    """Zeroed x [m], ẋ [m/s], ẍ [m/s²], phase, E_df/m [J/kg] and E_I/m [J/kg] for ``n`` steps."""
    return np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n, dtype=np.int8), np.zeros(n), np.zeros(n)


@numba.njit(cache=True)
def _literal_kernel(ag, vg, h, friction, a_tol, v_tol):
    """Algorithm 1 as printed; per unit mass. See the module docstring."""
    n = ag.size
    x, xd, xdd, phase, e_df, e_i = _zero_histories(n)
    xdd[0] = -ag[0]
    sliding = False
    path = 0.0
    slip_time = 0.0
    episodes = 0
    for i in range(n - 1):
        s = _sign(xd[i])
        x[i + 1] = x[i] + h * xd[i] + 0.25 * h * h * (xdd[i] - ag[i + 1] - s * friction)  # Eq. 12
        xd[i + 1] = 2.0 / h * (x[i + 1] - x[i]) - xd[i]  # Eq. 9
        if not sliding:
            sliding_next = abs(ag[i + 1]) - friction >= a_tol
            xdd[i + 1] = 0.0
        elif abs(xd[i]) > v_tol:
            sliding_next = True
            xdd[i + 1] = 4.0 / (h * h) * (x[i + 1] - x[i]) - 4.0 / h * xd[i] - xdd[i]  # Eq. 8
        else:
            sliding_next = False
            xdd[i + 1] = 0.0
        if sliding_next and not sliding:
            episodes += 1
        sliding = sliding_next
        if sliding:
            phase[i + 1] = np.int8(_sign(xd[i + 1]))
            slip_time += h
        path += abs(x[i + 1] - x[i])
        absolute_acceleration = ag[i + 1] + xdd[i + 1]
        e_df[i + 1] = e_df[i] - absolute_acceleration * xd[i + 1] * h  # Eqs. 18-19
        e_i[i + 1] = e_i[i] + absolute_acceleration * vg[i + 1] * h  # Eqs. 20-21
    return x, xd, xdd, phase, e_df, e_i, path, slip_time, episodes


@numba.njit(cache=True)
def _newmark_slide(x0, v0, a0, a1, tau):
    """One Newmark (γ = 1/2, β = 1/4) step of length tau [s]: Eqs. 12 and 9 with Eq. 8's a1."""
    x1 = x0 + tau * v0 + 0.25 * tau * tau * (a0 + a1)
    v1 = v0 + 0.5 * tau * (a0 + a1)
    return x1, v1


@numba.njit(cache=True)
def _converging_kernel(ag, vg, h, friction, a_tol):
    """Algorithm 1 with its gaps filled so that it converges to ``exact``; see the module docstring.

    Each step is split at the events inside it (breakaway, stop, reversal);
    every sliding segment is one Newmark step of its own length.
    """
    n = ag.size
    x, xd, xdd, phase, e_df, e_i = _zero_histories(n)
    threshold = friction + a_tol
    direction = 0.0  # 0: stuck; +1 / -1: sliding with ẋ > 0 / ẋ < 0
    path = 0.0
    slip_time = 0.0
    episodes = 0
    for i in range(n - 1):
        jerk_step = ag[i + 1] - ag[i]  # ü_g(t_i + f·Δt) = ag[i] + f·jerk_step
        fraction = 0.0  # how far into the step the current segment starts
        x0, v0, a0 = x[i], xd[i], xdd[i]
        x1, v1, a1 = x0, 0.0, 0.0
        while True:
            if direction == 0.0:
                x1, v1, a1 = x0, 0.0, 0.0
                if abs(ag[i + 1]) < threshold:
                    break  # stuck to the end of the step
                # Breakaway where |ü_g| reaches μg + a_t (the paper's test), located on the linear ü_g.
                direction = -_sign(ag[i + 1])
                ag_start = ag[i] + fraction * jerk_step
                if abs(ag_start) < threshold:
                    fraction = (-direction * threshold - ag[i]) / jerk_step
                    ag_start = -direction * threshold
                x0, v0, a0 = x1, 0.0, -(ag_start + direction * friction)
                episodes += 1
            tau = (1.0 - fraction) * h
            a1 = -(ag[i + 1] + direction * friction)  # Eq. 8 = Eq. 11 solved for ẍ
            x1, v1 = _newmark_slide(x0, v0, a0, a1, tau)
            if v1 * direction > 0.0:
                path += abs(x1 - x0)
                slip_time += tau
                break
            if v0 == 0.0:
                # A slide that cannot start (its average acceleration opposes it): stick.
                direction = 0.0
                x1, v1, a1 = x0, 0.0, 0.0
                break
            # ẋ changes sign inside the segment: stop where the linear ẋ crosses zero.
            stop = v0 / (v0 - v1)
            x_stop = x0 + 0.5 * stop * tau * v0
            path += abs(x_stop - x0)
            slip_time += stop * tau
            fraction += stop * (1.0 - fraction)
            ag_stop = ag[i] + fraction * jerk_step
            if abs(ag_stop) < threshold:
                direction = 0.0
                x0, v0, a0 = x_stop, 0.0, 0.0
            else:  # reversal without sticking
                direction = -direction
                x0, v0, a0 = x_stop, 0.0, -(ag_stop + direction * friction)
        x[i + 1] = x1
        xd[i + 1] = v1
        xdd[i + 1] = a1
        phase[i + 1] = np.int8(direction)
        absolute_acceleration = ag[i + 1] + a1
        e_df[i + 1] = e_df[i] - absolute_acceleration * v1 * h  # Eqs. 18-19
        e_i[i + 1] = e_i[i] + absolute_acceleration * vg[i + 1] * h  # Eqs. 20-21
    return x, xd, xdd, phase, e_df, e_i, path, slip_time, episodes
