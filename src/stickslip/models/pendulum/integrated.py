"""The friction pendulum in one direction with a vertical motion and a velocity-dependent friction, integrated.

Per unit mass, relative to the ground, with the horizontal ground
acceleration a(t), the normal force n(t) = N/m = g + a_v(t)
(:mod:`stickslip.models.pendulum.normal_force`), both linear between samples, the
curvature c = 1/R of the sliding surface (0 for a flat one) and the friction
law μ(v) of :mod:`stickslip.solvers.friction_law`, the slider

* **sticks** (u̇ = 0) while the force that holds it stays within μ(0)·n:
  |a + c·n·u| ≤ μ(0)·n, two conditions linear in time (u is constant), so that
  breakaway is a linear crossing located exactly, along the force;
* **slides** in the direction s = ±1 with

      ü = −a − c·n·u − s·μ(s·u̇)·n,

  the small-angle friction pendulum under a normal force that varies; with
  n or μ varying it has no closed form in general (with n constant and μ
  constant it has: :mod:`stickslip.models.pendulum.exact`);
* **lifts off** where n reaches zero and **touches down** where it turns
  positive: in between ü = −a exactly (no friction, no restoring force),
  a cubic in time, as in :mod:`stickslip.models.pendulum.vertical_exact`.

The slip is integrated by the 8th-order Runge–Kutta pair of Dormand and
Prince (DOP853; the tableau of :mod:`stickslip.solvers.dop853`,
SciPy's), with the error of each step measured on u and u̇ against
``rtol``·(|u| + floor) and ``rtol``·(|u̇| + floor), the floors a thousandth of
the speed scale S = 2·(max|a| + μ_max·max n)·dt and S·dt.  A step never
crosses a sample (a and n have their kinks there) nor a lift-off; a step that
carries s·u̇ through zero is brought onto the stop by Newton's method on its
length, each iterate a whole step from the same start, so the stop is located
and not stepped over (within one sliding direction the right-hand side is
smooth, μ continued analytically past zero).  At the stop the slider sticks
if the holding force is within μ(0)·n, and otherwise slides back.

The ledger per unit mass is integrated as four more states of the same steps,
so that the balance is a check: the path ∫s·u̇ dt, E_I = ∫ü·u̇_g dt (ü = a in
stick, integrated exactly), E_df = ∫μ·n·s·u̇ dt and the vertical motion's work
W_v = −∫c·(n − g)·u·u̇ dt (zero where n = g; in flight n = 0 and it is
½·g·c·(u² − u₀²) over the flight, exactly); with the potential energy
E_p = ½·g·c·u², a state, E_k − E_k(0) + E_p − E_p(0) + E_df = E_I + W_v closes
to the tolerance.  Peaks of |u| are at
stops, samples and, in flight, at u̇ = 0 (located); the peak |ü| is taken at the
step ends, samples and events.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.records.process import integrate_linear_acceleration
from stickslip.solvers.friction_law import FrictionLaw, friction_coefficient, law_columns
from stickslip.models.pendulum.normal_force import normal_acceleration
from stickslip.models.pendulum.surface import surface_curvature
from stickslip.solvers.compilation import engine_pieces, sweep_engine
from stickslip.solvers.events import offsets, run_in_calls
from stickslip.solvers.ledger import FLIGHT, HISTORY_COLUMNS, SCALAR_NAMES, STICK, history_dict, store_scalars
from stickslip.solvers.dop853 import A as _A
from stickslip.solvers.dop853 import B as _B
from stickslip.solvers.dop853 import E3 as _E3
from stickslip.solvers.dop853 import E5 as _E5
from stickslip.solvers.dop853 import next_step
from stickslip.models.pendulum.vertical_exact import flight_peak, liftoff_time

_PIECES = engine_pieces()
ground_at = _PIECES["ground_at"]
stick_input_energy = _PIECES["stick_input_energy"]

#: The state of a slip: u [m], u̇ [m/s], E_I/m, E_df/m, W_v/m [J/kg].
N_STATE = 5
#: The stage times of the tableau, as fractions of the step: the row sums of its matrix.
_C = np.ascontiguousarray(_A.sum(axis=1))
#: Default relative tolerance of u and u̇ per step.
RTOL = 1e-10
#: The error floors of u̇ and u (times dt) as a fraction of the speed scale S = 2·(max|a| + μ_max·max n)·dt.
FLOOR = 1e-3
#: Newton iterations that bring a step onto a stop.
LANDING_ITERATIONS = 16
#: Indices of the parameters of one sample interval in ``p`` (:func:`advance_interval`).
A0, SLOPE, N0, N_SLOPE, VG0, CURVATURE, MU_SLOW, MU_FAST, RATE, GRAVITY = range(10)
#: Indices of ``clock``: the time τ [s] from the interval's start, the path slid [m].
TAU, PATH = 0, 1


@numba.njit(cache=True)
def _rhs(tau, y, s, p, out):
    """d y/dt at τ [s] of a slip in direction s into ``out``; ``p``: the interval's a, n, u̇_g, c, μ(v) and g."""
    a = p[A0] + p[SLOPE] * tau
    n = p[N0] + p[N_SLOPE] * tau
    ground_velocity = p[VG0] + tau * (p[A0] + 0.5 * p[SLOPE] * tau)
    v = y[1]
    mu = friction_coefficient(s * v, p[MU_SLOW], p[MU_FAST], p[RATE])
    restoring = p[CURVATURE] * n * y[0]
    absolute = -restoring - s * mu * n
    out[0] = v
    out[1] = absolute - a
    out[2] = absolute * ground_velocity
    out[3] = mu * n * s * v
    out[4] = -p[CURVATURE] * (n - p[GRAVITY]) * y[0] * v


