"""Record pairs solved in the plane, one case or many in parallel: the plane's entry points.

:func:`solve_pair_on_surface` solves one record pair for one case (the friction
law and the surface's curvature a model composes,
:mod:`~stickslip.solvers.plane.resistance`) with or without the vertical
motion, with its history or without; :func:`sweep_pairs_on_surface` solves
every (pair, case) in parallel, the friction-independent arrays of each pair
computed once; :func:`check_progress` refuses, with one line, a solve on which
the solver gave up.  With the speed scale S = 2·(max|a| + μ·max n)·dt the
regimes' thresholds are s_switch = :data:`SWITCH_RATIO`·S and s_lock =
``lock_ratio``·S (:mod:`stickslip.solvers.plane`).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.solvers.plane.interval import MAX_PASSES, advance_interval
from stickslip.solvers.plane.manifold import FLAT_ORDER
from stickslip.solvers.plane.resistance import LAW_SIZE, MU_FAST, MU_SLOW, ORDER, fill_law, ground_acceleration
from stickslip.solvers.plane.settled import settled_plan, settled_velocity
from stickslip.solvers.plane.state import (
    A1, A2, DISSIPATED, FLIGHT, G1, G2, GRAVITY, INPUT, K1, K2, N_STATE, NORMAL, NORMAL_RATE, PATH, SEGMENT_SIZE,
    SETTLED_SLIDING, SLIDING, STALLED, STICK, TAU, U1, U2, V1, V2, VERTICAL)
from stickslip.solvers.plane.stepping import WORK_ROWS
from stickslip.solvers.plane.stick import AMAX2, BLOCK, NMAX, block_sticks, interval_sticks, n_blocks, prepare_record, \
    stuck_peak

#: Default relative tolerance of the velocity per step.
RTOL = 1e-10
#: Default ratio s_lock / S below which the closed-form stops are tried (:mod:`~stickslip.solvers.plane.stopping`).
LOCK_RATIO = 1e-5
#: The velocity error is measured against rtol·(|v| + VELOCITY_FLOOR·S): below that speed, absolutely.
VELOCITY_FLOOR = 1e-3
#: Default ratio s_switch / (2·(max|a| + μ·g)·dt) below which the slow regime takes over.
SWITCH_RATIO = 0.01

#: Columns of the end-of-record scalars of a flat surface, Coulomb friction and no vertical motion, per unit mass.
PLANAR_SCALAR_NAMES = (
    "energy_dissipated",       # J/kg
    "energy_input",            # J/kg
    "kinetic_energy_final",    # J/kg
    "residual_displacement_1",  # m
    "residual_displacement_2",  # m
    "peak_displacement",       # m, largest |u|
    "sliding_path",            # m
    "slip_fraction",           # 1
    "n_slip_episodes",         # 1
)
#: Columns of the end-of-record scalars on a curved surface or with the vertical (:func:`solve_pair_on_surface`).
SURFACE_SCALAR_NAMES = PLANAR_SCALAR_NAMES + (
    "energy_input_vertical",   # J/kg, W_v/m = −∫κ·(n − g)·u·v dt
    "flight_time",             # s, time with n ≤ 0
    "peak_absolute_acceleration",  # m/s², largest |ü| (the base shear per unit mass), at samples, step ends, events
)
#: Columns of a history (one row per sample, the state just after it); a flat block's keeps the first eight.
HISTORY_NAMES = (
    "displacement_1", "displacement_2",  # m
    "velocity_1", "velocity_2",          # m/s
    "moving",                            # 1 when sliding or flying, 0 when stuck
    "energy_dissipated",                 # J/kg
    "energy_input",                      # J/kg
    "sliding_path",                      # m
    "energy_input_vertical",             # J/kg
    "flying",                            # 1 when n ≤ 0 (lifted off)
)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _store_row(history, row, y, motion):
    """Write the state after sample ``row`` into ``history`` (:data:`HISTORY_NAMES`; as many columns as it has)."""
    history[row, 0] = y[U1]
    history[row, 1] = y[U2]
    history[row, 2] = y[V1]
    history[row, 3] = y[V2]
    history[row, 4] = 0.0 if motion == STICK else 1.0
    history[row, 5] = y[DISSIPATED]
    history[row, 6] = y[INPUT]
    history[row, 7] = y[PATH]
    if history.shape[1] > 8:
        history[row, 8] = y[VERTICAL]
        history[row, 9] = 1.0 if motion == FLIGHT else 0.0


@numba.njit(cache=True, error_model="numpy")
def _solve_record(first, second, normal, gravity, dt, law, rtol, lock_ratio, velocity, stick_energy, bounds, history,
                  out):
    """Solve one record pair for one friction law and surface (``law``); see :func:`solve_pair_on_surface`.

    ``velocity``, ``stick_energy`` and ``bounds`` are the record's arrays of
    :func:`~stickslip.solvers.plane.stick.prepare_record`; ``out`` receives :data:`SURFACE_SCALAR_NAMES`
    (the first nine where it has nine).  Returns NaN, or the record's time [s]
    at which the solver gave up (:data:`~stickslip.solvers.plane.interval.MAX_PASSES`; ``out`` is then NaN).
    """
    n = first.size
    keep = history.shape[0] > 0
    has_normal = normal.size > 0
    peak_ground = 0.0
    highest_normal = bounds[0, NMAX]
    for block in range(bounds.shape[0]):
        peak_ground = max(peak_ground, math.sqrt(bounds[block, AMAX2]))
        highest_normal = max(highest_normal, bounds[block, NMAX])
    friction_scale = max(law[MU_SLOW], law[MU_FAST]) * max(highest_normal, 0.0)
    speed_scale = 2.0 * (peak_ground + friction_scale) * dt
    s_switch = SWITCH_RATIO * speed_scale
    s_lock = lock_ratio * speed_scale
    velocity_floor = VELOCITY_FLOOR * speed_scale
    tolerance = rtol * s_switch * dt
    y = np.zeros(N_STATE)
    f = np.zeros(N_STATE)
    y_new = np.zeros(N_STATE)
    f_new = np.zeros(N_STATE)
    y_try = np.zeros(N_STATE)
    f_try = np.zeros(N_STATE)
    work = np.zeros((WORK_ROWS, N_STATE))
    phi = np.zeros(FLAT_ORDER + 1)
    segment = np.zeros(SEGMENT_SIZE)
    totals = np.zeros(5)
    motion = STICK
    steps = np.array([dt, 0.1 / (peak_ground + friction_scale), dt])
    if keep:
        history[0, :] = 0.0
    i = 0
    while i < n - 1:
        if motion == STICK:  # whole blocks that certainly stick
            skipped = i
            while skipped < n - 1 and block_sticks(bounds, skipped // BLOCK, law, y[U1], y[U2]):
                skipped = min((skipped // BLOCK + 1) * BLOCK, n - 1)
            if skipped > i:
                y[INPUT] += stick_energy[skipped] - stick_energy[i]
                totals[4] = max(totals[4], stuck_peak(first, second, bounds, i, skipped))
                if keep:
                    for row in range(i + 1, skipped + 1):
                        _store_row(history, row, y, motion)
                        history[row, 6] = y[INPUT] - (stick_energy[skipped] - stick_energy[row])
                i = skipped
                continue
        segment[A1] = first[i]
        segment[A2] = second[i]
        segment[K1] = (first[i + 1] - first[i]) / dt
        segment[K2] = (second[i + 1] - second[i]) / dt
        if has_normal:
            segment[NORMAL] = normal[i]
            segment[NORMAL_RATE] = (normal[i + 1] - normal[i]) / dt
        else:
            segment[NORMAL] = gravity
            segment[NORMAL_RATE] = 0.0
        segment[G1] = velocity[i, 0]
        segment[G2] = velocity[i, 1]
        segment[GRAVITY] = gravity
        if motion == STICK and interval_sticks(segment, law, y[U1], y[U2], dt):
            y[INPUT] += stick_energy[i + 1] - stick_energy[i]
            totals[4] = max(totals[4], ground_acceleration(segment, 0.0), ground_acceleration(segment, dt))
        else:
            motion = advance_interval(segment, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f,
                                      motion, steps, work, y_new, f_new, y_try, f_try, phi, totals)
            if motion == STALLED:  # where in the interval it got to (its start where the state is not a number)
                out[:] = math.nan
                return i * dt + (y[TAU] if 0.0 <= y[TAU] <= dt else 0.0)
            if motion == SETTLED_SLIDING and y[V1] > 0.0:
                # the slow manifold depends on the rate of a, which jumps at the sample: the velocity, which does not,
                # goes on from the manifold of the interval that ends (and settles on the next one's)
                settled_velocity(y, y[V1], settled_plan(y, y[V1], segment, law, phi, rtol, velocity_floor,
                                                        int(law[ORDER]))[3], segment, law)
                motion = SLIDING
        if keep:
            _store_row(history, i + 1, y, motion)
        i += 1
    wx = velocity[n - 1, 0] + y[V1]
    wy = velocity[n - 1, 1] + y[V2]
    out[0] = y[DISSIPATED]
    out[1] = y[INPUT]
    out[2] = 0.5 * (wx * wx + wy * wy)
    out[3] = y[U1]
    out[4] = y[U2]
    out[5] = totals[2]
    out[6] = y[PATH]
    out[7] = totals[0] / ((n - 1) * dt)
    out[8] = totals[1]
    if out.size > 9:
        out[9] = y[VERTICAL]
        out[10] = totals[3]
    if out.size > 11:
        out[11] = totals[4]
    return math.nan


@numba.njit(cache=True, error_model="numpy")
def solve_pair_on_surface(first, second, vertical, dt, gravity, mu_slow, mu_fast, rate, inverse_radius, rtol,
                          lock_ratio, history, out):
    """Solve one record pair on a flat or spherical surface, with or without the vertical ground motion.

    Parameters
    ----------
    first, second:
        The horizontal ground acceleration on two orthogonal axes at the samples [m/s²].
    vertical:
        The vertical ground acceleration at the samples [m/s², positive up], or an empty array for none.
    dt:
        The sample interval [s].
    gravity:
        g [m/s²]; the normal force per unit mass is n = g + a_v.
    mu_slow, mu_fast, rate:
        The friction law μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} [1, 1, s/m]; Coulomb where
        μ_fast = μ_slow.
    inverse_radius:
        The surface's curvature 1/R [1/m]; 0 for a flat surface.
    rtol, lock_ratio:
        The relative tolerance of the velocity per step (:data:`RTOL`) and the ratio s_lock/S of the closed-form
        stops (:data:`LOCK_RATIO`).
    history:
        Shape (n, 10), (n, 8) or (0, c): the state just after each sample (:data:`HISTORY_NAMES`, per unit mass).
    out:
        Receives :data:`SURFACE_SCALAR_NAMES` (per unit mass).

    Returns NaN, or the record's time [s] at which the solver gave up
    (:data:`~stickslip.solvers.plane.interval.MAX_PASSES`; ``out`` is then NaN: :func:`check_progress`).
    """
    n = first.size
    law = np.zeros(LAW_SIZE)
    fill_law(mu_slow, mu_fast, rate, inverse_radius, law)
    velocity = np.zeros((n, 2))
    stick_energy = np.zeros(n)
    bounds = np.zeros((n_blocks(n), 7))
    prepare_record(first, second, vertical + gravity, gravity, dt, velocity, stick_energy, bounds)
    return _solve_record(first, second, vertical + gravity, gravity, dt, law, rtol, lock_ratio, velocity,
                         stick_energy, bounds, history, out)


@numba.njit(cache=True, parallel=True, error_model="numpy")
def _sweep_kernel(samples_1, samples_2, vertical, offsets, dts, gravity, cases, rtol, lock_ratio, lanes, out,
                  stalled_at):
    """The compiled :func:`sweep_pairs_on_surface`, its (pair, case) jobs dealt to ``lanes`` threads in turn."""
    n_pairs = offsets.size - 1
    n_cases = cases.shape[0]
    total = offsets[-1]
    has_vertical = vertical.size > 0
    normal = vertical + gravity
    velocity = np.zeros((total, 2))
    stick_energy = np.zeros(total)
    block_offsets = np.zeros(n_pairs + 1, dtype=np.int64)
    for pair in range(n_pairs):
        block_offsets[pair + 1] = block_offsets[pair] + n_blocks(offsets[pair + 1] - offsets[pair])
    bounds = np.zeros((block_offsets[-1], 7))
    for pair in numba.prange(n_pairs):
        first = offsets[pair]
        last = offsets[pair + 1]
        prepare_record(samples_1[first:last], samples_2[first:last], normal[first:last] if has_vertical else normal,
                       gravity, dts[pair], velocity[first:last], stick_energy[first:last],
                       bounds[block_offsets[pair]:block_offsets[pair + 1]])
    no_history = np.zeros((0, 8))
    for lane in numba.prange(lanes):
        law = np.zeros(LAW_SIZE)
        for job in range(lane, n_pairs * n_cases, lanes):
            pair = job // n_cases
            case = job - pair * n_cases
            first = offsets[pair]
            last = offsets[pair + 1]
            fill_law(cases[case, 0], cases[case, 1], cases[case, 2], cases[case, 3], law)
            stalled_at[pair, case] = _solve_record(
                samples_1[first:last], samples_2[first:last], normal[first:last] if has_vertical else normal, gravity,
                dts[pair], law, rtol, lock_ratio, velocity[first:last], stick_energy[first:last],
                bounds[block_offsets[pair]:block_offsets[pair + 1]], no_history, out[pair, case])


def sweep_pairs_on_surface(samples_1, samples_2, vertical, offsets, dts, gravity, cases, rtol, lock_ratio, out):
    """:func:`solve_pair_on_surface` for every (pair, case), in parallel.

    ``samples_1``, ``samples_2`` [m/s²] (and ``vertical`` [m/s², positive up],
    or empty for none) hold the pairs one after the other, pair p in
    ``offsets[p]:offsets[p + 1]``, with intervals ``dts`` [s]; ``gravity`` g
    [m/s²]; ``cases`` has one row (μ_slow, μ_fast, rate [s/m], 1/R [1/m]) per
    case; ``out`` has shape (pairs, cases, len(:data:`SURFACE_SCALAR_NAMES`)) or
    (pairs, cases, 9).  The friction-independent arrays of each pair are
    computed once; the (pair, case) jobs are dealt to numba's threads in turn
    (neighbouring cases cost alike).  Returns, shape (pairs, cases), NaN or
    the record's time [s] at which the solver gave up on that pair and case
    (:func:`check_progress`).
    """
    stalled_at = np.empty(out.shape[:2])
    _sweep_kernel(samples_1, samples_2, vertical, offsets, dts, gravity, np.ascontiguousarray(cases, dtype=float),
                  rtol, lock_ratio, numba.get_num_threads(), out, stalled_at)
    return stalled_at


def check_progress(stalled_at, describe) -> None:
    """Refuse, with one line, a solve or sweep on which the solver gave up (:data:`MAX_PASSES` passes).

    ``stalled_at`` holds what :func:`solve_pair_on_surface` (a float) or
    :func:`sweep_pairs_on_surface` (an array) return: NaN, or the record's time
    [s] at which the solver gave up; ``describe(index)`` names the motion and
    the case at that index of it (``()`` for a float).  Raises
    :class:`~stickslip.errors.StickslipError` for the first that gave up.
    """
    from stickslip.errors import StickslipError

    stalled = ~np.isnan(np.asarray(stalled_at, dtype=float))
    if stalled.any():
        index = tuple(int(k) for k in np.unravel_index(np.argmax(stalled), stalled.shape))
        raise StickslipError(
            f"{describe(index)}: the solver gave up at t = {np.asarray(stalled_at)[index]:.6g} s of the record, after "
            f"{MAX_PASSES} passes of its event loop in one sample interval without reaching the interval's end")
