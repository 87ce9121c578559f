"""The compiled solver of a block sliding in the plane: flat or on a spherical dish, with or without the vertical.

Per unit mass and relative to the ground, with u, v ∈ ℝ² the block's
displacement and velocity, a(t) ∈ ℝ² the horizontal ground acceleration and
a_v(t) the vertical one (positive up), both linear between samples, the normal
force per unit mass is n(t) = g + a_v(t) and the block, on a surface of
curvature κ = 1/R (κ = 0: flat; small-angle geometry),

* sticks (v = 0) while the force needed to hold it, |b| with
  b = a + κ·n·u, stays within μ(0)·n;
* slides with v̇ = −b − μ(|v|)·n·v/|v|: the restoring force −κ·n·u and one
  friction force opposite to the sliding velocity (the friction circle), of
  coefficient μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} (Coulomb:
  μ_fast = μ_slow);
* breaks away when |b| rises past μ(0)·n, along −b/|b|, and stops when |v|
  reaches zero; it then sticks if |b| ≤ μ(0)·n and breaks away again otherwise;
* flies where n ≤ 0 (it lifts off the surface: no friction, no restoring
  force, v̇ = −a) and lands where n rises past 0, with its velocity.

Between the events the slip equation has no closed form in general: it is
integrated with the 8th-order Runge–Kutta pair of Dormand and Prince (DOP853;
the coefficients are SciPy's, :mod:`stickslip.solvers.dop853`), its step chosen for a
relative tolerance ``rtol`` on the velocity.  With the speed scale
S = 2·(max|a| + μ·max n)·dt, the regimes of the speed s = |v| keep the
integration non-stiff and the events exact:

* **fast** (s ≥ ``s_switch`` = :data:`SWITCH_RATIO`·S): the time t is the
  independent variable and the steps end on the samples, where a(t) has its
  kinks; a step that would carry v past zero is refused and shortened;
* **settled** (on the slow manifold of the direction): the angle φ of v from
  −b/|b| relaxes at the rate |b|/s, so at small speed it lies on its slow
  manifold Φ(s, t), a series in s whose coefficients
  :func:`stickslip.models.planar.manifold.manifold_series` computes in
  closed form (to third order on a flat surface, second on a curved one).  A
  block breaks away on it and a slow slip joins it once its direction is on it
  to the tolerance; there only s, u and the energies are integrated, in time,
  while the series' error estimate is within the tolerance (:func:`_settled_plan`);
  a stop (s = 0) and the speed where the series ends are located by Newton's
  method on the step (where the whole series ends the slip leaves the
  manifold there and then, rather than follow its limit, which moves with b),
  and a decelerating step goes no further than the stop at its present
  deceleration.  The manifold depends on the rate of a, which
  jumps at the samples: there the velocity goes on from the manifold of the
  interval that ends;
* **slow** (below ``s_switch``, off the manifold): the independent variable
  becomes σ with dt = s·dσ (a Sundman transformation): dv/dσ = −s·b − μ·n·v,
  every right-hand side polynomial in v and s, and s decays towards zero
  without reaching it; a step that would pass a sample is brought onto it by
  Newton's method;
* **stopping** (s < ``s_lock`` = ``lock_ratio``·S off the manifold,
  |b| < μ(0)·n): over the remaining time to the stop, of order
  s/(μ·n − |b|), b and n are held at their values and the slip has a closed
  form in σ (docs/solvers.md derives it); it is taken only where its estimated
  error is below the tolerance (:func:`_quick_stop`), and straight stops (v
  against −b/|b|, as in one dimension) are polynomials in time.

The ledger per unit mass, each term integrated as a state of its own so that
the balance E_k − E_k(0) + E_p − E_p(0) + E_df − E_I − W_v = 0 is a genuine
check: E_df/m = ∫μ·n·s dt (friction), W_v/m = −∫κ·(n − g)·u·v dt (the work of
the vertical motion through the normal force on the curved surface: zero where
n = g, and ½·g·κ·(|u|² − |u₀|²) over a flight, where n is 0), E_I/m = ∫ü·u̇_g dt
with ü = a in stick, −κ·n·u − μ·n·v/|v| in slip and 0 in flight,
E_k/m = ½·|u̇_g + v|², and the potential energy E_p/m = ½·g·κ·|u|², a state
(the restoring force's work ∫κ·n·u·v dt is E_p − E_p(0) − W_v).  The peak of |u| is located inside a step
where u·v changes sign, by a root of the step's cubic Hermite interpolant and
one more step to it.

A stick costs almost nothing: μ-independent prefix sums of the stick's input
energy and, per block of :data:`BLOCK` samples, the bounds of a and n prove
whole blocks stuck (:func:`_prepare_record`), as the 1-D kernel does.

All functions are numba kernels over plain arrays; :func:`solve_pair` and
:func:`sweep_pairs` (flat surface, Coulomb friction, no vertical motion) and
:func:`solve_pair_on_surface` and :func:`sweep_pairs_on_surface` (every case)
are the entry points (where the block flies:
:func:`stickslip.models.pendulum.normal_force.liftoff_intervals`), and
:mod:`stickslip.models.planar.response` and :mod:`stickslip.models.pendulum.pair`
are the Python interfaces.  The kernels that
allocate nothing are compiled without numba's reference counting of arrays
(``_nrt=False``): counting the arrays passed between them cost a third of the
time.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from stickslip.models.planar.manifold import (
    CURVED_ORDER,
    DENOMINATOR_MARGIN,
    FLAT_ORDER,
    friction_series,
    manifold_series,
    series_angle,
)
from stickslip.solvers.compilation import engine_pieces
from stickslip.solvers.dop853 import A as _A
from stickslip.solvers.dop853 import B as _B
from stickslip.solvers.dop853 import E3 as _E3
from stickslip.solvers.dop853 import E5 as _E5
from stickslip.solvers.dop853 import next_step

_PIECES = engine_pieces()
first_stop_time = _PIECES["first_stop_time"]
stick_input_energy = _PIECES["stick_input_energy"]

#: The state of a slip (indices): v₁, v₂ [m/s], τ [s] from the interval's start, u₁, u₂ [m], path [m],
#: E_I/m, E_df/m, W_v/m [J/kg].
V1, V2, TAU, U1, U2, PATH, INPUT, DISSIPATED, VERTICAL = range(9)
N_STATE = 9
#: The states that enter the right-hand side (v, τ, u), formed at every stage; the others are quadratures.
N_DYNAMIC = 5
#: The friction law and the surface (indices into the ``law`` array): μ(0), μ_fast, rate [s/m], κ = 1/R [1/m],
#: the order of the slow manifold's series; LAW_SERIES onwards, the Taylor coefficients of μ(s).
MU_SLOW, MU_FAST, RATE, CURVATURE, ORDER = range(5)
LAW_SERIES = 5
LAW_SIZE = LAW_SERIES + FLAT_ORDER + 1
#: One sample interval (indices into the ``segment`` array): a [m/s²] and its slope [m/s³] at the interval's start,
#: the normal force per unit mass n = g + a_v [m/s²] and its slope [m/s³], the ground velocity [m/s], g [m/s²].
A1, A2, K1, K2, NORMAL, NORMAL_RATE, G1, G2, GRAVITY = range(9)
SEGMENT_SIZE = 9
#: Default relative tolerance of the velocity per step.
RTOL = 1e-10
#: Default ratio s_lock / S below which the closed-form stops are tried (module docstring).
LOCK_RATIO = 1e-5
#: The velocity error is measured against rtol·(|v| + VELOCITY_FLOOR·S): below that speed, absolutely.
VELOCITY_FLOOR = 1e-3
#: Default ratio s_switch / (2·(max|a| + μ·g)·dt) below which the slow regime takes over.
SWITCH_RATIO = 0.01
#: The slow manifold's series holds while its error estimate, times s, stays within this share of rtol·(s + the floor).
SERIES_TOLERANCE = 1.0
#: A slip joins the slow manifold below this fraction of the series' last speed (it leaves at the speed itself).
SERIES_ENTRY = 0.9
#: The regimes of the speed (module docstring): which right-hand side :func:`_rhs` evaluates.
FAST, SLOW, SETTLED = 0, 1, 2
#: What the block does: sticks, slides, slides on the slow manifold of its direction, or flies (n ≤ 0); STALLED:
#: the solver gave up in a sample interval (:data:`MAX_PASSES`).
STICK, SLIDING, SETTLED_SLIDING, FLIGHT, STALLED = 0, 1, 2, 3, 4
#: The passes of the event loop (steps tried, stops and starts) one sample interval may take before the solver gives up
#: rather than run on without end; fifteen three-component stations take at most 2,235 (docs/solvers.md).
MAX_PASSES = 100_000
#: Rows of a step's work array: the 13 stage derivatives, the stage state, and (column 0) the lowest speed of a step
#: on the slow manifold over its stages [m/s].
STAGE, LOWEST = 13, 14
WORK_ROWS = 15
#: Newton iterations that bring a step onto an event (the interval's end in the slow regime, a speed in the settled).
_LANDING_ITERATIONS = 12
#: Samples per block whose bounds on a and n let a stick skip ahead.
BLOCK = 32
#: Columns of a record's block bounds: max |a|² [m²/s⁴], min and max of a₁ and a₂ [m/s²], min and max of n [m/s²].
_AMAX2, _A1MIN, _A1MAX, _A2MIN, _A2MAX, _NMIN, _NMAX = range(7)

#: Columns of the end-of-record scalars (:func:`solve_pair`, :func:`sweep_pairs`), per unit mass.
PLANAR_SCALAR_NAMES = (
    "energy_dissipated",       # J/kg
    "energy_input",            # J/kg
    "kinetic_energy_final",    # J/kg
    "residual_displacement_1",  # m
    "residual_displacement_2",  # m
    "peak_displacement",       # m, largest |u|
    "sliding_path",            # m
    "slip_fraction",           # 1
    "n_slip_episodes",         # 1
)
#: Columns of the end-of-record scalars on a curved surface or with the vertical (:func:`solve_pair_on_surface`).
SURFACE_SCALAR_NAMES = PLANAR_SCALAR_NAMES + (
    "energy_input_vertical",   # J/kg, W_v/m = −∫κ·(n − g)·u·v dt
    "flight_time",             # s, time with n ≤ 0
    "peak_absolute_acceleration",  # m/s², largest |ü| (the base shear per unit mass), at samples, step ends, events
)
#: Columns of a history (one row per sample, the state just after it); :func:`solve_pair` keeps the first eight.
HISTORY_NAMES = (
    "displacement_1", "displacement_2",  # m
    "velocity_1", "velocity_2",          # m/s
    "moving",                            # 1 when sliding or flying, 0 when stuck
    "energy_dissipated",                 # J/kg
    "energy_input",                      # J/kg
    "sliding_path",                      # m
    "energy_input_vertical",             # J/kg
    "flying",                            # 1 when n ≤ 0 (lifted off)
)


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def friction_coefficient(speed, mu_slow, mu_fast, rate):
    """μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} [1] at the sliding speed ``speed`` [m/s], ``rate`` [s/m].

    Constantinou, Mokha and Reinhorn (1990), OpenSees' ``VelDependent``;
    Coulomb friction where μ_fast = μ_slow.
    """
    if mu_fast == mu_slow:
        return mu_slow
    return mu_fast - (mu_fast - mu_slow) * math.exp(-rate * speed)


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def _driving(segment, law, tau, u1, u2):
    """The driving acceleration b = a + κ·n·u [m/s²] at τ [s] and u [m], its rate at that u [m/s³], and n [m/s²].

    Returns (b₁, b₂, ḃ₁, ḃ₂, n): the force needed to hold the block is −b per
    unit mass, and b is linear in time while u is held.
    """
    curvature = law[CURVATURE]
    normal = segment[NORMAL] + segment[NORMAL_RATE] * tau
    return (segment[A1] + segment[K1] * tau + curvature * normal * u1,
            segment[A2] + segment[K2] * tau + curvature * normal * u2,
            segment[K1] + curvature * segment[NORMAL_RATE] * u1,
            segment[K2] + curvature * segment[NORMAL_RATE] * u2, normal)


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def _sliding_acceleration(segment, law, tau, u1, u2, e1, e2, speed):
    """|ü| [m/s²] of a block sliding at u [m] along the unit vector e at the speed ``speed`` [m/s], at τ [s].

    The absolute acceleration of a sliding block is the restoring and the
    friction force per unit mass, ü = −κ·n·u − μ(s)·n·e: the base shear over
    the mass.
    """
    normal = segment[NORMAL] + segment[NORMAL_RATE] * tau
    stiffness = law[CURVATURE] * normal
    friction = friction_coefficient(speed, law[MU_SLOW], law[MU_FAST], law[RATE]) * normal
    x = stiffness * u1 + friction * e1
    z = stiffness * u2 + friction * e2
    return math.sqrt(x * x + z * z)


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def _ground_acceleration(segment, tau):
    """|a(τ)| [m/s²], the absolute acceleration of a block stuck to the ground at τ [s] of the interval."""
    x = segment[A1] + segment[K1] * tau
    z = segment[A2] + segment[K2] * tau
    return math.sqrt(x * x + z * z)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _step_end_acceleration(y_new, f_new, regime, segment, law):
    """|ü| [m/s²] at the end of an accepted step (:func:`_sliding_acceleration`), the direction from the state.

    On the slow manifold y[V1] is the speed and u̇ = s·e (``f_new``); at s = 0
    there the block points along −b/|b|.
    """
    if regime == SETTLED:
        speed = y_new[V1]
        if speed > 0.0:
            return _sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], f_new[U1] / speed,
                                         f_new[U2] / speed, speed)
        bx, by, _, _, _ = _driving(segment, law, y_new[TAU], y_new[U1], y_new[U2])
        size = math.sqrt(bx * bx + by * by)
        if size == 0.0:
            return _sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], 0.0, 0.0, 0.0)
        return _sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], -bx / size, -by / size, 0.0)
    speed = math.sqrt(y_new[V1] * y_new[V1] + y_new[V2] * y_new[V2])
    if speed == 0.0:
        return _sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], 0.0, 0.0, 0.0)
    return _sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], y_new[V1] / speed,
                                 y_new[V2] / speed, speed)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _manifold_angle(bx, by, rate_x, rate_y, normal, normal_rate, law, phi, speed):
    """The angle Φ [rad] of the sliding velocity from −b/|b| on the slow manifold at the speed ``speed`` [m/s].

    The series (:func:`~stickslip.models.planar.manifold.manifold_series`) is taken to the order ``phi[0]``
    that :func:`_settled_plan` chose for the step.
    """
    order = manifold_series(bx, by, rate_x, rate_y, normal, normal_rate, law[LAW_SERIES:], int(phi[0]), phi)
    return series_angle(phi, order, speed)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _rhs_settled(y, segment, law, phi, out, row):
    """The right-hand side d y/dt of a slip on the slow manifold (:func:`_rhs`, regime SETTLED) into ``out[row]``.

    y[V1] is the speed.
    """
    tau = y[TAU]
    gx = segment[G1] + tau * (segment[A1] + 0.5 * segment[K1] * tau)
    gy = segment[G2] + tau * (segment[A2] + 0.5 * segment[K2] * tau)
    bx, by, rate_x, rate_y, normal = _driving(segment, law, y[TAU], y[U1], y[U2])
    stiffness = law[CURVATURE] * normal
    rx = stiffness * y[U1]  # the restoring force per unit mass is −(rx, ry)
    ry = stiffness * y[U2]
    s = y[V1]
    size = math.sqrt(bx * bx + by * by)
    angle = _manifold_angle(bx, by, rate_x, rate_y, normal, segment[NORMAL_RATE], law, phi, s)
    cos_phi = math.cos(angle)
    sin_phi = math.sin(angle)
    ux = bx / size
    uy = by / size
    e1 = -(ux * cos_phi - uy * sin_phi)
    e2 = -(ux * sin_phi + uy * cos_phi)
    m = friction_coefficient(s, law[MU_SLOW], law[MU_FAST], law[RATE]) * normal
    out[row, V1] = size * cos_phi - m
    out[row, V2] = 0.0
    out[row, TAU] = 1.0
    out[row, U1] = s * e1
    out[row, U2] = s * e2
    out[row, PATH] = s
    out[row, DISSIPATED] = m * s
    out[row, VERTICAL] = -law[CURVATURE] * (normal - segment[GRAVITY]) * s * (y[U1] * e1 + y[U2] * e2)
    out[row, INPUT] = -((rx + m * e1) * gx + (ry + m * e2) * gy)


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def _rhs_sliding(y, slow, a1, a2, k1, k2, n0, nu, g1, g2, gravity, curvature, mu_slow, mu_fast, rate, out, row):
    """The right-hand side d y/dt (``slow`` false) or d y/dσ = s·d y/dt (``slow`` true) of a slip off the manifold.

    The interval's data as scalars (:data:`A1` ... of the segment, κ and the
    friction law), so that the compiler keeps them in registers; the result
    goes into ``out[row]`` (no view of ``out`` is made: views cost reference
    counting).
    """
    tau = y[TAU]
    normal = n0 + nu * tau
    gx = g1 + tau * (a1 + 0.5 * k1 * tau)
    gy = g2 + tau * (a2 + 0.5 * k2 * tau)
    stiffness = curvature * normal
    rx = stiffness * y[U1]  # the restoring force per unit mass is −(rx, ry)
    ry = stiffness * y[U2]
    bx = a1 + k1 * tau + rx
    by = a2 + k2 * tau + ry
    vx = y[V1]
    vy = y[V2]
    s = math.sqrt(vx * vx + vy * vy)
    m = friction_coefficient(s, mu_slow, mu_fast, rate) * normal
    excess = -curvature * (normal - gravity)  # W_v's rate is excess·u·v
    if slow:
        out[row, V1] = -s * bx - m * vx
        out[row, V2] = -s * by - m * vy
        out[row, TAU] = s
        out[row, U1] = s * vx
        out[row, U2] = s * vy
        out[row, PATH] = s * s
        out[row, DISSIPATED] = m * s * s
        out[row, VERTICAL] = s * excess * (y[U1] * vx + y[U2] * vy)
        out[row, INPUT] = -(s * (rx * gx + ry * gy) + m * (vx * gx + vy * gy))
    else:
        f = m / s
        out[row, V1] = -bx - f * vx
        out[row, V2] = -by - f * vy
        out[row, TAU] = 1.0
        out[row, U1] = vx
        out[row, U2] = vy
        out[row, PATH] = s
        out[row, DISSIPATED] = m * s
        out[row, VERTICAL] = excess * (y[U1] * vx + y[U2] * vy)
        out[row, INPUT] = -((rx + f * vx) * gx + (ry + f * vy) * gy)


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def _rhs(y, regime, segment, law, phi, out):
    """The slip's right-hand side into ``out``: d y/dt (FAST, SETTLED) or d y/dσ = s·d y/dt (SLOW).

    The ground acceleration is a₀ + k·τ [m/s²], the normal force per unit mass
    n₀ + ν·τ [m/s²] and the ground velocity g₀ + a₀·τ + k·τ²/2 [m/s]
    (``segment``), τ = y[TAU] the time since the interval's start [s].  In the
    SETTLED regime y[V1] is the speed s, y[V2] is not used, and the direction
    is the slow manifold's (:func:`_rhs_settled`).
    """
    if regime == SETTLED:
        _rhs_settled(y, segment, law, phi, out.reshape((1, N_STATE)), 0)
    else:
        _rhs_sliding(y, regime == SLOW, segment[A1], segment[A2], segment[K1], segment[K2], segment[NORMAL],
                     segment[NORMAL_RATE], segment[G1], segment[G2], segment[GRAVITY], law[CURVATURE], law[MU_SLOW],
                     law[MU_FAST], law[RATE], out.reshape((1, N_STATE)), 0)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _step(y, f0, h, regime, segment, law, phi, rtol, v_scale, dt, work, y_new, f_new):
    """One DOP853 step of size h from (y, f0 = rhs(y)) into y_new, f_new; returns the scaled error norm.

    Only the states that enter the right-hand side (v, τ, u) are formed at the
    inner stages, side by side; the others are quadratures.  The
    error is measured on v (on s in the SETTLED regime; scale
    rtol·(|v| + v_scale), v_scale [m/s]) and, in the SLOW regime, on τ (scale
    rtol·dt); a norm ≤ 1 accepts the step.
    """
    k = work
    for j in range(N_STATE):
        k[0, j] = f0[j]
    stage = work[STAGE]
    for j in range(N_DYNAMIC, N_STATE):
        stage[j] = y[j]
    a1, a2, k1, k2 = segment[A1], segment[A2], segment[K1], segment[K2]
    n0, nu, g1, g2, gravity = segment[NORMAL], segment[NORMAL_RATE], segment[G1], segment[G2], segment[GRAVITY]
    curvature, mu_slow, mu_fast, rate = law[CURVATURE], law[MU_SLOW], law[MU_FAST], law[RATE]
    slow = regime == SLOW
    lowest = y[V1]
    for i in range(1, 12):
        # the five dynamic states side by side: independent sums the processor overlaps
        sum_0 = 0.0
        sum_1 = 0.0
        sum_2 = 0.0
        sum_3 = 0.0
        sum_4 = 0.0
        for m in range(i):
            weight = _A[i, m]
            sum_0 += weight * k[m, 0]
            sum_1 += weight * k[m, 1]
            sum_2 += weight * k[m, 2]
            sum_3 += weight * k[m, 3]
            sum_4 += weight * k[m, 4]
        stage[0] = y[0] + h * sum_0
        lowest = min(lowest, stage[0])
        stage[1] = y[1] + h * sum_1
        stage[2] = y[2] + h * sum_2
        stage[3] = y[3] + h * sum_3
        stage[4] = y[4] + h * sum_4
        if regime == SETTLED:
            _rhs_settled(stage, segment, law, phi, k, i)
        else:
            _rhs_sliding(stage, slow, a1, a2, k1, k2, n0, nu, g1, g2, gravity, curvature, mu_slow, mu_fast, rate, k,
                         i)
    for j in range(N_STATE):
        y_new[j] = 0.0
    for m in range(12):
        weight = _B[m]
        for j in range(N_STATE):
            y_new[j] += weight * k[m, j]
    for j in range(N_STATE):
        y_new[j] = y[j] + h * y_new[j]
    work[LOWEST, 0] = min(lowest, y_new[V1])  # on the slow manifold, the speed at the stages
    if regime == SETTLED:
        _rhs_settled(y_new, segment, law, phi, k, 12)
    else:
        _rhs_sliding(y_new, slow, a1, a2, k1, k2, n0, nu, g1, g2, gravity, curvature, mu_slow, mu_fast, rate, k, 12)
    for j in range(N_STATE):
        f_new[j] = k[12, j]
    speed = max(math.sqrt(y[V1] * y[V1] + y[V2] * y[V2]), math.sqrt(y_new[V1] * y_new[V1] + y_new[V2] * y_new[V2]))
    velocity_scale = rtol * (speed + v_scale)
    e5x = 0.0
    e5y = 0.0
    e3x = 0.0
    e3y = 0.0
    e5t = 0.0
    e3t = 0.0
    for m in range(13):
        e5x += _E5[m] * k[m, V1]
        e5y += _E5[m] * k[m, V2]
        e3x += _E3[m] * k[m, V1]
        e3y += _E3[m] * k[m, V2]
        e5t += _E5[m] * k[m, TAU]
        e3t += _E3[m] * k[m, TAU]
    err5 = (e5x * e5x + e5y * e5y) / (velocity_scale * velocity_scale)
    err3 = (e3x * e3x + e3y * e3y) / (velocity_scale * velocity_scale)
    n_checked = 2
    if regime == SLOW:  # and τ
        err5 += (e5t / (rtol * dt)) ** 2
        err3 += (e3t / (rtol * dt)) ** 2
        n_checked = 3
    if err5 == 0.0 and err3 == 0.0:
        return 0.0
    norm = abs(h) * err5 / math.sqrt((err5 + 0.01 * err3) * n_checked)
    # a step far beyond the method's stability overflows, and its estimate with it (inf, or NaN from inf/inf, which
    # no comparison with 1 refuses): such a step is refused as infinitely wrong
    return norm if norm < math.inf else math.inf


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _hermite(p0, d0, p1, d1, h, u):
    """The cubic Hermite interpolant on [0, h] of end values p0, p1 and slopes d0, d1, and its slope, at u."""
    r = u / h
    r2 = r * r
    r3 = r2 * r
    value = (2 * r3 - 3 * r2 + 1) * p0 + (r3 - 2 * r2 + r) * h * d0 + (-2 * r3 + 3 * r2) * p1 + (r3 - r2) * h * d1
    slope = ((6 * r2 - 6 * r) * p0 + (3 * r2 - 4 * r + 1) * h * d0 + (-6 * r2 + 6 * r) * p1
             + (3 * r2 - 2 * r) * h * d1) / h
    return value, slope


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _interior_peak(y, f0, y_new, f_new, h, regime, segment, law, phi, rtol, v_scale, dt, work, y_try, f_try):
    """The largest |u| [m] inside a step whose u·u̇ falls from positive to negative (0 when it does not)."""
    if y[U1] * f0[U1] + y[U2] * f0[U2] <= 0.0 or y_new[U1] * f_new[U1] + y_new[U2] * f_new[U2] >= 0.0:
        return 0.0
    low = 0.0
    high = h
    for _ in range(60):
        middle = 0.5 * (low + high)
        x1, d1 = _hermite(y[U1], f0[U1], y_new[U1], f_new[U1], h, middle)
        x2, d2 = _hermite(y[U2], f0[U2], y_new[U2], f_new[U2], h, middle)
        if x1 * d1 + x2 * d2 > 0.0:
            low = middle
        else:
            high = middle
    _step(y, f0, 0.5 * (low + high), regime, segment, law, phi, rtol, v_scale, dt, work, y_try, f_try)
    return math.sqrt(y_try[U1] * y_try[U1] + y_try[U2] * y_try[U2])


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _hold_quadratic(segment, law, u1, u2, tau):
    """The coefficients (c₀, c₁, c₂) of |b|² − (μ(0)·n)² [m²/s⁴] in τ' = τ − ``tau`` for a block held at u [m].

    b = a + κ·n·u and n are linear in time, so the excess of the force needed
    to hold the block over the friction limit is a quadratic; it is convex
    without the vertical motion.
    """
    bx, by, rx, ry, normal = _driving(segment, law, tau, u1, u2)
    hold = law[MU_SLOW] * normal
    hold_rate = law[MU_SLOW] * segment[NORMAL_RATE]
    return (bx * bx + by * by - hold * hold, 2.0 * (bx * rx + by * ry - hold * hold_rate),
            rx * rx + ry * ry - hold_rate * hold_rate)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _breakaway_time(segment, law, u1, u2, tau, stalled):
    """The first τ' ≥ 0 after τ at which the block held at u breaks away (|b| exceeds μ(0)·n), or +inf.

    The excess q(τ') = c₀ + c₁·τ' + c₂·τ'² (:func:`_hold_quadratic`) is at
    most 0 now; its first up-crossing is the root −2c₀/(c₁ + √disc) where it
    rises now (c₁ ≥ 0), the larger root where it falls but is convex, and none
    where it falls and is concave.  ``stalled``: the block was just found not
    to slide at τ although q is not below 0 (to round-off, not rising); then
    the next crossing after τ is sought.
    """
    c0, c1, c2 = _hold_quadratic(segment, law, u1, u2, tau)
    if stalled:
        c0 = min(c0, 0.0)
    elif c0 > 0.0:
        return 0.0
    disc = c1 * c1 - 4.0 * c2 * c0
    if c1 >= 0.0:
        if disc < 0.0:
            return math.inf
        denominator = c1 + math.sqrt(disc)
        if denominator > 0.0:
            return -2.0 * c0 / denominator
        return 0.0 if c2 > 0.0 else math.inf
    if c2 <= 0.0:
        return math.inf
    return (-c1 + math.sqrt(max(disc, 0.0))) / (2.0 * c2)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _interval_sticks(segment, law, u1, u2, dt):
    """Whether a block held at u [m] stays stuck over the whole interval [0, dt] [s] (n > 0, |b| ≤ μ(0)·n)."""
    if segment[NORMAL] <= 0.0 or segment[NORMAL] + segment[NORMAL_RATE] * dt <= 0.0:
        return False
    c0, c1, c2 = _hold_quadratic(segment, law, u1, u2, 0.0)
    if c0 > 0.0 or c0 + dt * (c1 + dt * c2) > 0.0:
        return False
    if c2 < 0.0:
        vertex = -c1 / (2.0 * c2)
        if 0.0 < vertex < dt and c0 + vertex * (c1 + vertex * c2) > 0.0:
            return False
    return True


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _land(y, f, h, target, component, regime, segment, law, phi, rtol, v_scale, dt, work, y_new, f_new,
          error):
    """Bring a step of size h that passed ``y_new[component]`` = ``target`` onto it, by safeguarded Newton on h.

    The step sizes that fall short and that pass bracket the root; a Newton
    step outside the bracket is replaced by bisection.  Returns (h, error) of
    the last step tried, which y_new, f_new hold; tolerance 1e-13 of the
    target's scale.
    """
    tolerance = 1e-13 * (abs(target) + (dt if component == TAU else v_scale))
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
        error = _step(y, f, h, regime, segment, law, phi, rtol, v_scale, dt, work, y_new, f_new)
    return h, error


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _quick_stop(y, segment, law, within, tolerance):
    """The time [s] to the stop of a slow slip (|v| < s_lock) off its slow manifold, where a closed form holds.

    The driving acceleration b = a + κ·n·u, its rate at a fixed position, the
    normal force n and the ground velocity are taken at y[TAU] from
    ``segment``.  Two closed forms, each used only where its error is below
    ``tolerance`` [m] in the path and μ(0)·n·``tolerance`` [J/kg] in E_I/m:

    * the direction held (a straight stop, with b(τ) and n(τ) linear): exact
      when v points straight against −b/|b| on a flat surface with Coulomb
      friction (one dimension); otherwise the part of b across v, up to |b|,
      is left out of the absolute acceleration over the stop's
      t_stop ≈ s/(μ·n), an error of about |u̇_g|·|b|·s/(μ·n) in E_I/m, and
      the restoring force's change and μ(s) − μ(0) are left out of the
      deceleration;
    * b and n held at their values (|b| < μ(0)·n): the closed form in σ of
      the module's docstring, with errors of about s·t_stop·|ḃ|·t_stop/(μ·n −
      |b|) in the path (ḃ including the rate of μ(0)·n, the restoring force's
      change and μ(s) − μ(0)) and μ·n·|a|·t_stop² in E_I/m (the ground velocity
      is held too).

    Returns +inf, leaving y alone, when neither holds or the stop is later than
    ``within`` [s]; otherwise advances y (u, path, energies, τ) to the stop and
    sets v = 0.
    """
    tau = y[TAU]
    mu_0 = law[MU_SLOW]
    friction_slope = (law[MU_FAST] - law[MU_SLOW]) * law[RATE]  # dμ/ds at s = 0 [s/m]
    ax = segment[A1] + segment[K1] * tau
    ay = segment[A2] + segment[K2] * tau
    bx, by, kx, ky, normal = _driving(segment, law, y[TAU], y[U1], y[U2])
    normal_rate = segment[NORMAL_RATE]
    stiffness = law[CURVATURE] * normal
    excess = law[CURVATURE] * (normal - segment[GRAVITY])  # the part of the stiffness the vertical motion adds
    rx = stiffness * y[U1]
    ry = stiffness * y[U2]
    gx = segment[G1] + tau * (segment[A1] + 0.5 * segment[K1] * tau)
    gy = segment[G2] + tau * (segment[A2] + 0.5 * segment[K2] * tau)
    m0 = mu_0 * normal
    vx = y[V1]
    vy = y[V2]
    s0 = math.sqrt(vx * vx + vy * vy)
    size = math.sqrt(bx * bx + by * by)
    wx = -bx / size if size > 0.0 else vx / s0  # −b/|b|, the direction the slip settles on
    wy = -by / size if size > 0.0 else vy / s0
    cos_phi = (wx * vx + wy * vy) / s0
    sin_phi = (wx * vy - wy * vx) / s0
    ground_speed = math.sqrt(gx * gx + gy * gy)
    drift = stiffness * s0 + mu_0 * abs(normal_rate)  # the rates of b and of μ(0)·n the closed forms leave out
    if 1.0 + cos_phi <= 1e-12 or ground_speed * size * s0 <= tolerance * m0 * m0:
        e1 = vx / s0
        e2 = vy / s0
        rate = m0 + bx * e1 + by * e2
        turn = kx * e1 + ky * e2 + mu_0 * normal_rate
        duration = first_stop_time(s0, -rate, -0.5 * turn)
        if duration > within:
            return math.inf
        if s0 * duration * duration * (stiffness * duration / 6.0 + 0.5 * normal * friction_slope) > tolerance or \
                ground_speed * drift * duration * duration > tolerance * m0:
            return math.inf
        distance = duration * (s0 - duration * (0.5 * rate + turn * duration / 6.0))
        moment = duration * duration * (0.5 * s0 - duration * (rate / 3.0 + turn * duration / 8.0))  # ∫τ'·s dτ'
        y[U1] += e1 * distance
        y[U2] += e2 * distance
        y[PATH] += distance
        y[DISSIPATED] += mu_0 * (normal * distance + normal_rate * moment)
        y[VERTICAL] -= excess * ((y[U1] - e1 * distance) * e1 + (y[U2] - e2 * distance) * e2 + 0.5 * distance) \
            * distance
        held = duration * (duration * duration * (segment[K1] * e1 + segment[K2] * e2) / 6.0
                           + 0.5 * duration * (ax * e1 + ay * e2) + (gx * e1 + gy * e2))
        swept_x = duration * (gx + duration * (0.5 * ax + duration * segment[K1] / 6.0))  # ∫u̇_g dτ'
        swept_y = duration * (gy + duration * (0.5 * ay + duration * segment[K2] / 6.0))
        y[INPUT] -= m0 * held + rx * swept_x + ry * swept_y
    else:
        if size >= m0:
            return math.inf
        c = m0 - size
        t0 = sin_phi / (1.0 + cos_phi)
        u0 = t0 * t0
        duration = s0 / (1.0 + u0) * (1.0 / c + u0 / (c + 2.0 * size))
        change = math.sqrt(kx * kx + ky * ky) + drift
        if duration > within or s0 * duration * (change * duration + normal * friction_slope * s0) > tolerance * c \
                or (size + drift) * duration * duration > tolerance:
            return math.inf
        distance = s0 * s0 / (1.0 + u0) ** 2 * (0.5 / c + u0 / (c + size) + 0.5 * u0 * u0 / (c + 2.0 * size))
        # ∫ s·e dσ and ∫ s²·e dσ as complex numbers in the frame of −b/|b|, then turned into the plane
        along_1 = s0 / (1.0 + u0) * (1.0 / c - u0 / (c + 2.0 * size))
        across_1 = s0 / (1.0 + u0) * 2.0 * t0 / (c + size)
        scale_2 = s0 * s0 / (1.0 + u0) ** 2
        along_2 = scale_2 * (0.5 / c - 0.5 * u0 * u0 / (c + 2.0 * size))
        across_2 = scale_2 * (2.0 * t0 / (2.0 * c + size) + 2.0 * t0 * u0 / (2.0 * c + 3.0 * size))
        dx = wx * along_2 - wy * across_2
        dy = wy * along_2 + wx * across_2
        y[VERTICAL] -= excess * (y[U1] * dx + y[U2] * dy + 0.5 * (dx * dx + dy * dy))
        y[U1] += dx
        y[U2] += dy
        y[PATH] += distance
        y[DISSIPATED] += m0 * distance
        y[INPUT] -= m0 * ((wx * along_1 - wy * across_1) * gx + (wy * along_1 + wx * across_1) * gy) \
            + (rx * gx + ry * gy) * duration
    y[V1] = 0.0
    y[V2] = 0.0
    y[TAU] += duration
    return duration


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _series_speed(coefficient, power, allowed, v_scale):
    """The largest speed s [m/s] with |coefficient|·s^(power + 1) ≤ allowed·(s + v_scale), from below."""
    if coefficient == 0.0:
        return math.inf
    size = abs(coefficient)
    return max((allowed / size) ** (1.0 / power), (allowed * v_scale / size) ** (1.0 / (power + 1)))


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _settled_plan(y, speed, segment, law, phi, rtol, v_scale, order):
    """Where the slow manifold's series holds at y, and the order a step at the speed ``speed`` [m/s] needs.

    The series to ``order`` terms is computed into ``phi``.  A truncation after
    k terms errs by about the next term, φ_{k+1}·s^{k+1} (by the last term
    itself for the last), which times s must stay within
    :data:`SERIES_TOLERANCE`·rtol·(s + ``v_scale``); the first term |φ₁|·s
    within 0.1 rad.  Returns (the speed [m/s] up to which the whole series
    holds, 0 where it does not; the smallest order that holds to twice
    ``speed``, or the whole; the speed up to which that order holds; the angle
    Φ [rad] at ``speed`` from the whole series).  ``phi[0]`` is set to the order.
    """
    bx, by, rate_x, rate_y, normal = _driving(segment, law, y[TAU], y[U1], y[U2])
    valid = manifold_series(bx, by, rate_x, rate_y, normal, segment[NORMAL_RATE], law[LAW_SERIES:], order, phi)
    if valid == 0:
        phi[0] = 0.0
        return 0.0, 0, 0.0, 0.0
    angle = series_angle(phi, valid, speed)
    allowed = SERIES_TOLERANCE * rtol
    cap = math.inf if phi[1] == 0.0 else 0.1 / abs(phi[1])
    whole = min(cap, _series_speed(phi[valid], valid, allowed, v_scale))
    chosen = valid
    chosen_limit = whole
    for k in range(1, valid):
        limit = min(cap, _series_speed(phi[k + 1], k + 1, allowed, v_scale))
        if limit >= 2.0 * speed or limit >= whole:
            chosen = k
            chosen_limit = min(limit, whole)
            break
    phi[0] = chosen
    return whole, chosen, chosen_limit, angle


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _settled_reach(segment, law, y, span):
    """How long [s] from y[TAU], at most ``span``, the slow manifold keeps its first denominator, u held.

    The series holds while D₁ = 2|b| − μ(0)·n exceeds
    :data:`~stickslip.models.planar.manifold.DENOMINATOR_MARGIN`·μ(0)·n:
    where |b| falls towards zero the direction no longer relaxes onto −b/|b|
    (and −b/|b| turns over where b passes zero), so a step on the manifold must
    end before.  With u held b and n are linear in time, and
    q(t) = 4|b|² − ((1 + margin)·μ(0)·n)² is a quadratic whose first
    down-crossing ends the reach (u moves by s·t meanwhile, which the step's
    next plan sees).
    """
    bx, by, rx, ry, normal = _driving(segment, law, y[TAU], y[U1], y[U2])
    level = (1.0 + DENOMINATOR_MARGIN) * law[MU_SLOW]
    rate = segment[NORMAL_RATE]
    c0 = 4.0 * (bx * bx + by * by) - (level * normal) ** 2
    if c0 <= 0.0:
        return 0.0
    c1 = 8.0 * (bx * rx + by * ry) - 2.0 * level * level * normal * rate
    c2 = 4.0 * (rx * rx + ry * ry) - (level * rate) ** 2
    first = math.inf
    if c2 == 0.0:
        if c1 < 0.0:
            first = -c0 / c1
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc >= 0.0:
            half = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
            for root in (half / c2, c0 / half if half != 0.0 else math.inf):
                if 0.0 < root < first:
                    first = root
    return min(first, span)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _first_order_angle(y, speed, segment, law, phi):
    """The slow manifold's angle [rad] at the speed ``speed`` [m/s] to first order, φ₁·s (0 where it does not hold)."""
    bx, by, rate_x, rate_y, normal = _driving(segment, law, y[TAU], y[U1], y[U2])
    order = manifold_series(bx, by, rate_x, rate_y, normal, segment[NORMAL_RATE], law[LAW_SERIES:], 1, phi)
    return phi[1] * speed if order > 0 else 0.0


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _direction_angle(y, segment, law):
    """The angle [rad] of the sliding velocity y[V1:V2] from −b/|b| at y (π where b = 0)."""
    bx, by, _, _, _ = _driving(segment, law, y[TAU], y[U1], y[U2])
    if bx == 0.0 and by == 0.0:
        return math.pi
    return math.atan2(-bx * y[V2] + by * y[V1], -(bx * y[V1] + by * y[V2]))


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _settled_velocity(y, speed, angle, segment, law):
    """Set y[V1:V2] to the velocity of speed ``speed`` [m/s] at ``angle`` [rad] from −b/|b| at y."""
    bx, by, _, _, _ = _driving(segment, law, y[TAU], y[U1], y[U2])
    size = math.sqrt(bx * bx + by * by)
    ux = bx / size
    uy = by / size
    cos_phi = math.cos(angle)
    sin_phi = math.sin(angle)
    y[V1] = -(ux * cos_phi - uy * sin_phi) * speed
    y[V2] = -(ux * sin_phi + uy * cos_phi) * speed


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _fly(y, segment, law, end, totals):
    """Advance a block off the surface (n ≤ 0: v̇ = −a) from y[TAU] to ``end`` [s], in closed form.

    No force acts on it: its absolute velocity u̇_g + v is constant, so E_I,
    E_df and the path do not change, and W_v (N = 0: −κ·(0 − g)·u·v) takes
    the change of E_p = ½·g·κ·|u|².  The largest |u| on the way
    (|u|² is a polynomial) goes into totals[2].
    """
    start = y[TAU]
    span = end - start
    if span <= 0.0:
        return
    ax = segment[A1] + segment[K1] * start
    ay = segment[A2] + segment[K2] * start
    kx = segment[K1]
    ky = segment[K2]
    u1, u2, v1, v2 = y[U1], y[U2], y[V1], y[V2]

    def position(t):
        return (u1 + t * (v1 - t * (0.5 * ax + kx * t / 6.0)), u2 + t * (v2 - t * (0.5 * ay + ky * t / 6.0)),
                v1 - t * (ax + 0.5 * kx * t), v2 - t * (ay + 0.5 * ky * t))

    pieces = 16
    previous = 0.0
    x1, x2, w1, w2 = position(0.0)
    before = x1 * w1 + x2 * w2
    for piece in range(1, pieces + 1):
        t = span * piece / pieces
        x1, x2, w1, w2 = position(t)
        after = x1 * w1 + x2 * w2
        totals[2] = max(totals[2], math.sqrt(x1 * x1 + x2 * x2))
        if before > 0.0 >= after:  # |u| has a maximum inside the piece
            low = previous
            high = t
            for _ in range(60):
                middle = 0.5 * (low + high)
                z1, z2, q1, q2 = position(middle)
                if z1 * q1 + z2 * q2 > 0.0:
                    low = middle
                else:
                    high = middle
            z1, z2, q1, q2 = position(0.5 * (low + high))
            totals[2] = max(totals[2], math.sqrt(z1 * z1 + z2 * z2))
        before = after
        previous = t
    y[VERTICAL] -= 0.5 * segment[GRAVITY] * law[CURVATURE] * (u1 * u1 + u2 * u2)
    y[U1], y[U2], y[V1], y[V2] = position(span)
    y[VERTICAL] += 0.5 * segment[GRAVITY] * law[CURVATURE] * (y[U1] * y[U1] + y[U2] * y[U2])
    y[TAU] = end
    totals[3] += span


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _advance_contact(segment, end, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f, motion, steps,
                     work, y_new, f_new, y_try, f_try, phi, totals):
    """Advance the block in contact (n > 0) from y[TAU] to ``end`` [s] of the interval [0, dt]; returns its motion.

    ``tolerance`` [m] bounds the path error of a closed-form stop (:func:`_quick_stop`);
    ``steps`` holds the step size of each regime, carried from interval to interval
    ([s], [s/(m/s)], [s]); ``totals`` accumulates [slip time (s), episodes, peak |u| (m), flight time (s),
    peak |ü| (m/s²): at the stick's ends, step ends and stops].  Returns STALLED, y left where it got to, after
    :data:`MAX_PASSES` passes that have not reached ``end``.
    """
    stalled = False
    leave = False  # the last step on the slow manifold was landed where its whole series ends
    passes = 0
    while y[TAU] < end:
        passes += 1
        if passes > MAX_PASSES:
            return STALLED
        start = y[TAU]
        if motion == STICK:
            wait = _breakaway_time(segment, law, y[U1], y[U2], start, stalled)
            if stalled:
                wait = max(wait, 1e-12 * dt)
                stalled = False
            span = min(wait, end - start)
            totals[4] = max(totals[4], _ground_acceleration(segment, start), _ground_acceleration(segment, start + span))
            gx = segment[G1] + start * (segment[A1] + 0.5 * segment[K1] * start)
            gy = segment[G2] + start * (segment[A2] + 0.5 * segment[K2] * start)
            y[INPUT] += (stick_input_energy(segment[A1] + segment[K1] * start, segment[K1], gx, span)
                         + stick_input_energy(segment[A2] + segment[K2] * start, segment[K2], gy, span))
            if wait >= end - start:
                y[TAU] = end
                break
            y[TAU] = start + wait
            motion = SETTLED_SLIDING
            totals[1] += 1.0
            y[V1] = 0.0
            y[V2] = 0.0
            continue
        if motion == SETTLED_SLIDING:
            speed = y[V1]
            whole, _, settled_limit, angle = _settled_plan(y, speed, segment, law, phi, rtol, velocity_floor,
                                                           int(law[ORDER]))
            if speed >= whole or leave:  # the slow manifold's series no longer holds: the full equations
                _settled_velocity(y, speed, angle, segment, law)
                motion = SLIDING
                leave = False
        else:
            speed = math.sqrt(y[V1] * y[V1] + y[V2] * y[V2])
        if motion == SETTLED_SLIDING:
            regime = SETTLED
            _rhs(y, regime, segment, law, phi, f)
            if speed == 0.0 and f[V1] <= 0.0 and _hold_quadratic(segment, law, y[U1], y[U2], start)[1] <= 0.0:
                motion = STICK  # |b| = μ(0)·n to round-off, not rising
                stalled = True
                continue
        else:
            if speed < 100.0 * s_switch and speed > 0.0:
                allowed_miss = SERIES_TOLERANCE * rtol * (speed + velocity_floor) / speed
                direction = _direction_angle(y, segment, law)
                first = _first_order_angle(y, speed, segment, law, phi)
                if abs(direction - first) <= 0.5 * abs(first) + allowed_miss:  # near the manifold: look closer
                    whole, _, _, angle = _settled_plan(y, speed, segment, law, phi, rtol, velocity_floor,
                                                       int(law[ORDER]))
                    if (speed < SERIES_ENTRY * whole and abs(direction - angle) <= allowed_miss
                            and _settled_reach(segment, law, y, end - start) >= min(end - start, 1e-3 * dt)):  # on it
                        y[V1] = speed
                        y[V2] = 0.0
                        motion = SETTLED_SLIDING
                        continue
            if speed < s_lock:
                saved_peak = math.sqrt(y[U1] * y[U1] + y[U2] * y[U2])
                e1 = y[V1] / speed if speed > 0.0 else 0.0
                e2 = y[V2] / speed if speed > 0.0 else 0.0
                duration = _quick_stop(y, segment, law, end - start, tolerance)
                if duration < math.inf:
                    totals[0] += duration
                    totals[2] = max(totals[2], saved_peak, math.sqrt(y[U1] * y[U1] + y[U2] * y[U2]))
                    totals[4] = max(totals[4], _sliding_acceleration(segment, law, y[TAU], y[U1], y[U2], e1, e2,
                                                                     0.0))
                    motion = SETTLED_SLIDING if _hold_quadratic(segment, law, y[U1], y[U2], y[TAU])[0] > 0.0 \
                        else STICK
                    continue
            regime = SLOW if speed < s_switch else FAST
            _rhs(y, regime, segment, law, phi, f)
        if regime == SLOW:
            h = steps[SLOW]
        else:
            h = min(steps[regime], end - start)
        if regime == SETTLED:
            reach = _settled_reach(segment, law, y, end - start)
            if reach <= 1e-9 * dt:  # the manifold ends here: the full equations, from its direction
                _settled_velocity(y, y[V1], angle, segment, law)
                motion = SLIDING
                continue
            h = min(h, reach)
        if regime == SETTLED and f[V1] < 0.0 and y[V1] > 0.0:
            # no further than the stop at the present deceleration: a slip that slows down faster ends the
            # step below zero and is landed on the stop; one that recovers inside the step never reached it
            h = min(h, 1.0001 * y[V1] / -f[V1])
        error = _step(y, f, h, regime, segment, law, phi, rtol, velocity_floor, dt, work, y_new, f_new)
        stopped = False
        series_end = False
        if regime != SETTLED and y_new[V1] * y[V1] + y_new[V2] * y[V2] <= 0.0:  # a step past the stop: shorter
            steps[regime] = 0.25 * h
            continue
        if regime == SETTLED and y_new[V1] >= 0.0 and work[LOWEST, 0] < -rtol * velocity_floor:
            # the speed dipped below zero inside the step and rose again: the block may have stopped (and stuck,
            # or broken away anew) in between, which a step through zero would miss: shorter
            steps[regime] = 0.5 * h
            continue
        if regime == SLOW and error <= 1.0 and y_new[TAU] > end:
            h, error = _land(y, f, h, end, TAU, regime, segment, law, phi, rtol, velocity_floor, dt, work,
                             y_new, f_new, error)
        elif regime == SETTLED and error <= 1.0 and (y_new[V1] < 0.0 or y_new[V1] > settled_limit):
            target = 0.0 if y_new[V1] < 0.0 else settled_limit * (1.0 + 1e-9)
            h, error = _land(y, f, h, target, V1, regime, segment, law, phi, rtol, velocity_floor, dt, work,
                             y_new, f_new, error)
            stopped = target == 0.0
            # where the whole series ends, the slip leaves the manifold at once: the limit moves with b, and a slip
            # that stayed on would chase it, one landing after another
            series_end = not stopped and settled_limit >= whole
        if error > 1.0:
            steps[regime] = next_step(h, error)
            continue
        if regime == SLOW:
            if end - y_new[TAU] <= 2e-13 * dt:
                y_new[TAU] = end
        elif h >= end - start:
            y_new[TAU] = end
        steps[regime] = next_step(h, error)
        totals[2] = max(totals[2], math.sqrt(y_new[U1] * y_new[U1] + y_new[U2] * y_new[U2]))
        totals[4] = max(totals[4], _step_end_acceleration(y_new, f_new, regime, segment, law))
        if y[U1] * f[U1] + y[U2] * f[U2] > 0.0 and y_new[U1] * f_new[U1] + y_new[U2] * f_new[U2] < 0.0:
            totals[2] = max(totals[2], _interior_peak(y, f, y_new, f_new, h, regime, segment, law, phi, rtol,
                                                      velocity_floor, dt, work, y_try, f_try))
        totals[0] += y_new[TAU] - start
        for j in range(N_STATE):
            y[j] = y_new[j]
        if regime == SETTLED:
            if stopped:
                y[V1] = 0.0
                y[V2] = 0.0
                motion = SETTLED_SLIDING if _hold_quadratic(segment, law, y[U1], y[U2], y[TAU])[0] > 0.0 else STICK
            else:
                y[V2] = 0.0
                leave = series_end
    return motion


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def advance_interval(segment, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f, motion, steps, work,
                     y_new, f_new, y_try, f_try, phi, totals):
    """Advance the block over one sample interval [0, dt] [s] in place; returns its motion (STICK, ...) at the end.

    The interval's data are in ``segment`` (:data:`A1` ...); where the normal
    force n crosses zero inside it, the block lifts off there or lands there
    (:func:`_fly` in between).  ``y`` holds the state (its τ is set to 0
    here); the other arguments are those of :func:`_advance_contact`, which
    may give up (STALLED, y[TAU] where it did).
    """
    y[TAU] = 0.0
    start_normal = segment[NORMAL]
    end_normal = start_normal + segment[NORMAL_RATE] * dt
    if start_normal > 0.0 and end_normal > 0.0:
        return _advance_contact(segment, dt, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f,
                                motion, steps, work, y_new, f_new, y_try, f_try, phi, totals)
    if start_normal <= 0.0 and end_normal <= 0.0:
        _fly(y, segment, law, dt, totals)
        return FLIGHT
    crossing = min(max(-start_normal / segment[NORMAL_RATE], 0.0), dt)
    if start_normal > 0.0:  # lifts off inside the interval
        if crossing > 0.0:
            motion = _advance_contact(segment, crossing, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y,
                                      f, motion, steps, work, y_new, f_new, y_try, f_try, phi, totals)
        if motion == STALLED:
            return STALLED
        if motion == SETTLED_SLIDING:
            _settled_velocity(y, y[V1], _settled_plan(y, y[V1], segment, law, phi, rtol, velocity_floor,
                                                      int(law[ORDER]))[3], segment, law)
        _fly(y, segment, law, dt, totals)
        return FLIGHT
    _fly(y, segment, law, crossing, totals)  # lands inside the interval
    motion = STICK if y[V1] == 0.0 and y[V2] == 0.0 else SLIDING
    return _advance_contact(segment, dt, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f, motion,
                            steps, work, y_new, f_new, y_try, f_try, phi, totals)


