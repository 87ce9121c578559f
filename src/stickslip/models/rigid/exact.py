"""The compiled exact solver: numba kernels over records × resistances (friction ratios, yield coefficients).

The physics and the event-driven step, :func:`advance_interval`, live in
:mod:`stickslip.models.rigid.events` as plain Python; this module compiles them with
numba (:func:`~stickslip.solvers.compilation.compiled_kernels`) and builds on them:

* :func:`sweep_scalars`: the event engine (:mod:`stickslip.solvers.events`)
  on the block's phase functions, over records × resistances in parallel,
  keeping only end-of-record scalars: it skips each stick stretch with block
  maxima and minima of a and a prefix sum of the stick input energy, so its
  cost follows the slip;
* :func:`record_scalars`: one case of it, serially;
* :func:`sweep_scalars_reference`: the kernel that visits every interval, kept
  as the test oracle and the benchmark's baseline;
* :func:`history_kernel`, which the exact scheme's history
  (:func:`stickslip.models.rigid.exact_scheme.sliding_history`) uses for long records.

Every kernel takes a resistance as the floats (T₊, T₋, b) [m/s²] of
:meth:`stickslip.models.rigid.resistance.Resistance.thresholds`; the Python
functions take friction ratios ``mu`` with ``g``, or ``Resistance`` objects.
"""

from __future__ import annotations

from collections.abc import Sequence

import numba
import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.errors import StickslipError
from stickslip.models.rigid import events
from stickslip.models.rigid.history import SCALAR_NAMES
from stickslip.models.rigid.resistance import Resistance
from stickslip.solvers.compilation import compiled_kernels, engine_pieces, record_engine, sweep_engine
from stickslip.solvers.events import BLOCK, offsets, run_in_calls

_PIECES = engine_pieces()
prepare_record = _PIECES["prepare_record"]
prepare_records = _PIECES["prepare_records"]

_KERNELS = compiled_kernels(events, events.KERNELS, bound=_PIECES, cache=True,
                            inlined=("band", "slide_edge", "stop_time", "slid"))
slip_stop_time = _KERNELS["slip_stop_time"]
slip_increments = _KERNELS["slip_increments"]
resisting_work = _KERNELS["resisting_work"]
advance_interval = _KERNELS["advance_interval"]
history_kernel = _KERNELS["history_kernel"]


@numba.njit(cache=True)
def _store_scalars(out, energy_dissipated, energy_input, absolute_velocity, x, peak, path, slip_time, duration, episodes):
    """Write the end-of-record scalars into ``out`` in the order of :data:`SCALAR_NAMES`."""
    out[0] = energy_dissipated
    out[1] = energy_input
    out[2] = 0.5 * absolute_velocity * absolute_velocity
    out[3] = x
    out[4] = peak
    out[5] = path
    out[6] = slip_time / duration
    out[7] = episodes


@numba.njit(cache=True)
def _reference_record_scalars(acceleration, dt, t_pos, t_neg, body, out):
    """The scalars of one record and one resistance (T₊, T₋, b [m/s²]), one :func:`advance_interval` per interval.

    The straightforward kernel, kept as the test oracle of :func:`_record_scalars`
    and as the benchmark's baseline.
    """
    band_bounds = (body - t_pos, body + t_neg)
    x, v, s = 0.0, 0.0, 0
    vg = 0.0
    energy_input = 0.0
    path = 0.0
    slip_time = 0.0
    episodes = 0
    peak = 0.0
    for i in range(acceleration.size - 1):
        a0 = acceleration[i]
        a1 = acceleration[i + 1]
        x, v, s, _, d_input, d_path, d_slip, d_episodes, d_peak, _ = advance_interval(
            band_bounds, a0, a1, (a1 - a0) / dt, dt, vg, x, v, s
        )
        vg += 0.5 * dt * (a0 + a1)  # as integrate_linear_acceleration, to the same round-off
        energy_input += d_input
        path += d_path
        slip_time += d_slip
        episodes += d_episodes
        peak = max(peak, d_peak)
    _store_scalars(out, resisting_work(path, x, t_pos, t_neg), energy_input, vg + v, x, peak, path,
                   slip_time, (acceleration.size - 1) * dt, episodes)


