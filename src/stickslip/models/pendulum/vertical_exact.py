"""The flat block with Coulomb friction under a horizontal and a vertical ground motion, solved exactly.

Per unit mass, relative to the ground, with the horizontal ground
acceleration a(t) and the normal force N/m = n(t) = g + a_v(t)
(:mod:`stickslip.models.pendulum.normal_force`; a_v positive up), both linear between
samples, the block

* **sticks** (u̇ = 0) while |a| ≤ μ·n: a − μn ≤ 0 and −a − μn ≤ 0, two
  functions linear in time, so that breakaway is a linear crossing;
* **slides** in the direction s = ±1 with ü = −a − s·μ·n = −d(τ), d linear in
  time: u̇ is quadratic and u cubic, and a stop is the quadratic root of the
  flat block (:func:`stickslip.solvers.events.first_stop_time`);
* **lifts off** where n reaches zero (a linear crossing): no friction, ü = −a,
  and **touches down** where n turns positive, sliding on along u̇ (or, at
  rest, as a stuck block breaks away at n = 0: along −a).

Every event is located to round-off, as on the flat block without the
vertical motion (which is this block with a_v = 0).  The ledger per unit mass,
each term an exact polynomial integral over every sub-interval:
E_df = ∫μ·n·|du| = μ·s·(n₀·Δu + ṅ·∫σ·u̇ dσ) over each slip, E_I = ∫ü·u̇_g dt
with ü = a in stick, −s·μ·n in slip and 0 in flight, E_k = ½·(u̇_g + u̇)²;
E_k − E_k(0) + E_df = E_I closes to round-off (on a flat surface the
potential energy E_p and the vertical motion's work W_v are zero).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.records.process import integrate_linear_acceleration
from stickslip.models.pendulum.normal_force import normal_acceleration
from stickslip.solvers.compilation import engine_pieces, sweep_engine
from stickslip.solvers.events import BLOCK, offsets, run_in_calls
from stickslip.solvers.ledger import FLIGHT, HISTORY_COLUMNS, SCALAR_NAMES, history_dict, store_scalars

_PIECES = engine_pieces()
first_stop_time = _PIECES["first_stop_time"]
ground_at = _PIECES["ground_at"]
stick_input_energy = _PIECES["stick_input_energy"]
largest_magnitude = _PIECES["largest_magnitude"]
prepare_records = _PIECES["prepare_records"]
next_exceedance = _PIECES["next_exceedance"]


@numba.njit(cache=True)
def flight_peak(x, v, a, slope, span):
    """max |u| [m] where u̇ = 0 inside a flight of ``span`` [s] from u = x [m], u̇ = v [m/s] under ü = −a − slope·σ.

    u̇(σ) = v − a·σ − slope·σ²/2: both roots in (0, span), by the
    cancellation-free quadratic formula; 0 when there is none.
    """
    peak = 0.0
    c0, c1, c2 = v, -a, -0.5 * slope
    roots = (math.inf, math.inf)
    if c2 == 0.0:
        if c1 != 0.0:
            roots = (-c0 / c1, math.inf)
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc >= 0.0:
            q = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
            roots = (q / c2, c0 / q if q != 0.0 else math.inf)
    for root in roots:
        if 0.0 < root < span:
            peak = max(peak, abs(x + root * (v - root * (0.5 * a + slope * root / 6.0))))
    return peak


@numba.njit(cache=True)
def liftoff_time(n, n_slope, n_end):
    """The time [s] from now to lift-off, where N/m = n + n_slope·τ [m/s², m/s³] reaches zero, or +inf.

    At once when n < 0, or n = 0 not rising (a touchdown leaves n = 0 rising);
    inside the interval when the sample value ``n_end`` is at most zero.
    """
    if n < 0.0 or (n == 0.0 and n_slope <= 0.0):
        return 0.0
    if n_slope < 0.0 and n_end <= 0.0:
        return -n / n_slope
    return math.inf


@numba.njit(cache=True)
def advance_interval(a_start, a_end, slope, n_start, n_end, n_slope, dt, vg_start, mu, x, v, s):
    """Advance the block across one sample interval [s] with every event inside it; see the module docstring.

    a_start, a_end [m/s²] and ``slope`` [m/s³]: the horizontal ground
    acceleration; n_start, n_end [m/s²] and ``n_slope`` [m/s³]: N/m = g + a_v;
    vg_start u̇_g [m/s] at the start; ``mu`` μ [-]; x [m], v [m/s] and s (0
    stick, ±1 slip, :data:`FLIGHT`) the state at the start.  Returns ``(x, v,
    s, phase_after_start, input_energy, dissipated, sliding_path, slip_time,
    flight_time, new_episodes, peak_abs_x, peak_abs_acceleration)``: the state
    at the end, the phase just after the start, the increments of E_I/m and
    E_df/m [J/kg], of the path [m], of the time sliding and lifted off [s] and
    of the stick-to-motion transitions, max |u| [m] and max |ü| [m/s²] over the interval.
    """
    t = 0.0
    a = a_start
    n = n_start
    vg = vg_start
    phase_after_start = s
    input_energy = 0.0
    dissipated = 0.0
    sliding_path = 0.0
    slip_time = 0.0
    flight_time = 0.0
    new_episodes = 0
    peak_abs_x = abs(x)
    peak_acceleration = 0.0
    while True:
        remaining = dt - t
        if s == FLIGHT:
            if n > 0.0:
                tau = 0.0
            elif n_slope > 0.0 and n_end > 0.0:
                tau = -n / n_slope
            else:
                tau = math.inf
            span = min(tau, remaining)
            peak_abs_x = max(peak_abs_x, flight_peak(x, v, a, slope, span))
            x += span * (v - span * (0.5 * a + slope * span / 6.0))
            v -= span * (a + 0.5 * slope * span)
            peak_abs_x = max(peak_abs_x, abs(x))
            flight_time += span
            if tau >= remaining:
                break
            t += tau
            a, vg = ground_at(t, a_start, a_end, slope, vg_start)
            n = 0.0
            # touch down sliding on along u̇; from rest, as a stuck block breaks away at n = 0: along −a
            if v > 0.0 or (v == 0.0 and a < 0.0):
                s = 1
            elif v < 0.0 or a > 0.0:
                s = -1
            else:
                s = 0
        elif s == 0:
            lift = liftoff_time(n, n_slope, n_end)
            upper_excess = a - mu * n  # > 0: slides towards −u
            lower_excess = -a - mu * n  # > 0: slides towards +u
            if upper_excess > 0.0:
                tau, s_next = 0.0, -1
            elif lower_excess > 0.0:
                tau, s_next = 0.0, 1
            else:
                tau, s_next = math.inf, 0
                rate = slope - mu * n_slope
                if rate > 0.0 and a_end - mu * n_end > 0.0:
                    tau, s_next = -upper_excess / rate, -1
                rate = -slope - mu * n_slope
                if rate > 0.0 and -a_end - mu * n_end > 0.0 and -lower_excess / rate < tau:
                    tau, s_next = -lower_excess / rate, 1
            if lift <= tau:
                tau, s_next = lift, FLIGHT
            if tau > 0.0:  # held: |ü| = |a| up to the stick's end
                held_end = a_end if tau >= remaining else a + slope * tau
                peak_acceleration = max(peak_acceleration, abs(a), abs(held_end))
            if tau >= remaining:
                input_energy += stick_input_energy(a, slope, vg, remaining)
                break
            input_energy += stick_input_energy(a, slope, vg, tau)
            if tau > 0.0:
                t += tau
                a_then, vg = ground_at(t, a_start, a_end, slope, vg_start)
                if s_next == FLIGHT:
                    n = 0.0
                    a = a_then
                else:
                    n = n_start + n_slope * t
                    a = -s_next * mu * n  # the slip starts with a + s·μ·n = 0 exactly
            s = s_next
            new_episodes += 1
        else:
            drift = a + s * mu * n
            drift_slope = slope + s * mu * n_slope
            stop = first_stop_time(s * v, -s * drift, -0.5 * s * drift_slope)
            lift = liftoff_time(n, n_slope, n_end)
            lifts = lift < stop
            tau = min(stop, lift)
            at_end = tau >= remaining
            if at_end:
                tau = remaining
            t2 = tau * tau
            dx = tau * (v - tau * (0.5 * drift + drift_slope * tau / 6.0))
            v_end = v - tau * (drift + 0.5 * drift_slope * tau)
            input_energy -= s * mu * tau * (n * vg + tau * (0.5 * (n * a + n_slope * vg)
                                                            + tau * ((0.5 * n * slope + n_slope * a) / 3.0
                                                                     + 0.125 * n_slope * slope * tau)))
            dissipated += s * mu * (n * dx + n_slope * t2 * (0.5 * v - tau * (drift / 3.0 + 0.125 * drift_slope * tau)))
            peak_acceleration = max(peak_acceleration, mu * n, mu * (n + n_slope * tau))
            sliding_path += abs(dx)  # u is monotone within a slip
            slip_time += tau
            x += dx
            peak_abs_x = max(peak_abs_x, abs(x))
            if at_end:
                if s * v_end > 0.0:
                    v = v_end
                    break
                a, n = a_end, n_end
            elif lifts:
                v = v_end
                t += tau
                a, vg = ground_at(t, a_start, a_end, slope, vg_start)
                n = 0.0
                s = FLIGHT
                if t == 0.0:
                    phase_after_start = s
                continue
            else:
                t_stop = t + tau
                if t_stop == t and v == 0.0:
                    # a slip shorter than the time resolution: the block stays at the edge it slid past and sticks
                    a = -s * mu * n
                else:
                    t = t_stop
                    a, vg = ground_at(t, a_start, a_end, slope, vg_start)
                    n = n_start + n_slope * t
            v = 0.0
            if n <= 0.0:
                s = FLIGHT
            elif a > mu * n:
                s = -1
            elif a < -mu * n:
                s = 1
            else:
                s = 0
            if at_end:
                break
        if t == 0.0:
            phase_after_start = s
    return (x, v, s, phase_after_start, input_energy, dissipated, sliding_path, slip_time, flight_time,
            new_episodes, peak_abs_x, peak_acceleration)


@numba.njit(cache=True)
def history_kernel(acceleration, normal, ground_velocity, dt, mu, g, history, out):
    """One record's history into ``history`` (n × len(HISTORY_COLUMNS)) and its scalars into ``out``.

    ``acceleration`` a [m/s²], ``normal`` N/m = g + a_v [m/s²] and
    ``ground_velocity`` [m/s] at the samples; ``mu`` μ [-]; ``g`` [m/s²] for
    the base shear over the weight.
    """
    n = acceleration.size
    x, v, s = 0.0, 0.0, 0
    energy_input = 0.0
    dissipated = 0.0
    path = 0.0
    slip_time = 0.0
    flight_time = 0.0
    episodes = 0
    peak = 0.0
    peak_acceleration = 0.0
    history[0, :] = 0.0
    for i in range(n - 1):
        a0, n0 = acceleration[i], normal[i]
        x, v, s, phase_i, d_input, d_dissipated, d_path, d_slip, d_flight, d_episodes, d_peak, d_acceleration = \
            advance_interval(a0, acceleration[i + 1], (acceleration[i + 1] - a0) / dt, n0, normal[i + 1],
                             (normal[i + 1] - n0) / dt, dt, ground_velocity[i], mu, x, v, s)
        history[i, 2] = phase_i
        energy_input += d_input
        dissipated += d_dissipated
        path += d_path
        slip_time += d_slip
        flight_time += d_flight
        episodes += d_episodes
        peak = max(peak, d_peak)
        peak_acceleration = max(peak_acceleration, d_acceleration)
        history[i + 1, 0] = x
        history[i + 1, 1] = v
        history[i + 1, 3] = dissipated
        history[i + 1, 4] = energy_input
        history[i + 1, 5] = 0.0  # W_v: no work on a flat surface
        history[i + 1, 6] = path
    history[n - 1, 2] = s
    store_scalars(out, dissipated, energy_input, 0.0, ground_velocity[n - 1] + v, 0.0, x, peak, path, slip_time,
                  (n - 1) * dt, episodes, peak_acceleration, g, flight_time)


@numba.njit(cache=True)
def _prepare_ratio(acceleration, normal, ratio, ratio_max, ratio_min):
    """|a|/n at the samples (+inf where n ≤ 0: lifted off) and its maxima and minima over blocks of :data:`BLOCK`.

    A block sticks from sample i to sample j exactly when the ratio stays at
    most μ at every sample between: both stick conditions are linear between samples.
    """
    for k in range(acceleration.size):
        ratio[k] = abs(acceleration[k]) / normal[k] if normal[k] > 0.0 else math.inf
    for block in range(ratio_max.size):
        highest = ratio[block * BLOCK]
        lowest = highest
        for k in range(block * BLOCK + 1, min((block + 1) * BLOCK, acceleration.size)):
            highest = max(highest, ratio[k])
            lowest = min(lowest, ratio[k])
        ratio_max[block] = highest
        ratio_min[block] = lowest


@numba.njit(cache=True)
def _record_scalars(acceleration, normal, dt, ground_velocity, slope, stick_energy, block_max, block_min, ratio,
                    ratio_max, ratio_min, mu, g, out):
    """The scalars of one record and one μ into ``out``, at a cost that follows the slip.

    A stick skips to the first sample whose |a|/n exceeds μ; a slipping
    interval without a stop or a lift-off is one polynomial step; any other
    goes through :func:`advance_interval`.  Equal to :func:`history_kernel`'s
    scalars to round-off.  The loop of :func:`stickslip.solvers.events.record_state`
    written out: on the engine's own, driven by phase functions over this
    record's eleven arrays, the sweep took 30 % more CPU time.
    """
    n = acceleration.size
    x, v, s = 0.0, 0.0, 0
    energy_input = 0.0
    dissipated = 0.0
    path = 0.0
    slip_time = 0.0
    flight_time = 0.0
    episodes = 0
    peak = 0.0
    peak_acceleration = 0.0
    i = 0
    while i < n - 1:
        if s == 0:
            stick_end = min(max(next_exceedance(ratio, ratio_max, ratio_min, i, -math.inf, mu) - 1, i), n - 1)
            energy_input += stick_energy[stick_end] - stick_energy[i]
            peak_acceleration = max(peak_acceleration, largest_magnitude(acceleration, block_max, block_min, i,
                                                                          stick_end))
            i = stick_end
            if i == n - 1:
                break
        a0, n0 = acceleration[i], normal[i]
        n_slope = (normal[i + 1] - n0) / dt
        if s != 0 and s != FLIGHT and normal[i + 1] > 0.0:
            drift = a0 + s * mu * n0
            drift_slope = slope[i] + s * mu * n_slope
            if first_stop_time(s * v, -s * drift, -0.5 * s * drift_slope) >= dt:
                v_end = v - dt * (drift + 0.5 * drift_slope * dt)
                if s * v_end > 0.0:
                    vg = ground_velocity[i]
                    dx = dt * (v - dt * (0.5 * drift + drift_slope * dt / 6.0))
                    energy_input -= s * mu * dt * (n0 * vg + dt * (0.5 * (n0 * a0 + n_slope * vg) + dt * (
                        (0.5 * n0 * slope[i] + n_slope * a0) / 3.0 + 0.125 * n_slope * slope[i] * dt)))
                    dissipated += s * mu * (n0 * dx + n_slope * dt * dt * (0.5 * v - dt * (
                        drift / 3.0 + 0.125 * drift_slope * dt)))
                    peak_acceleration = max(peak_acceleration, mu * n0, mu * (n0 + n_slope * dt))
                    path += abs(dx)
                    slip_time += dt
                    x += dx
                    v = v_end
                    peak = max(peak, abs(x))
                    i += 1
                    continue
        x, v, s, _, d_input, d_dissipated, d_path, d_slip, d_flight, d_episodes, d_peak, d_acceleration = \
            advance_interval(a0, acceleration[i + 1], slope[i], n0, normal[i + 1], n_slope, dt, ground_velocity[i],
                             mu, x, v, s)
        energy_input += d_input
        dissipated += d_dissipated
        path += d_path
        slip_time += d_slip
        flight_time += d_flight
        episodes += d_episodes
        peak = max(peak, d_peak)
        peak_acceleration = max(peak_acceleration, d_acceleration)
        i += 1
    store_scalars(out, dissipated, energy_input, 0.0, ground_velocity[n - 1] + v, 0.0, x, peak, path, slip_time,
                  (n - 1) * dt, episodes, peak_acceleration, g, flight_time)


@numba.njit(cache=True)
def _prepare_records(samples, normals, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min,
                     ratio, ratio_max, ratio_min, block_offsets):
    """The μ-independent arrays of every record: the engine's (:func:`~stickslip.solvers.events.prepare_records`)
    and those of |a|/n."""
    prepare_records(samples, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min, block_offsets)
    for record in range(offsets.size - 1):
        first, last = offsets[record], offsets[record + 1]
        blocks = slice(block_offsets[record], block_offsets[record + 1])
        _prepare_ratio(samples[first:last], normals[first:last], ratio[first:last], ratio_max[blocks],
                       ratio_min[blocks])


@numba.njit(cache=True, inline="always")
def _solved_pair(group, record, mus, column, out):
    """:func:`_record_scalars` of one record of a group and one friction ratio ``mus[column]``."""
    (samples, normals, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min, ratio, ratio_max,
     ratio_min, block_offsets, g) = group
    first, last = offsets[record], offsets[record + 1]
    blocks = slice(block_offsets[record], block_offsets[record + 1])
    _record_scalars(samples[first:last], normals[first:last], dts[record], ground_velocity[first:last],
                    slope[first:last], stick_energy[first:last], block_max[blocks], block_min[blocks],
                    ratio[first:last], ratio_max[blocks], ratio_min[blocks], mus[column], g, out)


_sweep_pairs = sweep_engine(__name__, _solved_pair)


def vertical_history(acceleration, vertical, dt: float, mu: float, g: float = STANDARD_GRAVITY) -> dict:
    """The exact history of a flat block with Coulomb friction under a horizontal and a vertical ground motion.

    Parameters
    ----------
    acceleration:
        Horizontal ground acceleration a [m/s²] at the samples, linear in between.
    vertical:
        Vertical ground acceleration a_v [m/s², positive up] at the same
        samples, or ``None`` (N = m·g: the flat block of :mod:`~stickslip.models.rigid.events`).
    dt:
        Sample interval [s].
    mu:
        Friction ratio μ [-].
    g:
        Gravity [m/s²].

    Returns
    -------
    dict
        As :func:`stickslip.models.pendulum.exact.pendulum_history` (``phase``
        2 where the block has lifted off; ``potential_energy`` and
        ``energy_input_vertical`` zero on a flat surface), with
        ``energy_dissipated`` = ∫μ·(g + a_v)·|du| [J/kg].
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    mu = checked_positive(mu, "friction ratio mu (--mu)")
    normal = normal_acceleration(vertical, acceleration.size, g)
    ground_velocity, _ = integrate_linear_acceleration(acceleration, dt)
    history = np.empty((acceleration.size, len(HISTORY_COLUMNS)))
    scalars = np.empty(len(SCALAR_NAMES))
    history_kernel(acceleration, normal, ground_velocity, dt, mu, g, history, scalars)
    return history_dict(history, scalars, ground_velocity, dt, 0.0)


