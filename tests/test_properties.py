"""Hypothesis properties of the exact solver on small random records."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from stickslip.records.process import resample
from stickslip.records.record import Record
from stickslip.models import solve
from stickslip.models.rigid.exact_scheme import solve_history

G = 9.81
MASS = 5.1

accelerations = arrays(
    np.float64,
    st.integers(min_value=2, max_value=60),
    elements=st.floats(min_value=-20.0, max_value=20.0, allow_nan=False, allow_subnormal=False),
)
time_steps = st.floats(min_value=1e-3, max_value=0.05)
friction_ratios = st.floats(min_value=0.01, max_value=1.0)


def energy_scale(acceleration: np.ndarray, dt: float) -> float:
    """An upper bound of the energies per unit mass, (Σ|a|·dt)² [J/kg], floored to stay positive."""
    return max(float(np.sum(np.abs(acceleration)) * dt) ** 2, 1e-30)


def length_scale(acceleration: np.ndarray, dt: float) -> float:
    """An upper bound of the displacements, Σ|a|·dt·duration [m], floored to stay positive."""
    return max(float(np.sum(np.abs(acceleration)) * dt * dt * acceleration.size), 1e-30)


@settings(max_examples=150, deadline=None)
@given(accelerations, time_steps, friction_ratios)
def test_flipping_the_record_mirrors_the_motion(acceleration, dt, mu):
    forward = solve_history(acceleration, dt, mu, G)
    mirrored = solve_history(-acceleration, dt, mu, G)
    np.testing.assert_array_equal(mirrored.relative_displacement, -forward.relative_displacement)
    np.testing.assert_array_equal(mirrored.phase, -forward.phase)
    np.testing.assert_array_equal(mirrored.energy_dissipated, forward.energy_dissipated)
    np.testing.assert_array_equal(mirrored.energy_input, forward.energy_input)
    assert mirrored.n_slip_episodes == forward.n_slip_episodes


@settings(max_examples=150, deadline=None)
@given(accelerations, time_steps, friction_ratios, st.floats(min_value=0.1, max_value=10.0))
def test_scaling_record_and_mu_by_k_scales_energies_by_k_squared(acceleration, dt, mu, factor):
    base = solve_history(acceleration, dt, mu, G)
    scaled = solve_history(factor * acceleration, dt, factor * mu, G)
    energy_tolerance = 1e-9 * factor**2 * energy_scale(acceleration, dt)
    np.testing.assert_allclose(scaled.energy_dissipated, factor**2 * base.energy_dissipated, rtol=0, atol=energy_tolerance)
    np.testing.assert_allclose(scaled.energy_input, factor**2 * base.energy_input, rtol=0, atol=energy_tolerance)
    np.testing.assert_allclose(
        scaled.relative_displacement,
        factor * base.relative_displacement,
        rtol=0,
        atol=1e-9 * factor * length_scale(acceleration, dt),
    )


@settings(max_examples=150, deadline=None)
@given(accelerations, time_steps, friction_ratios)
def test_dissipation_is_non_negative_non_decreasing_and_balanced(acceleration, dt, mu):
    response = solve(Record(acceleration, dt), mu=mu, mass=MASS, g=G)
    dissipated = response.energy_dissipated_history
    assert dissipated[0] == 0.0
    assert np.all(np.diff(dissipated) >= 0.0)
    assert np.isclose(response.energy_dissipated, mu * MASS * G * response.sliding_path, rtol=1e-14, atol=0)
    assert response.balance_residual <= 1e-9 * MASS * energy_scale(acceleration, dt)
    assert 0.0 <= response.slip_fraction <= 1.0 + 1e-12
    friction_limit = mu * MASS * G
    assert np.max(np.abs(response.friction_force)) <= friction_limit * (1 + 1e-12) + 1e-12


@settings(max_examples=60, deadline=None)
@given(accelerations, time_steps, friction_ratios, st.integers(min_value=2, max_value=7))
def test_resampling_by_an_integer_factor_changes_nothing(acceleration, dt, mu, factor):
    record = Record(acceleration, dt)
    fine_record = resample(record, dt / factor)
    coarse = solve_history(record.acceleration, record.dt, mu, G)
    fine = solve_history(fine_record.acceleration, fine_record.dt, mu, G)
    energy_tolerance = 1e-9 * energy_scale(acceleration, dt)
    assert abs(fine.energy_dissipated[-1] - coarse.energy_dissipated[-1]) <= energy_tolerance
    assert abs(fine.energy_input[-1] - coarse.energy_input[-1]) <= energy_tolerance
    length_tolerance = 1e-9 * length_scale(acceleration, dt)
    assert abs(fine.relative_displacement[-1] - coarse.relative_displacement[-1]) <= length_tolerance
    assert abs(fine.peak_relative_displacement - coarse.peak_relative_displacement) <= length_tolerance
    assert abs(fine.slip_time - coarse.slip_time) <= 1e-9 * record.duration
