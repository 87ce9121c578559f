"""A slider under Coulomb friction and a linear restoring stiffness, in one direction: solved exactly on the event engine.

Per unit mass, relative to the ground, with a(t) the ground acceleration
[m/s²] linear between samples, a friction limit μ·g [m/s²] and a restoring
stiffness ω² [1/s²] (g/R for the friction pendulum of radius R,
:mod:`stickslip.models.pendulum.exact`; k/m for the block on a spring,
:mod:`stickslip.models.spring`):

* **stick** (u̇ = 0) while the force that holds it, |a + ω²·u|, is at most
  μ·g: the ground acceleration stays inside the band
  [−ω²u − μg, −ω²u + μg], shifted by the displacement it sticks at;
* **slip** in the direction s = ±1 (u̇ ≷ 0): ü = −a(t) − ω²·u − s·μ·g;
* **breakaway** where a leaves the band, along the force; **stop** where u̇
  returns to zero, then stick or slide back.

ω = 0 is the flat block of :mod:`stickslip.models.rigid.events`.  On a
sub-interval of length τ, with a(σ) = a₀ + k·σ, each slip is a linear
oscillator under a linear force: with f₀ = ü(0) and p₁ = −k,

    u(τ) = u₀ + u̇₀·S₁ + f₀·S₂ + p₁·S₃,
    u̇(τ) = u̇₀·C + f₀·S₁ + p₁·S₂,
    ü(τ) = f₀·C + (p₁ − ω²·u̇₀)·S₁,

C = cos ωτ and S_j its j-th integral from 0 (S₁ = sin ωτ/ω, S₂ = (1 − C)/ω²,
…), which tend to τ^j/j! as ω → 0 (:func:`phi_functions`: a series for
ωτ ≤ 2, so that no small ω loses digits).  ü is a sinusoid, so in a stretch
of at most a quarter period it vanishes at most once, at a point given by
atan2: there u̇ has its extremum, and the stretch splits into at most two
pieces on which u̇ is monotone.  A stop is a sign change of s·u̇ on such a
piece, located to round-off by Newton's method kept inside its bracket
(:func:`slip_stop_time`); a sample interval without one is proved quiet by
the same test (u̇ at its end and at its interior extremum), so most slipping
intervals cost one linear map whose coefficients are computed once per record.
Breakaway is the linear crossing of a band edge, as on the flat block.

The ledger per unit mass (:mod:`stickslip.solvers.ledger`), every term
integrated on its own: E_df = μ·g·(path), E_p = ½·ω²·u² (the energy stored
by the restoring force), E_k = ½·(u̇_g + u̇)², W_v = 0 (no vertical), and
E_I = ∫ü·u̇_g dt with ü = a in stick and ü = −ω²·u − s·μ·g in slip, whose
integral against the ground velocity u̇_g (quadratic in time) is closed in
S₁ … S₆ (:func:`slip_input_energy`).  E_k − E_k(0) + E_p − E_p(0) + E_df =
E_I then closes to round-off.

A sweep's scalars come from the event engine (:mod:`stickslip.solvers.events`)
on the phase functions here; a history visits every sample interval.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.records.process import integrate_linear_acceleration
from stickslip.solvers.compilation import engine_pieces, interval_engine, record_engine, sweep_engine
from stickslip.solvers.events import BLOCK, offsets, run_in_calls
from stickslip.solvers.ledger import HISTORY_COLUMNS, SCALAR_NAMES, history_dict, store_scalars

_PIECES = engine_pieces()
first_stop_time = _PIECES["first_stop_time"]
largest_magnitude = _PIECES["largest_magnitude"]
prepare_records = _PIECES["prepare_records"]

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
def _parameters(mug, w2, dt):
    """The slider's numbers for the phase functions: μ·g [m/s²], ω² [1/s²], :func:`phi_functions` (ω², dt), dt [s]
    and whether ü vanishes at most once in a sample interval (ω·dt ≤ π/2)."""
    return mug, w2, phi_functions(w2, dt), dt, w2 * dt * dt <= HALF_PI * HALF_PI


@numba.njit(cache=True, inline="always")
def _band(parameters, x):
    """(lower, upper) [m/s²]: the slider at u = x holds while −ω²u − μg ≤ a ≤ −ω²u + μg."""
    mug, w2, _, _, _ = parameters
    return level(w2, x, mug, 1), level(w2, x, mug, -1)


@numba.njit(cache=True, inline="always")
def _slide_edge(parameters, x, s):
    """The band's edge [m/s²] that a slide in direction s from u = x crossed: its absolute acceleration then."""
    mug, w2, _, _, _ = parameters
    return level(w2, x, mug, s)