@numba.njit(cache=True, parallel=True)
def _reference_sweep_kernel(samples, offsets, dts, thresholds, out):
    """:func:`_reference_record_scalars` for every (record, resistance) pair, in parallel over the flattened pairs.

    ``thresholds`` has one row (T₊, T₋, b) [m/s²] per resistance.
    """
    n_columns = thresholds.shape[0]
    for pair in numba.prange((offsets.size - 1) * n_columns):
        record = pair // n_columns
        column = pair - record * n_columns
        acceleration = samples[offsets[record] : offsets[record + 1]]
        _reference_record_scalars(acceleration, dts[record], thresholds[column, 0], thresholds[column, 1],
                                  thresholds[column, 2], out[record, column])


@numba.njit(cache=True, inline="always")
def _hold_band(record, parameters, state):
    """The block holds while lower ≤ a ≤ upper [m/s²]: the samples of a and their block extremes."""
    acceleration, _, _, _, _, block_max, block_min = record
    return acceleration, block_max, block_min, parameters[2], parameters[3]


@numba.njit(cache=True, inline="always")
def _held_over(record, parameters, state, first, last):
    """The state after holding from sample ``first`` to ``last``: the hold's input energy from the prefix sums."""
    stick_energy = record[4]
    x, v, s, energy_input, path, slip_time, episodes, peak = state
    return x, v, s, energy_input + (stick_energy[last] - stick_energy[first]), path, slip_time, episodes, peak


@numba.njit(cache=True, inline="always")
def _slid_through(record, parameters, state, i):
    """The state after sliding through interval i without a stop (the arithmetic of :func:`advance_interval`)."""
    acceleration, dt, ground_velocity, slope, _, _, _ = record
    x, v, s, energy_input, path, slip_time, episodes, peak = state
    a0 = acceleration[i]
    level = parameters[3] if s < 0 else parameters[2]
    if slip_stop_time(a0, slope[i], level, v, s) >= dt:
        dx, d_input, v_end = slip_increments(a0, slope[i], ground_velocity[i], level, v, s, dt)
        if s * v_end > 0.0:
            x += dx
            return (x, v_end, s, energy_input + d_input, path + abs(dx), slip_time + dt, episodes,
                    max(peak, abs(x))), True
    return state, False


@numba.njit(cache=True, inline="always")
def _crossed(record, parameters, state, i):
    """The state after interval i with every event inside it (:func:`advance_interval`)."""
    acceleration, dt, ground_velocity, slope, _, _, _ = record
    x, v, s, energy_input, path, slip_time, episodes, peak = state
    x, v, s, _, d_input, d_path, d_slip, d_episodes, d_peak, _ = advance_interval(
        (parameters[2], parameters[3]), acceleration[i], acceleration[i + 1], slope[i], dt, ground_velocity[i], x, v, s
    )
    return (x, v, s, energy_input + d_input, path + d_path, slip_time + d_slip, episodes + d_episodes,
            max(peak, d_peak))


_record_state = record_engine(__name__, hold_band=_hold_band, held_over=_held_over,
                              slid_through=_slid_through, crossed=_crossed)


@numba.njit(cache=True)
def _record_scalars(acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min, t_pos, t_neg, body,
                    out):
    """The scalars of one record and one resistance (T₊, T₋, b [m/s²]) into ``out``, at a cost that follows the slip.

    The event engine (:func:`stickslip.solvers.events.record_state`) on the
    block's phase functions: while the block sticks nothing depends on the
    resistance but where the stick ends, the interval before the first sample
    outside [lower, upper]; the stick's input energy is a difference of
    ``stick_energy``; an interval that the block slides through without
    stopping takes the arithmetic of :func:`advance_interval` but none of its
    event loop, any other :func:`advance_interval`.  Equal to
    :func:`_reference_record_scalars` to round-off (identical except for the
    summation order of E_I).
    """
    n = acceleration.size
    x, v, s, energy_input, path, slip_time, episodes, peak = _record_state(
        (acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min),
        (t_pos, t_neg, body - t_pos, body + t_neg), (0.0, 0.0, 0, 0.0, 0.0, 0.0, 0, 0.0), n)
    _store_scalars(out, resisting_work(path, x, t_pos, t_neg), energy_input, ground_velocity[n - 1] + v,
                   x, peak, path, slip_time, (n - 1) * dt, episodes)


