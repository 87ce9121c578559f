"""The flexible sliding block solved exactly for the piecewise-linear record: closed forms per step, located events.

The physics is :mod:`stickslip.models.layer.layer`'s, in the decoupled frame
(u driven by −(L/M)·a; SLAMMER's coupled code uses −u, which changes no
result).  Between two samples the ground acceleration a(τ) = a_i + s·τ is
linear, and in each phase the layer's equation is linear with constant
coefficients and a forcing linear in τ,

    ü + 2ξ'ω' u̇ + ω'² u = P₀ + P₁ τ,

so its response from (u₀, u̇₀) has the closed form (ω_d = ω'√(1 − ξ'²))

    u(τ) = c₀ + c₁τ + e^{−ξ'ω'τ} (A cos ω_d τ + B sin ω_d τ),
    c₁ = P₁/ω'²,  c₀ = (P₀ − 2ξ'ω'c₁)/ω'²,  A = u₀ − c₀,  B = (u̇₀ − c₁ + ξ'ω'A)/ω_d,

and ü = P₀ + P₁τ − 2ξ'ω'u̇ − ω'²u.  Phases:

* **the layer on its base** (the decoupled layer always; the coupled one
  while the block sticks): ω' = ω, ξ' = ξ, P₀ + P₁τ = −(L/M)·a(τ);
* **the coupled layer while the block slides**: (1 − L²/(M M_tot))·ü + 2ξωu̇ + ω²u
  = −(L/M)·k_y g, i.e. ω' = ω/√d, ξ' = ξ/√d with d = 1 − 8/π², P₀ = −(L/M)k_y g/d, P₁ = 0
  (SLAMMER's ``Coupled``: the layer's base carries the resisting acceleration).

The block's downslope velocity w relative to the sliding surface obeys
ẇ = a − k_y g + (L/M_tot)·ü in both models (for the decoupled block,
a + (L/M_tot)ü is the layer's average acceleration k·g), so that over a
phase its velocity and displacement are closed forms too:

    w(τ) = w₀ + (a_i − k_y g)τ + s τ²/2 + (L/M_tot)(u̇(τ) − u̇₀),
    D(τ) = D₀ + w₀τ + (a_i − k_y g)τ²/2 + s τ³/6 + (L/M_tot)(u(τ) − u₀ − u̇₀τ).

The block starts to slide when k·g − k_y g = a + (L/M_tot)ü_base − k_y g turns
positive (for the coupled block this is the base shear exceeding the resistance)
and stops when w returns to zero; each event is located to round-off inside the
sub-interval where its function changes sign (:func:`_root`).  A sample
interval is cut into sub-intervals of at most 1/16 of the shortest period of the
phases (the closed forms are exact on any of them; the cut is only where events
are searched: at 4 points in each, whose exponential, cosine and sine follow by
recurrence from each phase's rotation over a quarter sub-interval, computed once
per record; only a sub-interval cut by an event computes its own).  Where a function touches zero between
two of those points without changing sign there (a slip shorter than about
1/64 of the layer's period), the event is missed: the one approximation, and
measured in docs/solvers.md.  The answer otherwise depends on the record alone,
not on its sampling: resampling the record linearly changes nothing.

Most sample intervals need no search: where a bound on the transient proves
that nothing happens in one (:func:`_quiet`), it is one step of the closed form,
a linear map of (u₀, u̇₀, P₀, P₁) computed once per record.

k_max, the largest |k|, is reported both at the samples (SLAMMER's) and
between them (:func:`average_peak`): k·g of the layer on its base is a + sτ
plus (L/M_tot) times the transient's second derivative, so that each of its
extrema in a sample interval is located as a root of (k·g)', in the same
closed form.

Requires ξ' < 1 in every phase: ξ < 1, and for the coupled block ξ < √d ≈ 0.435.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from stickslip.errors import StickslipError
from stickslip.models.layer.layer import (
    COUPLING,
    PARTICIPATION_OVER_MASS,
    PARTICIPATION_OVER_MODAL_MASS,
    circular_frequency,
    settled_properties,
)
from stickslip.models.layer.energy import flexible_ledger

#: Sub-intervals per shortest period of the layer's phases, and event-search points per sub-interval.
SUBSTEPS_PER_PERIOD = 16
SEARCH_POINTS = 4

#: The most steps that locate an event or an extremum (to round-off on any sub-interval; about 10 do).
ROOT_STEPS = 256

#: What a located root is: the block starts to slide, it stops, the layer's u̇ changes sign (an extremum of u),
#: the slope of the layer's average acceleration k·g changes sign (an extremum of k·g), or its curvature does.
STARTS, STOPS, TURNS, PEAKS, INFLECTS = 0, 1, 2, 3, 4


def _coefficients(u0, v0, omega, decay, damped, p0, p1):
    """c₀, c₁, A, B of the closed form from (u₀, u̇₀), ω', ξ'ω' (``decay``), ω_d (``damped``), P₀, P₁."""
    c1 = p1 / (omega * omega)
    c0 = (p0 - 2.0 * decay * c1) / (omega * omega)
    a = u0 - c0
    b = (v0 - c1 + decay * a) / damped
    return c0, c1, a, b


