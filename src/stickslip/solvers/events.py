"""The exact event-driven solver of a rigid block with Coulomb friction (the paper's Eq. 1), in plain Python.

Per unit mass the equation of motion is ẍ + sgn(ẋ)·μ·g = −ü_g, with the ground
acceleration ü_g linear between samples.  Inside one sample interval of length
dt, with a(τ) = a₀ + k·τ:

* **stick** (ẋ = 0): lasts while |a(τ)| ≤ μ·g.  Breakaway is the linear crossing
  of ±μ·g; the block then slides in the direction s = −sgn(a).
* **slip** in direction s = ±1: ẍ = −a(τ) − s·μ·g, so ẋ is quadratic and x cubic
  in τ.  The slip ends at the first positive root of ẋ(τ) = 0, found with the
  cancellation-free quadratic formula.  At that stop the block sticks if
  |a| ≤ μ·g there and otherwise slides back (s = −sgn(a)).

Several events may fall inside one interval; :func:`advance_interval` loops over
the sub-intervals between them.  No tolerance and no sub-stepping enter the
solution: a record resampled linearly to a finer dt gives the same answer to
round-off.

Energies per unit mass are exact polynomial integrals over every sub-interval,
each computed on its own, so that the balance E_k − E_k(0) + E_df − E_I = 0 is
a genuine check:

* E_df/m = μ·g·∫|ẋ|dt = μ·g·(sliding path) [J/kg];
* E_I/m = ∫ü·u̇_g dt with ü = ü_g in stick and ü = −s·μ·g in slip, u̇_g being the
  exact integral of the linear ground acceleration with u̇_g(0) = 0 [J/kg];
* E_k/m = ½·(u̇_g + ẋ)² [J/kg].

The functions named in :data:`KERNELS` are written for numba's nopython mode
but import nothing of numba: :mod:`stickslip.solvers.exact` compiles them (and
its sweep kernels on top of them), and :func:`solve_history` runs them as plain
Python for a record of up to :data:`PYTHON_SAMPLES` samples.  One history of a
few ten thousand samples then takes a tenth of a second or so, instead of the
second that importing numba and loading the compiled kernels costs a fresh
process such as ``stickslip solve``.  Both give the same numbers: the same
IEEE double operations in the same order.
"""

from __future__ import annotations

import math

import numpy as np

from stickslip.checks import checked_acceleration, checked_friction_limit, checked_positive
from stickslip.records.process import integrate_linear_acceleration
from stickslip.solvers.history import SolverHistory

def first_stop_time(c0, c1, c2):
    """Smallest τ > 0 with c0 + c1·τ + c2·τ² = 0, or +inf if there is none.

    The polynomial is s·ẋ(τ) (speed in the sliding direction [m/s]) with
    c0 = s·ẋ(0) ≥ 0 [m/s], c1 [m/s²], c2 [m/s³].  A root at τ = 0 (c0 = 0, the
    start of a slip) does not count.  Roots are computed as q/c2 and c0/q with
    q = −(c1 + sgn(c1)·√disc)/2, which avoids cancellation.
    """
    if c2 == 0.0:
        if c1 < 0.0:
            return -c0 / c1
        return math.inf
    disc = c1 * c1 - 4.0 * c2 * c0
    if disc < 0.0:
        return math.inf
    q = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
    if q == 0.0:
        return math.inf
    root = math.inf
    near = q / c2
    if near > 0.0:
        root = near
    far = c0 / q
    if 0.0 < far < root:
        root = far
    return root


def stick_input_energy(a, slope, vg, tau):
    """∫₀^τ a(σ)·u̇_g(σ) dσ [J/kg] for a(σ) = a + slope·σ [m/s²], u̇_g(σ) = vg + a·σ + slope·σ²/2 [m/s]."""
    return tau * (a * vg + tau * (0.5 * (a * a + slope * vg) + tau * (0.5 * a * slope + 0.125 * slope * slope * tau)))


def slip_stop_time(a, slope, mu_g, v, s):
    """Time [s] to the first stop of a slip in direction s = ±1 from velocity v [m/s], or +inf.

    a [m/s²] and slope [m/s³] give the ground acceleration a + slope·τ; mu_g = μ·g [m/s²].
    """
    return first_stop_time(s * v, -(s * a + mu_g), -0.5 * s * slope)


def slip_increments(a, slope, vg, mu_g, v, s, tau):
    """Changes over a slip of τ [s] in direction s = ±1 that starts at velocity v [m/s].

    a [m/s²], slope [m/s³] and vg [m/s] are the ground acceleration, its slope
    and the ground velocity at the slip's start; mu_g = μ·g [m/s²].  Returns
    ``(dx, d_input, v_end)``: the displacement [m], the input energy E_I/m
    [J/kg] and the velocity at τ [m/s].
    """
    drift = a + s * mu_g
    dx = tau * (v - tau * (0.5 * drift + slope * tau / 6.0))
    d_input = -(s * mu_g * tau * (vg + tau * (0.5 * a + slope * tau / 6.0)))
    v_end = v - tau * (drift + 0.5 * slope * tau)
    return dx, d_input, v_end