@numba.njit(cache=True)
def _step(tau, y, f0, h, s, p, rtol, v_floor, x_floor, work, y_new, f_new):
    """One DOP853 step of size h [s] from (τ, y, f0 = rhs(τ, y)) into y_new, f_new; returns the scaled error norm.

    The stages are formed for u and u̇ only: the energies' rates depend on
    them, not on the energies, whose new values are the quadrature
    y + h·Σ b_i·k_i of the same rates, as if they were integrated states.  The error is measured on u (scale rtol·(|u| + x_floor)) and u̇ (scale
    rtol·(|u̇| + v_floor)) as SciPy measures it; a norm ≤ 1 accepts the step.
    """
    k = work
    for j in range(N_STATE):
        k[0, j] = f0[j]
    stage = work[13]
    for i in range(1, 12):
        for j in range(2):  # the energies do not act back on the motion: their stage values are never needed
            acc = 0.0
            for m in range(i):
                acc += _A[i, m] * k[m, j]
            stage[j] = y[j] + h * acc
        _rhs(tau + _C[i] * h, stage, s, p, k[i])
    for j in range(N_STATE):
        acc = 0.0
        for m in range(12):
            acc += _B[m] * k[m, j]
        y_new[j] = y[j] + h * acc
    _rhs(tau + h, y_new, s, p, f_new)
    for j in range(N_STATE):
        k[12, j] = f_new[j]
    err5 = 0.0
    err3 = 0.0
    for j in range(2):
        e5 = 0.0
        e3 = 0.0
        for m in range(13):
            e5 += _E5[m] * k[m, j]
            e3 += _E3[m] * k[m, j]
        scale = rtol * (max(abs(y[j]), abs(y_new[j])) + (x_floor if j == 0 else v_floor))
        err5 += (e5 / scale) ** 2
        err3 += (e3 / scale) ** 2
    if err5 == 0.0 and err3 == 0.0:
        return 0.0
    return abs(h) * err5 / math.sqrt((err5 + 0.01 * err3) * 2.0)


