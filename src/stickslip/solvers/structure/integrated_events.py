"""The integrated structure's event loop over a whole record: its regimes, events and stops, as numba kernels.

:func:`solve_record` takes the friction-linked structure of
:mod:`~stickslip.solvers.structure.integrated` across every sample interval:
in contact it alternates holding (STICK), sliding on the slow manifold's
zeroth order (SETTLED), off it in time or in σ (FAST, SLOW) and the last
straight stretch of a slip (STOPPING), each step a DOP853 step of
:func:`~stickslip.solvers.structure.integrated_step.step`, each event (a
breakaway, a stop, a speed that leaves the manifold, the end of an interval
in σ) landed on by safeguarded Newton on the step (:func:`_land`); where N
crosses zero it lifts off or lands (FLIGHT).  It writes the state after each
sample into the history's arrays.

The state travels in two tuples.  ``state``: y and the trial step's y_new,
f_new (the state's size), the stages ``work`` (14 rows), the step of each
regime ``steps`` (6, [s], or σ in SLOW), ``times`` (the slip time and the
flight time [s]) and ``counts`` (the motion, the hold-to-slip episodes).
``model``: ``law``, ``vectors``, ``matrices`` of
:mod:`~stickslip.solvers.structure.integrated_step` and ``setting``
(:data:`SETTING_SIZE` floats: rtol [1], the velocity floor [m/s], dt [s],
s_switch, s_lock and the speed scale S [m/s]).

numba renews a kernel's cache when the kernel's own file changes, not when a
module it calls does: after editing
:mod:`~stickslip.solvers.structure.integrated_step` (or what it calls), delete
this module's cached kernels too (``integrated_events.*.nbi``, ``*.nbc`` in its
``__pycache__``).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.solvers.dop853 import next_step
from stickslip.solvers.plane.interval import MAX_PASSES
from stickslip.solvers.plane.manifold import DENOMINATOR_MARGIN
from stickslip.solvers.structure.integrated_step import (
    AIM1, AIM2, FAST, FLIGHT, MOBILITY, MU_FAST, MU_SLOW, NORMAL, NORMAL_RATE, SETTLED, SLIP_MODE, SLOW, STICK,
    STOPPING, VISCOUS, driving, driving_rate, evaluate, layout, step)

#: The interface slides off the slow manifold (its steps FAST or SLOW by the speed).
SLIDING = FAST
#: ``setting``: rtol [1], the velocity floor [m/s], dt [s], s_switch [m/s], s_lock [m/s], the speed scale S [m/s].
RTOL_AT, FLOOR_AT, DT_AT, SWITCH_AT, LOCK_AT, SCALE_AT = range(6)
SETTING_SIZE = 6
#: ``times``: the slip time and the flight time [s]; ``counts``: the motion and the hold-to-slip episodes.
SLIP_TIME, FLIGHT_TIME = range(2)
MOTION, EPISODES = range(2)
#: Newton iterations that bring a step onto an event.
_LANDING_ITERATIONS = 16
#: The largest step in σ times the slip's fastest rate there, μ_max·n + |β| (DOP853: stable to about 6 on the real
#: axis).
_SLOW_STABILITY = 4.5
#: The event of :func:`_land` that is the hold's margin |β| − μ(0)·n (the others: y[index] − target).
_MARGIN = -1


# ---------------------------------------------------------------------- the state and its forces
@numba.njit(cache=True, inline="always")
def _tau(y):
    """The index of τ in the state y: the sixth from its end, before the five quadratures (:func:`layout`)."""
    return y.size - 6


@numba.njit(cache=True, error_model="numpy", inline="always")
def _normal(segment, tau):
    """N [N] at τ [s] of the interval, 0 where it is not positive."""
    return max(segment[NORMAL] + segment[NORMAL_RATE] * tau, 0.0)


@numba.njit(cache=True, error_model="numpy", inline="always")
def _limit(segment, tau, law):
    """μ(0)·n [m/s²]: the radius of the friction circle per unit of the interface's effective mass."""
    return law[MU_SLOW] * law[MOBILITY] * _normal(segment, tau)


@numba.njit(cache=True, error_model="numpy", inline="always")
def _driving(y, segment, law, vectors):
    """β [m/s²] (a pair) at y."""
    n = vectors.shape[1]
    return driving(y, segment, law, vectors, n, _normal(segment, y[_tau(y)]))


