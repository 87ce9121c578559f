"""The settled regime: a slow slip whose direction lies on the slow manifold of its speed.

At small speed s the angle φ of the sliding velocity from −b/|b| relaxes at
the rate |b|/s, so it lies on its slow manifold Φ(s, t), a series in s whose
coefficients :func:`stickslip.solvers.plane.manifold.manifold_series` computes
in closed form (to third order on a flat surface, second on a curved one).  A
block breaks away on it and a slow slip joins it once its direction is on it
to the tolerance; there only s, u and the energies are integrated, in time,
while the series' error estimate is within the tolerance (:func:`settled_plan`)
and its first denominator holds (:func:`settled_reach`).  y[V1] is then the
speed and y[V2] is not used; :func:`settled_velocity` turns the speed back into
a velocity where the slip leaves the manifold.
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers.plane.manifold import DENOMINATOR_MARGIN, manifold_series, series_angle
from stickslip.solvers.plane.resistance import CURVATURE, LAW_SERIES, MU_FAST, MU_SLOW, RATE, driving, \
    friction_coefficient
from stickslip.solvers.plane.state import (
    A1, A2, DISSIPATED, G1, G2, GRAVITY, INPUT, K1, K2, NORMAL_RATE, PATH, TAU, U1, U2, V1, V2, VERTICAL)

#: The slow manifold's series holds while its error estimate, times s, stays within this share of rtol·(s + the floor).
SERIES_TOLERANCE = 1.0
#: A slip joins the slow manifold below this fraction of the series' last speed (it leaves at the speed itself).
SERIES_ENTRY = 0.9


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _manifold_angle(bx, by, rate_x, rate_y, normal, normal_rate, law, phi, speed):
    """The angle Φ [rad] of the sliding velocity from −b/|b| on the slow manifold at the speed ``speed`` [m/s].

    The series (:func:`~stickslip.solvers.plane.manifold.manifold_series`) is taken to the order ``phi[0]``
    that :func:`settled_plan` chose for the step.
    """
    order = manifold_series(bx, by, rate_x, rate_y, normal, normal_rate, law[LAW_SERIES:], int(phi[0]), phi)
    return series_angle(phi, order, speed)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def rhs_settled(y, segment, law, phi, out, row):
    """The right-hand side d y/dt of a slip on the slow manifold into ``out[row]``.

    :func:`~stickslip.solvers.plane.stepping.rhs` in the regime SETTLED: y[V1] is the speed.
    """
    tau = y[TAU]
    gx = segment[G1] + tau * (segment[A1] + 0.5 * segment[K1] * tau)
    gy = segment[G2] + tau * (segment[A2] + 0.5 * segment[K2] * tau)
    bx, by, rate_x, rate_y, normal = driving(segment, law, y[TAU], y[U1], y[U2])
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


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def _series_speed(coefficient, power, allowed, v_scale):
    """The largest speed s [m/s] with |coefficient|·s^(power + 1) ≤ allowed·(s + v_scale), from below."""
    if coefficient == 0.0:
        return math.inf
    size = abs(coefficient)
    return max((allowed / size) ** (1.0 / power), (allowed * v_scale / size) ** (1.0 / (power + 1)))


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def settled_plan(y, speed, segment, law, phi, rtol, v_scale, order):
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
    bx, by, rate_x, rate_y, normal = driving(segment, law, y[TAU], y[U1], y[U2])
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
def settled_reach(segment, law, y, span):
    """How long [s] from y[TAU], at most ``span``, the slow manifold keeps its first denominator, u held.

    The series holds while D₁ = 2|b| − μ(0)·n exceeds
    :data:`~stickslip.solvers.plane.manifold.DENOMINATOR_MARGIN`·μ(0)·n:
    where |b| falls towards zero the direction no longer relaxes onto −b/|b|
    (and −b/|b| turns over where b passes zero), so a step on the manifold must
    end before.  With u held b and n are linear in time, and
    q(t) = 4|b|² − ((1 + margin)·μ(0)·n)² is a quadratic whose first
    down-crossing ends the reach (u moves by s·t meanwhile, which the step's
    next plan sees).
    """
    bx, by, rx, ry, normal = driving(segment, law, y[TAU], y[U1], y[U2])
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
def first_order_angle(y, speed, segment, law, phi):
    """The slow manifold's angle [rad] at the speed ``speed`` [m/s] to first order, φ₁·s (0 where it does not hold)."""
    bx, by, rate_x, rate_y, normal = driving(segment, law, y[TAU], y[U1], y[U2])
    order = manifold_series(bx, by, rate_x, rate_y, normal, segment[NORMAL_RATE], law[LAW_SERIES:], 1, phi)
    return phi[1] * speed if order > 0 else 0.0


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def direction_angle(y, segment, law):
    """The angle [rad] of the sliding velocity y[V1:V2] from −b/|b| at y (π where b = 0)."""
    bx, by, _, _, _ = driving(segment, law, y[TAU], y[U1], y[U2])
    if bx == 0.0 and by == 0.0:
        return math.pi
    return math.atan2(-bx * y[V2] + by * y[V1], -(bx * y[V1] + by * y[V2]))


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def settled_velocity(y, speed, angle, segment, law):
    """Set y[V1:V2] to the velocity of speed ``speed`` [m/s] at ``angle`` [rad] from −b/|b| at y."""
    bx, by, _, _, _ = driving(segment, law, y[TAU], y[U1], y[U2])
    size = math.sqrt(bx * bx + by * by)
    ux = bx / size
    uy = by / size
    cos_phi = math.cos(angle)
    sin_phi = math.sin(angle)
    y[V1] = -(ux * cos_phi - uy * sin_phi) * speed
    y[V2] = -(ux * sin_phi + uy * cos_phi) * speed
