"""The event engine: the stick → slip → stop loop over a record, written once, driven by a model's phase functions.

Every model of a block that holds and slides under a ground acceleration
linear between samples moves the same way through a record: while it holds,
nothing but where the hold ends depends on the model's parameters, so whole
stretches of samples are skipped at once; while it slides, an interval with
no event in it is one closed-form step; any other interval goes through the
model's event loop inside the interval (breakaway, stop, lift-off located to
round-off).  :func:`record_state` is that loop and :func:`sweep_pairs` deals
the (record, column) pairs of a sweep to parallel lanes.  A model gives them
its phase functions, by these names:

``holding(state)``
    Whether the state holds (sticks) at a sample; by default (:func:`holding`)
    the state's third number, its phase s, is 0.
``hold_band(record, parameters, state)``
    ``(values, block_max, block_min, lower, upper)``: the model holds while
    every sample of ``values`` stays in [lower, upper] (the ground
    acceleration against the thresholds, or |a|/n against μ), with the
    maxima and minima of ``values`` over blocks of :data:`BLOCK` samples
    (:func:`prepare_record`).
``held_over(record, parameters, state, first, last)``
    The state after holding from sample ``first`` to sample ``last`` (the
    input energy of the hold, its largest |a|).
``slid_through(record, parameters, state, i)``
    ``(state, True)`` after sliding through interval i without an event, or
    ``(state, False)`` when an event may fall inside it.
``crossed(record, parameters, state, i)``
    The state after interval i with every event inside it.
``solved_pair(group, record, columns, column, out)``
    One (record, column) pair of a sweep solved into ``out``.

Inside one sample interval, :func:`interval_state` is the loop over the
events (the hold's breakaway, the slide's stop, the slide back or the hold
after it), driven by four more:

``band(parameters, x)``
    ``(lower, upper)`` [m/s²]: the ground accelerations between which the
    state holds at the displacement x [m].
``slide_edge(parameters, x, s)``
    The ground acceleration [m/s²] at which a slide in direction s from x
    started (the band's edge it crossed); where a stop shorter than the time
    resolution leaves the ground.
``stop_time(parameters, a, slope, edge, v, s, remaining)``
    The time [s] to the first stop of a slide from velocity v [m/s] under the
    ground a + slope·τ, or +inf.
``slid(parameters, a, slope, vg, edge, x, v, s, tau)``
    ``(x, v, input energy, path, largest |ü|)`` after sliding for τ [s].

``record`` and ``group`` are tuples of the model's arrays, ``parameters``
and ``state`` tuples of its numbers: the engine never looks inside them.
The model compiles the engine on its phase functions with
:func:`stickslip.solvers.compilation.record_engine` (and its kin), so that each model has its
own machine code of the loop, with no call through a pointer, and no reference
counting in :func:`record_state` (a phase function must not make an array).

The module imports nothing of numba: the engine and the shared pieces a model
composes (with :func:`~stickslip.solvers.closed_forms.first_stop_time` and
:func:`~stickslip.solvers.closed_forms.stick_input_energy`) also run as plain
Python (:mod:`stickslip.models.rigid.events` solves short records so).
"""

from __future__ import annotations

import math
import time

import numpy as np

from stickslip.solvers.closed_forms import first_stop_time, stick_input_energy

#: The codes of a state's phase just after a sample that every model shares: it holds (sticks), or has lifted off;
#: sliding is any other code (−1, +1: towards ∓x).
STICK, FLIGHT = 0, 2

#: Samples per block of the block maxima and minima that let a hold skip ahead.
BLOCK = 32

#: Independent work streams of :func:`sweep_pairs` (a power of 2); each takes every LANES-th pair,
#: starting at :func:`lane_start`.
LANES = 64

#: Wall time [s] aimed at per call of a parallel sweep kernel (:func:`run_in_calls`): Ctrl-C is handled by
#: Python between calls, and each call's start and end cost the threads a little.
CALL_SECONDS = 0.25

#: The shared pieces, compiled by :func:`stickslip.solvers.compilation.compiled_kernels` where a model needs them.
PIECES = ("first_stop_time", "stick_input_energy", "breakaway", "ground_at", "prepare_record", "prepare_records",
          "next_exceedance", "largest_magnitude", "lane_start")