@numba.njit(cache=True, inline="always")
def _solved_pair(group, record, thresholds, column, out):
    """:func:`_record_scalars` of one record of a group and one row (T₊, T₋, b) of ``thresholds``."""
    samples, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min, block_offsets = group
    first, last = offsets[record], offsets[record + 1]
    blocks = slice(block_offsets[record], block_offsets[record + 1])
    _record_scalars(samples[first:last], dts[record], ground_velocity[first:last], slope[first:last],
                    stick_energy[first:last], block_max[blocks], block_min[blocks], thresholds[column, 0],
                    thresholds[column, 1], thresholds[column, 2], out)


_sweep_pairs = sweep_engine(__name__, _solved_pair)


@numba.njit(cache=True)
def _single_kernel(acceleration, dt, t_pos, t_neg, body, out):
    """:func:`_record_scalars` for one record and one resistance (T₊, T₋, b [m/s²]), serially (no thread start)."""
    n = acceleration.size
    ground_velocity = np.empty(n)
    slope = np.empty(n)
    stick_energy = np.empty(n)
    block_max = np.empty((n + BLOCK - 1) // BLOCK)
    block_min = np.empty_like(block_max)
    prepare_record(acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min)
    _record_scalars(acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min, t_pos, t_neg, body,
                    out)


#: Samples per group of records whose μ-independent arrays are held at once (~100 MB).
GROUP_SAMPLES = 1 << 22

#: Sample·μ updates of the first call; later calls are sized from the measured speed.
FIRST_CHUNK_WORK = 20_000_000


def _checked_sweep_inputs(accelerations, dts, mu, g, resistances) -> tuple[list[np.ndarray], np.ndarray, np.ndarray]:
    """The records, their time steps [s] and the thresholds (one row T₊, T₋, b [m/s²] per column) of a sweep."""
    records = [checked_acceleration(a, f"record {i}") for i, a in enumerate(accelerations)]
    if not records:
        raise StickslipError("sweep_scalars: no records given")
    dts = np.broadcast_to(np.asarray(dts, dtype=np.float64), (len(records),))
    dts = np.ascontiguousarray([checked_positive(dt, f"time step of record {i} [s]") for i, dt in enumerate(dts)])
    return records, dts, _thresholds(mu, g, resistances)


def _thresholds(mu, g, resistances) -> np.ndarray:
    """The (n, 3) array of (T₊, T₋, b) [m/s²] for friction ratios ``mu`` under ``g``, or for ``resistances``."""
    if resistances is not None:
        if mu is not None or g is not None:
            raise StickslipError("give friction ratios mu (with g) or resistances, not both")
        rows = [resistance.thresholds() for resistance in resistances]
        if not rows:
            raise StickslipError("resistances: expected at least one")
        return np.array(rows, dtype=np.float64)
    if mu is None or g is None:
        raise StickslipError("give friction ratios mu and gravity g, or resistances")
    mu = np.atleast_1d(np.asarray(mu, dtype=np.float64))
    if mu.ndim != 1 or mu.size == 0:
        raise StickslipError(f"friction ratios mu: expected a non-empty 1-D array, got shape {mu.shape}")
    bad = mu[~(np.isfinite(mu) & (mu > 0.0))]
    if bad.size:
        checked_positive(bad[0], "friction ratio mu")  # raises, naming the first bad value
    mu_g = mu * checked_positive(g, "gravity g [m/s2]")
    thresholds = np.zeros((mu.size, 3))
    thresholds[:, 0] = mu_g
    thresholds[:, 1] = mu_g
    return thresholds


def _groups(sizes: np.ndarray) -> list[tuple[int, int]]:
    """Consecutive record ranges [first, last) of at most :data:`GROUP_SAMPLES` samples (or one record)."""
    groups, first, total = [], 0, 0
    for index, size in enumerate(sizes):
        if index > first and total + size > GROUP_SAMPLES:
            groups.append((first, index))
            first, total = index, 0
        total += size
    groups.append((first, len(sizes)))
    return groups


def sweep_scalars(
    accelerations: Sequence[np.ndarray] | np.ndarray,
    dts: Sequence[float] | np.ndarray | float,
    mu: np.ndarray | None = None,
    g: float | None = None,
    *,
    resistances: Sequence[Resistance] | None = None,
) -> np.ndarray:
    """End-of-record scalars for every record and friction ratio (or resistance), in parallel.

    The work is split into groups of records and calls of a fraction of a
    second each, so memory stays bounded and Ctrl-C stops a long sweep at once.

    Parameters
    ----------
    accelerations:
        The records' ground accelerations [m/s²]: a list of 1-D arrays (any
        lengths) or a 2-D array with one record per row.
    dts:
        Sample interval of each record [s] (one number for all records, or one per record).
    mu:
        Friction ratios μ [-], 1-D: a flat surface, T₊ = T₋ = μ·g.
    g:
        Gravitational acceleration [m/s²], with ``mu``.
    resistances:
        Instead of ``mu`` and ``g``: one :class:`Resistance` per column, e.g.
        ``[Resistance.one_way(ky, g) for ky in grid]``.

    Returns
    -------
    numpy.ndarray
        Shape (n_records, n_columns, len(SCALAR_NAMES)), columns as in
        :data:`SCALAR_NAMES`: energies per unit mass [J/kg] (multiply by the
        block mass for J; E_df = Σ T_s·|Δx|, see
        :func:`~stickslip.models.rigid.events.resisting_work`), displacements and
        sliding path [m], slip_fraction = slip time / record duration [-],
        n_slip_episodes (a count, as float).
    """
    records, dts, thresholds = _checked_sweep_inputs(accelerations, dts, mu, g, resistances)
    n_columns = thresholds.shape[0]
    sizes = np.array([a.size for a in records], dtype=np.int64)
    out = np.empty((len(records), n_columns, len(SCALAR_NAMES)))
    for first, last in _groups(sizes):
        group_sizes = sizes[first:last]
        record_offsets = offsets(group_sizes)
        block_offsets = offsets((group_sizes + BLOCK - 1) // BLOCK)
        samples = np.concatenate(records[first:last])
        ground_velocity = np.empty_like(samples)
        slope = np.empty_like(samples)
        stick_energy = np.empty_like(samples)
        block_max = np.empty(block_offsets[-1])
        block_min = np.empty_like(block_max)
        group_dts = dts[first:last]
        prepare_records(samples, record_offsets, group_dts, ground_velocity, slope, stick_energy, block_max,
                        block_min, block_offsets)
        group = (samples, record_offsets, group_dts, ground_velocity, slope, stick_energy, block_max, block_min,
                 block_offsets)
        run_in_calls(lambda first_pair, last_pair: _sweep_pairs(group, thresholds, first_pair, last_pair,
                                                                out[first:last]),
                     np.repeat(group_sizes, n_columns), FIRST_CHUNK_WORK)
    return out


def sweep_scalars_reference(
    accelerations: Sequence[np.ndarray] | np.ndarray,
    dts: Sequence[float] | np.ndarray | float,
    mu: np.ndarray | None = None,
    g: float | None = None,
    *,
    resistances: Sequence[Resistance] | None = None,
) -> np.ndarray:
    """:func:`sweep_scalars` by the straightforward kernel that visits every sample interval.

    The test oracle of :func:`sweep_scalars` and the benchmark's baseline; same
    arguments and result.
    """
    records, dts, thresholds = _checked_sweep_inputs(accelerations, dts, mu, g, resistances)
    out = np.empty((len(records), thresholds.shape[0], len(SCALAR_NAMES)))
    _reference_sweep_kernel(np.concatenate(records), offsets([a.size for a in records]), dts, thresholds, out)
    return out


def record_scalars(
    acceleration: np.ndarray,
    dt: float,
    mu: float | None = None,
    g: float | None = None,
    *,
    resistance: Resistance | None = None,
) -> np.ndarray:
    """:func:`sweep_scalars` for one record and one friction ratio (or ``resistance``), in the calling thread.

    Cheaper than starting the parallel kernel for a single case, as when a
    maximum over μ is refined one μ at a time.  Returns the len(SCALAR_NAMES)
    scalars (units as in :func:`sweep_scalars`).
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    if resistance is None:
        if mu is None or g is None:
            raise StickslipError("give a friction ratio mu and gravity g, or a resistance")
        resistance = Resistance.friction(mu, g)
    elif mu is not None or g is not None:
        raise StickslipError("give a friction ratio mu (with g) or a resistance, not both")
    out = np.empty(len(SCALAR_NAMES))
    _single_kernel(acceleration, checked_positive(dt, "time step dt [s]"), *resistance.thresholds(), out)
    return out