@numba.njit(cache=True)
def _interior_stop(q0, q1, r0, r1, h):
    """The first τ [s] inside a step of size h where the cubic Hermite interpolant of q = s·u̇ reaches zero, or −1.

    q0 ≥ 0 and q1 > 0 [m/s] are s·u̇ at the step's ends and r0, r1 [m/s²]
    their rates s·ü: a speed that dips through zero and back inside one step
    (a stop, then a slip that resumes) leaves both ends positive.  Only a
    minimum of the interpolant inside the step, below zero, counts.
    """
    c1 = h * r0
    c2 = -3.0 * q0 - 2.0 * h * r0 + 3.0 * q1 - h * r1
    c3 = 2.0 * q0 + h * r0 - 2.0 * q1 + h * r1
    # H'(θ) = c1 + 2c2·θ + 3c3·θ²: its roots in (0, 1) where H'' = 2c2 + 6c3·θ > 0
    lowest = 2.0
    if c3 == 0.0:
        if c2 > 0.0:
            lowest = -c1 / (2.0 * c2)
    else:
        disc = c2 * c2 - 3.0 * c3 * c1
        if disc >= 0.0:
            root = math.sqrt(disc)
            for theta in ((-c2 + root) / (3.0 * c3), (-c2 - root) / (3.0 * c3)):
                if 2.0 * c2 + 6.0 * c3 * theta > 0.0:
                    lowest = theta
    if not 1e-9 < lowest < 1.0:
        return -1.0
    if q0 + lowest * (c1 + lowest * (c2 + lowest * c3)) >= 0.0:
        return -1.0
    low, high = 0.0, lowest
    for _ in range(60):
        middle = 0.5 * (low + high)
        if q0 + middle * (c1 + middle * (c2 + middle * c3)) > 0.0:
            low = middle
        else:
            high = middle
    return high * h


@numba.njit(cache=True)
def _land(tau, y, f, h, s, p, rtol, v_floor, x_floor, work, y_new, f_new, error):
    """Bring a step of size h whose s·u̇ ended at or below zero onto the stop s·u̇ = 0, by Newton's method on h.

    The lengths that fall short and that pass bracket the stop; an iterate
    outside the bracket is replaced by bisection.  Returns (h, error) of the
    last step, which y_new, f_new hold; a step whose error exceeds 1 ends it.
    """
    tolerance = max(1e-3 * rtol * v_floor, 4e-16 * abs(y[1]))
    short = 0.0
    past = h
    for _ in range(LANDING_ITERATIONS):
        q = s * y_new[1]
        if abs(q) <= tolerance or error > 1.0:
            break
        if q > 0.0:
            short = h
        else:
            past = h
        rate = s * f_new[1]
        landed = h - q / rate if rate != 0.0 else -1.0
        h = landed if short < landed < past else 0.5 * (short + past)
        error = _step(tau, y, f, h, s, p, rtol, v_floor, x_floor, work, y_new, f_new)
    return h, error


@numba.njit(cache=True)
def _stick_excesses(a, n, x, curvature, mu_rest):
    """How far the holding force −a − c·n·u [m/s²] of a slider stuck at u = x [m] lies beyond ±μ(0)·n.

    Returns (a + c·n·u − μ(0)·n, −a − c·n·u − μ(0)·n): it slides towards −u
    once the first is positive, towards +u once the second is.
    """
    return a + n * (curvature * x - mu_rest), -a - n * (curvature * x + mu_rest)