def _state(tau, e, cosine, sine, c0, c1, a, b, damped, decay):
    """u, u̇ at τ of the closed form, given e^{−ξ'ω'τ}, cos ω_dτ and sin ω_dτ (``decay`` = ξ'ω')."""
    u = c0 + c1 * tau + e * (a * cosine + b * sine)
    v = c1 + e * ((-decay * a + damped * b) * cosine + (-decay * b - damped * a) * sine)
    return u, v


def _layer(tau, c0, c1, a, b, damped, decay):
    """u, u̇ at τ of the closed form (``decay`` = ξ'ω')."""
    return _state(tau, math.exp(-decay * tau), math.cos(damped * tau), math.sin(damped * tau), c0, c1, a, b, damped,
                  decay)


def _event_from_state(u, v, tau, sliding, decay, omega, p0, p1, a0, slope, threshold, ratio, w0, v0):
    """The function whose sign change is the next event, from the layer's u, u̇ at τ: w while sliding,
    k·g − k_y g (layer on its base) while stuck."""
    if sliding:
        return w0 + (a0 - threshold) * tau + 0.5 * slope * tau * tau + ratio * (v - v0)
    acceleration = p0 + p1 * tau - 2.0 * decay * v - omega * omega * u
    return a0 + slope * tau + ratio * acceleration - threshold


def _average_rates(tau, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, ratio):
    """k·g [m/s²] of the layer on its base at τ and its first two derivatives [m/s³, m/s⁴], from the closed form.

    k·g = a + (L/M_tot)·ü, and the layer's equation and its derivatives give
    ü = P₀ + P₁τ − 2ξωu̇ − ω²u, u⃛ = P₁ − 2ξωü − ω²u̇ and u⁗ = −2ξωu⃛ − ω²ü.
    """
    u, v = _layer(tau, c0, c1, a, b, damped, decay)
    acceleration = p0 + p1 * tau - 2.0 * decay * v - omega * omega * u
    jerk = p1 - 2.0 * decay * acceleration - omega * omega * v
    snap = -2.0 * decay * jerk - omega * omega * acceleration
    return a0 + slope * tau + ratio * acceleration, slope + ratio * jerk, ratio * snap


def _watched(tau, kind, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, threshold, ratio, w0, v0):
    """q(τ), which turns positive (or reaches zero, but for :data:`STARTS`) once the event ``kind`` has happened:
    k·g − k_y g (:data:`STARTS`), −w (:data:`STOPS`), −u̇·sign v₀ (:data:`TURNS`), −(k·g)'·sign v₀
    (:data:`PEAKS`), −(k·g)''·sign v₀ (:data:`INFLECTS`); for the last three, v₀ is the watched rate at the
    start of the bracket."""
    if kind >= PEAKS:
        rate = _average_rates(tau, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, ratio)[kind - PEAKS + 1]
        return -rate if v0 > 0.0 else rate
    u, v = _layer(tau, c0, c1, a, b, damped, decay)
    if kind == TURNS:
        return -v if v0 > 0.0 else v
    f = _event_from_state(u, v, tau, kind == STOPS, decay, omega, p0, p1, a0, slope, threshold, ratio, w0, v0)
    return -f if kind == STOPS else f


def _happened(q, kind):
    """Whether q of :func:`_watched` says that the event ``kind`` has happened."""
    return q > 0.0 or (q == 0.0 and kind != STARTS)


def _root(low, high, q_low, q_high, kind, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, threshold, ratio,
          w0, v0):
    """The bracket (low, high] [s], shrunk to round-off, of the first time the event ``kind`` happens: it has not
    at ``low`` (q_low), it has at ``high`` (q_high).

    False position with the Illinois rule (the end that stays twice has its q
    halved), and every fourth step a bisection: about ten evaluations where
    bisection takes some fifty.
    """
    side = 0
    for step in range(ROOT_STEPS):
        middle = 0.5 * (low + high)
        if middle <= low or middle >= high:
            break
        if step % 4 != 3 and q_high != q_low:
            secant = low - q_low * (high - low) / (q_high - q_low)
            if low < secant < high:
                middle = secant
        q = _watched(middle, kind, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, threshold, ratio, w0, v0)
        if _happened(q, kind):
            high, q_high = middle, q
            if side == 1:
                q_low *= 0.5
            side = 1
        else:
            low, q_low = middle, q
            if side == -1:
                q_high *= 0.5
            side = -1
    return low, high


