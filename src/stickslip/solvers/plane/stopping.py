"""The stopping regime: the last of a slow slip off its slow manifold, in closed form.

Below s_lock = ``lock_ratio``·S off the manifold, with |b| < μ(0)·n, over the
remaining time to the stop, of order s/(μ·n − |b|), b and n are held at their
values and the slip has a closed form in σ (docs/solvers.md derives it); it is
taken only where its estimated error is below the tolerance
(:func:`quick_stop`), and straight stops (v against −b/|b|, as in one
dimension) are polynomials in time.
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers import closed_forms
from stickslip.solvers.plane.resistance import CURVATURE, MU_FAST, MU_SLOW, RATE, driving
from stickslip.solvers.plane.state import (
    A1, A2, DISSIPATED, G1, G2, GRAVITY, INPUT, K1, K2, NORMAL_RATE, PATH, TAU, U1, U2, V1, V2, VERTICAL)

#: The first τ > 0 [s] where a quadratic velocity reaches zero (:func:`stickslip.solvers.closed_forms.first_stop_time`).
first_stop_time = numba.njit(cache=True)(closed_forms.first_stop_time)


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def quick_stop(y, segment, law, within, tolerance):
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
    bx, by, kx, ky, normal = driving(segment, law, y[TAU], y[U1], y[U2])
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