@numba.njit(cache=True)
def advance_interval(a_start, a_end, n_start, n_end, dt, vg_start, p, rtol, v_floor, x_floor, y, clock, phase, steps,
                     work, f, y_new, f_new, totals):
    """Advance the slider over one sample interval [0, dt] [s] in place; returns its phase at the end.

    a_start, a_end and n_start, n_end [m/s²] are the ground acceleration and
    N/m = g + a_v at the interval's ends, vg_start u̇_g [m/s] at its start;
    ``p`` the interval's parameters (:data:`A0` …, filled here from them and
    the curvature [1/m], friction law and g [m/s²] already in it).  ``y`` holds the
    state (u, u̇, E_I/m, E_df/m, W_v/m), ``clock`` τ (set to 0 here) and the
    path [m]; ``phase`` the phase (0 stick, ±1 slip, :data:`FLIGHT`);
    ``steps[0]`` the step size [s] carried from interval to interval and
    ``steps[1]`` 1 while ``f`` holds the slip's right-hand side at ``y`` (the
    last step's, reused); ``totals`` accumulates [slip time (s), flight time
    (s), episodes, peak |u| (m), peak |ü| (m/s²)].  Returns the phase at the
    end and the phase just after the start.
    """
    slope = (a_end - a_start) / dt
    n_slope = (n_end - n_start) / dt
    p[A0] = a_start
    p[SLOPE] = slope
    p[N0] = n_start
    p[N_SLOPE] = n_slope
    p[VG0] = vg_start
    curvature = p[CURVATURE]
    mu_rest = p[MU_SLOW]
    clock[TAU] = 0.0
    n = n_start  # N/m now, exactly zero at a lift-off or a touchdown
    phase_after_start = phase
    while clock[TAU] < dt:
        tau = clock[TAU]
        if tau == 0.0:
            phase_after_start = phase
        remaining = dt - tau
        a, ground_velocity = ground_at(tau, a_start, a_end, slope, vg_start)
        if phase == FLIGHT:
            if n > 0.0:
                down = 0.0
            elif n_slope > 0.0 and n_end > 0.0:
                down = -n / n_slope
            else:
                down = math.inf
            span = min(down, remaining)
            x, v = y[0], y[1]
            totals[3] = max(totals[3], flight_peak(x, v, a, slope, span))
            y[0] = x + span * (v - span * (0.5 * a + slope * span / 6.0))
            y[1] = v - span * (a + 0.5 * slope * span)
            y[4] += 0.5 * p[GRAVITY] * curvature * (y[0] * y[0] - x * x)  # N = 0: −c·(0 − g)·u·u̇ integrated
            totals[3] = max(totals[3], abs(y[0]))
            totals[1] += span
            if down >= remaining:
                clock[TAU] = dt
                break
            clock[TAU] = tau + down
            n = 0.0
            a = min(max(a_start + slope * clock[TAU], min(a_start, a_end)), max(a_start, a_end))
            # touch down sliding on along u̇; from rest, as a stuck slider breaks away at n = 0: along −a
            if y[1] > 0.0 or (y[1] == 0.0 and a < 0.0):
                phase = 1
            elif y[1] < 0.0 or a > 0.0:
                phase = -1
            else:
                phase = STICK
            steps[1] = 0.0
            continue
        if phase == STICK:
            x = y[0]
            lift = liftoff_time(n, n_slope, n_end)
            upper_excess, lower_excess = _stick_excesses(a, n, x, curvature, mu_rest)
            if upper_excess > 0.0:
                wait, following = 0.0, -1
            elif lower_excess > 0.0:
                wait, following = 0.0, 1
            else:
                wait, following = math.inf, STICK
                upper_end, lower_end = _stick_excesses(a_end, n_end, x, curvature, mu_rest)
                rate = slope + n_slope * (curvature * x - mu_rest)
                if rate > 0.0 and upper_end > 0.0:
                    wait, following = -upper_excess / rate, -1
                rate = -slope - n_slope * (curvature * x + mu_rest)
                if rate > 0.0 and lower_end > 0.0 and -lower_excess / rate < wait:
                    wait, following = -lower_excess / rate, 1
            if lift <= wait:
                wait, following = lift, FLIGHT
            span = min(wait, remaining)
            y[2] += stick_input_energy(a, slope, ground_velocity, span)
            if span > 0.0:  # held: |ü| = |a| up to the stick's end
                totals[4] = max(totals[4], abs(a), abs(a_end) if wait >= remaining else abs(a + slope * span))
            if wait >= remaining:
                clock[TAU] = dt
                break
            clock[TAU] = tau + wait
            n = 0.0 if following == FLIGHT else n_start + n_slope * clock[TAU]
            phase = following
            y[1] = 0.0
            steps[1] = 0.0
            totals[2] += 1.0
            continue
        # a slip in direction s = phase, up to the interval's end or the lift-off
        s = phase
        lift = liftoff_time(n, n_slope, n_end)
        if lift == 0.0:
            phase = FLIGHT
            n = 0.0
            steps[1] = 0.0
            continue
        target = min(dt, tau + lift)
        if steps[1] == 0.0:
            _rhs(tau, y, s, p, f)
            steps[1] = 1.0
        h = min(steps[0], target - tau)
        error = _step(tau, y, f, h, s, p, rtol, v_floor, x_floor, work, y_new, f_new)
        stopped = s * y_new[1] <= 0.0
        if not stopped and error <= 1.0:
            dip = _interior_stop(s * y[1], s * y_new[1], s * f[1], s * f_new[1], h)
            if dip > 0.0:  # a stop inside: a step to just past it, landed on it if it ends below zero
                h = min(h, 1.001 * dip)
                error = _step(tau, y, f, h, s, p, rtol, v_floor, x_floor, work, y_new, f_new)
                stopped = s * y_new[1] <= 0.0
        if stopped and error <= 1.0:
            h, error = _land(tau, y, f, h, s, p, rtol, v_floor, x_floor, work, y_new, f_new, error)
        if error > 1.0:
            steps[0] = next_step(h, error)
            continue
        stopped = s * y_new[1] <= 0.0 or (stopped and h < target - tau)
        reached = not stopped and h >= target - tau
        if reached:
            steps[0] = max(steps[0], next_step(h, error))
        else:
            steps[0] = next_step(h, error)
        clock[PATH] += abs(y_new[0] - y[0])  # u is monotone within a slip
        for j in range(N_STATE):
            y[j] = y_new[j]
            f[j] = f_new[j]
        clock[TAU] = target if reached else tau + h
        totals[0] += clock[TAU] - tau
        totals[3] = max(totals[3], abs(y[0]))
        totals[4] = max(totals[4], abs(f_new[1] + a_start + slope * clock[TAU]))
        if stopped or (reached and target < dt):
            steps[1] = 0.0
        if stopped:
            y[1] = 0.0
            a = min(max(a_start + slope * clock[TAU], min(a_start, a_end)), max(a_start, a_end))
            n = n_start + n_slope * clock[TAU]
            upper_excess, lower_excess = _stick_excesses(a, n, y[0], curvature, mu_rest)
            if n <= 0.0:
                phase = FLIGHT
                n = 0.0
            elif upper_excess > 0.0:
                phase = -1
            elif lower_excess > 0.0:
                phase = 1
            else:
                phase = STICK
        elif reached and target < dt:
            phase = FLIGHT
            n = 0.0
    if clock[TAU] == 0.0:
        phase_after_start = phase
    return phase, phase_after_start


