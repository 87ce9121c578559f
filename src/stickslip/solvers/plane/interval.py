"""The events of one sample interval in the plane: stick, breakaway, the regimes of a slip, stops, lift-off, landing.

:func:`advance_interval` takes the block across one sample interval, where a
and n are linear: in contact (:func:`_advance_contact`) it alternates holding
(:mod:`~stickslip.solvers.plane.stick`) and sliding, each slip step in the
regime of its speed (fast, slow, settled, stopping: :mod:`stickslip.solvers.plane`),
stops located and the block then held or broken away anew; where n crosses
zero it lifts off or lands (:mod:`~stickslip.solvers.plane.flight`).
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers.dop853 import next_step
from stickslip.solvers.plane.flight import fly
from stickslip.solvers.plane.resistance import ORDER, ground_acceleration, sliding_acceleration, step_end_acceleration
from stickslip.solvers.plane.settled import (
    SERIES_ENTRY, SERIES_TOLERANCE, direction_angle, first_order_angle, settled_plan, settled_reach, settled_velocity)
from stickslip.solvers.plane.state import (
    A1, A2, FAST, FLIGHT, G1, G2, INPUT, K1, K2, N_STATE, NORMAL, NORMAL_RATE, SETTLED, SETTLED_SLIDING, SLIDING, SLOW,
    STALLED, STICK, TAU, U1, U2, V1, V2)
from stickslip.solvers.plane.stepping import LOWEST, interior_peak, land, rhs, step
from stickslip.solvers.plane.stick import breakaway_time, hold_quadratic, stick_input_energy
from stickslip.solvers.plane.stopping import quick_stop

#: The passes of the event loop (steps tried, stops and starts) one sample interval may take before the solver gives up
#: rather than run on without end; fifteen three-component stations take at most 2,235 (docs/solvers.md).
MAX_PASSES = 100_000


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _advance_contact(segment, end, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f, motion, steps,
                     work, y_new, f_new, y_try, f_try, phi, totals):
    """Advance the block in contact (n > 0) from y[TAU] to ``end`` [s] of the interval [0, dt]; returns its motion.

    ``tolerance`` [m] bounds the path error of a closed-form stop
    (:func:`~stickslip.solvers.plane.stopping.quick_stop`); ``steps`` holds the step size of each regime, carried
    from interval to interval ([s], [s/(m/s)], [s]); ``totals`` accumulates [slip time (s), episodes, peak |u| (m), flight time (s),
    peak |ü| (m/s²): at the stick's ends, step ends and stops].  Returns STALLED, y left where it got to, after
    :data:`MAX_PASSES` passes that have not reached ``end``.
    """
    stalled = False
    leave = False  # the last step on the slow manifold was landed where its whole series ends
    passes = 0
    while y[TAU] < end:
        passes += 1
        if passes > MAX_PASSES:
            return STALLED
        start = y[TAU]
        if motion == STICK:
            wait = breakaway_time(segment, law, y[U1], y[U2], start, stalled)
            if stalled:
                wait = max(wait, 1e-12 * dt)
                stalled = False
            span = min(wait, end - start)
            totals[4] = max(totals[4], ground_acceleration(segment, start), ground_acceleration(segment, start + span))
            gx = segment[G1] + start * (segment[A1] + 0.5 * segment[K1] * start)
            gy = segment[G2] + start * (segment[A2] + 0.5 * segment[K2] * start)
            y[INPUT] += (stick_input_energy(segment[A1] + segment[K1] * start, segment[K1], gx, span)
                         + stick_input_energy(segment[A2] + segment[K2] * start, segment[K2], gy, span))
            if wait >= end - start:
                y[TAU] = end
                break
            y[TAU] = start + wait
            motion = SETTLED_SLIDING
            totals[1] += 1.0
            y[V1] = 0.0
            y[V2] = 0.0
            continue
        if motion == SETTLED_SLIDING:
            speed = y[V1]
            whole, _, settled_limit, angle = settled_plan(y, speed, segment, law, phi, rtol, velocity_floor,
                                                          int(law[ORDER]))
            if speed >= whole or leave:  # the slow manifold's series no longer holds: the full equations
                settled_velocity(y, speed, angle, segment, law)
                motion = SLIDING
                leave = False
        else:
            speed = math.sqrt(y[V1] * y[V1] + y[V2] * y[V2])
        if motion == SETTLED_SLIDING:
            regime = SETTLED
            rhs(y, regime, segment, law, phi, f)
            if speed == 0.0 and f[V1] <= 0.0 and hold_quadratic(segment, law, y[U1], y[U2], start)[1] <= 0.0:
                motion = STICK  # |b| = μ(0)·n to round-off, not rising
                stalled = True
                continue
        else:
            if speed < 100.0 * s_switch and speed > 0.0:
                allowed_miss = SERIES_TOLERANCE * rtol * (speed + velocity_floor) / speed
                direction = direction_angle(y, segment, law)
                first = first_order_angle(y, speed, segment, law, phi)
                if abs(direction - first) <= 0.5 * abs(first) + allowed_miss:  # near the manifold: look closer
                    whole, _, _, angle = settled_plan(y, speed, segment, law, phi, rtol, velocity_floor,
                                                      int(law[ORDER]))
                    if (speed < SERIES_ENTRY * whole and abs(direction - angle) <= allowed_miss
                            and settled_reach(segment, law, y, end - start) >= min(end - start, 1e-3 * dt)):  # on it
                        y[V1] = speed
                        y[V2] = 0.0
                        motion = SETTLED_SLIDING
                        continue
            if speed < s_lock:
                saved_peak = math.sqrt(y[U1] * y[U1] + y[U2] * y[U2])
                e1 = y[V1] / speed if speed > 0.0 else 0.0
                e2 = y[V2] / speed if speed > 0.0 else 0.0
                duration = quick_stop(y, segment, law, end - start, tolerance)
                if duration < math.inf:
                    totals[0] += duration
                    totals[2] = max(totals[2], saved_peak, math.sqrt(y[U1] * y[U1] + y[U2] * y[U2]))
                    totals[4] = max(totals[4], sliding_acceleration(segment, law, y[TAU], y[U1], y[U2], e1, e2,
                                                                    0.0))
                    motion = SETTLED_SLIDING if hold_quadratic(segment, law, y[U1], y[U2], y[TAU])[0] > 0.0 \
                        else STICK
                    continue
            regime = SLOW if speed < s_switch else FAST
            rhs(y, regime, segment, law, phi, f)
        if regime == SLOW:
            h = steps[SLOW]
        else:
            h = min(steps[regime], end - start)
        if regime == SETTLED:
            reach = settled_reach(segment, law, y, end - start)
            if reach <= 1e-9 * dt:  # the manifold ends here: the full equations, from its direction
                settled_velocity(y, y[V1], angle, segment, law)
                motion = SLIDING
                continue
            h = min(h, reach)
        if regime == SETTLED and f[V1] < 0.0 and y[V1] > 0.0:
            # no further than the stop at the present deceleration: a slip that slows down faster ends the
            # step below zero and is landed on the stop; one that recovers inside the step never reached it
            h = min(h, 1.0001 * y[V1] / -f[V1])
        error = step(y, f, h, regime, segment, law, phi, rtol, velocity_floor, dt, work, y_new, f_new)
        stopped = False
        series_end = False
        if regime != SETTLED and y_new[V1] * y[V1] + y_new[V2] * y[V2] <= 0.0:  # a step past the stop: shorter
            steps[regime] = 0.25 * h
            continue
        if regime == SETTLED and y_new[V1] >= 0.0 and work[LOWEST, 0] < -rtol * velocity_floor:
            # the speed dipped below zero inside the step and rose again: the block may have stopped (and stuck,
            # or broken away anew) in between, which a step through zero would miss: shorter
            steps[regime] = 0.5 * h
            continue
        if regime == SLOW and error <= 1.0 and y_new[TAU] > end:
            h, error = land(y, f, h, end, TAU, regime, segment, law, phi, rtol, velocity_floor, dt, work,
                            y_new, f_new, error)
        elif regime == SETTLED and error <= 1.0 and (y_new[V1] < 0.0 or y_new[V1] > settled_limit):
            target = 0.0 if y_new[V1] < 0.0 else settled_limit * (1.0 + 1e-9)
            h, error = land(y, f, h, target, V1, regime, segment, law, phi, rtol, velocity_floor, dt, work,
                            y_new, f_new, error)
            stopped = target == 0.0
            # where the whole series ends, the slip leaves the manifold at once: the limit moves with b, and a slip
            # that stayed on would chase it, one landing after another
            series_end = not stopped and settled_limit >= whole
        if error > 1.0:
            steps[regime] = next_step(h, error)
            continue
        if regime == SLOW:
            if end - y_new[TAU] <= 2e-13 * dt:
                y_new[TAU] = end
        elif h >= end - start:
            y_new[TAU] = end
        steps[regime] = next_step(h, error)
        totals[2] = max(totals[2], math.sqrt(y_new[U1] * y_new[U1] + y_new[U2] * y_new[U2]))
        totals[4] = max(totals[4], step_end_acceleration(y_new, f_new, regime, segment, law))
        if y[U1] * f[U1] + y[U2] * f[U2] > 0.0 and y_new[U1] * f_new[U1] + y_new[U2] * f_new[U2] < 0.0:
            totals[2] = max(totals[2], interior_peak(y, f, y_new, f_new, h, regime, segment, law, phi, rtol,
                                                     velocity_floor, dt, work, y_try, f_try))
        totals[0] += y_new[TAU] - start
        for j in range(N_STATE):
            y[j] = y_new[j]
        if regime == SETTLED:
            if stopped:
                y[V1] = 0.0
                y[V2] = 0.0
                motion = SETTLED_SLIDING if hold_quadratic(segment, law, y[U1], y[U2], y[TAU])[0] > 0.0 else STICK
            else:
                y[V2] = 0.0
                leave = series_end
    return motion


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def advance_interval(segment, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f, motion, steps, work,
                     y_new, f_new, y_try, f_try, phi, totals):
    """Advance the block over one sample interval [0, dt] [s] in place; returns its motion (STICK, ...) at the end.

    The interval's data are in ``segment`` (:data:`~stickslip.solvers.plane.state.A1` ...); where the normal
    force n crosses zero inside it, the block lifts off there or lands there
    (:func:`~stickslip.solvers.plane.flight.fly` in between).  ``y`` holds the state (its τ is set to 0
    here); the other arguments are those of :func:`_advance_contact`, which
    may give up (STALLED, y[TAU] where it did).
    """
    y[TAU] = 0.0
    start_normal = segment[NORMAL]
    end_normal = start_normal + segment[NORMAL_RATE] * dt
    if start_normal > 0.0 and end_normal > 0.0:
        return _advance_contact(segment, dt, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f,
                                motion, steps, work, y_new, f_new, y_try, f_try, phi, totals)
    if start_normal <= 0.0 and end_normal <= 0.0:
        fly(y, segment, law, dt, totals)
        return FLIGHT
    crossing = min(max(-start_normal / segment[NORMAL_RATE], 0.0), dt)
    if start_normal > 0.0:  # lifts off inside the interval
        if crossing > 0.0:
            motion = _advance_contact(segment, crossing, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y,
                                      f, motion, steps, work, y_new, f_new, y_try, f_try, phi, totals)
        if motion == STALLED:
            return STALLED
        if motion == SETTLED_SLIDING:
            settled_velocity(y, y[V1], settled_plan(y, y[V1], segment, law, phi, rtol, velocity_floor,
                                                    int(law[ORDER]))[3], segment, law)
        fly(y, segment, law, dt, totals)
        return FLIGHT
    fly(y, segment, law, crossing, totals)  # lands inside the interval
    motion = STICK if y[V1] == 0.0 and y[V2] == 0.0 else SLIDING
    return _advance_contact(segment, dt, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f, motion,
                            steps, work, y_new, f_new, y_try, f_try, phi, totals)