@numba.njit(cache=True, error_model="numpy", inline="always")
def _rhs(y, regime, segment, model):
    """dy/dt (dy/dσ in SLOW) at y in ``regime``."""
    law, vectors, matrices, _ = model
    n = vectors.shape[1]
    f = np.empty(y.size)
    evaluate(y, regime, segment, law, vectors, matrices, n, f, np.empty((n, 2)), np.empty(2), np.empty(2))
    return f


@numba.njit(cache=True, error_model="numpy", inline="always")
def _step(y, f, h, regime, segment, state, model):
    """One DOP853 step of size h (s, or σ in SLOW) from (y, f) into ``state``'s y_new, f_new; the scaled error."""
    law, vectors, matrices, setting = model
    _, y_new, f_new, work, _, _, _ = state
    return step(y, f, h, regime, segment, law, vectors, matrices, vectors.shape[1], setting[RTOL_AT],
                setting[FLOOR_AT], setting[DT_AT], work, y_new, f_new)


@numba.njit(cache=True, error_model="numpy")
def _stick_margin(y, f, segment, model):
    """(|β| − μ(0)·n [m/s²], its rate [m/s³]) while the interface holds, at y with f = dy/dt in STICK."""
    law, vectors, _, _ = model
    n = vectors.shape[1]
    tau = y[layout(n)[2]]
    beta = _driving(y, segment, law, vectors)
    rate = driving_rate(y, f, segment, law, vectors, n)
    size = math.hypot(beta[0], beta[1])
    normal_rate = segment[NORMAL_RATE] if segment[NORMAL] + segment[NORMAL_RATE] * tau > 0.0 else 0.0
    along = (beta[0] * rate[0] + beta[1] * rate[1]) / size if size > 0.0 else math.hypot(rate[0], rate[1])
    return size - _limit(segment, tau, law), along - law[MU_SLOW] * law[MOBILITY] * normal_rate


@numba.njit(cache=True, error_model="numpy")
def _land(y, f, h, regime, segment, index, target, scale, error, state, model):
    """Bring a step of size h, already taken into ``state``'s y_new, f_new, whose end passed the zero of the event
    (the hold's margin where ``index`` is :data:`_MARGIN`, else y[index] − ``target``) onto it, by safeguarded
    Newton on h, to 1e-13 of ``scale``; returns (h, error), the landed step in y_new, f_new."""
    _, y_new, f_new, _, _, _, _ = state
    short, past = 0.0, h
    sign = 0.0
    for iteration in range(_LANDING_ITERATIONS):
        if index == _MARGIN:
            value, rate = _stick_margin(y_new, f_new, segment, model)
        else:
            value, rate = y_new[index] - target, f_new[index]
        if iteration == 0:
            sign = 1.0 if value > 0.0 else -1.0
        if error > 1.0 or abs(value) <= 1e-13 * scale:
            break
        if sign * value > 0.0:
            past = h
        else:
            short = h
        landed = h - value / rate if rate != 0.0 else -1.0
        h = landed if short < landed < past else 0.5 * (short + past)
        error = _step(y, f, h, regime, segment, state, model)
    return h, error


@numba.njit(cache=True, error_model="numpy", inline="always")
def _accept(state, end, start, h, error, regime, to_end, slipping):
    """Take the trial step into y (its τ on ``end`` where ``to_end``), the next step of ``regime``, the slip time."""
    y, y_new, _, _, steps, times, _ = state
    if to_end:
        y_new[_tau(y)] = end
    steps[regime] = next_step(h, error)
    if slipping:
        times[SLIP_TIME] += y_new[_tau(y)] - start
    y[:] = y_new


# ---------------------------------------------------------------------- stick and stops
@numba.njit(cache=True, error_model="numpy")
def _breaks_away(y, segment, model):
    """Whether the interface at rest at y breaks away: |β| beyond μ(0)·n, or on it to round-off and rising."""
    margin, rate = _stick_margin(y, _rhs(y, STICK, segment, model), segment, model)
    limit = _limit(segment, y[_tau(y)], model[0])
    return margin > 0.0 or (margin > -1e-12 * max(limit, 1e-300) and rate > 0.0)