def _quiet(length, searched, track_peak, sliding, c0, c1, a, b, omega, decay, p0, p1, a0, slope, threshold, ratio,
           u0, v0, w0, u, v, peak):
    """Whether a bound proves that nothing happens over the next ``length`` [s], from (u₀, u̇₀) to (u, u̇): no event
    of the block, or no |u| above ``peak`` where that is tracked (nothing to watch: quiet).

    The transient e^{−ξ'ω'τ}(A cos ω_dτ + B sin ω_dτ) and its k-th derivative
    are at most ω'^k R in size (R = √(A² + B²), ω'² = (ξ'ω')² + ω_d²), and the
    rest of each watched function g is a polynomial in τ of degree two at most:
    stuck, g = k·g − k_y g = a₀ + sτ + (L/M_tot)ü − k_y g (ü's particular part
    is zero) must stay at or below zero; sliding, g = w must stay positive; the
    layer alone, g = ±u must stay at or below the peak.  Two bounds: the
    transient's whole size added to the polynomial's extreme over the length,
    and the curvature's, g ≤ max(g(0), g(length)) + max|g''|·length²/8.
    """
    if not searched and not track_peak:
        return True
    amplitude = math.sqrt(a * a + b * b)
    curvature = 0.125 * length * length
    if not searched:
        return min(max(abs(c0), abs(c0 + c1 * length)) + amplitude,
                   max(abs(u0), abs(u)) + curvature * omega * omega * amplitude) <= peak
    if sliding:
        rate = a0 - threshold
        least = min(0.0, rate * length + 0.5 * slope * length * length)
        if slope > 0.0 and 0.0 < -rate < slope * length:  # the parabola's vertex inside
            least = min(least, -0.5 * rate * rate / slope)
        if w0 + ratio * (c1 - v0) - ratio * omega * amplitude + least > 0.0:
            return True
    elif a0 - threshold + max(0.0, slope * length) + ratio * omega * omega * amplitude <= 0.0:
        return True
    start = _event_from_state(u0, v0, 0.0, sliding, decay, omega, p0, p1, a0, slope, threshold, ratio, w0, v0)
    end = _event_from_state(u, v, length, sliding, decay, omega, p0, p1, a0, slope, threshold, ratio, w0, v0)
    if sliding:
        return min(start, end) - curvature * (abs(slope) + ratio * omega ** 3 * amplitude) > 0.0
    return max(start, end) + curvature * ratio * omega ** 4 * amplitude <= 0.0


def _slid(step, d0, w0, a0, slope, threshold, ratio, u0, v0, u, v):
    """The block's D [m] and w [m/s] after sliding ``step`` [s] from (D₀, w₀), the layer from (u₀, u̇₀) to (u, u̇)."""
    d = (d0 + w0 * step + 0.5 * (a0 - threshold) * step * step + slope * step ** 3 / 6.0
         + ratio * (u - u0 - v0 * step))
    return d, w0 + (a0 - threshold) * step + 0.5 * slope * step * step + ratio * (v - v0)