def breakaway(a, a_end, slope, lower, upper):
    """``(τ, s)``: in how long [s] a held state breaks away, and which way, or ``(inf, 0)`` if not in this interval.

    The ground acceleration is ``a`` now and ``a_end`` at the interval's end
    [m/s²], ``slope`` [m/s³] in between; the state holds while
    lower ≤ a ≤ upper [m/s²] (a band that stays put while it holds), and
    slides towards −x (s = −1) above it, towards +x (s = +1) below it.
    Whether it breaks away before the interval's end is decided by the sample
    ``a_end`` itself, not by the round-off of the crossing time, so an
    interval ending exactly at an edge never starts a slip of zero length.
    """
    if a > upper:
        return 0.0, -1
    if a < lower:
        return 0.0, 1
    if slope > 0.0 and a_end > upper:
        return (upper - a) / slope, -1
    if slope < 0.0 and a_end < lower:
        return (lower - a) / slope, 1
    return math.inf, 0


def ground_at(t, a_start, a_end, slope, vg_start):
    """The ground acceleration [m/s²] and velocity [m/s] at ``t`` [s] into an interval that starts with a_start and
    vg_start and ends with a_end, ``slope`` [m/s³] in between.

    The acceleration is kept between the interval's end values: an event just
    before an end exactly at an edge must not see the ground beyond it
    through round-off.
    """
    return (min(max(a_start + slope * t, min(a_start, a_end)), max(a_start, a_end)),
            vg_start + t * (a_start + 0.5 * slope * t))


def prepare_record(acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min):
    """Fill the arrays of one record that no model parameter changes.

    ``ground_velocity`` [m/s] at the samples (the trapezoid sums of
    :func:`stickslip.records.process.integrate_linear_acceleration`, in the
    same order); ``slope`` [m/s³], (a[i+1] − a[i])/dt of each interval (0
    after the last sample); ``stick_energy`` [J/kg], the prefix sums of the
    input energy of a block that holds over whole intervals, so that a hold
    from sample i to sample j adds stick_energy[j] − stick_energy[i];
    ``block_max`` and ``block_min`` [m/s²], max a and min a over each
    :data:`BLOCK` samples.
    """
    n = acceleration.size
    ground_velocity[0] = 0.0
    stick_energy[0] = 0.0
    slope[n - 1] = 0.0
    for i in range(n - 1):
        a0 = acceleration[i]
        a1 = acceleration[i + 1]
        slope[i] = (a1 - a0) / dt
        stick_energy[i + 1] = stick_energy[i] + stick_input_energy(a0, slope[i], ground_velocity[i], dt)
        ground_velocity[i + 1] = ground_velocity[i] + 0.5 * dt * (a0 + a1)
    for block in range(block_max.size):
        highest = acceleration[block * BLOCK]
        lowest = highest
        for k in range(block * BLOCK + 1, min((block + 1) * BLOCK, n)):
            highest = max(highest, acceleration[k])
            lowest = min(lowest, acceleration[k])
        block_max[block] = highest
        block_min[block] = lowest


def prepare_records(samples, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min,
                    block_offsets):
    """:func:`prepare_record` for every record of a group, concatenated (serially: a parallel start costs more).

    Record r is ``samples[offsets[r]:offsets[r + 1]]`` and its blocks
    ``block_max[block_offsets[r]:block_offsets[r + 1]]``.
    """
    for record in range(offsets.size - 1):
        first, last = offsets[record], offsets[record + 1]
        blocks = slice(block_offsets[record], block_offsets[record + 1])
        prepare_record(samples[first:last], dts[record], ground_velocity[first:last], slope[first:last],
                       stick_energy[first:last], block_max[blocks], block_min[blocks])