@numba.njit(cache=True, error_model="numpy")
def _after_stop(state, segment, model):
    """The interface at rest (w = 0): holds, or slides on along −β/|β| (SETTLED at s = 0: a slip that turns round
    without holding, which is no new episode)."""
    y = state[0]
    slip = layout(model[1].shape[1])[1]
    y[slip] = 0.0
    y[slip + 1] = 0.0
    state[6][MOTION] = SETTLED if _breaks_away(y, segment, model) else STICK


@numba.njit(cache=True, error_model="numpy")
def _stops_straight(state, segment, model):
    """Whether a slip below s_lock goes straight to its stop; if so, it slides on in STOPPING.

    Straight: it decelerates, and its acceleration across w, times the time to the stop at the present
    deceleration, is a velocity within rtol·(s + the velocity floor) (or s itself is within rtol·(the floor)):
    the direction is then held to the stop.  A slip that still turns goes on in σ, where its direction settles
    on −β/|β| as its speed falls (or it turns round without stopping).
    """
    y = state[0]
    setting = model[3]
    slip = layout(model[1].shape[1])[1]
    f = _rhs(y, FAST, segment, model)
    w0, w1 = y[slip], y[slip + 1]
    speed = math.hypot(w0, w1)
    a0, a1 = f[slip], f[slip + 1]
    deceleration = -(a0 * w0 + a1 * w1) / speed
    if deceleration <= 0.0:
        return False
    across = abs(a0 * w1 - a1 * w0) / speed
    rtol, floor = setting[RTOL_AT], setting[FLOOR_AT]
    if across * speed / deceleration > rtol * (speed + floor) and speed > rtol * floor:
        return False
    y[slip] = speed
    y[slip + 1] = 0.0
    segment[AIM1] = w0 / speed
    segment[AIM2] = w1 / speed
    state[6][MOTION] = STOPPING
    return True


@numba.njit(cache=True, error_model="numpy")
def _to_sliding(state, segment, model):
    """Turn the speed of a slip on the slow manifold (along −β/|β|) or of a straight one (along its angle) into the
    slip velocity (SLIDING), or hold where s = 0."""
    y, counts = state[0], state[6]
    slip = layout(model[1].shape[1])[1]
    speed = y[slip]
    if counts[MOTION] == STOPPING:
        aim0, aim1 = segment[AIM1], segment[AIM2]
    else:
        beta = _driving(y, segment, model[0], model[1])
        size = math.hypot(beta[0], beta[1])
        aim0, aim1 = (-beta[0] / size, -beta[1] / size) if size > 0.0 else (0.0, 0.0)
    if speed <= 0.0 or (aim0 == 0.0 and aim1 == 0.0):
        _after_stop(state, segment, model)
        return
    y[slip] = speed * aim0
    y[slip + 1] = speed * aim1
    counts[MOTION] = SLIDING


@numba.njit(cache=True, error_model="numpy")
def _stopping_step(state, segment, end, model):
    """One step of a straight slip to its stop, the stop located; back to SLIDING where it speeds up."""
    y, y_new, steps = state[0], state[1], state[4]
    slip = layout(model[1].shape[1])[1]
    start = y[_tau(y)]
    speed = y[slip]
    f = _rhs(y, STOPPING, segment, model)
    if f[slip] >= 0.0:
        _to_sliding(state, segment, model)
        return
    h = min(steps[STOPPING], end - start, 1.0001 * speed / -f[slip])
    error = _step(y, f, h, STOPPING, segment, state, model)
    stopped = error <= 1.0 and y_new[slip] < 0.0
    if stopped:
        h, error = _land(y, f, h, STOPPING, segment, slip, 0.0, model[3][SWITCH_AT], error, state, model)
    if error > 1.0:
        steps[STOPPING] = next_step(h, error)
        return
    _accept(state, end, start, h, error, STOPPING, not stopped and h >= end - start, True)
    if stopped:
        _after_stop(state, segment, model)


