"""The exact event-driven solver of a rigid sliding block, in plain Python.

Per unit mass, on an axis x along the sliding surface (x relative to the base),
with the ground acceleration a(t) = ü_g linear between samples and the
thresholds of :class:`~stickslip.models.rigid.resistance.Resistance` (T₊ and T₋
for sliding towards +x and −x, a constant body acceleration b), the block
sticks while ``lower`` = b − T₊ ≤ a ≤ b + T₋ = ``upper`` and slides in the
direction s = ±1 with ẍ = −(a − level_s), level₋₁ = ``upper``, level₊₁ =
``lower``: the block's absolute acceleration ü = a + ẍ is the level itself.
The flat case of the paper's Eq. 1 (ẍ + sgn(ẋ)·μ·g = −ü_g) has
``upper`` = −``lower`` = μ·g.  Inside one sample interval of length dt, with
a(τ) = a₀ + k·τ:

* **stick** (ẋ = 0): lasts while lower ≤ a(τ) ≤ upper.  Breakaway is the
  linear crossing of a level; the block then slides towards −x above
  ``upper`` and towards +x below ``lower``.
* **slip** in direction s: ẋ is quadratic and x cubic in τ.  The slip ends at
  the first positive root of ẋ(τ) = 0, found with the cancellation-free
  quadratic formula.  At that stop the block sticks if a is inside the band
  and otherwise slides back.

Several events may fall inside one interval; :func:`advance_interval` loops over
the sub-intervals between them.  No tolerance and no sub-stepping enter the
solution: a record resampled linearly to a finer dt gives the same answer to
round-off.

Energies per unit mass are exact polynomial integrals over every sub-interval,
each computed on its own, so that the balance
E_k − E_k(0) + E_df − E_I − W_b = 0 is a genuine check:

* E_df/m = Σ T_s·|Δx| over the slips (:func:`resisting_work`) [J/kg];
  μ·g·(sliding path) on a flat surface;
* E_I/m = ∫ü·u̇_g dt with ü = a in stick and ü = level_s in slip, u̇_g being
  the exact integral of the linear ground acceleration with u̇_g(0) = 0 [J/kg];
* E_k/m = ½·(u̇_g + ẋ)² [J/kg];
* W_b/m = b·x, the work of the body force over the relative displacement
  [J/kg] (zero on a flat surface; :class:`stickslip.models.rigid.response.Response` adds it).

The functions named in :data:`KERNELS` are written for numba's nopython mode
but import nothing of numba: :mod:`stickslip.models.rigid.exact` compiles them (and
its sweep kernels on top of them), and :func:`stickslip.models.rigid.exact_scheme.sliding_history` runs them as
plain Python for a record of up to :data:`PYTHON_SAMPLES` samples.  One history
of a few ten thousand samples then takes a tenth of a second or so, instead of
the second that importing numba and loading the compiled kernels costs a fresh
process such as ``stickslip solve``.  Both give the same numbers: the same
IEEE double operations in the same order.  With T₊ = T₋ and b = 0 every
operation is the one the flat-only solver did (a − 0.0 and 0.0 + T are exact),
so flat results are unchanged bit for bit.
"""

from __future__ import annotations

import math

import numpy as np

from stickslip.solvers.closed_forms import first_stop_time, stick_input_energy


def slip_stop_time(a, slope, level, v, s):
    """Time [s] to the first stop of a slip in direction s = ±1 from velocity v [m/s], or +inf.

    a [m/s²] and slope [m/s³] give the ground acceleration a + slope·τ; the
    block's acceleration is ẍ = −(a + slope·τ − level), ``level`` [m/s²] being
    ``upper`` for s = −1 and ``lower`` for s = +1 (−s·μ·g on a flat surface).
    """
    return first_stop_time(s * v, -(s * (a - level)), -0.5 * s * slope)


