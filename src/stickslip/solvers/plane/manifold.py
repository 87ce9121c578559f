"""The slow manifold of the sliding direction in the plane: its series in the speed, to third order.

A block that slides slowly in the plane turns its velocity towards the force
that drives it at the rate |b|/s (s the speed, −b the driving acceleration:
the ground's and the restoring force's, per unit mass), far faster than
anything else changes.  Its direction then lies on the slow manifold: the
angle φ of the velocity from −b/|b| is a function of the speed and of time,

    Φ(s, t) = φ₁(t)·s + φ₂(t)·s² + φ₃(t)·s³ + …,

whose coefficients follow one from the other by equating powers of s in the
equation of the angle (docs/solvers.md, "The slow manifold of the direction"):

    φ_{p+1}·D_{p+1} = −φ̇_p − Σ_{j=1..p} j·φ_j·d_{p+1−j} − |b|·ρ_{p+1},   D_p = (p + 1)·|b| − p·μ₀·n,

with φ₁ = −Ω/D₁, Ω the rate [rad/s] at which b turns, n the normal force per
unit mass [m/s²], μ(s) = μ₀ + μ₁·s + … the friction law, d_i = |b|·γ_i −
n·μ_i, and γ_i, ρ_i the coefficients of s^i in cos Φ and in sin Φ − Φ.  φ̇_p
is the derivative in time at a fixed position of the block: b is then linear
in time (b = a + κ·n·u with a and n linear between samples), so the
coefficients and their derivatives have closed forms
(:func:`manifold_series`).  The displacement u of a block on a curved surface
(curvature κ) enters b; its own rate u̇ = v is of order s and first enters
φ₃, so on a curved surface the series stops at φ₂.

All functions are numba kernels over plain floats and arrays.  They allocate
nothing, and are compiled without numba's reference counting of arrays
(``_nrt=False``), which costs a third of the plane solver's time otherwise.
"""

from __future__ import annotations

import math

import numba

#: The order of the series on a flat surface, the highest :func:`manifold_series` computes.
FLAT_ORDER = 3
#: The order on a curved surface: beyond it the block's own displacement rate enters the coefficients.
CURVED_ORDER = 2
#: Each denominator D_p = (p + 1)·|b| − p·μ₀·n must exceed this fraction of μ₀·n for φ_p to be kept.
DENOMINATOR_MARGIN = 0.2


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def friction_series(mu_slow, mu_fast, rate, order, out):
    """Taylor coefficients μ_j [(s/m)^j] of μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} at s = 0, j = 0..order.

    ``rate`` [s/m]; Coulomb friction (μ_fast = μ_slow) has μ_j = 0 for j ≥ 1.
    """
    out[0] = mu_slow
    term = mu_fast - mu_slow
    for j in range(1, order + 1):
        term *= -rate / j
        out[j] = -term


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def manifold_series(bx, by, rate_x, rate_y, normal, normal_rate, friction, order, phi):
    """The coefficients φ_j [rad·(s/m)^j] of the slow manifold's angle, j = 1..order (order ≤ 3), into ``phi``.

    ``(bx, by)`` [m/s²] is the driving acceleration b (the block is driven
    along −b), ``(rate_x, rate_y)`` [m/s³] its rate at a fixed position of the
    block, ``normal`` [m/s²] and ``normal_rate`` [m/s³] the normal force per
    unit mass and its rate, ``friction`` the Taylor coefficients of μ(s)
    (:func:`friction_series`).  Returns the number of coefficients that hold:
    the largest K ≤ ``order`` with every denominator D_p = (p + 1)·|b| −
    p·μ₀·n, p ≤ K, above :data:`DENOMINATOR_MARGIN`·μ₀·n (the direction
    relaxes faster than the speed changes); 0 where |b| = 0.

    At a fixed position b is linear in time, so with r = |b|, P = b·ḃ,
    W = |ḃ|², C = b × ḃ (constant): ṙ = P/r, r̈ = (W − ṙ²)/r, Ω = C/r²,
    Ω̇ = −2Ω·ṙ/r, Ω̈ = −2(Ω̇·ṙ + Ω·r̈ − Ω·ṙ²/r)/r.  With D_p = (p + 1)·r −
    p·μ₀·n, each φ_p·D_p = N_p differentiates into φ̇_p·D_p + φ_p·Ḋ_p = Ṅ_p:
    φ₁ = −Ω/D₁, φ₂ = −(φ̇₁ − n·μ₁·φ₁)/D₂,
    φ₃ = (−φ̇₂ − φ₁·d₂ − 2φ₂·d₁ + r·φ₁³/6)/D₃ with d₁ = −n·μ₁,
    d₂ = −r·φ₁²/2 − n·μ₂.  The same denominators' margins as
    :func:`manifold_series` decide the order kept.
    """
    size2 = bx * bx + by * by
    mu_0 = friction[0]
    limit = mu_0 * normal
    if size2 == 0.0 or limit <= 0.0:
        return 0
    size = math.sqrt(size2)
    first = 2.0 * size - limit
    if first < DENOMINATOR_MARGIN * limit:
        return 0
    turn = (bx * rate_y - by * rate_x) / size2
    phi[1] = -turn / first
    second = 3.0 * size - 2.0 * limit
    if order < 2 or second < DENOMINATOR_MARGIN * limit:
        return 1
    size_rate = (bx * rate_x + by * rate_y) / size
    turn_rate = -2.0 * turn * size_rate / size
    first_rate = 2.0 * size_rate - mu_0 * normal_rate
    phi_1_rate = -(turn_rate + phi[1] * first_rate) / first
    numerator = phi_1_rate - normal * friction[1] * phi[1]
    phi[2] = -numerator / second
    third = 4.0 * size - 3.0 * limit
    if order < 3 or third < DENOMINATOR_MARGIN * limit:
        return 2
    size_acceleration = (rate_x * rate_x + rate_y * rate_y - size_rate * size_rate) / size
    turn_acceleration = -2.0 * (turn_rate * size_rate + turn * size_acceleration
                                - turn * size_rate * size_rate / size) / size
    phi_1_acceleration = -(turn_acceleration + 2.0 * phi_1_rate * first_rate
                           + 2.0 * phi[1] * size_acceleration) / first
    numerator_rate = (phi_1_acceleration - normal_rate * friction[1] * phi[1]
                      - normal * friction[1] * phi_1_rate)
    phi_2_rate = -(numerator_rate + phi[2] * (3.0 * size_rate - 2.0 * mu_0 * normal_rate)) / second
    rate_1 = -normal * friction[1]
    rate_2 = -0.5 * size * phi[1] * phi[1] - normal * friction[2]
    phi[3] = (-phi_2_rate - phi[1] * rate_2 - 2.0 * phi[2] * rate_1 + size * phi[1] ** 3 / 6.0) / third
    return 3


@numba.njit(cache=True, error_model="numpy", _nrt=False)
def series_angle(phi, order, speed):
    """Φ(s) = Σ_{j=1..order} φ_j·s^j [rad] at the speed ``speed`` [m/s] (Horner)."""
    total = 0.0
    for j in range(order, 0, -1):
        total = (total + phi[j]) * speed
    return total