# ---------------------------------------------------------------------- the regimes in contact
@numba.njit(cache=True, error_model="numpy")
def _stick_step(state, segment, end, model):
    """One step with the interface held; a breakaway inside it is located."""
    y, y_new, f_new, _, steps, _, counts = state
    setting = model[3]
    start = y[_tau(y)]
    if _breaks_away(y, segment, model):
        counts[MOTION] = SETTLED
        counts[EPISODES] += 1
        return
    f = _rhs(y, STICK, segment, model)
    h = min(steps[STICK], end - start)
    error = _step(y, f, h, STICK, segment, state, model)
    broke = False
    if error <= 1.0 and _stick_margin(y_new, f_new, segment, model)[0] > 0.0:
        scale = _limit(segment, start, model[0]) + setting[SWITCH_AT] / setting[DT_AT]
        h, error = _land(y, f, h, STICK, segment, _MARGIN, 0.0, scale, error, state, model)
        broke = True
    if error > 1.0:
        steps[STICK] = next_step(h, error)
        return
    _accept(state, end, start, h, error, STICK, not broke and h >= end - start, False)
    if broke:
        counts[MOTION] = SETTLED
        counts[EPISODES] += 1


@numba.njit(cache=True, error_model="numpy")
def _sliding_step(state, segment, end, model):
    """One step off the slow manifold: in time (FAST) or in σ (SLOW), or the last straight stretch below s_lock."""
    y, y_new, _, _, steps, _, _ = state
    law, vectors, _, setting = model
    _, slip, tau_index, _ = layout(vectors.shape[1])
    start = y[tau_index]
    speed = math.hypot(y[slip], y[slip + 1])
    if speed < setting[LOCK_AT] and _stops_straight(state, segment, model):
        return
    regime = SLOW if speed < setting[SWITCH_AT] else FAST
    f = _rhs(y, regime, segment, model)
    if regime == SLOW:
        # in σ the slip relaxes at rates up to μ_max·n + |β|: steps well inside DOP853's stability, where a
        # tolerance measured near the velocity floor would let them sit on its edge and never decay
        beta = _driving(y, segment, law, vectors)
        fastest = (max(law[MU_SLOW], law[MU_FAST]) * law[MOBILITY] * _normal(segment, start)
                   + math.hypot(beta[0], beta[1]))
        h = min(steps[SLOW], _SLOW_STABILITY / fastest)
    else:
        h = min(steps[regime], end - start)
    error = _step(y, f, h, regime, segment, state, model)
    if y_new[slip] * y[slip] + y_new[slip + 1] * y[slip + 1] <= 0.0:  # a step past the stop: shorter
        steps[regime] = 0.25 * h
        return
    if regime == SLOW and error <= 1.0 and y_new[tau_index] > end:
        h, error = _land(y, f, h, regime, segment, tau_index, end, setting[DT_AT], error, state, model)
    if error > 1.0:
        steps[regime] = next_step(h, error)
        return
    if regime == SLOW:
        to_end = end - y_new[tau_index] <= 2e-13 * setting[DT_AT]
    else:
        to_end = h >= end - start
    _accept(state, end, start, h, error, regime, to_end, True)


@numba.njit(cache=True, error_model="numpy")
def _settled_exit(y, segment, model):
    """The speed [m/s] up to which the slip stays on the slow manifold's zeroth order (0: leave now).

    The first-order angle φ₁·s, φ₁ = −Ω/D₁ (Ω [rad/s] the rate at which β turns with the slip held,
    D₁ = 2|β| − μ(0)·n), left out, times s, must stay within rtol·(s + the velocity floor); D₁ must keep its
    margin (:data:`~stickslip.solvers.plane.manifold.DENOMINATOR_MARGIN`).  At most s_switch.
    """
    law, vectors, _, setting = model
    beta = _driving(y, segment, law, vectors)
    rate = driving_rate(y, _rhs(y, STICK, segment, model), segment, law, vectors, vectors.shape[1])
    size2 = beta[0] * beta[0] + beta[1] * beta[1]
    if size2 == 0.0:
        return 0.0
    limit = _limit(segment, y[_tau(y)], law)
    denominator = 2.0 * math.sqrt(size2) - limit
    if denominator <= 0.0 or denominator < DENOMINATOR_MARGIN * limit:
        return 0.0
    first = abs(beta[0] * rate[1] - beta[1] * rate[0]) / size2 / denominator  # |φ₁| [rad·s/m]
    if first == 0.0:
        return setting[SWITCH_AT]
    rtol, floor = setting[RTOL_AT], setting[FLOOR_AT]
    exit_speed = (rtol + math.sqrt(rtol ** 2 + 4.0 * first * rtol * floor)) / (2.0 * first)
    return min(exit_speed, setting[SWITCH_AT])