def advance_interval(a_start, a_end, slope, dt, vg_start, mu_g, x, v, s):
    """Advance the block across one sample interval, handling every event inside it.

    Parameters
    ----------
    a_start, a_end:
        Ground acceleration at the interval's ends [m/s²] (linear in between).
    slope:
        (a_end − a_start)/dt [m/s³], computed so by every caller (the sweep
        kernel reads it from a μ-independent array).
    dt:
        Interval length [s].
    vg_start:
        Ground velocity at the interval's start [m/s].
    mu_g:
        Friction limit μ·g [m/s²].
    x, v, s:
        Relative displacement [m], relative velocity [m/s] and phase (0 stick,
        ±1 sliding with ẋ ≷ 0) at the start.

    Returns
    -------
    tuple
        ``(x, v, s, phase_after_start, input_energy, sliding_path, slip_time,
        new_episodes, peak_abs_x)``: the state at the interval's end, the phase
        just after its start [-], the increments of E_I/m [J/kg], of ∫|ẋ|dt [m],
        of the time spent sliding [s] and of the number of slip episodes, and
        max |x| over the interval [m].
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
            # Stick: find where |a| first exceeds mu_g.  Whether it does before the interval's
            # end is decided by the sample a_end itself, not by the round-off of the crossing
            # time, so an interval ending exactly at ±mu_g never starts a zero-length slip.
            if a > mu_g:
                tau, s_next = 0.0, -1
            elif a < -mu_g:
                tau, s_next = 0.0, 1
            elif slope > 0.0 and a_end > mu_g:
                tau, s_next = (mu_g - a) / slope, -1
            elif slope < 0.0 and a_end < -mu_g:
                tau, s_next = (-mu_g - a) / slope, 1
            else:
                tau, s_next = math.inf, 0
            if tau >= remaining:
                input_energy += stick_input_energy(a, slope, vg, remaining)
                break
            input_energy += stick_input_energy(a, slope, vg, tau)
            if tau > 0.0:
                t += tau
                # Start the slip at the crossing value itself: c1 = 0 exactly, so it cannot stop at once.
                a = -s_next * mu_g
                vg = vg_start + t * (a_start + 0.5 * slope * t)
            s = s_next
            new_episodes += 1
        else:
            tau = slip_stop_time(a, slope, mu_g, v, s)
            at_end = tau >= remaining
            if at_end:
                tau = remaining
            dx, d_input, v_end = slip_increments(a, slope, vg, mu_g, v, s, tau)
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
                    # friction limit and sticks (|a| decreases here), instead of looping.
                    a = math.copysign(mu_g, a)
                else:
                    t = t_stop
                    # Kept between the interval's end values: a stop just before an end at
                    # exactly ±mu_g must not see |a| > mu_g through round-off.
                    a = min(max(a_start + slope * t, min(a_start, a_end)), max(a_start, a_end))
                    vg = vg_start + t * (a_start + 0.5 * slope * t)
            v = 0.0
            if abs(a) <= mu_g:
                s = 0
            else:
                s = -1 if a > 0.0 else 1
            if at_end:
                break
        if t == 0.0:
            phase_after_start = s
    return x, v, s, phase_after_start, input_energy, sliding_path, slip_time, new_episodes, peak_abs_x


def history_kernel(acceleration, ground_velocity, dt, mu_g):
    """Block histories at the samples, given the ground velocity there; see :func:`solve_history`.

    ``acceleration`` [m/s²] and ``ground_velocity`` [m/s] are arrays when
    compiled, Python lists of floats when run as Python (their arithmetic is
    several times faster than that of numpy scalars).
    """
    n = len(acceleration)
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
            a0, acceleration[i + 1], (acceleration[i + 1] - a0) / dt, dt, ground_velocity[i], mu_g, x, v, s
        )
        phase[i] = phase_i
        if phase_i != 0:
            relative_acceleration[i] = -a0 - phase_i * mu_g
        relative_displacement[i + 1] = x
        relative_velocity[i + 1] = v
        path += d_path
        energy_dissipated[i + 1] = mu_g * path
        energy_input[i + 1] = energy_input[i] + d_input
        slip_time += d_slip
        episodes += d_episodes
        peak = max(peak, d_peak)
    phase[n - 1] = s
    if s != 0:
        relative_acceleration[n - 1] = -acceleration[n - 1] - s * mu_g
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


#: The functions :mod:`stickslip.solvers.exact` compiles with numba (each calls the others compiled).
KERNELS = (
    "first_stop_time",
    "stick_input_energy",
    "slip_stop_time",
    "slip_increments",
    "advance_interval",
    "history_kernel",
)

#: Longest record [samples] whose history :func:`solve_history` computes as plain Python
#: (about 2-5 µs a sample, slip costing the most); a longer one goes to the compiled kernel.
PYTHON_SAMPLES = 100_000


def solve_history(acceleration: np.ndarray, dt: float, mu: float, g: float) -> SolverHistory:
    """Solve Eq. 1 exactly for one record and one friction ratio.

    Parameters
    ----------
    acceleration:
        Ground acceleration ü_g [m/s²] at the samples, linear in between.
    dt:
        Sample interval [s].
    mu:
        Friction ratio μ [-].
    g:
        Gravitational acceleration [m/s²].

    Returns
    -------
    SolverHistory
        Per-unit-mass histories at the sample times.  The phase at a sample is
        the phase just after it; energies are in J/kg.  Records of up to
        :data:`PYTHON_SAMPLES` samples are solved as plain Python, longer
        ones by the compiled kernel; the results are identical.
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    mu_g = checked_friction_limit(mu, g)
    ground_velocity, ground_displacement = integrate_linear_acceleration(acceleration, dt)
    if acceleration.size <= PYTHON_SAMPLES:
        outputs = history_kernel(acceleration.tolist(), ground_velocity.tolist(), dt, mu_g)
    else:
        from stickslip.solvers.exact import history_kernel as compiled_history_kernel

        outputs = compiled_history_kernel(acceleration, ground_velocity, dt, mu_g)
    return SolverHistory.from_kernel_outputs(
        np.arange(acceleration.size) * dt,
        acceleration.copy(),
        ground_velocity,
        ground_displacement,
        outputs,
    )