def slip_increments(a, slope, vg, level, v, s, tau):
    """Changes over a slip of τ [s] in direction s = ±1 that starts at velocity v [m/s].

    a [m/s²], slope [m/s³] and vg [m/s] are the ground acceleration, its slope
    and the ground velocity at the slip's start; ``level`` [m/s²] is the
    block's absolute acceleration while it slides (see :func:`slip_stop_time`).
    Returns ``(dx, d_input, v_end)``: the displacement [m], the input energy
    E_I/m [J/kg] and the velocity at τ [m/s].
    """
    drift = a - level
    dx = tau * (v - tau * (0.5 * drift + slope * tau / 6.0))
    d_input = level * tau * (vg + tau * (0.5 * a + slope * tau / 6.0))
    v_end = v - tau * (drift + 0.5 * slope * tau)
    return dx, d_input, v_end


def resisting_work(path, x, t_pos, t_neg):
    """E_df/m = T₊·(path slid towards +x) + T₋·(path slid towards −x) [J/kg].

    ``path`` [m] is the whole sliding path ∫|ẋ|dt and ``x`` [m] the relative
    displacement reached from x = 0; t_pos, t_neg [m/s²] are T₊ and T₋.  With
    equal thresholds (flat, two-way) it is T₋·path; when the block cannot
    slide towards +x (T₊ = inf, one-way) all of the path is towards −x.
    Otherwise the path towards +x is (path + x)/2, exact up to round-off.
    """
    if t_pos == t_neg or t_pos == math.inf:
        return t_neg * path
    positive_path = min(max(0.5 * (path + x), 0.0), path)
    return t_neg * (path - positive_path) + t_pos * positive_path