def _ledger_step(length, e, cosine, sine, sliding, coupled, c0, c1, a, b, omega, decay, damped, p0, p1, a0, slope,
                 threshold, ratio, u0, v0, u, v, ground_velocity):
    """Over ``length`` [s] of one phase, from (u₀, u̇₀) to (u, u̇): the input energy to the sliding mass per unit
    mass [J/kg], ∫u̇² dτ [m²/s], and the decoupled block's input energy from the layer [J/kg].

    ``e``, ``cosine``, ``sine`` are e^{−ξ'ω'ℓ}, cos ω_dℓ, sin ω_dℓ; ``ground_velocity``
    v_g [m/s] at the start.  Every integral is a closed form: the ground's force
    per unit mass is a + (L/M_tot)ü while the block sticks (or on the decoupled
    layer) and k_y g while it slides; ∫ü v_g = [u̇ v_g] − [u a] + s∫u by parts,
    with ∫u = (∫P − [u̇] − 2ξ'ω'[u])/ω'² from the layer's equation; and u̇² =
    c₁² + 2c₁ Re(Z e^{zτ}) + ½|Z|² e^{−2ξ'ω'τ} + ½ Re(Z² e^{2zτ}), z = −ξ'ω' + iω_d.
    """
    ground_end = ground_velocity + a0 * length + 0.5 * slope * length * length
    a_end = a0 + slope * length
    integral_u = (p0 * length + 0.5 * p1 * length * length - (v - v0) - 2.0 * decay * (u - u0)) / (omega * omega)
    layer_input = (0.5 * (ground_end * ground_end - ground_velocity * ground_velocity)
                   + ratio * ((v * ground_end - v0 * ground_velocity) - (a_end * u - a0 * u0) + slope * integral_u))
    ground_path = ground_velocity * length + 0.5 * a0 * length * length + slope * length ** 3 / 6.0
    z = complex(-decay, damped)
    zeta = complex(-decay * a + damped * b, decay * b + damped * a)  # u̇'s transient is Re(ζ e^{zτ})
    turn = e * complex(cosine, sine)
    decayed = length if decay == 0.0 else (1.0 - e * e) / (2.0 * decay)
    velocity_square = (c1 * c1 * length + 2.0 * c1 * (zeta * (turn - 1.0) / z).real + 0.5 * abs(zeta) ** 2 * decayed
                       + 0.5 * (zeta * zeta * (turn * turn - 1.0) / (2.0 * z)).real)
    if coupled:
        return (threshold * ground_path if sliding else layer_input), velocity_square, 0.0
    if sliding:
        block_input = threshold * (ground_path + ratio * (u - u0))
    else:
        base_start, base_end = ground_velocity + ratio * v0, ground_end + ratio * v
        block_input = 0.5 * (base_end * base_end - base_start * base_start)
    return layer_input, velocity_square, block_input


def _peak_between(low, high, rate_low, rate_high, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, ratio,
                  peak):
    """max(``peak``, |k·g| [m/s²] at the extremum of k·g inside (low, high] [s]), where its slope (k·g)' changes
    sign from ``rate_low`` to ``rate_high`` [m/s³]; the extremum located to round-off."""
    low, high = _root(low, high, -abs(rate_low), abs(rate_high), PEAKS, c0, c1, a, b, damped, decay, omega, p0, p1,
                      a0, slope, 0.0, ratio, 0.0, rate_low)
    return max(peak, abs(_average_rates(0.5 * (low + high), c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope,
                                        ratio)[0]))


def _interval_average_peak(length, pieces, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, ratio, peak):
    """max(``peak``, the largest |k·g| [m/s²] of the layer on its base over [0, ``length``] [s]), each extremum located.

    The closed form (from the state at the interval's start, ω, ξω = ``decay``,
    ω_d = ``damped``, P₀ + P₁τ, the ground's a₀ + sτ) is cut into ``pieces`` of
    at most 1/16 of the layer's period.  (k·g)'' = (L/M_tot)·u⁗ is the transient's
    fourth derivative, a damped sinusoid of frequency ω_d whose zeros lie π/ω_d
    > T/2 apart, so it changes sign at most once in a piece and (k·g)' at most
    twice: once where its signs at the ends differ; otherwise twice or never, on
    either side of the zero of (k·g)'' (where it changes sign) if (k·g)' has
    the other sign there.  A piece of length ℓ is skipped where the bound
    |k·g| ≤ max(|k·g| at its ends) + ℓ²/8·(L/M_tot)·ω⁴·R (R = √(A² + B²), the
    transient's amplitude) proves it at most ``peak``.
    """
    curvature = 0.125 * ratio * omega ** 4 * math.sqrt(a * a + b * b)
    step = length / pieces
    high = 0.0
    f_high, d_high, e_high = _average_rates(high, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, ratio)
    peak = max(peak, abs(f_high))
    for piece in range(pieces):
        low, f_low, d_low, e_low = high, f_high, d_high, e_high
        high = length if piece == pieces - 1 else (piece + 1) * step
        f_high, d_high, e_high = _average_rates(high, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, ratio)
        peak = max(peak, abs(f_high))
        if max(abs(f_low), abs(f_high)) + curvature * (high - low) ** 2 <= peak:
            continue
        if d_low * d_high < 0.0:
            peak = _peak_between(low, high, d_low, d_high, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope,
                                 ratio, peak)
        elif e_low * e_high < 0.0:
            bracket = _root(low, high, -abs(e_low), abs(e_high), INFLECTS, c0, c1, a, b, damped, decay, omega, p0, p1,
                            a0, slope, 0.0, ratio, 0.0, e_low)
            middle = 0.5 * (bracket[0] + bracket[1])
            d_middle = _average_rates(middle, c0, c1, a, b, damped, decay, omega, p0, p1, a0, slope, ratio)[1]
            if d_middle * d_low < 0.0:
                peak = _peak_between(low, middle, d_low, d_middle, c0, c1, a, b, damped, decay, omega, p0, p1, a0,
                                     slope, ratio, peak)
                peak = _peak_between(middle, high, d_middle, d_high, c0, c1, a, b, damped, decay, omega, p0, p1, a0,
                                     slope, ratio, peak)
    return peak