@numba.njit(cache=True)
def solve_record(acceleration, normal, ground_velocity, dt, curvature, law, g, rtol, x0, v0, history, out):
    """Solve one record: a [m/s²], N/m = g + a_v [m/s²] and u̇_g [m/s] at the samples, interval dt [s].

    ``curvature`` c = 1/R [1/m] (0 flat); ``law`` (μ_slow, μ_fast, rate [s/m]);
    ``g`` [m/s²] for the base shear over the weight and the potential energy; the slider starts at
    u = x0 [m], u̇ = v0 [m/s].  ``out`` receives the scalars of
    :data:`~stickslip.solvers.ledger.SCALAR_NAMES`; ``history``,
    of shape (n, len(HISTORY_COLUMNS)) or (0, ·), the state just after each
    sample.  An interval whose ends both hold a stuck slider is stuck
    throughout (both conditions are linear in time) and costs one closed form.
    """
    n_samples = acceleration.size
    keep = history.shape[0] > 0
    largest_a = 0.0
    largest_n = 0.0
    for i in range(n_samples):
        largest_a = max(largest_a, abs(acceleration[i]))
        largest_n = max(largest_n, abs(normal[i]))
    speed_scale = 2.0 * (largest_a + max(law[0], law[1]) * largest_n) * dt
    v_floor = FLOOR * speed_scale
    x_floor = v_floor * dt
    mu_rest = law[0]
    p = np.zeros(10)
    p[CURVATURE] = curvature
    p[GRAVITY] = g
    p[MU_SLOW] = law[0]
    p[MU_FAST] = law[1]
    p[RATE] = law[2]
    y = np.zeros(N_STATE)
    y[0] = x0
    y[1] = v0
    clock = np.zeros(2)
    f = np.zeros(N_STATE)
    y_new = np.zeros(N_STATE)
    f_new = np.zeros(N_STATE)
    work = np.zeros((14, N_STATE))
    steps = np.array([dt, 0.0])
    totals = np.zeros(5)
    totals[3] = abs(x0)
    phase = STICK if v0 == 0.0 else (1 if v0 > 0.0 else -1)
    if normal[0] <= 0.0:
        phase = FLIGHT
    if keep:
        history[0, :] = 0.0
        history[0, 0] = x0
        history[0, 1] = v0
    for i in range(n_samples - 1):
        a0, a1, n0, n1 = acceleration[i], acceleration[i + 1], normal[i], normal[i + 1]
        start_phase = phase
        stuck = phase == STICK and n0 > 0.0 and n1 > 0.0
        if stuck:
            for excess in _stick_excesses(a0, n0, y[0], curvature, mu_rest) + _stick_excesses(a1, n1, y[0],
                                                                                               curvature, mu_rest):
                stuck = stuck and excess <= 0.0
        if stuck:
            slope = (a1 - a0) / dt
            y[2] += stick_input_energy(a0, slope, ground_velocity[i], dt)
            totals[4] = max(totals[4], abs(a0), abs(a1))
        else:
            phase, start_phase = advance_interval(a0, a1, n0, n1, dt, ground_velocity[i], p, rtol, v_floor, x_floor, y,
                                                  clock, phase, steps, work, f, y_new, f_new, totals)
        if keep:
            history[i, 2] = start_phase
            history[i + 1, 0] = y[0]
            history[i + 1, 1] = y[1]
            history[i + 1, 3] = y[3]
            history[i + 1, 4] = y[2]
            history[i + 1, 5] = y[4]
            history[i + 1, 6] = clock[PATH]
    if keep:
        history[n_samples - 1, 2] = phase
    store_scalars(out, y[3], y[2], y[4], ground_velocity[n_samples - 1] + y[1], g * curvature, y[0], totals[3],
                  clock[PATH], totals[0], (n_samples - 1) * dt, totals[2], totals[4], g, totals[1])


