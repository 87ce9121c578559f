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

Several events may fall inside one interval; :func:`advance_interval`, the
event engine's loop (:func:`stickslip.solvers.events.interval_state`) on the
block's phase functions :func:`band`, :func:`slide_edge`, :func:`stop_time`
and :func:`slid`, loops over the sub-intervals between them.  No tolerance and no sub-stepping enter the
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
import sys

import numpy as np

from stickslip.solvers import events as engine
from stickslip.solvers.compilation import bound_functions
from stickslip.solvers.closed_forms import first_stop_time


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


def band(parameters, x):
    """(lower, upper) [m/s²]: the block holds while lower ≤ a ≤ upper, wherever it is; ``parameters`` is that pair."""
    return parameters


def slide_edge(parameters, x, s):
    """The level [m/s²] of a slide in direction s: ``upper`` towards −x, ``lower`` towards +x (its absolute
    acceleration, and the ground acceleration at which it started)."""
    return parameters[1] if s < 0 else parameters[0]


def stop_time(parameters, a, slope, edge, v, s, remaining):
    """The time [s] to the first stop of a slide at the level ``edge`` (:func:`slip_stop_time`), or +inf."""
    return slip_stop_time(a, slope, edge, v, s)


def slid(parameters, a, slope, vg, edge, x, v, s, tau):
    """``(x, v, E_I/m, path, 0)`` after sliding for τ [s] at the level ``edge`` (:func:`slip_increments`); the
    block's largest |ü| is not asked for (0)."""
    dx, d_input, v_end = slip_increments(a, slope, vg, edge, v, s, tau)
    return x + dx, v_end, d_input, abs(dx), 0.0


#: The event engine's loop over one sample interval (:func:`stickslip.solvers.events.interval_state`) on the
#: block's phase functions, as plain Python: ``advance_interval((lower, upper), a_start, a_end, slope, dt,
#: vg_start, x, v, s)`` with the stick band's bounds b − T₊ (−inf when the block never slides towards +x) and
#: b + T₋ [m/s²] (∓μ·g on a flat surface).
advance_interval = bound_functions(engine, ("interval_state",), owner=sys.modules[__name__],
                                   bound={"band": band, "slide_edge": slide_edge, "stop_time": stop_time,
                                          "slid": slid})["interval_state"]


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
    band_bounds = (lower, upper)
    for i in range(n - 1):
        a0 = acceleration[i]
        x, v, s, phase_i, d_input, d_path, d_slip, d_episodes, d_peak, _ = advance_interval(
            band_bounds, a0, acceleration[i + 1], (acceleration[i + 1] - a0) / dt, dt, ground_velocity[i], x, v, s
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


#: The functions :mod:`stickslip.models.rigid.exact` compiles with numba (each calls the others, and the engine's
#: pieces, compiled).
KERNELS = (
    "slip_stop_time",
    "slip_increments",
    "resisting_work",
    "band",
    "slide_edge",
    "stop_time",
    "slid",
    "advance_interval",
    "history_kernel",
)

#: Longest record [samples] whose history the exact scheme computes as plain Python
#: (:func:`stickslip.models.rigid.exact_scheme.sliding_history`; about 2-5 µs a sample, slip costing the most);
#: a longer one goes to the compiled kernel.
PYTHON_SAMPLES = 100_000
