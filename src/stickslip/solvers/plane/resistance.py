"""The resistance of the plane that a model composes: one friction force on a circle, a restoring term, n(t).

Per unit mass, a block on a surface of curvature κ = 1/R (κ = 0: flat;
small-angle geometry) under the normal force per unit mass n(t) = g + a_v(t)
(a_v the vertical ground acceleration, positive up; n ≤ 0 where it lifts off:
:mod:`~stickslip.solvers.plane.flight`) is held by −b with

    b = a + κ·n·u   (the ground's acceleration and the restoring term),

and while it slides at the speed s along the unit vector e it is resisted by
μ(s)·n·e, one friction force opposite to the velocity (the friction circle),
μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} (Coulomb: μ_fast = μ_slow).  A
model says what it composes in the ``law`` array (:func:`fill_law`): the flat
block Coulomb's μ and κ = 0, the friction pendulum its friction law and 1/R;
the vertical motion enters through n in the interval's ``segment``
(:mod:`~stickslip.solvers.plane.state`).
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers.plane.manifold import CURVED_ORDER, FLAT_ORDER, friction_series
from stickslip.solvers.plane.state import A1, A2, K1, K2, NORMAL, NORMAL_RATE, SETTLED, TAU, U1, U2, V1, V2

#: The friction law and the surface (indices into the ``law`` array): μ(0), μ_fast, rate [s/m], κ = 1/R [1/m],
#: the order of the slow manifold's series; LAW_SERIES onwards, the Taylor coefficients of μ(s).
MU_SLOW, MU_FAST, RATE, CURVATURE, ORDER = range(5)
LAW_SERIES = 5
LAW_SIZE = LAW_SERIES + FLAT_ORDER + 1


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def friction_coefficient(speed, mu_slow, mu_fast, rate):
    """μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} [1] at the sliding speed ``speed`` [m/s], ``rate`` [s/m].

    Constantinou, Mokha and Reinhorn (1990), OpenSees' ``VelDependent``;
    Coulomb friction where μ_fast = μ_slow.
    """
    if mu_fast == mu_slow:
        return mu_slow
    return mu_fast - (mu_fast - mu_slow) * math.exp(-rate * speed)


@numba.njit(cache=True, error_model="numpy")
def fill_law(mu_slow, mu_fast, rate, inverse_radius, law):
    """Fill the kernels' ``law`` array: μ(0), μ_fast [1], rate [s/m], κ = 1/R [1/m], the series' order, and the
    Taylor coefficients of μ(s) (:func:`~stickslip.solvers.plane.manifold.friction_series`)."""
    law[MU_SLOW] = mu_slow
    law[MU_FAST] = mu_fast
    law[RATE] = rate
    law[CURVATURE] = inverse_radius
    law[ORDER] = FLAT_ORDER if inverse_radius == 0.0 else CURVED_ORDER
    friction_series(mu_slow, mu_fast, rate, FLAT_ORDER, law[LAW_SERIES:])


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def driving(segment, law, tau, u1, u2):
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
def sliding_acceleration(segment, law, tau, u1, u2, e1, e2, speed):
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
def ground_acceleration(segment, tau):
    """|a(τ)| [m/s²], the absolute acceleration of a block stuck to the ground at τ [s] of the interval."""
    x = segment[A1] + segment[K1] * tau
    z = segment[A2] + segment[K2] * tau
    return math.sqrt(x * x + z * z)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def step_end_acceleration(y_new, f_new, regime, segment, law):
    """|ü| [m/s²] at the end of an accepted step (:func:`sliding_acceleration`), the direction from the state.

    On the slow manifold y[V1] is the speed and u̇ = s·e (``f_new``); at s = 0
    there the block points along −b/|b|.
    """
    if regime == SETTLED:
        speed = y_new[V1]
        if speed > 0.0:
            return sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], f_new[U1] / speed,
                                        f_new[U2] / speed, speed)
        bx, by, _, _, _ = driving(segment, law, y_new[TAU], y_new[U1], y_new[U2])
        size = math.sqrt(bx * bx + by * by)
        if size == 0.0:
            return sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], 0.0, 0.0, 0.0)
        return sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], -bx / size, -by / size, 0.0)
    speed = math.sqrt(y_new[V1] * y_new[V1] + y_new[V2] * y_new[V2])
    if speed == 0.0:
        return sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], 0.0, 0.0, 0.0)
    return sliding_acceleration(segment, law, y_new[TAU], y_new[U1], y_new[U2], y_new[V1] / speed,
                                y_new[V2] / speed, speed)
