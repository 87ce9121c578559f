"""The compiled solver of a rigid block sliding in the plane under both horizontal components.

Per unit mass, with the relative velocity v ∈ ℝ² of the block on its base and
the ground acceleration a(t) ∈ ℝ² linear between samples, the block

* sticks (v = 0) while |a(t)| ≤ μ·g;
* slides with v̇ = −a(t) − μ·g·v/|v|: one friction force of magnitude μ·m·g
  opposite to the sliding velocity (the friction circle);
* breaks away when |a| rises past μ·g, along −a/|a|, and stops when |v|
  reaches zero; it then sticks if |a| ≤ μ·g and breaks away again otherwise.

Between the events the slip equation has no closed form in general: it is
integrated with the 8th-order Runge–Kutta pair of Dormand and Prince (DOP853;
the coefficients are SciPy's, :mod:`stickslip.solvers.dop853`), its step chosen for a
relative tolerance ``rtol`` on the velocity.  With the speed scale
S = 2·(max|a| + μ·g)·dt, the regimes of the speed s = |v| keep the
integration non-stiff and the events exact:

* **fast** (s ≥ ``s_switch`` = :data:`SWITCH_RATIO`·S): the time t is the
  independent variable and the steps end on the samples, where a(t) has its
  kinks; a step that would carry v past zero is refused and shortened;
* **slow** (``s_lock`` ≤ s < ``s_switch``): the direction of v relaxes to
  −a/|a| at the rate |a|/s, which makes small time steps stiff and s = 0 a
  point that time steps overshoot.  The independent variable becomes σ with
  dt = s·dσ (a Sundman transformation): dv/dσ = −s·a − μ·g·v, dt/dσ = s,
  every right-hand side polynomial in v and s, and s decays towards zero
  without reaching it; a step that would pass a sample is brought onto it by
  Newton's method;
* **settled** (s < ``s_lock`` = ``lock_ratio``·S, on the slow manifold): the
  angle φ of v from −a/|a| obeys φ̇ = −(|a|/s)·sin φ − ω_a (ω_a, the rate at
  which a turns), whose invariant manifold is, to first order in s,
  sin φ = −ω_a·s/(2|a| − μ·g).  A block breaks away on it (along −a/|a|)
  and a slow slip with |a| > 0.6·μ·g settles on it; there only s, x and the
  energies are integrated, in time, with ṡ = |a|·cos φ − μ·g, while
  |sin φ| ≤ :data:`MANIFOLD_ANGLE`; a stop (s = 0) and the return to the
  slow regime are located by Newton's method on the step, and a decelerating
  step goes no further than the stop at its present deceleration;
* **stopping** (s < s_lock off the manifold, |a| < μ·g): over the remaining
  time to the stop, of order s/(μ·g − |a|), a is held at its value, and the
  slip has a closed form in σ: with T = tan(φ/2), dφ/dσ = −|a|·sin φ gives
  T = T₀·e^{−|a|σ} and s = s₀·e^{−(μg−|a|)σ}·(1 + T²)/(1 + T₀²), whose
  integrals give the time to the stop, the path, the displacement and the
  input energy (docs/solvers.md derives them); it is taken only where its
  estimated error is below the tolerance (:func:`_quick_stop`), and straight
  stops (v against −a/|a|, as in one dimension) are exact polynomials.

The ledger per unit mass, each term integrated as a state of its own so that
the balance E_k − E_k(0) + E_df − E_I = 0 is a genuine check: E_df/m = μ·g·(path
slid), E_I/m = ∫ü·u̇_g dt with ü = a in stick and ü = −μ·g·v/|v| in slip,
E_k/m = ½·|u̇_g + v|².  The peak of |x| is located inside a step where x·v
changes sign, by a root of the step's cubic Hermite interpolant and one more
step to it.

All functions are numba kernels; :mod:`stickslip.models.planar.response` is the
Python interface.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.models.rigid.exact import first_stop_time, stick_input_energy
from stickslip.solvers.dop853 import A as _A
from stickslip.solvers.dop853 import B as _B
from stickslip.solvers.dop853 import E3 as _E3
from stickslip.solvers.dop853 import E5 as _E5
from stickslip.solvers.dop853 import next_step

#: The state of a slip: v₁, v₂ [m/s], x₁, x₂ [m], path [m], E_I/m [J/kg], τ [s] from the interval's start.
N_STATE = 7
#: Default relative tolerance of the velocity per step.
RTOL = 1e-10
#: Default ratio s_lock / s_switch below which the direction is on its slow manifold (module docstring).
LOCK_RATIO = 1e-5
#: The largest angle [rad] of the velocity from −a/|a| on the first-order slow manifold that the settled regime takes.
MANIFOLD_ANGLE = 1e-3
#: The velocity error is measured against rtol·(|v| + VELOCITY_FLOOR·S): below that speed, absolutely.
VELOCITY_FLOOR = 1e-3
#: Default ratio s_switch / (2·(max|a| + μ·g)·dt) below which the slow regime takes over.
SWITCH_RATIO = 0.01
#: The regimes of the speed (module docstring): which right-hand side :func:`_rhs` evaluates.
FAST, SLOW, SETTLED = 0, 1, 2
#: What the block does: sticks, slides, or slides slowly on the slow manifold of its direction (s < s_lock).
STICK, SLIDING, SETTLED_SLIDING = 0, 1, 2
#: Newton iterations that bring a step onto an event (the interval's end in the slow regime, a speed in the settled).
_LANDING_ITERATIONS = 12

#: Columns of the end-of-record scalars (:func:`pair_scalars`), per unit mass.
PLANAR_SCALAR_NAMES = (
    "energy_dissipated",       # J/kg
    "energy_input",            # J/kg
    "kinetic_energy_final",    # J/kg
    "residual_displacement_1",  # m
    "residual_displacement_2",  # m
    "peak_displacement",       # m, largest |x|
    "sliding_path",            # m
    "slip_fraction",           # 1
    "n_slip_episodes",         # 1
)


@numba.njit(cache=True)
def _settled_direction(ax, ay, kx, ky, speed, mug):
    """The unit direction (e₁, e₂) of a slow sliding velocity on its slow manifold (module docstring).

    ``ax, ay`` [m/s²] is the ground acceleration, ``kx, ky`` [m/s³] its rate,
    ``speed`` [m/s] the sliding speed, ``mug`` μ·g [m/s²]: e = −a/|a| turned by
    φ, sin φ = −ω_a·s/(2|a| − μ·g), the manifold to first order in s.
    Returns (e₁, e₂, cos φ).
    """
    size = math.sqrt(ax * ax + ay * ay)
    if size == 0.0:
        return 1.0, 0.0, 1.0
    turn_rate = (ax * ky - ay * kx) / (size * size)
    sin_phi = min(max(-turn_rate * speed / (2.0 * size - mug), -1.0), 1.0)
    cos_phi = math.sqrt(1.0 - sin_phi * sin_phi)
    ux = ax / size
    uy = ay / size
    return -(ux * cos_phi - uy * sin_phi), -(ux * sin_phi + uy * cos_phi), cos_phi


@numba.njit(cache=True)
def _rhs(y, regime, a0x, a0y, kx, ky, gx0, gy0, mug, out):
    """The slip's right-hand side into ``out``: d y/dt (FAST, SETTLED) or d y/dσ = s·d y/dt (SLOW).

    The ground acceleration is (a0x + kx·τ, a0y + ky·τ) [m/s²] and the ground
    velocity (gx0, gy0) + a0·τ + k·τ²/2 [m/s], τ = y[6] the time since the
    interval's start [s]; μ·g = ``mug`` [m/s²].  In the SETTLED regime y[0] is
    the speed s and y[1] is not used.
    """
    tau = y[6]
    ax = a0x + kx * tau
    ay = a0y + ky * tau
    gx = gx0 + tau * (a0x + 0.5 * kx * tau)
    gy = gy0 + tau * (a0y + 0.5 * ky * tau)
    if regime == SETTLED:
        s = y[0]
        e1, e2, cos_phi = _settled_direction(ax, ay, kx, ky, s, mug)
        out[0] = math.sqrt(ax * ax + ay * ay) * cos_phi - mug
        out[1] = 0.0
        out[2] = s * e1
        out[3] = s * e2
        out[4] = s
        out[5] = -mug * (e1 * gx + e2 * gy)
        out[6] = 1.0
        return
    vx = y[0]
    vy = y[1]
    s = math.sqrt(vx * vx + vy * vy)
    if regime == SLOW:
        out[0] = -s * ax - mug * vx
        out[1] = -s * ay - mug * vy
        out[2] = s * vx
        out[3] = s * vy
        out[4] = s * s
        out[5] = -mug * (vx * gx + vy * gy)
        out[6] = s
    else:
        f = mug / s
        out[0] = -ax - f * vx
        out[1] = -ay - f * vy
        out[2] = vx
        out[3] = vy
        out[4] = s
        out[5] = -f * (vx * gx + vy * gy)
        out[6] = 1.0


@numba.njit(cache=True)
def _step(y, f0, h, regime, a0x, a0y, kx, ky, gx0, gy0, mug, rtol, v_scale, dt, work, y_new, f_new):
    """One DOP853 step of size h from (y, f0 = rhs(y)) into y_new, f_new; returns the scaled error norm.

    The error is measured on v (on s in the SETTLED regime; scale
    rtol·(|v| + v_scale), v_scale [m/s]) and, in the SLOW regime, on τ (scale
    rtol·dt); a norm ≤ 1 accepts the step.
    """
    k = work
    for j in range(N_STATE):
        k[0, j] = f0[j]
    stage = work[13]
    for i in range(1, 12):
        for j in range(N_STATE):
            acc = 0.0
            for m in range(i):
                acc += _A[i, m] * k[m, j]
            stage[j] = y[j] + h * acc
        _rhs(stage, regime, a0x, a0y, kx, ky, gx0, gy0, mug, k[i])
    for j in range(N_STATE):
        acc = 0.0
        for m in range(12):
            acc += _B[m] * k[m, j]
        y_new[j] = y[j] + h * acc
    _rhs(y_new, regime, a0x, a0y, kx, ky, gx0, gy0, mug, f_new)
    for j in range(N_STATE):
        k[12, j] = f_new[j]
    speed = max(math.sqrt(y[0] * y[0] + y[1] * y[1]), math.sqrt(y_new[0] * y_new[0] + y_new[1] * y_new[1]))
    velocity_scale = rtol * (speed + v_scale)
    err5 = 0.0
    err3 = 0.0
    n_checked = 3 if regime == SLOW else 2
    for j in (0, 1, 6):
        if j == 6 and regime != SLOW:
            break
        e5 = 0.0
        e3 = 0.0
        for m in range(13):
            e5 += _E5[m] * k[m, j]
            e3 += _E3[m] * k[m, j]
        scale = velocity_scale if j < 2 else rtol * dt
        err5 += (e5 / scale) ** 2
        err3 += (e3 / scale) ** 2
    if err5 == 0.0 and err3 == 0.0:
        return 0.0
    return abs(h) * err5 / math.sqrt((err5 + 0.01 * err3) * n_checked)


@numba.njit(cache=True)
def _hermite(p0, d0, p1, d1, h, u):
    """The cubic Hermite interpolant on [0, h] of end values p0, p1 and slopes d0, d1, and its slope, at u."""
    r = u / h
    r2 = r * r
    r3 = r2 * r
    value = (2 * r3 - 3 * r2 + 1) * p0 + (r3 - 2 * r2 + r) * h * d0 + (-2 * r3 + 3 * r2) * p1 + (r3 - r2) * h * d1
    slope = ((6 * r2 - 6 * r) * p0 + (3 * r2 - 4 * r + 1) * h * d0 + (-6 * r2 + 6 * r) * p1
             + (3 * r2 - 2 * r) * h * d1) / h
    return value, slope


@numba.njit(cache=True)
def _interior_peak(y, f0, y_new, f_new, h, regime, a0x, a0y, kx, ky, gx0, gy0, mug, rtol, v_scale, dt,
                   work, y_try, f_try):
    """The largest |x| [m] inside a step whose x·ẋ falls from positive to negative (0 when it does not)."""
    if y[2] * f0[2] + y[3] * f0[3] <= 0.0 or y_new[2] * f_new[2] + y_new[3] * f_new[3] >= 0.0:
        return 0.0
    low = 0.0
    high = h
    for _ in range(60):
        middle = 0.5 * (low + high)
        x1, d1 = _hermite(y[2], f0[2], y_new[2], f_new[2], h, middle)
        x2, d2 = _hermite(y[3], f0[3], y_new[3], f_new[3], h, middle)
        if x1 * d1 + x2 * d2 > 0.0:
            low = middle
        else:
            high = middle
    _step(y, f0, 0.5 * (low + high), regime, a0x, a0y, kx, ky, gx0, gy0, mug, rtol, v_scale, dt, work,
          y_try, f_try)
    return math.sqrt(y_try[2] * y_try[2] + y_try[3] * y_try[3])


@numba.njit(cache=True)
def _ground_acceleration_norm2(a0x, a0y, kx, ky, tau):
    """|a(τ)|² [m²/s⁴]."""
    ax = a0x + kx * tau
    ay = a0y + ky * tau
    return ax * ax + ay * ay


@numba.njit(cache=True)
def _breakaway_time(a0x, a0y, kx, ky, tau, limit2, stalled):
    """The first τ' ≥ 0 after τ at which |a(τ + τ')|² exceeds ``limit2`` = (μ·g)², or +inf.

    |a|² is a convex quadratic in time, so once it is at most the limit it
    exceeds it only after its larger root.  ``stalled``: the block was just
    found not to slide at τ although |a|² is not below the limit (|a| = μ·g to
    round-off, not rising); then the next crossing after τ is sought.
    """
    ax = a0x + kx * tau
    ay = a0y + ky * tau
    c0 = ax * ax + ay * ay - limit2
    if stalled:
        c0 = min(c0, 0.0)
    elif c0 > 0.0:
        return 0.0
    c1 = 2.0 * (ax * kx + ay * ky)
    c2 = kx * kx + ky * ky
    if c2 == 0.0:
        return math.inf
    root_disc = math.sqrt(max(c1 * c1 - 4.0 * c2 * c0, 0.0))
    if c1 >= 0.0:
        return -2.0 * c0 / (c1 + root_disc) if c1 + root_disc > 0.0 else 0.0
    return (-c1 + root_disc) / (2.0 * c2)


@numba.njit(cache=True)
def _land(y, f, h, target, component, regime, ax0, ay0, kx, ky, gx0, gy0, mug, rtol, v_scale, dt, work, y_new, f_new,
          error):
    """Bring a step of size h that passed ``y_new[component]`` = ``target`` onto it, by safeguarded Newton on h.

    The step sizes that fall short and that pass bracket the root; a Newton
    step outside the bracket is replaced by bisection.  Returns (h, error) of
    the last step tried, which y_new, f_new hold; tolerance 1e-13 of the
    target's scale.
    """
    tolerance = 1e-13 * (abs(target) + (dt if component == 6 else v_scale))
    sign = 1.0 if y_new[component] > target else -1.0  # the side the first step passed to
    short = 0.0
    past = h
    for _ in range(_LANDING_ITERATIONS):
        miss = y_new[component] - target
        if abs(miss) <= tolerance or error > 1.0:
            break
        if sign * miss > 0.0:
            past = h
        else:
            short = h
        slope = f_new[component]
        landed = h - miss / slope if slope != 0.0 else -1.0
        h = landed if short < landed < past else 0.5 * (short + past)
        error = _step(y, f, h, regime, ax0, ay0, kx, ky, gx0, gy0, mug, rtol, v_scale, dt, work, y_new, f_new)
    return h, error


@numba.njit(cache=True)
def _quick_stop(y, ax, ay, kx, ky, gx, gy, mug, within, tolerance):
    """The time [s] to the stop of a slow slip (|v| < s_lock) off its slow manifold, where a closed form holds.

    ``(ax, ay)`` [m/s²], ``(kx, ky)`` [m/s³] and ``(gx, gy)`` [m/s] are the
    ground acceleration, its rate and the ground velocity now.  Two closed
    forms, each used only where its error is below ``tolerance`` [m] in the
    path and μ·g·``tolerance`` [J/kg] in E_I/m:

    * the direction held (a straight stop, with a(τ) linear): exact when v
      points straight against −a/|a| (one dimension); otherwise the part of a
      across v, up to |a|, is left out of the absolute acceleration over the
      stop's t_stop ≈ s/(μ·g), an error of about |u̇_g|·|a|·s/(μ·g) in E_I/m;
    * a held at its value (|a| < μ·g): the closed form in σ of the module's
      docstring, with errors of about s·t_stop·|k|·t_stop/(μ·g − |a|) in the
      path and μ·g·|a|·t_stop² in E_I/m (the ground velocity is held too).

    Returns +inf, leaving y alone, when neither holds or the stop is later than
    ``within`` [s]; otherwise advances y (x, path, E_I/m, τ) to the stop and sets v = 0.
    """
    vx = y[0]
    vy = y[1]
    s0 = math.sqrt(vx * vx + vy * vy)
    size = math.sqrt(ax * ax + ay * ay)
    wx = -ax / size if size > 0.0 else vx / s0  # −a/|a|, the direction the slip settles on
    wy = -ay / size if size > 0.0 else vy / s0
    cos_phi = (wx * vx + wy * vy) / s0
    sin_phi = (wx * vy - wy * vx) / s0
    ground_speed = math.sqrt(gx * gx + gy * gy)
    if 1.0 + cos_phi <= 1e-12 or ground_speed * size * s0 <= tolerance * mug * mug:
        e1 = vx / s0
        e2 = vy / s0
        rate = mug + ax * e1 + ay * e2
        turn = kx * e1 + ky * e2
        duration = first_stop_time(s0, -rate, -0.5 * turn)
        if duration > within:
            return math.inf
        distance = duration * (s0 - duration * (0.5 * rate + turn * duration / 6.0))
        y[2] += e1 * distance
        y[3] += e2 * distance
        y[4] += distance
        y[5] -= mug * duration * ((gx * e1 + gy * e2) + duration * (0.5 * (ax * e1 + ay * e2) + duration * turn / 6.0))
    else:
        if size >= mug:
            return math.inf
        c = mug - size
        t0 = sin_phi / (1.0 + cos_phi)
        u0 = t0 * t0
        duration = s0 / (1.0 + u0) * (1.0 / c + u0 / (c + 2.0 * size))
        if duration > within or s0 * duration * math.sqrt(kx * kx + ky * ky) * duration > tolerance * c \
                or size * duration * duration > tolerance:
            return math.inf
        distance = s0 * s0 / (1.0 + u0) ** 2 * (0.5 / c + u0 / (c + size) + 0.5 * u0 * u0 / (c + 2.0 * size))
        # ∫ s·e dσ and ∫ s²·e dσ as complex numbers in the frame of −a/|a|, then turned into the plane
        along_1 = s0 / (1.0 + u0) * (1.0 / c - u0 / (c + 2.0 * size))
        across_1 = s0 / (1.0 + u0) * 2.0 * t0 / (c + size)
        scale_2 = s0 * s0 / (1.0 + u0) ** 2
        along_2 = scale_2 * (0.5 / c - 0.5 * u0 * u0 / (c + 2.0 * size))
        across_2 = scale_2 * (2.0 * t0 / (2.0 * c + size) + 2.0 * t0 * u0 / (2.0 * c + 3.0 * size))
        y[2] += wx * along_2 - wy * across_2
        y[3] += wy * along_2 + wx * across_2
        y[4] += distance
        y[5] -= mug * ((wx * along_1 - wy * across_1) * gx + (wy * along_1 + wx * across_1) * gy)
    y[0] = 0.0
    y[1] = 0.0
    y[6] += duration
    return duration


@numba.njit(cache=True)
def _manifold_speed(ax, ay, kx, ky, mug):
    """The speed [m/s] below which the first-order slow manifold holds (0 where it does not attract).

    |sin φ| = |ω_a|·s/(2|a| − μ·g) ≤ MANIFOLD_ANGLE with |ω_a| ≤ |k|/|a|; the
    manifold is taken only where 2|a| − μ·g ≥ μ·g/5 (it attracts at the rate
    |a|/s, and its expansion in s holds while |a| is not small against μ·g).
    """
    size = math.sqrt(ax * ax + ay * ay)
    room = 2.0 * size - mug
    if room < 0.2 * mug:
        return 0.0
    rate = math.sqrt(kx * kx + ky * ky)
    return math.inf if rate == 0.0 else MANIFOLD_ANGLE * room * size / rate


@numba.njit(cache=True)
def advance_interval(ax0, ay0, kx, ky, gx0, gy0, dt, mug, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f,
                     motion, steps, work, y_new, f_new, y_try, f_try, totals):
    """Advance the block over one sample interval [0, dt] in place; returns its motion (STICK, ...) at the end.

    The ground acceleration is (ax0, ay0) + (kx, ky)·τ [m/s²] and the ground
    velocity at the interval's start (gx0, gy0) [m/s]; ``tolerance`` [m] bounds
    the path error of a closed-form stop (:func:`_quick_stop`).  ``y`` holds the state
    (v, x, path, E_I/m; its τ is set to 0 here), ``f`` is workspace;
    ``steps`` the step size of each regime, carried from interval to interval
    ([s], [s/(m/s)], [s]); ``totals`` accumulates [slip time (s), episodes, peak |x| (m)].
    """
    limit2 = mug * mug
    y[6] = 0.0
    stalled = False
    while y[6] < dt:
        start = y[6]
        ax = ax0 + kx * start
        ay = ay0 + ky * start
        if motion == STICK:
            wait = _breakaway_time(ax0, ay0, kx, ky, start, limit2, stalled)
            if stalled:
                wait = max(wait, 1e-12 * dt)
                stalled = False
            span = min(wait, dt - start)
            gx = gx0 + start * (ax0 + 0.5 * kx * start)
            gy = gy0 + start * (ay0 + 0.5 * ky * start)
            y[5] += stick_input_energy(ax, kx, gx, span) + stick_input_energy(ay, ky, gy, span)
            if wait >= dt - start:
                y[6] = dt
                break
            y[6] = start + wait
            motion = SETTLED_SLIDING
            totals[1] += 1.0
            y[0] = 0.0
            y[1] = 0.0
            continue
        speed = math.sqrt(y[0] * y[0] + y[1] * y[1])
        settled_limit = min(s_lock, _manifold_speed(ax, ay, kx, ky, mug))
        if motion == SETTLED_SLIDING and speed >= settled_limit:  # the slow manifold no longer holds
            motion = SLIDING
        if motion == SETTLED_SLIDING:
            regime = SETTLED
            y[0] = speed
            y[1] = 0.0
            _rhs(y, regime, ax0, ay0, kx, ky, gx0, gy0, mug, f)
            if speed == 0.0 and f[0] <= 0.0 and ax * kx + ay * ky <= 0.0:  # |a| = μ·g to round-off, not rising
                motion = STICK
                stalled = True
                continue
        else:
            if speed < s_lock:
                e1, e2, _ = _settled_direction(ax, ay, kx, ky, speed, mug)
                if speed < settled_limit and (e1 * y[0] + e2 * y[1]) / speed >= 1.0 - 1e-12:  # on the slow manifold
                    motion = SETTLED_SLIDING
                    continue
                gx = gx0 + start * (ax0 + 0.5 * kx * start)
                gy = gy0 + start * (ay0 + 0.5 * ky * start)
                saved_peak = math.sqrt(y[2] * y[2] + y[3] * y[3])
                duration = _quick_stop(y, ax, ay, kx, ky, gx, gy, mug, dt - start, tolerance)
                if duration < math.inf:
                    totals[0] += duration
                    totals[2] = max(totals[2], saved_peak, math.sqrt(y[2] * y[2] + y[3] * y[3]))
                    motion = SETTLED_SLIDING if _ground_acceleration_norm2(ax0, ay0, kx, ky, y[6]) > limit2 else STICK
                    continue
            regime = SLOW if speed < s_switch else FAST
            _rhs(y, regime, ax0, ay0, kx, ky, gx0, gy0, mug, f)
        if regime == SLOW:
            h = steps[SLOW]
        else:
            h = min(steps[regime], dt - start)
        if regime == SETTLED and f[0] < 0.0 and y[0] > 0.0:
            # no further than the stop at the present deceleration: a slip that slows down faster ends the
            # step below zero and is landed on the stop; one that recovers inside the step never reached it
            h = min(h, 1.0001 * y[0] / -f[0])
        error = _step(y, f, h, regime, ax0, ay0, kx, ky, gx0, gy0, mug, rtol, velocity_floor, dt, work, y_new, f_new)
        stopped = False
        if regime != SETTLED and y_new[0] * y[0] + y_new[1] * y[1] <= 0.0:  # a step past the stop: shorter
            steps[regime] = 0.25 * h
            continue
        if regime == SLOW and error <= 1.0 and y_new[6] > dt:
            h, error = _land(y, f, h, dt, 6, regime, ax0, ay0, kx, ky, gx0, gy0, mug, rtol, velocity_floor, dt, work,
                             y_new, f_new, error)
        elif regime == SETTLED and error <= 1.0 and (y_new[0] < 0.0 or y_new[0] > settled_limit):
            target = 0.0 if y_new[0] < 0.0 else settled_limit * (1.0 + 1e-9)
            h, error = _land(y, f, h, target, 0, regime, ax0, ay0, kx, ky, gx0, gy0, mug, rtol, velocity_floor, dt,
                             work,
                             y_new, f_new, error)
            stopped = target == 0.0
        if error > 1.0:
            steps[regime] = next_step(h, error)
            continue
        if regime == SLOW:
            if dt - y_new[6] <= 2e-13 * dt:
                y_new[6] = dt
        elif h >= dt - start:
            y_new[6] = dt
        if h < dt - start or regime == SLOW:
            steps[regime] = next_step(h, error)
        else:
            steps[regime] = max(steps[regime], next_step(h, error))
        totals[2] = max(totals[2], math.sqrt(y_new[2] * y_new[2] + y_new[3] * y_new[3]),
                        _interior_peak(y, f, y_new, f_new, h, regime, ax0, ay0, kx, ky, gx0, gy0, mug, rtol,
                                       velocity_floor, dt, work, y_try, f_try))
        totals[0] += y_new[6] - start
        for j in range(N_STATE):
            y[j] = y_new[j]
        if regime == SETTLED:
            speed = y[0]
            if stopped:
                y[0] = 0.0
                y[1] = 0.0
                motion = SETTLED_SLIDING if _ground_acceleration_norm2(ax0, ay0, kx, ky, y[6]) > limit2 else STICK
            else:
                e1, e2, _ = _settled_direction(ax0 + kx * y[6], ay0 + ky * y[6], kx, ky, speed, mug)
                y[0] = e1 * speed
                y[1] = e2 * speed
                if speed >= settled_limit:
                    motion = SLIDING
    return motion


@numba.njit(cache=True)
def solve_pair(ax, ay, dt, mug, rtol, lock_ratio, history, out):
    """Solve one record pair (a₁, a₂ [m/s²] at the samples, interval dt [s]) at μ·g = ``mug`` [m/s²].

    ``out`` receives the scalars of :data:`PLANAR_SCALAR_NAMES`; ``history``,
    of shape (n, 8) or (0, 8), the state just after each sample: x₁, x₂ [m],
    v₁, v₂ [m/s], sliding (1) or not (0), E_df/m, E_I/m [J/kg], path [m].
    """
    n = ax.size
    keep = history.shape[0] > 0
    limit2 = mug * mug
    peak_ground = 0.0
    for i in range(n):
        peak_ground = max(peak_ground, math.sqrt(ax[i] * ax[i] + ay[i] * ay[i]))
    speed_scale = 2.0 * (peak_ground + mug) * dt
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
    work = np.zeros((14, N_STATE))
    totals = np.zeros(3)
    motion = STICK
    steps = np.array([dt, 0.1 / (peak_ground + mug), dt])
    gx = 0.0
    gy = 0.0
    if keep:
        history[0, :] = 0.0
    for i in range(n - 1):
        kx = (ax[i + 1] - ax[i]) / dt
        ky = (ay[i + 1] - ay[i]) / dt
        if (motion == STICK and ax[i] * ax[i] + ay[i] * ay[i] <= limit2
                and ax[i + 1] * ax[i + 1] + ay[i + 1] * ay[i + 1] <= limit2):
            y[5] += stick_input_energy(ax[i], kx, gx, dt) + stick_input_energy(ay[i], ky, gy, dt)
        else:
            motion = advance_interval(ax[i], ay[i], kx, ky, gx, gy, dt, mug, s_switch, s_lock, rtol, velocity_floor,
                                      tolerance, y, f, motion, steps, work, y_new, f_new, y_try, f_try, totals)
        gx += 0.5 * dt * (ax[i] + ax[i + 1])
        gy += 0.5 * dt * (ay[i] + ay[i + 1])
        if keep:
            history[i + 1, 0] = y[2]
            history[i + 1, 1] = y[3]
            history[i + 1, 2] = y[0]
            history[i + 1, 3] = y[1]
            history[i + 1, 4] = 0.0 if motion == STICK else 1.0
            history[i + 1, 5] = mug * y[4]
            history[i + 1, 6] = y[5]
            history[i + 1, 7] = y[4]
    wx = gx + y[0]
    wy = gy + y[1]
    out[0] = mug * y[4]
    out[1] = y[5]
    out[2] = 0.5 * (wx * wx + wy * wy)
    out[3] = y[2]
    out[4] = y[3]
    out[5] = totals[2]
    out[6] = y[4]
    out[7] = totals[0] / ((n - 1) * dt)
    out[8] = totals[1]


@numba.njit(cache=True, parallel=True)
def sweep_pairs(samples_1, samples_2, offsets, dts, mugs, rtol, lock_ratio, out):
    """:func:`solve_pair` for every (pair, μ·g) in parallel; ``out`` has shape (pairs, len(mugs), 9)."""
    n_columns = mugs.size
    no_history = np.zeros((0, 8))
    for job in numba.prange((offsets.size - 1) * n_columns):
        pair = job // n_columns
        column = job - pair * n_columns
        first = offsets[pair]
        last = offsets[pair + 1]
        solve_pair(samples_1[first:last], samples_2[first:last], dts[pair], mugs[column], rtol, lock_ratio,
                   no_history, out[pair, column])