@numba.njit(cache=True, error_model="numpy")
def _prepare_record(first, second, normal, gravity, dt, velocity, stick_energy, bounds):
    """Fill one record's friction-independent arrays.

    ``velocity`` (n, 2) [m/s]: the ground velocity at the samples (trapezoid
    sums, exact for a linear between samples); ``stick_energy`` [J/kg]: prefix
    sums of the input energy of a block that sticks over whole intervals;
    ``bounds`` (blocks, 7): per :data:`BLOCK` samples (and the next block's
    first), max |a|², min and max of a₁, a₂ and of n [m/s², m²/s⁴].  ``normal``
    is n = g + a_v at the samples, or empty for n = ``gravity`` throughout.
    """
    n = first.size
    velocity[0, 0] = 0.0
    velocity[0, 1] = 0.0
    stick_energy[0] = 0.0
    for i in range(n - 1):
        slope_1 = (first[i + 1] - first[i]) / dt
        slope_2 = (second[i + 1] - second[i]) / dt
        stick_energy[i + 1] = (stick_energy[i] + stick_input_energy(first[i], slope_1, velocity[i, 0], dt)
                               + stick_input_energy(second[i], slope_2, velocity[i, 1], dt))
        velocity[i + 1, 0] = velocity[i, 0] + 0.5 * dt * (first[i] + first[i + 1])
        velocity[i + 1, 1] = velocity[i, 1] + 0.5 * dt * (second[i] + second[i + 1])
    for block in range(bounds.shape[0]):
        low = block * BLOCK
        high = min(low + BLOCK, n - 1)
        bounds[block, _AMAX2] = 0.0
        bounds[block, _A1MIN] = first[low]
        bounds[block, _A1MAX] = first[low]
        bounds[block, _A2MIN] = second[low]
        bounds[block, _A2MAX] = second[low]
        level = normal[low] if normal.size > 0 else gravity
        bounds[block, _NMIN] = level
        bounds[block, _NMAX] = level
        for k in range(low, high + 1):
            bounds[block, _AMAX2] = max(bounds[block, _AMAX2], first[k] * first[k] + second[k] * second[k])
            bounds[block, _A1MIN] = min(bounds[block, _A1MIN], first[k])
            bounds[block, _A1MAX] = max(bounds[block, _A1MAX], first[k])
            bounds[block, _A2MIN] = min(bounds[block, _A2MIN], second[k])
            bounds[block, _A2MAX] = max(bounds[block, _A2MAX], second[k])
            if normal.size > 0:
                bounds[block, _NMIN] = min(bounds[block, _NMIN], normal[k])
                bounds[block, _NMAX] = max(bounds[block, _NMAX], normal[k])


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _n_blocks(samples):
    """The number of blocks of :data:`BLOCK` sample intervals in a record of ``samples`` samples."""
    return max(1, (samples - 2) // BLOCK + 1)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _block_sticks(bounds, block, law, u1, u2):
    """Whether a block held at u [m] certainly sticks over the block of samples ``block`` of ``bounds``.

    |b| = |a + κ·n·u| is convex in (a, n), so its largest value over the
    samples' bounding box in a and range of n is at a corner; it must stay
    within μ(0)·min n, with min n > 0.
    """
    lowest = bounds[block, _NMIN]
    if lowest <= 0.0:
        return False
    limit = law[MU_SLOW] * lowest
    limit2 = limit * limit
    curvature = law[CURVATURE]
    if curvature == 0.0 or (u1 == 0.0 and u2 == 0.0):
        return bounds[block, _AMAX2] <= limit2
    for corner in range(8):
        a1 = bounds[block, _A1MAX] if corner & 1 else bounds[block, _A1MIN]
        a2 = bounds[block, _A2MAX] if corner & 2 else bounds[block, _A2MIN]
        level = bounds[block, _NMAX] if corner & 4 else bounds[block, _NMIN]
        b1 = a1 + curvature * level * u1
        b2 = a2 + curvature * level * u2
        if b1 * b1 + b2 * b2 > limit2:
            return False
    return True


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _stuck_peak(first, second, bounds, low, high):
    """max |a| [m/s²] over the samples ``low`` to ``high`` (a stretch of whole blocks after ``low``'s own block).

    The samples of ``low``'s block from ``low`` on one by one, the whole blocks after it from their bounds.
    """
    boundary = min((low // BLOCK + 1) * BLOCK, high)
    largest2 = 0.0
    for k in range(low, boundary + 1):
        largest2 = max(largest2, first[k] * first[k] + second[k] * second[k])
    for block in range(boundary // BLOCK, (high - 1) // BLOCK + 1):
        if block * BLOCK >= boundary and block * BLOCK < high:
            largest2 = max(largest2, bounds[block, _AMAX2])
    return math.sqrt(largest2)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _store_row(history, row, y, motion):
    """Write the state after sample ``row`` into ``history`` (:data:`HISTORY_NAMES`; as many columns as it has)."""
    history[row, 0] = y[U1]
    history[row, 1] = y[U2]
    history[row, 2] = y[V1]
    history[row, 3] = y[V2]
    history[row, 4] = 0.0 if motion == STICK else 1.0
    history[row, 5] = y[DISSIPATED]
    history[row, 6] = y[INPUT]
    history[row, 7] = y[PATH]
    if history.shape[1] > 8:
        history[row, 8] = y[VERTICAL]
        history[row, 9] = 1.0 if motion == FLIGHT else 0.0


@numba.njit(cache=True, error_model="numpy")
def _solve_record(first, second, normal, gravity, dt, law, rtol, lock_ratio, velocity, stick_energy, bounds, history,
                  out):
    """Solve one record pair for one friction law and surface (``law``); see :func:`solve_pair_on_surface`.

    ``velocity``, ``stick_energy`` and ``bounds`` are the record's arrays of
    :func:`_prepare_record`; ``out`` receives :data:`SURFACE_SCALAR_NAMES`
    (the first nine where it has nine).  Returns NaN, or the record's time [s]
    at which the solver gave up (:data:`MAX_PASSES`; ``out`` is then NaN).
    """
    n = first.size
    keep = history.shape[0] > 0
    has_normal = normal.size > 0
    peak_ground = 0.0
    highest_normal = bounds[0, _NMAX]
    for block in range(bounds.shape[0]):
        peak_ground = max(peak_ground, math.sqrt(bounds[block, _AMAX2]))
        highest_normal = max(highest_normal, bounds[block, _NMAX])
    friction_scale = max(law[MU_SLOW], law[MU_FAST]) * max(highest_normal, 0.0)
    speed_scale = 2.0 * (peak_ground + friction_scale) * dt
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
    work = np.zeros((WORK_ROWS, N_STATE))
    phi = np.zeros(FLAT_ORDER + 1)
    segment = np.zeros(SEGMENT_SIZE)
    totals = np.zeros(5)
    motion = STICK
    steps = np.array([dt, 0.1 / (peak_ground + friction_scale), dt])
    if keep:
        history[0, :] = 0.0
    i = 0
    while i < n - 1:
        if motion == STICK:  # whole blocks that certainly stick
            skipped = i
            while skipped < n - 1 and _block_sticks(bounds, skipped // BLOCK, law, y[U1], y[U2]):
                skipped = min((skipped // BLOCK + 1) * BLOCK, n - 1)
            if skipped > i:
                y[INPUT] += stick_energy[skipped] - stick_energy[i]
                totals[4] = max(totals[4], _stuck_peak(first, second, bounds, i, skipped))
                if keep:
                    for row in range(i + 1, skipped + 1):
                        _store_row(history, row, y, motion)
                        history[row, 6] = y[INPUT] - (stick_energy[skipped] - stick_energy[row])
                i = skipped
                continue
        segment[A1] = first[i]
        segment[A2] = second[i]
        segment[K1] = (first[i + 1] - first[i]) / dt
        segment[K2] = (second[i + 1] - second[i]) / dt
        if has_normal:
            segment[NORMAL] = normal[i]
            segment[NORMAL_RATE] = (normal[i + 1] - normal[i]) / dt
        else:
            segment[NORMAL] = gravity
            segment[NORMAL_RATE] = 0.0
        segment[G1] = velocity[i, 0]
        segment[G2] = velocity[i, 1]
        segment[GRAVITY] = gravity
        if motion == STICK and _interval_sticks(segment, law, y[U1], y[U2], dt):
            y[INPUT] += stick_energy[i + 1] - stick_energy[i]
            totals[4] = max(totals[4], _ground_acceleration(segment, 0.0), _ground_acceleration(segment, dt))
        else:
            motion = advance_interval(segment, dt, law, s_switch, s_lock, rtol, velocity_floor, tolerance, y, f,
                                      motion, steps, work, y_new, f_new, y_try, f_try, phi, totals)
            if motion == STALLED:  # where in the interval it got to (its start where the state is not a number)
                out[:] = math.nan
                return i * dt + (y[TAU] if 0.0 <= y[TAU] <= dt else 0.0)
            if motion == SETTLED_SLIDING and y[V1] > 0.0:
                # the slow manifold depends on the rate of a, which jumps at the sample: the velocity, which does not,
                # goes on from the manifold of the interval that ends (and settles on the next one's)
                _settled_velocity(y, y[V1], _settled_plan(y, y[V1], segment, law, phi, rtol, velocity_floor,
                                                          int(law[ORDER]))[3], segment, law)
                motion = SLIDING
        if keep:
            _store_row(history, i + 1, y, motion)
        i += 1
    wx = velocity[n - 1, 0] + y[V1]
    wy = velocity[n - 1, 1] + y[V2]
    out[0] = y[DISSIPATED]
    out[1] = y[INPUT]
    out[2] = 0.5 * (wx * wx + wy * wy)
    out[3] = y[U1]
    out[4] = y[U2]
    out[5] = totals[2]
    out[6] = y[PATH]
    out[7] = totals[0] / ((n - 1) * dt)
    out[8] = totals[1]
    if out.size > 9:
        out[9] = y[VERTICAL]
        out[10] = totals[3]
    if out.size > 11:
        out[11] = totals[4]
    return math.nan


@numba.njit(cache=True, error_model="numpy")
def _law(mu_slow, mu_fast, rate, inverse_radius, law):
    """Fill the kernels' ``law`` array: μ(0), μ_fast [1], rate [s/m], κ = 1/R [1/m], the series' order, and the
    Taylor coefficients of μ(s) (:func:`~stickslip.models.planar.manifold.friction_series`)."""
    law[MU_SLOW] = mu_slow
    law[MU_FAST] = mu_fast
    law[RATE] = rate
    law[CURVATURE] = inverse_radius
    law[ORDER] = FLAT_ORDER if inverse_radius == 0.0 else CURVED_ORDER
    friction_series(mu_slow, mu_fast, rate, FLAT_ORDER, law[LAW_SERIES:])


@numba.njit(cache=True, error_model="numpy")
def solve_pair_on_surface(first, second, vertical, dt, gravity, mu_slow, mu_fast, rate, inverse_radius, rtol,
                          lock_ratio, history, out):
    """Solve one record pair on a flat or spherical surface, with or without the vertical ground motion.

    Parameters
    ----------
    first, second:
        The horizontal ground acceleration on two orthogonal axes at the samples [m/s²].
    vertical:
        The vertical ground acceleration at the samples [m/s², positive up], or an empty array for none.
    dt:
        The sample interval [s].
    gravity:
        g [m/s²]; the normal force per unit mass is n = g + a_v.
    mu_slow, mu_fast, rate:
        The friction law μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} [1, 1, s/m]; Coulomb where
        μ_fast = μ_slow.
    inverse_radius:
        The surface's curvature 1/R [1/m]; 0 for a flat surface.
    rtol, lock_ratio:
        The relative tolerance of the velocity per step (:data:`RTOL`) and the ratio s_lock/S of the closed-form
        stops (:data:`LOCK_RATIO`).
    history:
        Shape (n, 10), (n, 8) or (0, c): the state just after each sample (:data:`HISTORY_NAMES`, per unit mass).
    out:
        Receives :data:`SURFACE_SCALAR_NAMES` (per unit mass).

    Returns NaN, or the record's time [s] at which the solver gave up (:data:`MAX_PASSES`; ``out`` is then NaN:
    :func:`check_progress`).
    """
    n = first.size
    law = np.zeros(LAW_SIZE)
    _law(mu_slow, mu_fast, rate, inverse_radius, law)
    velocity = np.zeros((n, 2))
    stick_energy = np.zeros(n)
    bounds = np.zeros((_n_blocks(n), 7))
    _prepare_record(first, second, vertical + gravity, gravity, dt, velocity, stick_energy, bounds)
    return _solve_record(first, second, vertical + gravity, gravity, dt, law, rtol, lock_ratio, velocity,
                         stick_energy, bounds, history, out)


@numba.njit(cache=True, error_model="numpy")
def solve_pair(ax, ay, dt, mug, rtol, lock_ratio, history, out):
    """Solve one record pair (a₁, a₂ [m/s²] at the samples, interval dt [s]) on a flat surface at μ·g = ``mug`` [m/s²].

    Coulomb friction, no vertical motion (:func:`solve_pair_on_surface` with
    n = 1 and μ = μ·g, whose product is all that enters).  ``out`` receives the scalars of
    :data:`PLANAR_SCALAR_NAMES`; ``history``, of shape (n, 8) or (0, 8), the
    state just after each sample: x₁, x₂ [m], v₁, v₂ [m/s], sliding (1) or not
    (0), E_df/m, E_I/m [J/kg], path [m].  Returns NaN, or the record's time [s]
    at which the solver gave up (:func:`check_progress`).
    """
    return solve_pair_on_surface(ax, ay, np.zeros(0), dt, 1.0, mug, mug, 0.0, 0.0, rtol, lock_ratio, history, out)


@numba.njit(cache=True, parallel=True, error_model="numpy")
def _sweep_kernel(samples_1, samples_2, vertical, offsets, dts, gravity, cases, rtol, lock_ratio, lanes, out,
                  stalled_at):
    """The compiled :func:`sweep_pairs_on_surface`, its (pair, case) jobs dealt to ``lanes`` threads in turn."""
    n_pairs = offsets.size - 1
    n_cases = cases.shape[0]
    total = offsets[-1]
    has_vertical = vertical.size > 0
    normal = vertical + gravity
    velocity = np.zeros((total, 2))
    stick_energy = np.zeros(total)
    block_offsets = np.zeros(n_pairs + 1, dtype=np.int64)
    for pair in range(n_pairs):
        block_offsets[pair + 1] = block_offsets[pair] + _n_blocks(offsets[pair + 1] - offsets[pair])
    bounds = np.zeros((block_offsets[-1], 7))
    for pair in numba.prange(n_pairs):
        first = offsets[pair]
        last = offsets[pair + 1]
        _prepare_record(samples_1[first:last], samples_2[first:last], normal[first:last] if has_vertical else normal,
                        gravity, dts[pair], velocity[first:last], stick_energy[first:last],
                        bounds[block_offsets[pair]:block_offsets[pair + 1]])
    no_history = np.zeros((0, 8))
    for lane in numba.prange(lanes):
        law = np.zeros(LAW_SIZE)
        for job in range(lane, n_pairs * n_cases, lanes):
            pair = job // n_cases
            case = job - pair * n_cases
            first = offsets[pair]
            last = offsets[pair + 1]
            _law(cases[case, 0], cases[case, 1], cases[case, 2], cases[case, 3], law)
            stalled_at[pair, case] = _solve_record(
                samples_1[first:last], samples_2[first:last], normal[first:last] if has_vertical else normal, gravity,
                dts[pair], law, rtol, lock_ratio, velocity[first:last], stick_energy[first:last],
                bounds[block_offsets[pair]:block_offsets[pair + 1]], no_history, out[pair, case])


def sweep_pairs_on_surface(samples_1, samples_2, vertical, offsets, dts, gravity, cases, rtol, lock_ratio, out):
    """:func:`solve_pair_on_surface` for every (pair, case), in parallel.

    ``samples_1``, ``samples_2`` [m/s²] (and ``vertical`` [m/s², positive up],
    or empty for none) hold the pairs one after the other, pair p in
    ``offsets[p]:offsets[p + 1]``, with intervals ``dts`` [s]; ``gravity`` g
    [m/s²]; ``cases`` has one row (μ_slow, μ_fast, rate [s/m], 1/R [1/m]) per
    case; ``out`` has shape (pairs, cases, len(:data:`SURFACE_SCALAR_NAMES`)) or
    (pairs, cases, 9).  The friction-independent arrays of each pair are
    computed once; the (pair, case) jobs are dealt to numba's threads in turn
    (neighbouring cases cost alike).  Returns, shape (pairs, cases), NaN or
    the record's time [s] at which the solver gave up on that pair and case
    (:func:`check_progress`).
    """
    stalled_at = np.empty(out.shape[:2])
    _sweep_kernel(samples_1, samples_2, vertical, offsets, dts, gravity, np.ascontiguousarray(cases, dtype=float),
                  rtol, lock_ratio, numba.get_num_threads(), out, stalled_at)
    return stalled_at


def sweep_pairs(samples_1, samples_2, offsets, dts, mugs, rtol, lock_ratio, out):
    """:func:`solve_pair` for every (pair, μ·g) in parallel; ``out`` has shape (pairs, len(mugs), 9).

    ``mugs`` [m/s²] are the values of μ·g (flat surface, Coulomb friction, no
    vertical motion): :func:`sweep_pairs_on_surface` with n = 1 and μ = μ·g,
    whose product is all that enters on a flat surface.  Returns its times
    at which the solver gave up, shape (pairs, len(mugs)) (:func:`check_progress`).
    """
    mugs = np.asarray(mugs, dtype=float)
    cases = np.zeros((mugs.size, 4))
    cases[:, 0] = mugs
    cases[:, 1] = mugs
    return sweep_pairs_on_surface(samples_1, samples_2, np.zeros(0), offsets, dts, 1.0, cases, rtol, lock_ratio, out)


def check_progress(stalled_at, describe) -> None:
    """Refuse, with one line, a solve or sweep on which the solver gave up (:data:`MAX_PASSES`).

    ``stalled_at`` holds what :func:`solve_pair_on_surface` (a float) or
    :func:`sweep_pairs_on_surface` (an array) return: NaN, or the record's time
    [s] at which the solver gave up; ``describe(index)`` names the motion and
    the case at that index of it (``()`` for a float).  Raises
    :class:`~stickslip.errors.StickslipError` for the first that gave up.
    """
    from stickslip.errors import StickslipError

    stalled = ~np.isnan(np.asarray(stalled_at, dtype=float))
    if stalled.any():
        index = tuple(int(k) for k in np.unravel_index(np.argmax(stalled), stalled.shape))
        raise StickslipError(
            f"{describe(index)}: the solver gave up at t = {np.asarray(stalled_at)[index]:.6g} s of the record, after "
            f"{MAX_PASSES} passes of its event loop in one sample interval without reaching the interval's end")