def average_peak(a, dt, omega, xi, participation, ratio, u, v, average, peak):
    """The largest |k·g| [m/s²] of the layer on its base over the record: between the samples as well as at them.

    ``a`` ground acceleration [m/s²], ``dt`` [s], ``omega`` ω [rad/s], ``xi`` ξ,
    ``participation`` L/M, ``ratio`` L/M_tot, and the layer on its base at the
    samples (:func:`flexible_exact`'s): u [m], u̇ [m/s], k·g [m/s²] and
    ``peak``, the largest |k·g| there.  A sample interval is searched
    (:func:`_interval_average_peak`) only where the bound
    max(|k·g| at its ends) + dt²/8·(L/M_tot)·ω⁴·R cannot prove it below that
    peak, which leaves a few intervals near it.  The bound's pass is a loop
    without branches (R² from the state at the interval's start, c₀ and c₁ as
    multiples of the samples), apart from the search.
    """
    n = a.size
    decay = xi * omega
    damped = omega * math.sqrt(1.0 - xi * xi)
    pieces = max(1, int(math.ceil(dt * SUBSTEPS_PER_PERIOD * omega / (2.0 * math.pi))))
    curvature = 0.125 * dt * dt * ratio * omega ** 4
    curvature_square = curvature * curvature
    # c₁ = P₁/ω² and c₀ = (P₀ − 2ξωc₁)/ω² of _coefficients, with P₀ = −(L/M)a_i and P₁ = −(L/M)(a_i+1 − a_i)/dt
    slope_factor = -participation / (dt * omega * omega)
    level_factor = -participation / (omega * omega)
    slope_level_factor = -2.0 * decay * slope_factor / (omega * omega)
    inverse_damped = 1.0 / damped
    searched = np.empty(max(n - 1, 0), dtype=np.bool_)
    for i in range(n - 1):
        room = peak - max(abs(average[i]), abs(average[i + 1]))
        difference = a[i + 1] - a[i]
        c1 = slope_factor * difference
        ca = u[i] - (level_factor * a[i] + slope_level_factor * difference)
        cb = (v[i] - c1 + decay * ca) * inverse_damped
        searched[i] = curvature_square * (ca * ca + cb * cb) > room * room
    for i in range(n - 1):
        if searched[i]:
            slope = (a[i + 1] - a[i]) / dt
            p0, p1 = -participation * a[i], -participation * slope
            c0, c1, ca, cb = _coefficients(u[i], v[i], omega, decay, damped, p0, p1)
            peak = _interval_average_peak(dt, pieces, c0, c1, ca, cb, damped, decay, omega, p0, p1, a[i], slope,
                                          ratio, peak)
    return peak


