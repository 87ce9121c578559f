"""The compiled kernels of the friction-linked structure: one sample interval with its events, a record, a sweep.

The state is the augmented vector w = (x, ẋ, u̇_g, a, ȧ, σμ) of m = 2n + 4
numbers (:mod:`~stickslip.solvers.structure.friction_linked` builds the
matrices): inside a sample interval it obeys ẇ = Â_p w with Â_p the phase's
matrix (p = 0 holds, p = 1 slides; the slide's friction is the last entry
σμ times the matrix's column, so that one matrix serves both directions and
every μ).  A search step of δ [s] (:data:`SEARCH_POINTS` per sub-interval of
at most 1/:data:`SUBSTEPS_PER_PERIOD` of the shortest period of either
phase) is one product with exp(Â_p δ) and two quadratic forms, the integrals
∫ẋᵀCẋ dt and ∫(Σ mᵢüᵢ)·u̇_g dt over it (Van Loan's integrals of the phase,
computed once per case).  After each step the watched functions are looked
at: sliding, σ·ṡ (the slide stops where it reaches 0); holding, the friction
force the hold needs against ±μN.  Where one has changed sign, the step is
taken again as the Taylor series of exp(Â_p τ) w from its start (at most
:data:`TERMS` terms, exact to round-off for |λ|τ ≤ 2π/64; the series of w,
of the watched row and of the ledger's factors on it in one product of w
with columns precomputed per case, Âᵏ/k! and its rows), the event located to
round-off on that series (:func:`_root`), and the interval goes on from it in
the new phase.  A sample interval whose search points show no event is one
step (:func:`_quiet_interval`), its search points read from rows precomputed
per case.

The sweep passes a hold in blocks of :data:`~stickslip.solvers.events.BLOCK`
samples where it can prove the block quiet (:func:`_skipped_block`): while the
interface holds, w = f + z with f the structure held from rest over the record
(:func:`held_record`, once per record, the same at every μ) and z the held
structure's free motion from their difference at the hold's start (its slip
s₀ held, the rest decaying), so that any row r on w is r·f + s₀ r·u_s +
Σᵢ (r·vᵢ)(ℓᵢ·δ) e^{λᵢτ}, u_s the held structure's static state at unit slip,
vᵢ, ℓᵢ and λᵢ its modes, δ = z − s₀u_s; |e^{λᵢτ}| ≤ 1 bounds the last sum by
Σᵢ |r·vᵢ||ℓᵢ·δ|.  Where that bound does not keep the hold's force below μN, the
force is taken at each search point of the block from f's (stored per record)
and the modal sum (a complex product per point and mode), and so is a tracked
row whose bound reaches its peak (its peak then taken at the points).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.solvers.compilation import sweep_engine
from stickslip.solvers.events import BLOCK

#: Sub-intervals per shortest period of the two phases, and event-search points per sub-interval (as the layer's
#: exact scheme, :mod:`stickslip.models.layer.exact`).
SUBSTEPS_PER_PERIOD = 16
SEARCH_POINTS = 4

#: The most terms of the Taylor series of exp(Â τ) w for a step of at most δ: |λ|δ ≤ 2π/64, so that the 15th
#: term of a product of two such series is < 1e-20 of the first; a case keeps as many as its δ needs for that
#: (:func:`~stickslip.solvers.structure.friction_linked.series_terms`).
TERMS = 15

#: The most steps that locate an event to round-off (about ten do).
ROOT_STEPS = 256

#: The running totals of a record, in this order (:func:`interval_with_events`).
VISCOUS, DISSIPATED, INPUT, PATH, SLIP_TIME, EPISODES = range(6)
TOTALS = 6

#: A block is passed only where the hold's force (its bound, or its value at a search point with this much of the
#: magnitudes that make it up) stays this much (relative) below μN: both are computed in floating point.
MARGIN = 1e-6


@numba.njit(cache=True)
def _times(matrix, vector, out):
    """out = matrix @ vector, for the small matrices here (faster than BLAS's call)."""
    rows, columns = matrix.shape
    for i in range(rows):
        total = 0.0
        for j in range(columns):
            total += matrix[i, j] * vector[j]
        out[i] = total


@numba.njit(cache=True)
def _dot(left, right):
    """leftᵀ right."""
    total = 0.0
    for i in range(left.size):
        total += left[i] * right[i]
    return total


@numba.njit(cache=True)
def _copy(source, out):
    """out = source, entry by entry (a slice's assignment allocates where they may overlap)."""
    for i in range(out.size):
        out[i] = source[i]


@numba.njit(cache=True)
def _form(vector, matrix):
    """vectorᵀ matrix vector."""
    total = 0.0
    size = vector.size
    for i in range(size):
        row = 0.0
        for j in range(size):
            row += matrix[i, j] * vector[j]
        total += vector[i] * row
    return total


@numba.njit(cache=True)
def _at(series, terms, tau, out):
    """w(τ) = Σₖ Âᵏw/k! τᵏ (Horner) from ``series``' first ``terms``·m numbers (:func:`_columns` of the phase's
    expansion: Âᵏw/k! entry i at k·m + i)."""
    size = out.size
    for j in range(size):
        total = series[(terms - 1) * size + j]
        for k in range(terms - 2, -1, -1):
            total = total * tau + series[k * size + j]
        out[j] = total


@numba.njit(cache=True)
def _polynomial(coefficients, tau):
    """Σ c_k τᵏ (Horner)."""
    total = 0.0
    for k in range(coefficients.size - 1, -1, -1):
        total = total * tau + coefficients[k]
    return total


@numba.njit(cache=True)
def _quadratic_integral(series, first, pairs, terms, tau):
    """∫₀^τ Σ_r (l_r·w(t))(ρ_r·w(t)) dt from the factors' Taylor series in ``series`` (``terms`` = K coefficients
    of l_r·w(t) from ``first`` + r·K, of ρ_r·w(t) ``pairs``·K further on, r < ``pairs``): their product to degree
    K − 1 (the degrees beyond, below (2|λ|τ)ᴷ/K! ≤ 1e-20 of the first, are left out as the series' own terms
    are), integrated exactly, degree by degree (each degree's sum in a register: no scratch array's stores)."""
    total = 0.0
    for degree in range(terms - 1, -1, -1):
        coefficient = 0.0
        for pair in range(pairs):
            left = first + pair * terms
            right = first + (pairs + pair) * terms + degree
            for j in range(degree + 1):
                coefficient += series[left + j] * series[right - j]
        total = total * tau + coefficient / (degree + 1)
    return total * tau


@numba.njit(cache=True)
def _root(coefficients, high, strict):
    """The first τ in (0, high] where Σ c_k τᵏ (negative at 0, past 0 at ``high``) has passed 0 (``strict``: > 0,
    else ≥ 0), to round-off.

    Newton's steps on the polynomial (its value and slope in one Horner
    pass), from the bracket's secant point, kept inside the bracket (a
    bisection where a step leaves it, and every eighth step); once a step no
    longer moves, the next point is the bracket's end moved by one unit in
    the last place toward its other end, until the bracket is one unit wide
    (or the function has reached zero at its end).  Returns the bracket's end
    where the function has passed zero.
    """
    low, q_low = 0.0, coefficients[0]
    q_high = _polynomial(coefficients, high)
    point = low - q_low * (high - low) / (q_high - q_low) if q_high != q_low else 0.5 * (low + high)
    for step in range(ROOT_STEPS):
        if not low < point < high:
            point = 0.5 * (low + high)
            if point <= low or point >= high:
                break
        value, slope = 0.0, 0.0
        for k in range(coefficients.size - 1, -1, -1):
            slope = slope * point + value
            value = value * point + coefficients[k]
        if value > 0.0 or (value == 0.0 and not strict):
            high = point
            if value == 0.0:
                break
        else:
            low = point
        following = point - value / slope if slope != 0.0 else point
        if step % 8 == 7 or not low <= following <= high:
            following = 0.5 * (low + high)
        elif abs(following - point) <= 2.0 * np.spacing(point):  # converged: close the bracket by units
            following = np.nextafter(high, low) if point == high else np.nextafter(low, high)
        if following <= low or following >= high:
            break
        point = following
    return high


@numba.njit(cache=True)
def _watched(sigma, w, stop_row, force_row, limit):
    """The watched function of the phase at w, and which: sliding, −σ·ṡ (≥ 0: stopped); holding, the larger of
    F − μN and −F − μN (> 0: broken away), its sign as the second number (+1 for F − μN)."""
    if sigma != 0:  # a frictionless interface (μN = 0) slides freely: it never stops
        return (-sigma * _dot(stop_row, w) if limit > 0.0 else -1.0), 0
    force = _dot(force_row, w)
    if force >= 0.0:
        return force - limit, 1
    return -force - limit, -1


@numba.njit(cache=True)
def _track(tracked, w, peaks):
    """peaks = max(peaks, |tracked @ w|), row by row."""
    for row in range(tracked.shape[0]):
        peaks[row] = max(peaks[row], abs(_dot(tracked[row], w)))


@numba.njit(cache=True)
def _held(start, end, interface, slips, velocity_slot):
    """Keep a hold's slip exact over a step: ``end``'s s = dᵀx set to ``start``'s and its ṡ to 0 (the step's
    exponential keeps them to round-off only)."""
    slip_error, rate = 0.0, 0.0
    for i in range(interface.size):
        slip_error += interface[i] * (end[i] - start[i])
        rate += interface[i] * end[velocity_slot + i]
    for i in range(interface.size):
        end[i] -= interface[i] * slip_error / slips
        end[velocity_slot + i] -= interface[i] * rate / slips


@numba.njit(cache=True)
def settled_phase(w, sigma, mu, normal_force, force_row, velocity_slot, interface, slips):
    """The phase after a stop (``sigma`` ≠ 0, ṡ = 0 enforced) or a breakaway (``sigma`` = 0): hold while the force
    the hold needs is at most μN, else slide along it; sets w's friction entry σμ and returns σ.

    ``velocity_slot`` is where ẋ starts in w, ``interface`` is d, and
    ``slips`` dᵀd; at a stop, ẋ loses its component along d (ṡ, zero to
    round-off) so that the hold keeps s exactly.
    """
    if sigma != 0:
        rate = 0.0
        for i in range(interface.size):
            rate += interface[i] * w[velocity_slot + i]
        for i in range(interface.size):
            w[velocity_slot + i] -= interface[i] * rate / slips
    w[w.size - 1] = 0.0
    force = _dot(force_row, w)
    if abs(force) <= mu * normal_force:
        new = 0
    else:
        new = 1 if force > 0.0 else -1
    w[w.size - 1] = new * mu
    return new


@numba.njit(cache=True, inline="always")
def _columns(table, w, out):
    """out = Σⱼ table[j] wⱼ: the dots of w with the rows whose columns ``table`` holds, side by side, four entries
    of w to a pass over ``out`` (the compiler takes the columns in vectors; a pass per entry cost as much in the
    loads and stores of ``out`` as in the products)."""
    size = w.size
    for q in range(out.size):
        out[q] = 0.0
    j = 0
    while j + 3 < size:
        first, second, third, fourth = w[j], w[j + 1], w[j + 2], w[j + 3]
        for q in range(out.size):
            out[q] += ((table[j, q] * first + table[j + 1, q] * second)
                       + (table[j + 2, q] * third + table[j + 3, q] * fourth))
        j += 4
    while j < size:
        weight = w[j]
        for q in range(out.size):
            out[q] += table[j, q] * weight
        j += 1


@numba.njit(cache=True, inline="always")
def _quiet_interval(system, dt_steps, w, sigma, mu, totals, highs, values, moments):
    """Advance w over a whole sample interval in one step where no search point shows an event, and say whether
    it did: the watched function at every search point is a dot of w with a row precomputed per case (the
    watched row times exp(Â_p kδ)), and so are the tracked rows and the state at the interval's end (the search
    steps' composed), all in one :func:`_columns` into ``values``.  The same points as
    :func:`interval_with_events`' search, so the same answer to round-off.

    The tracked rows' magnitudes are kept column by column in ``highs`` (as ``values``; :func:`_folded` takes
    them into the peaks), and the ledger's two integrals over the interval, quadratic forms of w, are gathered as
    w wᵀ into ``moments[p]`` (:func:`_gathered` adds them up): both without a reduction or a short loop, so that
    the compiler takes them in vectors.  Only (x, ẋ) of w is advanced: :func:`_start` puts the ground of the
    next interval."""
    interface, slips, velocity_slot = system[5], system[6], system[7]
    points, table = dt_steps[1], dt_steps[8]
    limit = mu * system[4]
    p = 0 if sigma == 0 else 1
    size = w.size
    rows = system[3].shape[1]
    padded = (table.shape[2] - 2 * velocity_slot) // (rows + 1)
    _columns(table[p], w, values)
    for k in range(points):
        if sigma != 0:
            if limit > 0.0 and -sigma * values[k] >= 0.0:
                return False
        elif abs(values[k]) > limit:
            return False
    for c in range(padded, padded + points * rows):
        high = abs(values[c])
        highs[c] = high if high > highs[c] else highs[c]
    for i in range(size):
        weight = w[i]
        for j in range(size):
            moments[p, i, j] += weight * w[j]
    new = values[padded * (rows + 1):]
    if sigma == 0:
        _held(w, new, interface, slips, velocity_slot)
    else:
        slip_start, slip_end = 0.0, 0.0
        for i in range(interface.size):
            slip_start += interface[i] * w[i]
            slip_end += interface[i] * new[i]
        totals[PATH] += abs(slip_end - slip_start)
        totals[DISSIPATED] += limit * abs(slip_end - slip_start)
        totals[SLIP_TIME] += points * dt_steps[0]
    for i in range(2 * velocity_slot):
        w[i] = new[i]
    return True


@numba.njit(cache=True)
def _gathered(dt_steps, moments, totals):
    """Add the ledger's two integrals of the quiet intervals gathered in ``moments`` (:func:`_quiet_interval`) to
    ``totals``, Σ_p Σ_{i≤j} U_p,ij M_p,ij with U the whole interval's integrals (upper triangular), and clear
    them."""
    whole_viscous, whole_input = dt_steps[6], dt_steps[7]
    for p in range(moments.shape[0]):
        viscous, work_input = 0.0, 0.0
        for i in range(moments.shape[1]):
            for j in range(i, moments.shape[2]):
                viscous += whole_viscous[p, i, j] * moments[p, i, j]
                work_input += whole_input[p, i, j] * moments[p, i, j]
        totals[VISCOUS] += viscous
        totals[INPUT] += work_input
    moments[:] = 0.0


@numba.njit(cache=True)
def _folded(system, highs, peaks):
    """Take the tracked rows' magnitudes kept column by column in ``highs`` (:func:`_quiet_interval`) into
    ``peaks``, and clear them."""
    rows = system[3].shape[1]
    padded = (highs.size - 2 * system[7]) // (rows + 1)
    for k in range(padded):
        for row in range(rows):
            c = padded + k * rows + row
            peaks[row] = max(peaks[row], highs[c])
            highs[c] = 0.0


@numba.njit(cache=True)
def interval_with_events(system, dt_steps, w, sigma, mu, totals, peaks, work):
    """Advance w over one sample interval with every event inside it, search point by search point; returns σ at
    its end (where :func:`_quiet_interval` finds an event at a search point).

    ``system`` is the case's arrays (:func:`stickslip.solvers.structure.friction_linked._kernel_system`),
    ``dt_steps`` the record's (δ, points per interval, exp(Â_p δ), the two
    Van Loan integrals over δ, and :func:`_quiet_interval`'s arrays); ``totals`` (:data:`TOTALS`) and ``peaks``
    (|tracked rows| of both phases' :data:`tracked` rows) are updated in
    place, ``work`` is scratch (:func:`_workspace`'s).
    """
    expansions, stop_row, force_row, tracked, normal_force, interface, slips, velocity_slot = system
    delta, points, steps, viscous_steps, input_steps = dt_steps[:5]
    limit = mu * normal_force
    size = w.size
    pairs = velocity_slot  # ẋᵀCẋ = Σᵢ ẋᵢ(Cẋ)ᵢ, one pair per degree of freedom
    terms = expansions.shape[2] // (size + 1 + 2 * pairs + 2)  # the state's, the watched row's, the pairs' series
    series = work[0, :expansions.shape[2]]
    new = work[1, :size]
    coefficients = work[2, :terms]
    watched_first = terms * size  # where the watched row's series starts in the expansion, then the ledger's pairs'
    viscous_first = watched_first + terms
    input_first = viscous_first + 2 * pairs * terms
    k = 0
    left = delta
    while k < points:
        p = 0 if sigma == 0 else 1
        full = left == delta
        if full:
            _times(steps[p], w, new)
        else:
            _columns(expansions[p], w, series)
            _at(series, terms, left, new)
        q_end, side = _watched(sigma, new, stop_row, force_row, limit)
        happened = q_end >= 0.0 if sigma != 0 else q_end > 0.0
        if not happened:
            if full:
                d_viscous, d_input = _form(w, viscous_steps[p]), _form(w, input_steps[p])
            else:
                d_viscous = _quadratic_integral(series, viscous_first, pairs, terms, left)
                d_input = _quadratic_integral(series, input_first, 1, terms, left)
            tau = left
        else:
            if full:
                _columns(expansions[p], w, series)
            sign = -sigma if sigma != 0 else side
            for j in range(terms):
                coefficients[j] = sign * series[watched_first + j]
            if sigma == 0:
                coefficients[0] -= limit
            tau = _root(coefficients, left, sigma == 0)
            _at(series, terms, tau, new)
            d_viscous = _quadratic_integral(series, viscous_first, pairs, terms, tau)
            d_input = _quadratic_integral(series, input_first, 1, terms, tau)
        totals[VISCOUS] += d_viscous
        totals[INPUT] += d_input
        if sigma == 0:
            _held(w, new, interface, slips, velocity_slot)
        else:
            slip_start, slip_end = 0.0, 0.0
            for i in range(interface.size):
                slip_start += interface[i] * w[i]
                slip_end += interface[i] * new[i]
            totals[PATH] += abs(slip_end - slip_start)
            totals[DISSIPATED] += limit * abs(slip_end - slip_start)
            totals[SLIP_TIME] += tau
        _copy(new, w)
        _track(tracked[p], w, peaks)
        if happened:
            if sigma == 0:  # the hold breaks along the force it needs
                sigma = side
                w[size - 1] = sigma * mu
                totals[EPISODES] += 1
            else:
                sigma = settled_phase(w, sigma, mu, normal_force, force_row, velocity_slot, interface, slips)
            _track(tracked[0 if sigma == 0 else 1], w, peaks)
        left -= tau
        if not happened or left <= 0.0:
            k += 1
            left = delta
    return sigma


@numba.njit(cache=True)
def _start(w, acceleration, slope, ground_velocity, i, mu, sigma):
    """Put the ground of interval i into w: u̇_g, a and ȧ at its start, and the friction entry σμ."""
    size = w.size
    w[size - 4] = ground_velocity[i]
    w[size - 3] = acceleration[i]
    w[size - 2] = slope[i]
    w[size - 1] = sigma * mu


@numba.njit(cache=True)
def _workspace(system, table, modes):
    """The arrays a record's kernel works in, for the case's ``system``, the columns ``table`` of
    :func:`_quiet_interval` and a held structure of ``modes`` modes: (w, values, highs, totals, moments, work,
    scratch) (:func:`record_end`)."""
    size = 2 * system[7] + 4
    return (np.zeros(size), np.zeros(table.shape[2]), np.zeros(table.shape[2]), np.zeros(TOTALS),
            np.zeros((2, size, size)), np.zeros((3, system[0].shape[2])), np.zeros((7, max(size, modes))))


@numba.njit(cache=True)
def _from_rest(system, acceleration, slope, ground_velocity, mu, w, totals, peaks):
    """Put the structure at rest on the record's first sample into w, in the phase it settles in (its episode
    counted, its tracked rows taken), and return σ."""
    _start(w, acceleration, slope, ground_velocity, 0, mu, 0)
    sigma = settled_phase(w, 0, mu, system[4], system[2], system[7], system[5], system[6])
    totals[EPISODES] += 1 if sigma != 0 else 0
    _track(system[3][0 if sigma == 0 else 1], w, peaks)
    return sigma


@numba.njit(cache=True)
def record_history(system, dt_steps, acceleration, slope, ground_velocity, mu, states, phases, forces, energies,
                   peaks):
    """The structure over a record from rest, at every sample: w's (x, ẋ) into ``states`` (samples × 2n), σ into
    ``phases``, the friction force F [N] into ``forces`` (σμN sliding, the force the hold needs holding) and the
    running totals (:data:`TOTALS`) into ``energies`` (samples × TOTALS); the peaks of the tracked rows into
    ``peaks``."""
    force_row, normal_force, velocity_slot = system[2], system[4], system[7]
    n = acceleration.size
    w, values, highs, totals, moments, work, _ = _workspace(system, dt_steps[8], 0)
    sigma = _from_rest(system, acceleration, slope, ground_velocity, mu, w, totals, peaks)
    for i in range(n):
        if i > 0:  # the ground at the sample exactly (w carried it across the interval to round-off)
            _start(w, acceleration, slope, ground_velocity, i, mu, sigma)
        states[i] = w[:2 * velocity_slot]
        phases[i] = sigma
        forces[i] = sigma * mu * normal_force if sigma != 0 else _dot(force_row, w)
        energies[i] = totals
        if i < n - 1:
            if not _quiet_interval(system, dt_steps, w, sigma, mu, totals, highs, values, moments):
                sigma = interval_with_events(system, dt_steps, w, sigma, mu, totals, peaks, work)
            _gathered(dt_steps, moments, totals)
    _folded(system, highs, peaks)


@numba.njit(cache=True)
def held_record(system, dt_steps, acceleration, slope, ground_velocity, step, held):
    """The structure held from rest over a record (the interface never slips), for :func:`_skipped_block`: into
    ``held`` = (w at every block's first sample, max |F| and max |tracked rows| of each block's search points,
    each interval's two ledger integrals, per block c = Σⱼ (Φʲ)ᵀ(G + Gᵀ) fⱼ for both integrals, with Φ = ``step``
    the held interval's map and fⱼ w at the block's j-th sample, F at each search point of each interval and the
    tracked rows there, point by point and row by row)."""
    (starts, block_force, block_tracked, interval_viscous, interval_input, block_viscous, block_input, point_force,
     point_tracked) = held
    velocity_slot = system[7]
    points = dt_steps[1]
    whole_viscous, whole_input = dt_steps[6:8]
    n = acceleration.size
    size = 2 * velocity_slot + 4
    rows = block_tracked.shape[1]
    padded = (dt_steps[8].shape[2] - 2 * velocity_slot) // (rows + 1)
    states = np.zeros((n, size))
    w, values, highs, totals, moments, _, _ = _workspace(system, dt_steps[8], 0)
    for i in range(n):
        _start(w, acceleration, slope, ground_velocity, i, 0.0, 0)
        states[i] = w
        block = i // BLOCK
        if i % BLOCK == 0:
            starts[block] = w
            block_force[block] = 0.0
            block_tracked[block] = 0.0
        if i == n - 1:
            break
        totals[:] = 0.0
        _quiet_interval(system, dt_steps, w, 0, math.inf, totals, highs, values, moments)
        _gathered(dt_steps, moments, totals)
        for k in range(points):  # the points as the interval found them
            point_force[i, k] = values[k]
            block_force[block] = max(block_force[block], abs(values[k]))
            for row in range(rows):
                point_tracked[i, k * rows + row] = values[padded + k * rows + row]
                block_tracked[block, row] = max(block_tracked[block, row], abs(values[padded + k * rows + row]))
        interval_viscous[i] = totals[VISCOUS]
        interval_input[i] = totals[INPUT]
    step = np.ascontiguousarray(step)
    for form, out in ((whole_viscous[0], block_viscous), (whole_input[0], block_input)):
        both = form + form.T
        carried = np.zeros(size)
        added = np.zeros(size)
        for block in range(starts.shape[0]):
            last = min((block + 1) * BLOCK, n - 1)
            out[block] = 0.0
            for j in range(last - 1, block * BLOCK - 1, -1):  # c ← Φᵀc + (G + Gᵀ) fⱼ, backwards, in vectors
                _columns(step, out[block], carried)
                _columns(both, states[j], added)
                for i in range(size):
                    out[block, i] = carried[i] + added[i]


@numba.njit(cache=True, inline="always")
def _modal_weights(gains_real, gains_imag, projected_real, projected_imag, weights_real, weights_imag):
    """The weights (r·vᵢ)(ℓᵢ·δ) of a row's free motion, complex, mode by mode (:func:`_skipped_block`)."""
    for mode in range(weights_real.size):
        weights_real[mode] = gains_real[mode] * projected_real[mode] - gains_imag[mode] * projected_imag[mode]
        weights_imag[mode] = gains_real[mode] * projected_imag[mode] + gains_imag[mode] * projected_real[mode]


@numba.njit(cache=True, inline="always")
def _free(weights_real, weights_imag, decays_real, decays_imag, at):
    """A row's free motion Σᵢ Re((r·vᵢ)(ℓᵢ·δ) e^{λᵢτ}) at the block's search point ``at``."""
    free = 0.0
    for mode in range(weights_real.size):
        free += weights_real[mode] * decays_real[mode, at] - weights_imag[mode] * decays_imag[mode, at]
    return free


@numba.njit(cache=True, inline="always")
def _skipped_block(held, skip, points, w, i, mu, normal_force, interface, totals, peaks, scratch):
    """Pass the hold over the block of samples i … i + BLOCK (i a multiple of BLOCK) in one step where no search
    point of it (``points`` per interval) can show an event, and say whether it did.

    With z = w − f (f :func:`held_record`'s), each tracked row is bounded
    over the block by the block's maximum of f's, plus s₀'s static part, plus
    the modal bound (module docstring), and so is the hold's force; where a
    bound does not settle it, the force (or the row) is taken at each search
    point from f's and the modes'.  The block is passed where the force stays
    below μN by :data:`MARGIN`; a tracked row (but the slip, held at s₀) whose
    bound reaches its peak has its peak taken at the points.  Where z = 0
    exactly (held from rest: w is f, computed alike) the block is f's, bit for
    bit: its peaks are taken, its integrals added interval by interval.
    Otherwise w ends at f + Φᴮz and each integral adds Σⱼ fⱼᵀGfⱼ + cᵀz + zᵀHz (H = Σⱼ (Φʲ)ᵀGΦʲ).  ``scratch``
    holds 7 rows of max(m, modes) numbers."""
    (starts, block_force, block_tracked, interval_viscous, interval_input, block_viscous, block_input, point_force,
     point_tracked) = held
    (jump, jump_viscous, jump_input, static, modes_real, modes_imag, gains, static_values, gains_real, gains_imag,
     decays_real, decays_imag) = skip
    block = i // BLOCK
    limit = mu * normal_force
    size = w.size
    z = scratch[0, :size]
    delta = scratch[1, :size]
    at_rest = True
    for j in range(size):
        z[j] = w[j] - starts[block, j]
        if z[j] != 0.0:
            at_rest = False
    if at_rest:
        if block_force[block] > limit:
            return False
        for row in range(peaks.size):
            peaks[row] = max(peaks[row], block_tracked[block, row])
        for j in range(i, i + BLOCK):
            totals[VISCOUS] += interval_viscous[j]
            totals[INPUT] += interval_input[j]
        _copy(starts[block + 1], w)
        return True
    slip = 0.0
    for j in range(interface.size):
        slip += interface[j] * z[j]
    for j in range(size):
        delta[j] = z[j] - slip * static[j]
    modes = modes_real.shape[0]
    amplitudes = scratch[2, :modes]
    projected_real = scratch[3, :modes]
    projected_imag = scratch[4, :modes]
    for mode in range(modes):
        projected_real[mode] = _dot(modes_real[mode], delta)
        projected_imag[mode] = _dot(modes_imag[mode], delta)
        amplitudes[mode] = math.hypot(projected_real[mode], projected_imag[mode])
    rows = block_tracked.shape[1]
    unbounded = 0
    for row in range(2, gains.shape[0]):  # the tracked rows but the slip's (held at s₀, its peak counts it)
        bound = abs(slip * static_values[row]) + _dot(gains[row], amplitudes)
        if bound != bound:  # NaN: the modes are no sound basis, not passed
            return False
        if not block_tracked[block, row - 1] + bound <= peaks[row - 1]:
            unbounded += 1
    held_force = slip * static_values[0]
    transient = _dot(gains[0], amplitudes)
    weights_real, weights_imag = scratch[5, :modes], scratch[6, :modes]
    if not (block_force[block] + abs(held_force) + transient) * (1.0 + MARGIN) < limit:
        _modal_weights(gains_real[0], gains_imag[0], projected_real, projected_imag, weights_real, weights_imag)
        for j in range(BLOCK):
            for k in range(points):
                forced = point_force[i + j, k]
                free = _free(weights_real, weights_imag, decays_real, decays_imag, j * points + k)
                if not (abs(forced + held_force + free)
                        + MARGIN * (abs(forced) + abs(held_force) + transient + limit) < limit):
                    return False
    for row in range(2, gains.shape[0] if unbounded else 0):  # the peaks the bound does not settle, at the points
        held_value = slip * static_values[row]
        if block_tracked[block, row - 1] + abs(held_value) + _dot(gains[row], amplitudes) <= peaks[row - 1]:
            continue
        _modal_weights(gains_real[row], gains_imag[row], projected_real, projected_imag, weights_real, weights_imag)
        peak = peaks[row - 1]
        for j in range(BLOCK):
            for k in range(points):
                forced = point_tracked[i + j, k * rows + row - 1]
                free = _free(weights_real, weights_imag, decays_real, decays_imag, j * points + k)
                peak = max(peak, abs(forced + held_value + free))
        peaks[row - 1] = peak
    viscous, work_input = 0.0, 0.0
    for j in range(i, i + BLOCK):
        viscous += interval_viscous[j]
        work_input += interval_input[j]
    totals[VISCOUS] += viscous + _dot(block_viscous[block], z) + _form(z, jump_viscous)
    totals[INPUT] += work_input + _dot(block_input[block], z) + _form(z, jump_input)
    _times(jump, z, delta)
    for j in range(size):
        w[j] = starts[block + 1, j] + delta[j]
    return True


@numba.njit(cache=True, _nrt=False)
def record_end(system, dt_steps, acceleration, slope, ground_velocity, mu, end, peaks, held, skip, workspace):
    """:func:`record_history`'s end values only: w at the last sample into ``end`` (its last entry σ), the totals
    after it (``end[2n + 1:]``), the peaks into ``peaks``; holds passed in blocks where :func:`_skipped_block`
    proves them quiet (``held`` :func:`held_record`'s arrays of the record, ``skip`` the case's: Φᴮ, Σⱼ (Φʲ)ᵀGΦʲ
    of both integrals, u_s, the modes' ℓᵢ (real and imaginary parts), |r·vᵢ| and r·u_s of the force's and the
    tracked rows, their r·vᵢ and e^{λᵢτ} at the block's search points, real and imaginary parts), in
    :func:`_workspace`'s arrays.

    Compiled without numba's reference counting (it makes no array): counting the references of the case's
    tuples of arrays, taken anew by every inlined interval, cost a fifth of the sweep's time."""
    normal_force, interface, velocity_slot = system[4], system[5], system[7]
    n = acceleration.size
    w, values, highs, totals, moments, work, scratch = workspace
    sigma = _from_rest(system, acceleration, slope, ground_velocity, mu, w, totals, peaks)
    i = 0
    while i < n - 1:
        if i > 0:
            _start(w, acceleration, slope, ground_velocity, i, mu, sigma)
        if i % BLOCK == 0:  # a short sum of w wᵀ: its terms (the ground's among them) cancel in the integrals
            _gathered(dt_steps, moments, totals)
            _folded(system, highs, peaks)  # the peaks whole where a block may be passed
        if (sigma == 0 and i % BLOCK == 0 and i + BLOCK <= n - 1
                and _skipped_block(held, skip, dt_steps[1], w, i, mu, normal_force, interface, totals, peaks,
                                   scratch)):
            i += BLOCK
            continue
        if not _quiet_interval(system, dt_steps, w, sigma, mu, totals, highs, values, moments):
            sigma = interval_with_events(system, dt_steps, w, sigma, mu, totals, peaks, work)
        i += 1
    _gathered(dt_steps, moments, totals)
    _folded(system, highs, peaks)
    _start(w, acceleration, slope, ground_velocity, n - 1, mu, sigma)
    for j in range(2 * velocity_slot):
        end[j] = w[j]
    end[2 * velocity_slot] = sigma
    for j in range(TOTALS):
        end[2 * velocity_slot + 1 + j] = totals[j]


@numba.njit(cache=True, inline="always")
def _solved_pair(group, record, columns, column, out):
    """:func:`record_end` of one record of a group at the friction ratio ``columns[column, 0]``; ``out`` holds the
    end values, then the peaks."""
    samples, offsets, slope, ground_velocity, deltas, points = group[:6]
    steps = group[6:13]
    block_offsets = group[13]
    held = group[14:23]
    skip = group[23:35]
    system = group[35:]  # flat in the group: numba's parallel loop takes no tuple inside a tuple
    first, last = offsets[record], offsets[record + 1]
    blocks, blocks_end = block_offsets[record], block_offsets[record + 1]
    size = 2 * system[7] + 1 + TOTALS
    out[size:] = 0.0
    record_end(system, (deltas[record], points[record], steps[0][record], steps[1][record], steps[2][record],
                        steps[3][record], steps[4][record], steps[5][record], steps[6][record]),
               samples[first:last], slope[first:last], ground_velocity[first:last], columns[column, 0], out[:size],
               out[size:],
               (held[0][blocks:blocks_end], held[1][blocks:blocks_end], held[2][blocks:blocks_end],
                held[3][first:last], held[4][first:last], held[5][blocks:blocks_end], held[6][blocks:blocks_end],
                held[7][first:last], held[8][first:last]),
               (skip[0][record], skip[1][record], skip[2][record], skip[3][record], skip[4][record],
                skip[5][record], skip[6][record], skip[7][record], skip[8][record], skip[9][record],
                skip[10][record], skip[11][record]), _workspace(system, steps[6][record], skip[4].shape[1]))


sweep_pairs = sweep_engine(__name__, _solved_pair)