def advance_interval(a_start, a_end, slope, dt, vg_start, lower, upper, x, v, s):
    """Advance the block across one sample interval, handling every event inside it.

    Parameters
    ----------
    a_start, a_end:
        Ground acceleration at the interval's ends [m/s²] (linear in between).
    slope:
        (a_end − a_start)/dt [m/s³], computed so by every caller (the sweep
        kernel reads it from a threshold-independent array).
    dt:
        Interval length [s].
    vg_start:
        Ground velocity at the interval's start [m/s].
    lower, upper:
        The ground accelerations that bound the stick band [m/s²]: b − T₊
        (−inf when the block never slides towards +x) and b + T₋; ∓μ·g on a
        flat surface.
    x, v, s:
        Relative displacement [m], relative velocity [m/s] and phase (0 stick,
        ±1 sliding with ẋ ≷ 0) at the start.

    Returns
    -------
    tuple
        ``(x, v, s, phase_after_start, input_energy, sliding_path, slip_time,
        new_episodes, peak_abs_x)``: the state at the interval's end, the phase
        just after its start [-], the increments of E_I/m [J/kg], of ∫|ẋ|dt
        [m], of the time spent sliding [s] and of the number of slip episodes,
        and max |x| over the interval [m].
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
    while True:
        remaining = dt - t
        if s == 0:
            # Stick: find where a first leaves [lower, upper].  Whether it does before the interval's
            # end is decided by the sample a_end itself, not by the round-off of the crossing
            # time, so an interval ending exactly at a level never starts a zero-length slip.
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
            if tau >= remaining:
                input_energy += stick_input_energy(a, slope, vg, remaining)
                break
            input_energy += stick_input_energy(a, slope, vg, tau)
            if tau > 0.0:
                t += tau
                # Start the slip at the crossing value itself: a − level = 0 exactly, so it cannot stop at once.
                a = upper if s_next < 0 else lower
                vg = vg_start + t * (a_start + 0.5 * slope * t)
            s = s_next
            new_episodes += 1
        else:
            level = upper if s < 0 else lower
            tau = slip_stop_time(a, slope, level, v, s)
            at_end = tau >= remaining
            if at_end:
                tau = remaining
            dx, d_input, v_end = slip_increments(a, slope, vg, level, v, s, tau)
            input_energy += d_input
            sliding_path += abs(dx)  # x is monotone within a slip
            slip_time += tau
            x += dx
            peak_abs_x = max(peak_abs_x, abs(x))
            if at_end:
                if s * v_end > 0.0:
                    v = v_end
                    break
                a = a_end
            else:
                t_stop = t + tau
                if t_stop == t and v == 0.0:
                    # A reversal shorter than the time resolution: the block stays at the
                    # level it slid past and sticks (a moves back into the band here), instead of looping.
                    a = level
                else:
                    t = t_stop
                    # Kept between the interval's end values: a stop just before an end exactly
                    # at a level must not see a beyond it through round-off.
                    a = min(max(a_start + slope * t, min(a_start, a_end)), max(a_start, a_end))
                    vg = vg_start + t * (a_start + 0.5 * slope * t)
            v = 0.0
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
    return x, v, s, phase_after_start, input_energy, sliding_path, slip_time, new_episodes, peak_abs_x


def history_kernel(acceleration, ground_velocity, dt, t_pos, t_neg=None, body=0.0):
    """Block histories at the samples, given the ground velocity there; see :func:`stickslip.models.rigid.exact_scheme.sliding_history`.

    ``acceleration`` [m/s²] and ``ground_velocity`` [m/s] are arrays when
    compiled, Python lists of floats when run as Python (their arithmetic is
    several times faster than that of numpy scalars); t_pos, t_neg and body
    are T₊, T₋ and b [m/s²] (:meth:`Resistance.thresholds`); by default T₋ =
    T₊ and b = 0, a flat surface whose friction limit μ·g is ``t_pos``.
    """
    if t_neg is None:
        t_neg = t_pos
    n = len(acceleration)
    lower = body - t_pos
    upper = body + t_neg
    relative_displacement = np.zeros(n)
    relative_velocity = np.zeros(n)
    relative_acceleration = np.zeros(n)
    phase = np.zeros(n, dtype=np.int8)
    energy_dissipated = np.zeros(n)
    energy_input = np.zeros(n)
    x, v, s = 0.0, 0.0, 0
    path = 0.0
    slip_time = 0.0
    episodes = 0
    peak = 0.0
    for i in range(n - 1):
        a0 = acceleration[i]
        x, v, s, phase_i, d_input, d_path, d_slip, d_episodes, d_peak = advance_interval(
            a0, acceleration[i + 1], (acceleration[i + 1] - a0) / dt, dt, ground_velocity[i], lower, upper, x, v, s
        )
        phase[i] = phase_i
        if phase_i != 0:
            relative_acceleration[i] = -(a0 - (upper if phase_i < 0 else lower))
        relative_displacement[i + 1] = x
        relative_velocity[i + 1] = v
        path += d_path
        energy_dissipated[i + 1] = resisting_work(path, x, t_pos, t_neg)
        energy_input[i + 1] = energy_input[i] + d_input
        slip_time += d_slip
        episodes += d_episodes
        peak = max(peak, d_peak)
    phase[n - 1] = s
    if s != 0:
        relative_acceleration[n - 1] = -(acceleration[n - 1] - (upper if s < 0 else lower))
    return (
        relative_displacement,
        relative_velocity,
        relative_acceleration,
        phase,
        energy_dissipated,
        energy_input,
        path,
        slip_time,
        episodes,
        peak,
    )


#: The functions :mod:`stickslip.models.rigid.exact` compiles with numba (each calls the others compiled).
KERNELS = (
    "first_stop_time",
    "stick_input_energy",
    "slip_stop_time",
    "slip_increments",
    "resisting_work",
    "advance_interval",
    "history_kernel",
)

#: Longest record [samples] whose history the exact scheme computes as plain Python
#: (:func:`stickslip.models.rigid.exact_scheme.sliding_history`; about 2-5 µs a sample, slip costing the most);
#: a longer one goes to the compiled kernel.
PYTHON_SAMPLES = 100_000