def flexible_exact(a, dt, omega, xi, threshold, coupled, participation, ratio, coupling, track_peak, ledger):
    """The exact solution at the samples: layer u [m] and u̇ [m/s], k·g [m/s²], block D [m] and w [m/s]; the largest
    |k·g| at the samples [m/s²], peak |u| [m] and episodes.

    The peak |u| is tracked where ``track_peak`` asks for it and there is no
    block (``threshold`` infinite: the equivalent-linear iteration's run);
    otherwise it is zero.

    ``a`` ground acceleration [m/s²] (one polarity), ``dt`` [s], ``omega`` ω
    [rad/s], ``xi`` ξ, ``threshold`` k_y·g [m/s²], ``coupled``: whether
    sliding acts on the layer; ``participation`` L/M, ``ratio`` L/M_tot,
    ``coupling`` L²/(M M_tot).  k·g is the layer's average acceleration on its
    base (the decoupled layer's).

    With ``ledger``, also the ledger's integrals at the samples (:func:`_ledger_step`),
    rows: the ground velocity v_g [m/s], the layer's u̇ [m/s], the input energy
    to the sliding mass per unit mass [J/kg], ∫u̇² dt [m²/s] and the decoupled
    block's input energy from the layer [J/kg]; without, one empty column.
    """
    n = a.size
    out_u, out_v, out_kg, out_d, out_w = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    out_ledger = np.zeros((5, n if ledger else 1))
    ground, energy_input, velocity_square, block_input = 0.0, 0.0, 0.0, 0.0
    mass = 1.0 - coupling
    fastest = omega / math.sqrt(mass) if coupled else omega
    period = 2.0 * math.pi / fastest
    substeps = max(1, int(math.ceil(dt * SUBSTEPS_PER_PERIOD / period)))
    h = dt / substeps
    # each phase's ω', ξ'ω', ω_d, and the rotation over a quarter and a whole of a full sub-interval
    omegas = np.array([omega, omega / math.sqrt(mass)])
    decays = np.array([xi * omega, xi * omega / mass])
    dampeds = omegas * np.sqrt(1.0 - (decays / omegas) ** 2)
    quarter_turns = np.empty((2, 3))
    whole_turns = np.empty((2, 3))
    sample_turns = np.empty((2, 3))
    for phase in range(2):
        for turns, length in ((quarter_turns, h / SEARCH_POINTS), (whole_turns, h), (sample_turns, dt)):
            turns[phase, 0] = math.exp(-decays[phase] * length)
            turns[phase, 1] = math.cos(dampeds[phase] * length)
            turns[phase, 2] = math.sin(dampeds[phase] * length)
    # over a whole sample interval the closed form is a linear map of (u₀, u̇₀, P₀, P₁) to (u, u̇): its columns
    sample_maps = np.empty((2, 2, 4))
    for phase in range(2):
        for column in range(4):
            unit = np.zeros(4)
            unit[column] = 1.0
            c0, c1, ca, cb = _coefficients(unit[0], unit[1], omegas[phase], decays[phase], dampeds[phase], unit[2],
                                           unit[3])
            sample_maps[phase, 0, column], sample_maps[phase, 1, column] = _layer(dt, c0, c1, ca, cb, dampeds[phase],
                                                                                  decays[phase])
    searched = threshold < math.inf  # a block's events to search
    track_peak = track_peak and not searched
    u, v, d, w = 0.0, 0.0, 0.0, 0.0
    peak = 0.0
    episodes = 0
    out_kg[0] = a[0] * (1.0 - ratio * participation)
    kg_peak = abs(out_kg[0])
    sliding = out_kg[0] > threshold
    if sliding:
        episodes += 1
    for i in range(n - 1):
        slope = (a[i + 1] - a[i]) / dt
        # the whole sample interval in one closed form where nothing happens in it (:func:`_quiet`)
        phase = 1 if coupled and sliding else 0
        if phase == 1:
            p0, p1 = -participation * threshold / mass, 0.0
        else:
            p0, p1 = -participation * a[i], -participation * slope
        om, decay, damped = omegas[phase], decays[phase], dampeds[phase]
        m = sample_maps[phase]
        un = m[0, 0] * u + m[0, 1] * v + m[0, 2] * p0 + m[0, 3] * p1
        vn = m[1, 0] * u + m[1, 1] * v + m[1, 2] * p0 + m[1, 3] * p1
        quiet = True
        if searched or track_peak:
            c0, c1, ca, cb = _coefficients(u, v, om, decay, damped, p0, p1)
            quiet = _quiet(dt, searched, track_peak, sliding, c0, c1, ca, cb, om, decay, p0, p1, a[i], slope,
                           threshold, ratio, u, v, w, un, vn, peak)
        if quiet:
            if ledger:
                if not (searched or track_peak):
                    c0, c1, ca, cb = _coefficients(u, v, om, decay, damped, p0, p1)
                step_input, step_square, step_block = _ledger_step(
                    dt, sample_turns[phase, 0], sample_turns[phase, 1], sample_turns[phase, 2], sliding, coupled, c0,
                    c1, ca, cb, om, decay, damped, p0, p1, a[i], slope, threshold, ratio, u, v, un, vn, ground)
                energy_input += step_input
                velocity_square += step_square
                block_input += step_block
                ground += a[i] * dt + 0.5 * slope * dt * dt
            if sliding:
                d, w = _slid(dt, d, w, a[i], slope, threshold, ratio, u, v, un, vn)
            u, v = un, vn
        for j in range(0 if quiet else substeps):
            start = j * h
            remaining = h
            while remaining > 0.0:
                a0 = a[i] + slope * start
                phase = 1 if coupled and sliding else 0
                if phase == 1:
                    p0, p1 = -participation * threshold / mass, 0.0
                else:
                    p0, p1 = -participation * a0, -participation * slope
                om, decay, damped = omegas[phase], decays[phase], dampeds[phase]
                c0, c1, ca, cb = _coefficients(u, v, om, decay, damped, p0, p1)
                event = -1.0
                low = 0.0
                whole = remaining == h
                if whole:
                    un, vn = _state(h, whole_turns[phase, 0], whole_turns[phase, 1], whole_turns[phase, 2],
                                    c0, c1, ca, cb, damped, decay)
                else:
                    un, vn = _layer(remaining, c0, c1, ca, cb, damped, decay)
                # search this sub-interval where a bound cannot prove that nothing happens in it
                look = not _quiet(remaining, searched, track_peak, sliding, c0, c1, ca, cb, om, decay, p0, p1, a0,
                                  slope, threshold, ratio, u, v, w, un, vn, peak)
                # the search points τ_k = k·q: e^{−ξ'ω'τ}, cos and sin by recurrence from the quarter's rotation
                quarter = remaining / SEARCH_POINTS
                if whole:
                    factor, turn_cos, turn_sin = quarter_turns[phase, 0], quarter_turns[phase, 1], \
                        quarter_turns[phase, 2]
                else:
                    factor, turn_cos, turn_sin = math.exp(-decay * quarter), math.cos(damped * quarter), \
                        math.sin(damped * quarter)
                e, cosine, sine = 1.0, 1.0, 0.0
                kind = STOPS if sliding else STARTS
                q_low = _watched(0.0, kind, c0, c1, ca, cb, damped, decay, om, p0, p1, a0, slope, threshold, ratio,
                                 w, v) if searched and look else 0.0
                for k in range(1, SEARCH_POINTS + 1 if searched and look else 1):
                    e, cosine, sine = e * factor, cosine * turn_cos - sine * turn_sin, sine * turn_cos + cosine * turn_sin
                    tau = remaining if k == SEARCH_POINTS else quarter * k
                    us, vs = _state(tau, e, cosine, sine, c0, c1, ca, cb, damped, decay)
                    f = _event_from_state(us, vs, tau, sliding, decay, om, p0, p1, a0, slope, threshold, ratio, w, v)
                    q = -f if sliding else f
                    if _happened(q, kind):
                        event = _root(low, tau, q_low, q, kind, c0, c1, ca, cb, damped, decay, om, p0, p1, a0, slope,
                                      threshold, ratio, w, v)[1]
                        break
                    low, q_low = tau, q
                step = remaining if event < 0.0 else event
                if event >= 0.0:
                    un, vn = _layer(step, c0, c1, ca, cb, damped, decay)
                if ledger:
                    step_input, step_square, step_block = _ledger_step(
                        step, math.exp(-decay * step), math.cos(damped * step), math.sin(damped * step), sliding,
                        coupled, c0, c1, ca, cb, om, decay, damped, p0, p1, a0, slope, threshold, ratio, u, v, un, vn,
                        ground)
                    energy_input += step_input
                    velocity_square += step_square
                    block_input += step_block
                    ground += a0 * step + 0.5 * slope * step * step
                if sliding:
                    d, w = _slid(step, d, w, a0, slope, threshold, ratio, u, v, un, vn)
                if track_peak and look and v * vn < 0.0:  # u has an extremum inside: locate u̇ = 0 for the exact peak |u|
                    low, high = _root(0.0, step, -abs(v), abs(vn), TURNS, c0, c1, ca, cb, damped, decay, om, p0, p1,
                                      a0, slope, threshold, ratio, w, v)
                    peak = max(peak, abs(_layer(0.5 * (low + high), c0, c1, ca, cb, damped, decay)[0]))
                u, v = un, vn
                if track_peak:
                    peak = max(peak, abs(u))
                start += step
                remaining -= step
                if event >= 0.0:
                    sliding = not sliding
                    w = 0.0
                    if sliding:
                        episodes += 1
                if remaining <= 1e-15 * h:
                    remaining = 0.0
        acceleration = -participation * a[i + 1] - 2.0 * xi * omega * v - omega * omega * u
        if coupled and sliding:
            acceleration = (-participation * threshold - 2.0 * xi * omega * v - omega * omega * u) / mass
        out_u[i + 1], out_v[i + 1], out_d[i + 1], out_w[i + 1] = u, v, d, w
        out_kg[i + 1] = a[i + 1] + ratio * acceleration
        kg_peak = max(kg_peak, abs(out_kg[i + 1]))
        if ledger:
            out_ledger[0, i + 1], out_ledger[1, i + 1], out_ledger[2, i + 1] = ground, v, energy_input
            out_ledger[3, i + 1], out_ledger[4, i + 1] = velocity_square, block_input
    return out_u, out_v, out_kg, out_d, out_w, kg_peak, peak, episodes, out_ledger