@numba.njit(cache=True, error_model="numpy")
def _settled_step(state, segment, end, model):
    """One step on the slow manifold's zeroth order: the speed along −β/|β| with the structure."""
    y, y_new, _, _, steps, _, counts = state
    setting = model[3]
    slip = layout(model[1].shape[1])[1]
    start = y[_tau(y)]
    speed = y[slip]
    exit_speed = _settled_exit(y, segment, model)
    if speed == 0.0 and _driving(y, segment, model[0], model[1]) == (0.0, 0.0):
        # a breakaway where nothing drives the slip yet (no friction, and the structure at rest): held for
        # 1e-9·dt, β takes the direction the slip will have
        h = min(1e-9 * setting[DT_AT], end - start)
        _step(y, _rhs(y, STICK, segment, model), h, STICK, segment, state, model)
        if h >= end - start:
            y_new[_tau(y)] = end
        y[:] = y_new
        return
    if speed >= exit_speed and not (speed == 0.0 and exit_speed > 0.0):
        _to_sliding(state, segment, model)
        return
    f = _rhs(y, SETTLED, segment, model)
    if (speed == 0.0 and f[slip] <= 0.0
            and _stick_margin(y, _rhs(y, STICK, segment, model), segment, model)[1] <= 0.0):
        counts[MOTION] = STICK
        return
    h = min(steps[SETTLED], end - start)
    if f[slip] < 0.0 and speed > 0.0:  # no further than the stop at the present deceleration
        h = min(h, 1.0001 * speed / -f[slip])
    error = _step(y, f, h, SETTLED, segment, state, model)
    stopped = leave = False
    if error <= 1.0 and (y_new[slip] < 0.0 or y_new[slip] > exit_speed):
        target = 0.0 if y_new[slip] < 0.0 else exit_speed
        h, error = _land(y, f, h, SETTLED, segment, slip, target, setting[SWITCH_AT], error, state, model)
        stopped = target == 0.0
        leave = not stopped
    if error > 1.0:
        steps[SETTLED] = next_step(h, error)
        return
    _accept(state, end, start, h, error, SETTLED, not (stopped or leave) and h >= end - start, True)
    if stopped:
        y[slip] = 0.0
        _after_stop(state, segment, model)
    elif leave:
        _to_sliding(state, segment, model)


@numba.njit(cache=True, error_model="numpy")
def _advance_contact(state, segment, end, model):
    """Advance from y[τ] to ``end`` [s] of the interval with the interface in contact (N > 0); False where the
    interval takes more than :data:`~stickslip.solvers.plane.interval.MAX_PASSES` passes."""
    y, counts = state[0], state[6]
    passes = 0
    while y[_tau(y)] < end:
        passes += 1
        if passes > MAX_PASSES:
            return False
        motion = counts[MOTION]
        if motion == STICK:
            _stick_step(state, segment, end, model)
        elif motion == SETTLED:
            _settled_step(state, segment, end, model)
        elif motion == STOPPING:
            _stopping_step(state, segment, end, model)
        else:
            _sliding_step(state, segment, end, model)
    return True


# ---------------------------------------------------------------------- flight and the sample interval
@numba.njit(cache=True, error_model="numpy")
def _fly(state, segment, end, model):
    """Advance from y[τ] to ``end`` [s] with the interface off its surface (N ≤ 0): no force on it."""
    y, y_new, _, _, steps, times, counts = state
    slip = layout(model[1].shape[1])[1]
    tau_index = _tau(y)
    if counts[MOTION] == SETTLED or counts[MOTION] == STOPPING:
        _to_sliding(state, segment, model)
    if counts[MOTION] == STICK:
        y[slip] = 0.0
        y[slip + 1] = 0.0
    counts[MOTION] = FLIGHT
    start = y[tau_index]
    while y[tau_index] < end:
        h = min(steps[FLIGHT], end - y[tau_index])
        error = _step(y, _rhs(y, FLIGHT, segment, model), h, FLIGHT, segment, state, model)
        if error > 1.0:
            steps[FLIGHT] = next_step(h, error)
            continue
        _accept(state, end, start, h, error, FLIGHT, h >= end - y[tau_index], False)
    times[FLIGHT_TIME] += end - start


