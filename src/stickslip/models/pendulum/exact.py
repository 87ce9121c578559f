"""The friction pendulum in one direction, Coulomb friction and a constant normal force: solved exactly.

A slider on a concave surface of radius R [m] (Zayas, Low and Mahin 1987),
per unit mass, relative to the ground, with a(t) the ground acceleration
[m/s²] linear between samples, at small angles: the restoring force is the
horizontal component N·u/R of the normal force with N = m·g, where the
spherical surface at u = R·sin θ gives N ≈ m·g/cos θ, and the friction's
projection and the slider's vertical acceleration on the bowl are left out
(docs/solvers.md, "The friction pendulum and the vertical motion"):

* **stick** (u̇ = 0) while the force that holds it, |a + ω²·u|, is at most
  μ·g, ω² = g/R: the ground acceleration stays inside the band
  [−ω²u − μg, −ω²u + μg], shifted by the displacement it sticks at;
* **slip** in the direction s = ±1 (u̇ ≷ 0): ü = −a(t) − ω²·u − s·μ·g;
* **breakaway** where a leaves the band, along the force; **stop** where u̇
  returns to zero, then stick or slide back.

R = ∞ (ω = 0) is the flat block of :mod:`stickslip.models.rigid.events`.  On a
sub-interval of length τ, with a(σ) = a₀ + k·σ, each slip is a linear
oscillator under a linear force: with f₀ = ü(0) and p₁ = −k,

    u(τ) = u₀ + u̇₀·S₁ + f₀·S₂ + p₁·S₃,
    u̇(τ) = u̇₀·C + f₀·S₁ + p₁·S₂,
    ü(τ) = f₀·C + (p₁ − ω²·u̇₀)·S₁,

C = cos ωτ and S_j its j-th integral from 0 (S₁ = sin ωτ/ω, S₂ = (1 − C)/ω²,
…), which tend to τ^j/j! as ω → 0 (:func:`phi_functions`: a series for
ωτ ≤ 2, so that no large R loses digits).  ü is a sinusoid, so in a stretch
of at most a quarter period it vanishes at most once, at a point given by
atan2: there u̇ has its extremum, and the stretch splits into at most two
pieces on which u̇ is monotone.  A stop is a sign change of s·u̇ on such a
piece, located to round-off by Newton's method kept inside its bracket
(:func:`slip_stop_time`); a sample interval without one is proved quiet by
the same test (u̇ at its end and at its interior extremum), so most slipping
intervals cost one linear map whose coefficients are computed once per record.
Breakaway is the linear crossing of a band edge, as on the flat block.

The ledger per unit mass, every term integrated on its own: E_df = μ·g·(path),
E_p = ½·ω²·u² (the slider's potential energy g·u²/(2R)), E_k = ½·(u̇_g + u̇)²,
W_v = 0 (N = m·g: no vertical), and E_I = ∫ü·u̇_g dt with ü = a in stick and
ü = −ω²·u − s·μ·g in slip, whose integral against the ground velocity u̇_g
(quadratic in time) is closed in S₁ … S₆ (:func:`slip_input_energy`).  E_k − E_k(0) + E_p − E_p(0) + E_df =
E_I then closes to round-off.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.records.process import integrate_linear_acceleration
from stickslip.models.rigid.exact import (
    BLOCK,
    LANES,
    _lane_start,
    _next_exceedance,
    _prepare_record,
    first_stop_time,
    stick_input_energy,
)
from stickslip.models.pendulum.results import (
    HISTORY_COLUMNS,
    SCALAR_NAMES,
    history_dict,
    run_in_calls,
    store_scalars,
    surface_curvature,
)

HALF_PI = 0.5 * math.pi

#: The most Newton or bisection steps that locate a stop to round-off.
ROOT_STEPS = 200


@numba.njit(cache=True)
def _integral_series(theta2, tau, order):
    """S_order(τ) = τ^order·Σ_m (−θ²)^m/(2m + order)!, θ² = ω²τ², summed until the terms fall below round-off."""
    term = 1.0
    for j in range(1, order + 1):
        term *= tau / j
    total = term
    m = 1
    while True:
        term *= -theta2 / ((2 * m + order - 1) * (2 * m + order))
        total += term
        if abs(term) <= 1e-17 * abs(total):
            return total
        m += 1


@numba.njit(cache=True)
def phi_functions(w2, tau):
    """(C, S₁, …, S₆) at τ [s] for ω² = ``w2`` [1/s²]: C = cos ωτ and S_j = ∫₀^τ S_{j−1} [s^j].

    For ωτ ≤ 2, S₅ and S₆ are summed as series and the others follow by the
    downward recurrence S_{j−2} = τ^{j−2}/(j−2)! − ω²·S_j, which loses no digits
    however small ω is (ω = 0 gives τ^j/j! exactly); beyond, from cos and sin
    by the upward one.
    """
    t2 = tau * tau
    theta2 = w2 * t2
    if theta2 <= 4.0:
        s5 = _integral_series(theta2, tau, 5)
        s6 = _integral_series(theta2, tau, 6)
        s4 = t2 * t2 / 24.0 - w2 * s6
        s3 = t2 * tau / 6.0 - w2 * s5
        s2 = 0.5 * t2 - w2 * s4
        s1 = tau - w2 * s3
        return 1.0 - w2 * s2, s1, s2, s3, s4, s5, s6
    w = math.sqrt(w2)
    theta = w * tau
    half = math.sin(0.5 * theta)
    s1 = math.sin(theta) / w
    s2 = 2.0 * half * half / w2
    s3 = (tau - s1) / w2
    s4 = (0.5 * t2 - s2) / w2
    return math.cos(theta), s1, s2, s3, s4, (t2 * tau / 6.0 - s3) / w2, (t2 * t2 / 24.0 - s4) / w2


@numba.njit(cache=True)
def level(w2, x, mug, s):
    """The ground acceleration [m/s²] at which a slider at u = ``x`` [m] holds still against friction in direction s.

    −ω²·u − s·μ·g: the band edge ``upper`` (s = −1) or ``lower`` (s = +1) while
    it sticks, and its absolute acceleration a + ü while it slides in direction
    s (its relative one is f₀ = level − a at the slip's start).
    """
    return -(w2 * x) - s * mug


@numba.njit(cache=True)
def _speed(v0, f0, p1, w2, tau):
    """u̇(τ) [m/s] and ü(τ) [m/s²] of a slip from u̇₀ with ü(0) = f₀ [m/s²] and forcing slope p₁ [m/s³]."""
    c, s1, s2, _, _, _, _ = phi_functions(w2, tau)
    return v0 * c + f0 * s1 + p1 * s2, f0 * c + (p1 - w2 * v0) * s1


@numba.njit(cache=True)
def _acceleration_zero(v0, f0, p1, w2, start, end):
    """The τ [s] in [start, end] where ü = f₀·C + (p₁ − ω²u̇₀)·S₁ vanishes, its sign known to change there.

    ü is a sinusoid whose zeros are θ₀ + mπ apart in θ = ωτ, θ₀ = atan2(−f₀ω, p₁ − ω²u̇₀);
    without the restoring force (ω = 0) it is linear.
    """
    jerk = p1 - w2 * v0
    if w2 == 0.0:
        tau = -f0 / jerk
    else:
        w = math.sqrt(w2)
        theta0 = math.atan2(-f0 * w, jerk)
        tau = (theta0 + (math.floor((w * start - theta0) / math.pi) + 1.0) * math.pi) / w
    return min(max(tau, start), end)


@numba.njit(cache=True)
def _falling_root(v0, f0, p1, w2, s, low, high):
    """The τ [s] in (low, high] where s·u̇ falls through zero, to round-off: s·u̇(low) > 0 ≥ s·u̇(high), monotone.

    Newton's method, replaced by bisection wherever it leaves the bracket.
    """
    tau = high
    for _ in range(ROOT_STEPS):
        v, acceleration = _speed(v0, f0, p1, w2, tau)
        q = s * v
        if q <= 0.0:
            high = tau
        else:
            low = tau
        if q == 0.0:
            return tau
        slope = s * acceleration
        following = tau - q / slope if slope != 0.0 else high
        if not low < following < high:
            following = 0.5 * (low + high)
        if following == tau:  # converged to round-off from one side
            return tau
        if following <= low or following >= high:  # the bracket is two neighbouring floats
            return high
        tau = following
    return high


@numba.njit(cache=True)
def slip_stop_time(v0, f0, p1, w2, s, length):
    """The first τ in (0, length] [s] at which a slip in direction s stops (s·u̇ ≤ 0), or +inf.

    The slip starts at u̇₀ [m/s] (s·u̇₀ ≥ 0) with ü(0) = f₀ [m/s²] under the
    forcing slope p₁ [m/s³] (module docstring).  Without the restoring force
    (ω² = ``w2`` = 0) the stop is the flat block's quadratic root.  Otherwise
    [0, length] is cut into stretches of at most a quarter period; in each,
    s·u̇ is monotone on either side of the one zero of ü it may hold.  A
    slip that cannot start (s·u̇ ≤ 0 from its start) stops at τ = 0.
    """
    if w2 == 0.0:
        return first_stop_time(s * v0, s * f0, 0.5 * s * p1)
    stretch = HALF_PI / math.sqrt(w2)
    start = 0.0
    q_start = s * v0
    rate_start = s * f0
    while start < length:
        end = min(start + stretch, length)
        v_end, acceleration_end = _speed(v0, f0, p1, w2, end)
        q_end = s * v_end
        rate_end = s * acceleration_end
        turns = (rate_start < 0.0 < rate_end) or (rate_start > 0.0 > rate_end)
        if q_end <= 0.0:
            low, high = start, end
            if turns:
                middle = _acceleration_zero(v0, f0, p1, w2, start, end)
                q_middle = s * _speed(v0, f0, p1, w2, middle)[0]
                if q_middle <= 0.0:
                    high = middle
                else:
                    low = middle
            elif q_start <= 0.0:
                return start
            return _falling_root(v0, f0, p1, w2, s, low, high)
        if rate_start < 0.0 < rate_end:  # a minimum of the speed inside
            middle = _acceleration_zero(v0, f0, p1, w2, start, end)
            if s * _speed(v0, f0, p1, w2, middle)[0] <= 0.0:
                if q_start <= 0.0:
                    return start
                return _falling_root(v0, f0, p1, w2, s, start, middle)
        start, q_start, rate_start = end, q_end, rate_end
    return math.inf


@numba.njit(cache=True)
def slip_input_energy(x0, v0, f0, p1, w2, s, mug, a0, slope, vg0, tau, phis):
    """E_I/m [J/kg] over a slip of τ [s]: ∫ü·u̇_g dσ with ü = −ω²u − s·μ·g, in closed form.

    ``phis`` = :func:`phi_functions` (ω², τ); a₀ [m/s²], ``slope`` [m/s³] and
    vg0 [m/s] give the ground's u̇_g(σ) = vg0 + a₀σ + slope·σ²/2.  With
    u = u₀ + u̇₀S₁ + f₀S₂ + p₁S₃, the integrals ∫σ^i·S_j dσ are τS_{j+1} − S_{j+2}
    (i = 1) and τ²S_{j+1} − 2τS_{j+2} + 2S_{j+3} (i = 2), by parts.
    """
    ground_path = tau * (vg0 + tau * (0.5 * a0 + slope * tau / 6.0))
    if w2 == 0.0:
        return -s * mug * ground_path
    _, _, s2, s3, s4, s5, s6 = phis
    t2 = tau * tau
    half_slope = 0.5 * slope
    k1 = vg0 * s2 + a0 * (tau * s2 - s3) + half_slope * (t2 * s2 - 2.0 * tau * s3 + 2.0 * s4)
    k2 = vg0 * s3 + a0 * (tau * s3 - s4) + half_slope * (t2 * s3 - 2.0 * tau * s4 + 2.0 * s5)
    k3 = vg0 * s4 + a0 * (tau * s4 - s5) + half_slope * (t2 * s4 - 2.0 * tau * s5 + 2.0 * s6)
    return -s * mug * ground_path - w2 * (x0 * ground_path + v0 * k1 + f0 * k2 + p1 * k3)


@numba.njit(cache=True)
def advance_interval(a_start, a_end, slope, dt, vg_start, mug, w2, phis_dt, x, v, s):
    """Advance the slider across one sample interval [s] with every event inside it; see the module docstring.

    a_start, a_end [m/s²] are the ground acceleration at the ends, ``slope``
    = (a_end − a_start)/dt [m/s³], vg_start u̇_g [m/s] at the start, ``mug``
    μ·g and ``w2`` ω² = g/R [1/s²] (0 for a flat surface), ``phis_dt``
    :func:`phi_functions` (ω², dt); x [m], v [m/s] and s (0 stick, ±1 slip) the
    state at the start.  Returns ``(x, v, s, phase_after_start, input_energy,
    sliding_path, slip_time, new_episodes, peak_abs_x, peak_abs_acceleration)``:
    the state at the end, the phase just after the start, the increments of
    E_I/m [J/kg], of the path [m], of the time sliding [s] and of the slip
    episodes, max |u| [m] and max |ü| [m/s²] over the interval.
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
            upper = level(w2, x, mug, -1)
            lower = level(w2, x, mug, 1)
            # as the flat block's stick: the crossing's existence is decided by the sample a_end itself
            if a > upper:
                tau, s_next = 0.0, -1
            elif a < lower:
                tau, s_next = 0.0, 1
            elif slope > 0.0 and a_end > upper:
                tau, s_next = (upper - a) / slope, -1
            elif slope < 0.0 and a_end < lower:
                tau, s_next = (lower - a) / slope, 1
            else:
                tau, s_next = math.inf, 0
            if tau > 0.0:  # held: |ü| = |a| up to the stick's end, where a is at most the band's edge
                held_end = a_end if tau >= remaining else a + slope * tau
                peak_acceleration = max(peak_acceleration, abs(a), abs(held_end))
            if tau >= remaining:
                input_energy += stick_input_energy(a, slope, vg, remaining)
                break
            input_energy += stick_input_energy(a, slope, vg, tau)
            if tau > 0.0:
                t += tau
                a = upper if s_next < 0 else lower  # the slip starts with ü(0) − a = 0 exactly
                vg = vg_start + t * (a_start + 0.5 * slope * t)
            s = s_next
            new_episodes += 1
        else:
            edge = level(w2, x, mug, s)
            f0 = edge - a
            p1 = -slope
            tau = slip_stop_time(v, f0, p1, w2, s, remaining)
            at_end = tau >= remaining
            if at_end:
                tau = remaining
            phis = phis_dt if tau == dt else phi_functions(w2, tau)
            c, s1, s2, s3, _, _, _ = phis
            x_end = x + v * s1 + f0 * s2 + p1 * s3
            v_end = v * c + f0 * s1 + p1 * s2
            input_energy += slip_input_energy(x, v, f0, p1, w2, s, mug, a, slope, vg, tau, phis)
            peak_acceleration = max(peak_acceleration, abs(edge), abs(level(w2, x_end, mug, s)))
            sliding_path += abs(x_end - x)  # u is monotone within a slip
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
                    # a slip shorter than the time resolution: the slider stays at the edge it slid past and sticks
                    a = edge
                else:
                    t = t_stop
                    a = min(max(a_start + slope * t, min(a_start, a_end)), max(a_start, a_end))
                    vg = vg_start + t * (a_start + 0.5 * slope * t)
            v = 0.0
            if a > level(w2, x, mug, -1):
                s = -1
            elif a < level(w2, x, mug, 1):
                s = 1
            else:
                s = 0
            if at_end:
                break
        if t == 0.0:
            phase_after_start = s
    return (x, v, s, phase_after_start, input_energy, sliding_path, slip_time, new_episodes, peak_abs_x,
            peak_acceleration)


@numba.njit(cache=True)
def history_kernel(acceleration, ground_velocity, dt, mug, w2, g, x0, v0, history, out):
    """One record's history into ``history`` (n × len(HISTORY_COLUMNS)) and its scalars into ``out``.

    ``acceleration`` [m/s²] and ``ground_velocity`` [m/s] at the samples;
    ``mug`` μ·g, ``w2`` ω² = g/R [1/s²], ``g`` [m/s²] (for the base shear over
    the weight); the slider starts at u = x0 [m] with u̇ = v0 [m/s].
    """
    n = acceleration.size
    phis_dt = phi_functions(w2, dt)
    x, v = x0, v0
    s = 0 if v0 == 0.0 else (1 if v0 > 0.0 else -1)
    energy_input = 0.0
    path = 0.0
    slip_time = 0.0
    episodes = 0
    peak = abs(x0)
    peak_acceleration = 0.0
    history[0, :] = 0.0
    history[0, 0] = x0
    history[0, 1] = v0
    for i in range(n - 1):
        a0 = acceleration[i]
        x, v, s, phase_i, d_input, d_path, d_slip, d_episodes, d_peak, d_acceleration = advance_interval(
            a0, acceleration[i + 1], (acceleration[i + 1] - a0) / dt, dt, ground_velocity[i], mug, w2, phis_dt, x, v,
            s)
        history[i, 2] = phase_i
        energy_input += d_input
        path += d_path
        slip_time += d_slip
        episodes += d_episodes
        peak = max(peak, d_peak)
        peak_acceleration = max(peak_acceleration, d_acceleration)
        history[i + 1, 0] = x
        history[i + 1, 1] = v
        history[i + 1, 3] = mug * path
        history[i + 1, 4] = energy_input
        history[i + 1, 5] = 0.0  # W_v: the normal force is the weight
        history[i + 1, 6] = path
    history[n - 1, 2] = s
    store_scalars(out, mug * path, energy_input, 0.0, ground_velocity[n - 1] + v, w2, x, peak, path, slip_time,
                  (n - 1) * dt, episodes, peak_acceleration, g, 0.0)


@numba.njit(cache=True)
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


@numba.njit(cache=True)
def _record_scalars(acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min, mug, w2, g, out):
    """The scalars of one record and one (μ·g, ω²) into ``out``, at a cost that follows the slip.

    A stick at u skips to the first sample outside its band [−ω²u − μg,
    −ω²u + μg] (the flat kernel's block extremes, :func:`_next_exceedance`),
    its input energy a difference of ``stick_energy``; a slipping interval that
    the quiet test (module docstring) clears is one linear map with the
    coefficients of :func:`phi_functions` (ω², dt); any other goes through
    :func:`advance_interval`.  Equal to :func:`history_kernel`'s scalars to round-off.
    """
    n = acceleration.size
    phis_dt = phi_functions(w2, dt)
    c, s1, s2, s3, _, _, _ = phis_dt
    one_stretch = w2 * dt * dt <= HALF_PI * HALF_PI  # ü vanishes at most once in an interval
    x, v, s = 0.0, 0.0, 0
    energy_input = 0.0
    path = 0.0
    slip_time = 0.0
    episodes = 0
    peak = 0.0
    peak_acceleration = 0.0
    i = 0
    while i < n - 1:
        if s == 0:
            stick_end = min(max(_next_exceedance(acceleration, block_max, block_min, i, level(w2, x, mug, 1),
                                                 level(w2, x, mug, -1)) - 1, i), n - 1)
            energy_input += stick_energy[stick_end] - stick_energy[i]
            peak_acceleration = max(peak_acceleration, largest_magnitude(acceleration, block_max, block_min, i,
                                                                          stick_end))
            i = stick_end
            if i == n - 1:
                break
        a0 = acceleration[i]
        if s != 0 and one_stretch:
            edge = level(w2, x, mug, s)
            f0 = edge - a0
            p1 = -slope[i]
            v_end = v * c + f0 * s1 + p1 * s2
            if s * v_end > 0.0:
                quiet = True
                if s * f0 < 0.0 < s * (f0 * c + (p1 - w2 * v) * s1):  # a minimum of the speed inside
                    middle = _acceleration_zero(v, f0, p1, w2, 0.0, dt)
                    quiet = s * _speed(v, f0, p1, w2, middle)[0] > 0.0
                if quiet:
                    x_end = x + v * s1 + f0 * s2 + p1 * s3
                    energy_input += slip_input_energy(x, v, f0, p1, w2, s, mug, a0, slope[i], ground_velocity[i], dt,
                                                      phis_dt)
                    peak_acceleration = max(peak_acceleration, abs(edge), abs(level(w2, x_end, mug, s)))
                    path += abs(x_end - x)
                    slip_time += dt
                    x = x_end
                    v = v_end
                    peak = max(peak, abs(x))
                    i += 1
                    continue
        x, v, s, _, d_input, d_path, d_slip, d_episodes, d_peak, d_acceleration = advance_interval(
            a0, acceleration[i + 1], slope[i], dt, ground_velocity[i], mug, w2, phis_dt, x, v, s)
        energy_input += d_input
        path += d_path
        slip_time += d_slip
        episodes += d_episodes
        peak = max(peak, d_peak)
        peak_acceleration = max(peak_acceleration, d_acceleration)
        i += 1
    store_scalars(out, mug * path, energy_input, 0.0, ground_velocity[n - 1] + v, w2, x, peak, path, slip_time,
                  (n - 1) * dt, episodes, peak_acceleration, g, 0.0)


@numba.njit(cache=True)
def _prepare_records(samples, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min,
                     block_offsets):
    """The flat kernel's record-independent arrays (:func:`stickslip.models.rigid.exact._prepare_record`) of every record."""
    for record in range(offsets.size - 1):
        first, last = offsets[record], offsets[record + 1]
        blocks = slice(block_offsets[record], block_offsets[record + 1])
        _prepare_record(samples[first:last], dts[record], ground_velocity[first:last], slope[first:last],
                        stick_energy[first:last], block_max[blocks], block_min[blocks])


@numba.njit(cache=True, parallel=True)
def sweep_kernel(samples, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min, block_offsets,
                 columns, g, first_pair, last_pair, out):
    """:func:`_record_scalars` for the (record, column) pairs first_pair ≤ pair < last_pair, in parallel.

    ``columns`` has one row (μ·g [m/s²], ω² [1/s²]) per column; pairs are
    numbered record-major and dealt to :data:`~stickslip.models.rigid.exact.LANES`
    lanes as the flat sweep deals them; ``out`` has shape (records, columns,
    len(SCALAR_NAMES)).
    """
    n_columns = columns.shape[0]
    for lane in numba.prange(LANES):
        for pair in range(first_pair + _lane_start(lane), last_pair, LANES):
            record = pair // n_columns
            column = pair - record * n_columns
            first, last = offsets[record], offsets[record + 1]
            blocks = slice(block_offsets[record], block_offsets[record + 1])
            _record_scalars(samples[first:last], dts[record], ground_velocity[first:last], slope[first:last],
                            stick_energy[first:last], block_max[blocks], block_min[blocks], columns[column, 0],
                            columns[column, 1], g, out[record, column])


def pendulum_history(acceleration, dt: float, mu: float, radius: float, g: float = STANDARD_GRAVITY, *,
                     initial_displacement: float = 0.0, initial_velocity: float = 0.0) -> dict:
    """The exact history of a friction pendulum (Coulomb friction, N = m·g) under one horizontal component.

    Parameters
    ----------
    acceleration:
        Ground acceleration a [m/s²] at the samples, linear in between; a
        positive value drives the slider towards −u.
    dt:
        Sample interval [s].
    mu:
        Friction ratio μ [-].
    radius:
        Radius R of the sliding surface [m]; ``math.inf`` for a flat surface.
    g:
        Gravity [m/s²].
    initial_displacement, initial_velocity:
        u [m] and u̇ [m/s] relative to the ground at t = 0 (the ground starts at rest).

    Returns
    -------
    dict
        Per unit mass (:func:`~stickslip.models.pendulum.results.history_dict`):
        ``time`` [s], ``ground_velocity`` [m/s], ``relative_displacement`` [m],
        ``relative_velocity`` [m/s], ``phase`` (0 stick, ±1 slip), the
        cumulative ``energy_dissipated`` E_df = μ·g·path, ``energy_input`` E_I,
        ``potential_energy`` E_p = ½·(g/R)·u², ``energy_input_vertical`` W_v = 0
        (the normal force is the weight), ``kinetic_energy`` E_k [J/kg],
        ``sliding_path`` [m], ``balance_residual`` [J/kg] and ``scalars``.
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    g = checked_positive(g, "gravity g [m/s2]")
    mu = checked_positive(mu, "friction ratio mu (--mu)")
    w2 = g * surface_curvature(radius)
    ground_velocity, _ = integrate_linear_acceleration(acceleration, dt)
    history = np.empty((acceleration.size, len(HISTORY_COLUMNS)))
    scalars = np.empty(len(SCALAR_NAMES))
    history_kernel(acceleration, ground_velocity, dt, mu * g, w2, g, float(initial_displacement),
                   float(initial_velocity), history, scalars)
    return history_dict(history, scalars, ground_velocity, dt, w2)


def pendulum_sweep(accelerations, dts, mu, radius, g: float = STANDARD_GRAVITY) -> np.ndarray:
    """End-of-record scalars of friction pendulums for every record and column (μ, R), in parallel.

    Parameters
    ----------
    accelerations:
        The records' ground accelerations [m/s²], a list of 1-D arrays.
    dts:
        Their sample intervals [s] (one number for all, or one per record).
    mu:
        Friction ratios μ [-], 1-D: one column each.
    radius:
        Radius R [m] of every column (one number) or of each (as long as ``mu``); ``math.inf`` is flat.
    g:
        Gravity [m/s²].

    Returns
    -------
    numpy.ndarray
        Shape (records, columns, len(SCALAR_NAMES)), per unit mass in the
        units of :data:`~stickslip.models.pendulum.results.SCALAR_UNITS`.
    """
    g = checked_positive(g, "gravity g [m/s2]")
    records = [checked_acceleration(a, f"record {i}") for i, a in enumerate(accelerations)]
    if not records:
        raise StickslipError("pendulum sweep: no records given")
    dts = np.ascontiguousarray([checked_positive(dt, f"time step of record {i} [s]")
                                for i, dt in enumerate(np.broadcast_to(np.asarray(dts, dtype=float),
                                                                       (len(records),)))])
    mu = np.atleast_1d(np.asarray(mu, dtype=float))
    if mu.ndim != 1 or mu.size == 0:
        raise StickslipError(f"friction ratios mu: expected a non-empty 1-D array, got shape {mu.shape}")
    try:
        radii = np.broadcast_to(np.asarray(radius, dtype=float), mu.shape)
    except ValueError:
        raise StickslipError(f"--radius: expected one radius or {mu.size} (one per friction ratio)") from None
    columns = np.array([[checked_positive(m, "friction ratio mu (--mu)") * g, g * surface_curvature(r)]
                        for m, r in zip(mu, radii)])
    sizes = np.array([a.size for a in records], dtype=np.int64)
    offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    block_offsets = np.concatenate([[0], np.cumsum((sizes + BLOCK - 1) // BLOCK)]).astype(np.int64)
    samples = np.concatenate(records)
    ground_velocity, slope, stick_energy = (np.empty_like(samples) for _ in range(3))
    block_max = np.empty(block_offsets[-1])
    block_min = np.empty_like(block_max)
    _prepare_records(samples, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min, block_offsets)
    out = np.empty((len(records), columns.shape[0], len(SCALAR_NAMES)))
    run_in_calls(lambda first, last: sweep_kernel(samples, offsets, dts, ground_velocity, slope, stick_energy,
                                                  block_max, block_min, block_offsets, columns, g, first, last, out),
                 np.repeat(sizes, columns.shape[0]))
    return out