@functools.cache
def _compiled():
    """:func:`flexible_exact`, :func:`average_peak` and their helpers compiled by numba (cached on disk), by name."""
    import sys

    from stickslip.solvers.compilation import compiled_kernels

    return compiled_kernels(sys.modules[__name__], ("_coefficients", "_state", "_layer", "_event_from_state",
                                                    "_average_rates", "_watched", "_happened", "_root", "_quiet",
                                                    "_slid", "_ledger_step", "_peak_between", "_interval_average_peak",
                                                    "average_peak", "flexible_exact"),
                            cache=True)


def exact_response(coupled: bool, a: np.ndarray, dt: float, threshold: float, vs: float, height: float,
                   damping: float, track_peak: bool = False, ledger: bool = False,
                   average_peak: bool = False) -> dict:
    """The exact solution, ``coupled`` or decoupled, on ``a`` [m/s²]; see :func:`flexible_exact`.

    The key ``sample_peak`` holds the largest |k·g| [m/s²] at the samples.
    With ``ledger``, the key ``ledger_integrals`` holds the ledger's integrals at the samples (5 × n).
    With ``average_peak`` (decoupled only: the layer on its base), the key
    ``average_peak`` holds the largest |k·g| [m/s²] between the samples as at them (:func:`average_peak`).
    """
    if coupled and damping >= math.sqrt(1.0 - COUPLING):
        raise StickslipError(f"the exact coupled scheme needs a total damping below {math.sqrt(1.0 - COUPLING):.3f} "
                             f"(the sliding layer would be overdamped), got {damping:.4g}; use method slammer")
    if coupled and average_peak:
        raise StickslipError("the continuous peak of k·g is the layer's on its base: ask the decoupled response")
    kernels = _compiled()
    a = np.ascontiguousarray(a, dtype=float)
    omega = circular_frequency(vs, height)
    u, v, kg, d, w, kg_peak, peak, episodes, integrals = kernels["flexible_exact"](
        a, dt, omega, damping, threshold, coupled, PARTICIPATION_OVER_MODAL_MASS, PARTICIPATION_OVER_MASS, COUPLING,
        track_peak, ledger)
    return {"u": u, "average_acceleration": kg, "sample_peak": kg_peak, "displacement": d, "velocity": w,
            "peak_u": peak, "episodes": episodes, "ledger_integrals": integrals if ledger else None,
            "average_peak": kernels["average_peak"](a, dt, omega, damping, PARTICIPATION_OVER_MODAL_MASS,
                                                    PARTICIPATION_OVER_MASS, u, v, kg, kg_peak)
            if average_peak else None}