@numba.njit(cache=True, error_model="numpy")
def _land_on_surface(state, segment, model):
    """The interface touches its surface again: slides on with its slip velocity, or holds where it has none."""
    y = state[0]
    slip = layout(model[1].shape[1])[1]
    if y[slip] == 0.0 and y[slip + 1] == 0.0:
        _after_stop(state, segment, model)
    else:
        state[6][MOTION] = SLIDING


@numba.njit(cache=True, error_model="numpy")
def _advance_interval(state, segment, model):
    """Advance over one sample interval [0, dt] [s], lift-off and landing at N's root inside it; False where the
    event loop gives up."""
    y, counts = state[0], state[6]
    y[_tau(y)] = 0.0
    dt = model[3][DT_AT]
    start_normal = segment[NORMAL]
    end_normal = segment[NORMAL] + segment[NORMAL_RATE] * dt
    if start_normal > 0.0 and end_normal > 0.0:
        if counts[MOTION] == FLIGHT:
            _land_on_surface(state, segment, model)
        return _advance_contact(state, segment, dt, model)
    if start_normal <= 0.0 and end_normal <= 0.0:
        _fly(state, segment, dt, model)
        return True
    crossing = min(max(-start_normal / segment[NORMAL_RATE], 0.0), dt)
    if start_normal > 0.0:  # lifts off inside the interval
        if counts[MOTION] == FLIGHT:
            _land_on_surface(state, segment, model)
        done = _advance_contact(state, segment, crossing, model)
        _fly(state, segment, dt, model)
        return done
    _fly(state, segment, crossing, model)  # lands inside the interval
    _land_on_surface(state, segment, model)
    return _advance_contact(state, segment, dt, model)


@numba.njit(cache=True, error_model="numpy")
def _sample(state, segment, model, k, displacement, velocity, absolute, friction, normal, moving):
    """The state, y[τ] in ``segment``, into row k of the history: x, ẋ (n × 2), ẍ_abs (n × 2), F (2), N, moving."""
    y, counts = state[0], state[6]
    law, vectors, matrices, _ = model
    n = vectors.shape[1]
    held = layout(n)[0]
    motion = counts[MOTION]
    w = np.empty(2)
    evaluate(y, motion, segment, law, vectors, matrices, n, np.empty(y.size), absolute[k], friction[k], w)
    for i in range(n):
        for j in range(2):
            displacement[k, i, j] = y[2 * i + j]
            velocity[k, i, j] = y[held + 2 * i + j] + vectors[SLIP_MODE, i] * w[j] / law[MOBILITY]
    normal[k] = 0.0 if motion == FLIGHT else _normal(segment, y[_tau(y)])
    moving[k] = 0.0 if motion == STICK else 1.0


@numba.njit(cache=True, error_model="numpy")
def solve_record(segments, law, vectors, matrices, setting, displacement, velocity, absolute, friction, normal,
                 moving, totals, times, counts):
    """Take the structure at rest across every interval of ``segments`` (samples − 1 rows of
    :data:`~stickslip.solvers.structure.integrated_step.SEGMENT_SIZE`), the state after each sample into the
    history's rows (``totals``: E_ζ, E_df, E_I, W_v [J] and the sliding path [m]); ``times`` (2) and ``counts``
    (2) as the module says.  Returns the index of the interval where the event loop gave up and the time into it
    [s], or (−1, 0.0)."""
    n = vectors.shape[1]
    size = layout(n)[3]
    tau_index = layout(n)[2]
    dt = setting[DT_AT]
    y = np.zeros(size)
    steps = np.full(6, dt)
    steps[SLOW] = 0.1 * dt / max(setting[SCALE_AT], 1e-300)
    state = (y, np.empty(size), np.empty(size), np.zeros((14, size)), steps, times, counts)
    model = (law, vectors, matrices, setting)
    counts[MOTION] = STICK
    segment = np.zeros(segments.shape[1])
    for i in range(segments.shape[0]):
        segment[:AIM1] = segments[i, :AIM1]
        if i == 0:
            _sample(state, segment, model, 0, displacement, velocity, absolute, friction, normal, moving)
        if not _advance_interval(state, segment, model):
            return i, y[tau_index]
        _sample(state, segment, model, i + 1, displacement, velocity, absolute, friction, normal, moving)
        for j in range(5):
            totals[i + 1, j] = y[tau_index + VISCOUS + j]
    return -1, 0.0