def integration(rtol: float | None) -> str:
    """How the tolerance-controlled kernels solve, in words, at the relative tolerance ``rtol`` (None: :data:`RTOL`)."""
    return f"integration to a relative tolerance of {RTOL if rtol is None else rtol:g}, events located"


@numba.njit(cache=True, inline="always")
def _solved_pair(group, record, curvatures, column, out):
    """:func:`solve_record` of one record and column j: the curvature ``curvatures[j]`` [1/m] with the law
    ``laws[j]`` (μ_slow, μ_fast, rate [s/m]) of the group, no history."""
    samples, normals, ground_velocity, offsets, dts, laws, g, rtol, no_history = group
    first, last = offsets[record], offsets[record + 1]
    solve_record(samples[first:last], normals[first:last], ground_velocity[first:last], dts[record],
                 curvatures[column], laws[column], g, rtol, 0.0, 0.0, no_history, out)


_sweep_pairs = sweep_engine(__name__, _solved_pair)


def integrated_history(acceleration, dt: float, friction: FrictionLaw, radius: float = math.inf, vertical=None,
                       g: float = STANDARD_GRAVITY, *, rtol: float = RTOL, initial_displacement: float = 0.0,
                       initial_velocity: float = 0.0) -> dict:
    """The history of a friction pendulum (or a flat block) under a horizontal and a vertical ground motion.

    Parameters
    ----------
    acceleration:
        Horizontal ground acceleration a [m/s²] at the samples, linear in between.
    dt:
        Sample interval [s].
    friction:
        The friction law μ(v) (:class:`~stickslip.solvers.friction_law.FrictionLaw`).
    radius:
        Radius R of the sliding surface [m]; ``math.inf`` (the default) for a flat surface.
    vertical:
        Vertical ground acceleration a_v [m/s², positive up] at the same samples, or ``None``.
    g:
        Gravity [m/s²].
    rtol:
        Relative tolerance of each step (module docstring).
    initial_displacement, initial_velocity:
        u [m] and u̇ [m/s] relative to the ground at t = 0 (the ground starts at rest).

    Returns
    -------
    dict
        As :func:`stickslip.models.pendulum.exact.pendulum_history`:
        ``energy_dissipated`` = ∫μ(u̇)·n·|du|, ``potential_energy`` = ½·(g/R)·u²,
        ``energy_input_vertical`` = −∫((n − g)/R)·u du [J/kg], ``phase`` 2 where
        lifted off (n = 0 there).
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    rtol = checked_positive(rtol, "relative tolerance rtol")
    normal = normal_acceleration(vertical, acceleration.size, g)
    ground_velocity, _ = integrate_linear_acceleration(acceleration, dt)
    history = np.empty((acceleration.size, len(HISTORY_COLUMNS)))
    scalars = np.empty(len(SCALAR_NAMES))
    solve_record(acceleration, normal, ground_velocity, dt, surface_curvature(radius), law_columns([friction])[0],
                 float(g), rtol, float(initial_displacement), float(initial_velocity), history, scalars)
    return history_dict(history, scalars, ground_velocity, dt, g * surface_curvature(radius))


def integrated_sweep(accelerations, verticals, dts, frictions, radius=math.inf, g: float = STANDARD_GRAVITY, *,
                     rtol: float = RTOL) -> np.ndarray:
    """End-of-record scalars for every record and column (friction law, R), in parallel.

    ``accelerations`` [m/s²] and ``verticals`` [m/s², positive up; ``None``
    for none, or an entry ``None``] are lists of 1-D arrays, one pair per
    record; ``dts`` [s] one number or one per record; ``frictions`` a
    sequence of :class:`~stickslip.solvers.friction_law.FrictionLaw`, one per
    column; ``radius`` [m] one number or one per column (``math.inf`` flat).
    Returns shape (records, columns, len(SCALAR_NAMES)) per unit mass, in the
    units of :data:`~stickslip.solvers.ledger.SCALAR_UNITS`.
    """
    g = checked_positive(g, "gravity g [m/s2]")
    rtol = checked_positive(rtol, "relative tolerance rtol")
    records = [checked_acceleration(a, f"record {i}") for i, a in enumerate(accelerations)]
    if not records:
        raise StickslipError("integrated sweep: no records given")
    verticals = [None] * len(records) if verticals is None else list(verticals)
    if len(verticals) != len(records):
        raise StickslipError(f"integrated sweep: {len(verticals)} vertical components for {len(records)} records")
    normals = [normal_acceleration(vertical, record.size, g) for vertical, record in zip(verticals, records)]
    dts = np.ascontiguousarray([checked_positive(dt, f"time step of record {i} [s]")
                                for i, dt in enumerate(np.broadcast_to(np.asarray(dts, dtype=float),
                                                                       (len(records),)))])
    laws = law_columns(list(frictions))
    try:
        radii = np.broadcast_to(np.asarray(radius, dtype=float), (laws.shape[0],))
    except ValueError:
        raise StickslipError(f"--radius: expected one radius or {laws.shape[0]} (one per friction law)") from None
    curvatures = np.array([surface_curvature(r) for r in radii])
    sizes = np.array([a.size for a in records], dtype=np.int64)
    samples = np.concatenate(records)
    normal_samples = np.concatenate(normals)
    ground_velocity = np.concatenate([integrate_linear_acceleration(a, dt)[0] for a, dt in zip(records, dts)])
    group = (samples, normal_samples, ground_velocity, offsets(sizes), dts, laws, float(g), float(rtol),
             np.zeros((0, len(HISTORY_COLUMNS))))
    out = np.empty((len(records), laws.shape[0], len(SCALAR_NAMES)))
    run_in_calls(lambda first, last: _sweep_pairs(group, curvatures, first, last, out),
                 np.repeat(sizes, laws.shape[0]), first_work=2e5)
    return out
