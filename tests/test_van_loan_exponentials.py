"""The friction-linked solver's matrix exponentials and Van Loan integrals, in extended precision, against closed
forms: a rotation, a Jordan block, a damped oscillator's energy integral."""

from __future__ import annotations

import math

import numpy as np
import pytest

from stickslip.solvers.structure.friction_linked import _exponential, _van_loan


@pytest.mark.parametrize("angle", [1e-3, 0.4, 3.0, 40.0])
def test_the_exponential_of_a_rotation_s_generator_is_the_rotation(angle):
    exact = np.array([[math.cos(angle), math.sin(angle)], [-math.sin(angle), math.cos(angle)]])
    found = _exponential(np.array([[0.0, angle], [-angle, 0.0]]))
    assert np.max(np.abs(found - exact)) < 4e-16 * max(1.0, angle)


def test_the_exponential_of_a_jordan_block_is_its_polynomial():
    rate, step = -3.0, 0.7
    block = np.array([[rate, 1.0, 0.0], [0.0, rate, 1.0], [0.0, 0.0, rate]]) * step
    decay = math.exp(rate * step)
    exact = decay * np.array([[1.0, step, step ** 2 / 2], [0.0, 1.0, step], [0.0, 0.0, 1.0]])
    assert np.allclose(_exponential(block), exact, rtol=1.6e-15, atol=0.0)


def test_the_van_loan_integral_of_an_oscillator_s_kinetic_energy_is_its_closed_form():
    """x'' + 2ζω x' + ω² x = 0 from (x, v) = (1, 0): ∫₀^δ v² dt in closed form, with the form scaled by 1e6 (its
    units must not matter)."""
    omega, zeta, delta = 12.0, 0.05, 0.3
    matrix = np.array([[0.0, 1.0], [-omega ** 2, -2 * zeta * omega]])
    form = np.diag([0.0, 1e6])
    (step, integral), = _van_loan([(matrix, form)], delta)
    damped = omega * math.sqrt(1 - zeta ** 2)
    time = np.linspace(0.0, delta, 200_001)
    velocity = -omega ** 2 / damped * np.exp(-zeta * omega * time) * np.sin(damped * time)
    # Simpson's rule on a fine grid: exact to far below the tolerance for this smooth integrand
    weights = np.ones(time.size)
    weights[1:-1:2], weights[2:-1:2] = 4.0, 2.0
    expected = 1e6 * (time[1] - time[0]) / 3.0 * np.sum(weights * velocity ** 2)
    assert integral[0, 0] == pytest.approx(expected, rel=1e-12)
    position = math.exp(-zeta * omega * delta) * (math.cos(damped * delta)
                                                   + zeta * omega / damped * math.sin(damped * delta))
    assert step[0, 0] == pytest.approx(position, rel=1e-14)