def vertical_sweep(accelerations, verticals, dts, mu, g: float = STANDARD_GRAVITY) -> np.ndarray:
    """End-of-record scalars of the flat block under both ground motions for every record and μ, in parallel.

    ``accelerations`` and ``verticals`` [m/s², a_v positive up; an entry
    ``None`` is no vertical motion] are lists of 1-D arrays, one pair per
    record; ``dts`` [s] one number or one per record; ``mu`` [-] 1-D.  Returns
    shape (records, len(mu), len(SCALAR_NAMES)) per unit mass, in the units of
    :data:`~stickslip.solvers.ledger.SCALAR_UNITS`.
    """
    g = checked_positive(g, "gravity g [m/s2]")
    records = [checked_acceleration(a, f"record {i}") for i, a in enumerate(accelerations)]
    if not records:
        raise StickslipError("vertical sweep: no records given")
    if len(verticals) != len(records):
        raise StickslipError(f"vertical sweep: {len(verticals)} vertical components for {len(records)} records")
    normals = [normal_acceleration(vertical, record.size, g) for vertical, record in zip(verticals, records)]
    dts = np.ascontiguousarray([checked_positive(dt, f"time step of record {i} [s]")
                                for i, dt in enumerate(np.broadcast_to(np.asarray(dts, dtype=float),
                                                                       (len(records),)))])
    mus = np.array([checked_positive(m, "friction ratio mu (--mu)") for m in np.atleast_1d(mu)], dtype=float)
    sizes = np.array([a.size for a in records], dtype=np.int64)
    record_offsets = offsets(sizes)
    block_offsets = offsets((sizes + BLOCK - 1) // BLOCK)
    samples = np.concatenate(records)
    normal_samples = np.concatenate(normals)
    ground_velocity, slope, stick_energy, ratio = (np.empty_like(samples) for _ in range(4))
    block_max, block_min, ratio_max, ratio_min = (np.empty(block_offsets[-1]) for _ in range(4))
    _prepare_records(samples, normal_samples, record_offsets, dts, ground_velocity, slope, stick_energy, block_max,
                     block_min, ratio, ratio_max, ratio_min, block_offsets)
    group = (samples, normal_samples, record_offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min,
             ratio, ratio_max, ratio_min, block_offsets, float(g))
    out = np.empty((len(records), mus.size, len(SCALAR_NAMES)))
    run_in_calls(lambda first, last: _sweep_pairs(group, mus, first, last, out), np.repeat(sizes, mus.size))
    return out
