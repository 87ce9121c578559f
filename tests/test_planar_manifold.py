"""The slow manifold of the sliding direction: its closed-form series against the direction of an integrated slip.

A slow slip integrated in the Sundman time σ (dt = s·dσ, in which the
direction relaxes at the rate |b|, not |b|/s) to a relative tolerance of
1e-13 leaves any initial direction for its slow manifold; once the start is
forgotten, the series Φ(s, t) = φ₁·s + φ₂·s² + φ₃·s³ of
:func:`stickslip.solvers.plane.manifold.manifold_series` must give its angle,
each order more closely than the one before.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.solvers.plane.manifold import friction_series, manifold_series, series_angle

G = 9.81


def friction(speed: float, mu_slow: float, mu_fast: float, rate: float) -> float:
    return mu_fast - (mu_fast - mu_slow) * math.exp(-rate * speed)


def slow_slip(ground, ground_rate, normal, normal_rate, law, curvature, start):
    """A slip from speed ``start`` [m/s] at 0.3 rad off −b/|b|, in σ: state (s, φ, t, u₁, u₂), dense output.

    b = a + κ·n·u with a = ``ground`` + ``ground_rate``·t [m/s²] and n = ``normal`` + ``normal_rate``·t [m/s²];
    φ is the angle of the velocity from −b/|b|.
    """
    def rhs(_, state):
        s, phi, t, u1, u2 = state
        n = normal + normal_rate * t
        b = ground + ground_rate * t + curvature * n * np.array([u1, u2])
        b_rate = ground_rate + curvature * normal_rate * np.array([u1, u2])
        size = math.hypot(*b)
        heading = math.atan2(-b[1], -b[0]) + phi
        velocity = s * np.array([math.cos(heading), math.sin(heading)])
        b_rate = b_rate + curvature * n * velocity  # u̇ = v moves b on a curved surface
        turn = (b[0] * b_rate[1] - b[1] * b_rate[0]) / size**2
        return [s * (size * math.cos(phi) - friction(s, *law) * n), -size * math.sin(phi) - s * turn, s,
                s * velocity[0], s * velocity[1]]

    return solve_ivp(rhs, (0.0, 80.0), [start, 0.3, 0.0, 0.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-22,
                     dense_output=True)


@pytest.mark.parametrize(("normal_rate", "law", "curvature", "order", "fastest"), [
    (0.0, (0.1, 0.1, 0.0), 0.0, 3, 3e-4),         # Coulomb, no vertical motion
    (-5.0, (0.1, 0.15, 20.0), 0.0, 3, 3e-4),      # velocity-dependent friction, a vertical motion
    (3.0, (0.1, 0.1, 0.0), 1.0 / 2.0, 2, 1e-4),  # a spherical dish of radius 2 m: the series stops at φ₂
])
def test_the_series_gives_the_angle_of_a_slip_that_has_forgotten_its_start(normal_rate, law, curvature, order,
                                                                          fastest):
    ground = np.array([1.05, 0.1])
    ground_rate = np.array([-3.0, 20.0])  # b turns at about 20 rad/s: φ₁·s is 1e-3 to 1e-2 here
    slip = slow_slip(ground, ground_rate, G, normal_rate, law, curvature, start=1e-6)
    coefficients = np.zeros(4)
    friction_terms = np.zeros(4)
    friction_series(*law, 3, friction_terms)
    residuals = []
    sigmas = np.linspace(30.0, slip.t[-1], 4000)  # the start, 0.3 rad off, has decayed by e^{-|b|·σ} < 1e-13
    speeds = slip.sol(sigmas)[0]
    for speed in np.geomspace(fastest / 15.0, fastest, 5):
        s, phi, t, u1, u2 = slip.sol(sigmas[np.argmin(np.abs(speeds - speed))])
        n = G + normal_rate * t
        b = ground + ground_rate * t + curvature * n * np.array([u1, u2])
        b_rate = ground_rate + curvature * normal_rate * np.array([u1, u2])
        kept = manifold_series(b[0], b[1], b_rate[0], b_rate[1], n, normal_rate, friction_terms, order, coefficients)
        assert kept == order
        residuals.append([abs(phi - series_angle(coefficients, k, s)) for k in range(1, order + 1)]
                         + [abs(coefficients[1] * s), s])
    residuals = np.array(residuals)
    speeds = residuals[:, -1]
    assert np.all(residuals[:, 0] < 0.1 * residuals[:, -2])  # φ₁·s: the angle to first order
    for k in range(1, order):
        assert np.all(residuals[:, k] < 0.2 * residuals[:, k - 1]), (k, residuals)
    for k in range(order):  # the series cut after φ_{k+1} errs by O(s^(k+2)): it vanishes as the slip slows
        assert residuals[0, k] < (speeds[0] / speeds[-1]) ** (k + 1) * residuals[-1, k], (k, residuals)
    assert np.max(residuals[:, order - 1]) < {3: 1e-8, 2: 1e-6}[order]


def test_the_friction_law_s_taylor_coefficients():
    terms = np.zeros(5)
    friction_series(0.05, 0.12, 20.0, 4, terms)
    speed = 1e-4  # the next term, 0.07·(rate·s)⁵/5!, is 2e-17
    series = sum(terms[j] * speed**j for j in range(5))
    assert abs(series - friction(speed, 0.05, 0.12, 20.0)) < 1e-15
    friction_series(0.05, 0.05, 20.0, 4, terms)
    assert list(terms) == [0.05, 0.0, 0.0, 0.0, 0.0]