def flexible_steps(coupled: bool, a: np.ndarray, dt: float, yield_thresholds, layer, ledger: bool = False) -> dict:
    """The exact decoupled or coupled analysis of ``a`` [m/s²] at a constant yield acceleration t [m/s²].

    ``yield_thresholds`` is the one pair ((0,), (t,)) of a constant t
    (the scheme's ``takes_yield_table`` is False: :func:`stickslip.models.layer.result.solve_flexible`
    gives this scheme no longer table).  The same keys as :func:`stickslip.models.layer.slammer.flexible_steps`,
    and with ``ledger`` the key ``ledger``, the final response's
    :class:`~stickslip.models.layer.energy.FlexibleLedger`; the equivalent-linear
    properties come from the exact peak |u| of the layer on its base (each
    extremum located), by SLAMMER's iteration rule.  ``peak_average_acceleration``
    is the largest |k·g| [m/s²] of the layer on its base between the samples
    as at them (:func:`average_peak`), ``sample_peak`` the one at the samples,
    where ``average_acceleration`` has k·g.
    """
    a = np.ascontiguousarray(a, dtype=float)
    vs, damping, iterations = settled_properties(
        layer, lambda vs, damping: exact_response(False, a, dt, math.inf, vs, layer.height, damping,
                                                  track_peak=True)["peak_u"])
    (threshold,) = yield_thresholds[1]
    solution = exact_response(coupled, a, dt, threshold, vs, layer.height, damping, ledger=ledger,
                              average_peak=not coupled)
    # k(t)·g is the layer's on its base, as SLAMMER's k_max: the coupled block's layer alone once more
    on_base = solution if not coupled else exact_response(False, a, dt, math.inf, vs, layer.height, damping,
                                                          average_peak=True)
    steps = {"vs": vs, "damping": damping, "iterations": iterations, "u": solution["u"],
             "average_acceleration": on_base["average_acceleration"], "sample_peak": on_base["sample_peak"],
             "displacement": solution["displacement"], "velocity": solution["velocity"],
             "peak_average_acceleration": on_base["average_peak"]}
    if ledger:
        steps["ledger"] = flexible_ledger(coupled, solution["ledger_integrals"], solution["u"], solution["velocity"],
                                          solution["displacement"], threshold,
                                          circular_frequency(vs, layer.height), damping)
    return steps