def next_exceedance(values, block_max, block_min, start, lower, upper):
    """The first sample k ≥ ``start`` with values[k] > ``upper`` or values[k] < ``lower``, or the length if none.

    Whole blocks of :data:`BLOCK` samples inside [lower, upper] are passed by
    their maxima and minima ``block_max`` and ``block_min``.
    """
    n = values.size
    k = start
    block_end = min((start // BLOCK + 1) * BLOCK, n)
    while k < block_end:
        if (values[k] > upper) | (values[k] < lower):
            return k
        k += 1
    block = block_end // BLOCK
    while block < block_max.size and (block_max[block] <= upper) & (block_min[block] >= lower):
        block += 1
    if block == block_max.size:
        return n
    k = block * BLOCK
    while (values[k] <= upper) & (values[k] >= lower):
        k += 1
    return k


def largest_magnitude(acceleration, block_max, block_min, first, last):
    """max |a[k]| [m/s²] for first ≤ k ≤ last, whole blocks of :data:`BLOCK` samples from their extremes."""
    largest = 0.0
    k = first
    while k <= last:
        if k % BLOCK == 0 and k + BLOCK - 1 <= last:
            block = k // BLOCK
            largest = max(largest, block_max[block], -block_min[block])
            k += BLOCK
        else:
            largest = max(largest, abs(acceleration[k]))
            k += 1
    return largest


def lane_start(lane):
    """The first pair offset of ``lane``: its index with the bits of 0 ≤ lane < LANES reversed.

    numba hands each of T threads (a power of 2) a contiguous run of LANES/T
    lanes; reversed bits give that run the offsets ≡ t (mod T) spread over the
    whole of [0, LANES), so slow (small μ) and fast pairs are shared evenly.
    With the lanes' offsets in order, the first thread got the smaller μ of
    every LANES consecutive ones: 25 % more work than the second on the
    benchmark job.
    """
    start, width = 0, LANES
    while width > 1:
        start = 2 * start + lane % 2
        lane //= 2
        width //= 2
    return start


def interval_state(parameters, a_start, a_end, slope, dt, vg_start, x, v, s):
    """Advance a state across one sample interval of ``dt`` [s], handling every event inside it.

    a_start, a_end [m/s²] are the ground acceleration at the interval's ends
    (linear in between), ``slope`` = (a_end − a_start)/dt [m/s³], computed so
    by every caller, vg_start the ground velocity at its start [m/s]; x [m],
    v [m/s] and s (0 holds, ±1 slides with ẋ ≷ 0) the state at its start.

    Returns ``(x, v, s, phase_after_start, input_energy, sliding_path,
    slip_time, new_episodes, peak_abs_x, peak_abs_acceleration)``: the state
    at the interval's end, the phase just after its start, the increments of
    E_I/m [J/kg], of ∫|ẋ|dt [m], of the time spent sliding [s] and of the
    number of slides, max |x| [m] and max |ü| [m/s²] over the interval.
    """
    t = 0.0
    a = a_start
    vg = vg_start
    phase_after_start = s
    input_energy = 0.0
    sliding_path = 0.0
    slip_time = 0.0
    new_episodes = 0
    peak_abs_x = abs(x)
    peak_acceleration = 0.0
    while True:
        remaining = dt - t
        if s == 0:
            lower, upper = band(parameters, x)
            tau, s_next = breakaway(a, a_end, slope, lower, upper)
            if tau > 0.0:  # held: |ü| = |a| up to the hold's end, where a is at most the band's edge
                held_end = a_end if tau >= remaining else a + slope * tau
                peak_acceleration = max(peak_acceleration, abs(a), abs(held_end))
            if tau >= remaining:
                input_energy += stick_input_energy(a, slope, vg, remaining)
                break
            input_energy += stick_input_energy(a, slope, vg, tau)
            if tau > 0.0:
                t += tau
                # the slide starts at the crossing value itself: a − edge = 0 exactly, so it cannot stop at once
                a = upper if s_next < 0 else lower
                vg = ground_at(t, a_start, a_end, slope, vg_start)[1]
            s = s_next
            new_episodes += 1
        else:
            edge = slide_edge(parameters, x, s)
            tau = stop_time(parameters, a, slope, edge, v, s, remaining)
            at_end = tau >= remaining
            if at_end:
                tau = remaining
            x_end, v_end, d_input, d_path, d_acceleration = slid(parameters, a, slope, vg, edge, x, v, s, tau)
            input_energy += d_input
            peak_acceleration = max(peak_acceleration, d_acceleration)
            sliding_path += d_path  # x is monotone within a slide
            slip_time += tau
            x = x_end
            peak_abs_x = max(peak_abs_x, abs(x))
            if at_end:
                if s * v_end > 0.0:
                    v = v_end
                    break
                a = a_end
            else:
                t_stop = t + tau
                if t_stop == t and v == 0.0:
                    # a reversal shorter than the time resolution: the state stays at the edge it slid past
                    # and holds (a moves back into the band here), instead of looping
                    a = edge
                else:
                    t = t_stop
                    a, vg = ground_at(t, a_start, a_end, slope, vg_start)
            v = 0.0
            lower, upper = band(parameters, x)
            if a > upper:
                s = -1
            elif a < lower:
                s = 1
            else:
                s = 0
            if at_end:
                break
        if t == 0.0:
            phase_after_start = s
    return (x, v, s, phase_after_start, input_energy, sliding_path, slip_time, new_episodes, peak_abs_x,
            peak_acceleration)


def holding(state):
    """Whether a state ``(x, v, s, …)`` holds: its phase s is 0."""
    return state[2] == 0


def record_state(record, parameters, state, n):
    """The state at the last of the ``n`` samples of ``record``, from ``state`` at the first, at a cost that follows the slip.

    A hold skips to the sample before the first one outside the model's band
    (:func:`next_exceedance`); a slide goes interval by interval, each one
    without an event in one step, any other through the model's event loop.
    """
    i = 0
    while i < n - 1:
        if holding(state):
            values, block_max, block_min, lower, upper = hold_band(record, parameters, state)
            stick_end = min(max(next_exceedance(values, block_max, block_min, i, lower, upper) - 1, i), n - 1)
            state = held_over(record, parameters, state, i, stick_end)
            i = stick_end
            if i == n - 1:
                break
        else:
            state, through = slid_through(record, parameters, state, i)
            if through:
                i += 1
                continue
        state = crossed(record, parameters, state, i)
        i += 1
    return state


def sweep_pairs(group, columns, first_pair, last_pair, out):
    """The model's ``solved_pair`` for the (record, column) pairs first_pair ≤ pair < last_pair, in parallel lanes.

    Pairs are numbered record-major (pair = record·n_columns + column), one
    column per row of ``columns``; lane j takes every :data:`LANES`-th pair
    from :func:`lane_start` (j).  ``out`` has shape (records, columns, …).
    """
    n_columns = columns.shape[0]
    for lane in prange(LANES):
        for pair in range(first_pair + lane_start(lane), last_pair, LANES):
            record = pair // n_columns
            column = pair - record * n_columns
            solved_pair(group, record, columns, column, out[record, column])


#: ``range`` as plain Python; numba's ``prange`` where :func:`sweep_pairs` is compiled.
prange = range


def offsets(sizes) -> np.ndarray:
    """[0, cumulative sizes…]: where each record (or block run) starts in the concatenated arrays, int64."""
    found = np.zeros(len(sizes) + 1, dtype=np.int64)
    found[1:] = np.cumsum(sizes)
    return found


def run_in_calls(call, pair_work: np.ndarray, first_work: float = 2e6) -> None:
    """Run ``call(first_pair, last_pair)`` over all pairs, in calls of about :data:`CALL_SECONDS` each.

    ``pair_work`` is each (record, column) pair's expected work (its samples);
    the first call does ``first_work`` of it and later ones are sized from the
    speed measured, so that a long sweep stops at once on Ctrl-C.
    """
    work = np.cumsum(pair_work)
    chunk = float(first_work)
    first = 0
    while first < work.size:
        done = work[first - 1] if first else 0
        last = max(int(np.searchsorted(work, done + chunk, side="right")), first + 1)
        start = time.perf_counter()
        call(first, last)
        elapsed = max(time.perf_counter() - start, 1e-6)
        chunk = min(max((work[last - 1] - done) * CALL_SECONDS / elapsed, chunk / 4), chunk * 4)
        first = last