@numba.njit(cache=True, inline="always")
def _stop_time(parameters, a, slope, edge, v, s, remaining):
    """The first stop [s] within ``remaining`` of a slide from u̇ = v with ü(0) = edge − a (:func:`slip_stop_time`)."""
    return slip_stop_time(v, edge - a, -slope, parameters[1], s, remaining)


@numba.njit(cache=True, inline="always")
def _slid(parameters, a, slope, vg, edge, x, v, s, tau):
    """``(u, u̇, E_I/m, path, max |ü|)`` after sliding for τ [s] from u = x, u̇ = v: the closed form of the module
    docstring, with the coefficients of a whole sample interval where τ is one."""
    mug, w2, phis_dt, dt, _ = parameters
    f0 = edge - a
    p1 = -slope
    phis = phis_dt if tau == dt else phi_functions(w2, tau)
    c, s1, s2, s3, _, _, _ = phis
    x_end = x + v * s1 + f0 * s2 + p1 * s3
    v_end = v * c + f0 * s1 + p1 * s2
    return (x_end, v_end, slip_input_energy(x, v, f0, p1, w2, s, mug, a, slope, vg, tau, phis), abs(x_end - x),
            max(abs(edge), abs(level(w2, x_end, mug, s))))


#: The event engine's loop over one sample interval (:func:`stickslip.solvers.events.interval_state`) on the
#: slider's phase functions: ``advance_interval(_parameters(μ·g, ω², dt), a_start, a_end, slope, dt, vg_start, x,
#: v, s)``.
advance_interval = interval_engine(__name__, band=_band, slide_edge=_slide_edge, stop_time=_stop_time, slid=_slid)


@numba.njit(cache=True)
def history_kernel(acceleration, ground_velocity, dt, mug, w2, g, x0, v0, history, out):
    """One record's history into ``history`` (n × len(HISTORY_COLUMNS)) and its scalars into ``out``.

    ``acceleration`` [m/s²] and ``ground_velocity`` [m/s] at the samples;
    ``mug`` μ·g, ``w2`` ω² = g/R [1/s²], ``g`` [m/s²] (for the base shear over
    the weight); the slider starts at u = x0 [m] with u̇ = v0 [m/s].
    """
    n = acceleration.size
    parameters = _parameters(mug, w2, dt)
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
            parameters, a0, acceleration[i + 1], (acceleration[i + 1] - a0) / dt, dt, ground_velocity[i], x, v, s)
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




@numba.njit(cache=True, inline="always")
def _hold_band(record, parameters, state):
    """The slider at u holds while −ω²u − μg ≤ a ≤ −ω²u + μg [m/s²]: the samples of a and their block extremes."""
    acceleration, _, _, _, _, block_max, block_min = record
    mug, w2, _, _, _ = parameters
    x = state[0]
    return acceleration, block_max, block_min, level(w2, x, mug, 1), level(w2, x, mug, -1)


@numba.njit(cache=True, inline="always")
def _held_over(record, parameters, state, first, last):
    """The state after holding from sample ``first`` to ``last``: the hold's input energy and largest |ü| = |a|."""
    acceleration, _, _, _, stick_energy, block_max, block_min = record
    x, v, s, energy_input, path, slip_time, episodes, peak, peak_acceleration = state
    return (x, v, s, energy_input + (stick_energy[last] - stick_energy[first]), path, slip_time, episodes, peak,
            max(peak_acceleration, largest_magnitude(acceleration, block_max, block_min, first, last)))


@numba.njit(cache=True, inline="always")
def _slid_through(record, parameters, state, i):
    """The state after sliding through interval i, when the quiet test (module docstring) clears it: one linear map."""
    acceleration, dt, ground_velocity, slope, _, _, _ = record
    mug, w2, phis_dt, _, one_stretch = parameters
    x, v, s, energy_input, path, slip_time, episodes, peak, peak_acceleration = state
    if one_stretch:
        c, s1, s2, s3, _, _, _ = phis_dt
        a0 = acceleration[i]
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
                return (x_end, v_end, s, energy_input, path + abs(x_end - x), slip_time + dt, episodes,
                        max(peak, abs(x_end)), peak_acceleration), True
    return state, False


@numba.njit(cache=True, inline="always")
def _crossed(record, parameters, state, i):
    """The state after interval i with every event inside it (:func:`advance_interval`)."""
    acceleration, dt, ground_velocity, slope, _, _, _ = record
    x, v, s, energy_input, path, slip_time, episodes, peak, peak_acceleration = state
    x, v, s, _, d_input, d_path, d_slip, d_episodes, d_peak, d_acceleration = advance_interval(
        parameters, acceleration[i], acceleration[i + 1], slope[i], dt, ground_velocity[i], x, v, s)
    return (x, v, s, energy_input + d_input, path + d_path, slip_time + d_slip, episodes + d_episodes,
            max(peak, d_peak), max(peak_acceleration, d_acceleration))


_record_state = record_engine(__name__, hold_band=_hold_band, held_over=_held_over,
                              slid_through=_slid_through, crossed=_crossed)


@numba.njit(cache=True)
def _record_scalars(acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min, mug, w2, g, out):
    """The scalars of one record and one (μ·g, ω²) into ``out``, at a cost that follows the slip.

    The event engine on the phase functions above: a stick at u skips to the
    first sample outside its band [−ω²u − μg, −ω²u + μg], its input energy a
    difference of ``stick_energy``; a slipping interval that the quiet test
    (module docstring) clears is one linear map with the coefficients of
    :func:`phi_functions` (ω², dt); any other goes through
    :func:`advance_interval`.  Equal to :func:`history_kernel`'s scalars to round-off.
    """
    n = acceleration.size
    parameters = _parameters(mug, w2, dt)
    x, v, s, energy_input, path, slip_time, episodes, peak, peak_acceleration = _record_state(
        (acceleration, dt, ground_velocity, slope, stick_energy, block_max, block_min), parameters,
        (0.0, 0.0, 0, 0.0, 0.0, 0.0, 0, 0.0, 0.0), n)
    store_scalars(out, mug * path, energy_input, 0.0, ground_velocity[n - 1] + v, w2, x, peak, path, slip_time,
                  (n - 1) * dt, episodes, peak_acceleration, g, 0.0)


@numba.njit(cache=True, inline="always")
def _solved_pair(group, record, columns, column, out):
    """:func:`_record_scalars` of one record of a group and one row (μ·g [m/s²], ω² [1/s²]) of ``columns``."""
    samples, offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min, block_offsets, g = group
    first, last = offsets[record], offsets[record + 1]
    blocks = slice(block_offsets[record], block_offsets[record + 1])
    _record_scalars(samples[first:last], dts[record], ground_velocity[first:last], slope[first:last],
                    stick_energy[first:last], block_max[blocks], block_min[blocks], columns[column, 0],
                    columns[column, 1], g, out)


_sweep_pairs = sweep_engine(__name__, _solved_pair)


def restoring_history(acceleration, dt: float, mug: float, w2: float, g: float, initial_displacement: float = 0.0,
                      initial_velocity: float = 0.0) -> dict:
    """The exact history of the slider under one ground acceleration [m/s²] sampled every ``dt`` [s].

    ``mug`` μ·g [m/s²] and ``w2`` ω² [1/s²] (0: no restoring force), ``g``
    [m/s²] for the base shear over the weight; the slider starts at u =
    ``initial_displacement`` [m] with u̇ = ``initial_velocity`` [m/s] (the
    ground at rest).  Returns :func:`stickslip.solvers.ledger.history_dict`
    with E_p = ½·ω²·u², per unit mass.
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    ground_velocity, _ = integrate_linear_acceleration(acceleration, dt)
    history = np.empty((acceleration.size, len(HISTORY_COLUMNS)))
    scalars = np.empty(len(SCALAR_NAMES))
    history_kernel(acceleration, ground_velocity, dt, mug, w2, g, float(initial_displacement),
                   float(initial_velocity), history, scalars)
    return history_dict(history, scalars, ground_velocity, dt, w2)


def restoring_sweep(records, dts: np.ndarray, columns: np.ndarray, g: float) -> np.ndarray:
    """End-of-record scalars of the slider for every record and column, in parallel on the event engine.

    ``records`` the checked ground accelerations [m/s²] (a list of 1-D
    arrays), ``dts`` their sample intervals [s] (one per record),
    ``columns`` one row (μ·g [m/s²], ω² [1/s²]) per column, ``g`` [m/s²] for
    the base shear over the weight.  Returns shape (records, columns,
    len(SCALAR_NAMES)) per unit mass, in the units of
    :data:`~stickslip.solvers.ledger.SCALAR_UNITS`.
    """
    sizes = np.array([a.size for a in records], dtype=np.int64)
    record_offsets = offsets(sizes)
    block_offsets = offsets((sizes + BLOCK - 1) // BLOCK)
    samples = np.concatenate(records)
    ground_velocity, slope, stick_energy = (np.empty_like(samples) for _ in range(3))
    block_max = np.empty(block_offsets[-1])
    block_min = np.empty_like(block_max)
    prepare_records(samples, record_offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min,
                    block_offsets)
    group = (samples, record_offsets, dts, ground_velocity, slope, stick_energy, block_max, block_min, block_offsets,
             float(g))
    out = np.empty((len(records), columns.shape[0], len(SCALAR_NAMES)))
    run_in_calls(lambda first, last: _sweep_pairs(group, columns, first, last, out),
                 np.repeat(sizes, columns.shape[0]))
    return out
