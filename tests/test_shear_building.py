"""The shear building under the sliders: its modes, its damping, and its exact linear response."""

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.solvers.structure.linear_response import linear_history, modal_displacements
from stickslip.solvers.structure.shear_building import ShearBuilding, uniform_building


def _record(samples=1500, dt=0.01, seed=3):
    rng = np.random.default_rng(seed)
    return np.convolve(rng.normal(0.0, 2.0, samples), np.ones(5) / 5, mode="same"), dt


@pytest.mark.parametrize("stories", [1, 3, 8])
def test_uniform_building_has_the_period_it_is_given(stories):
    building = uniform_building(stories, 0.7, 3.0e5, 0.05)
    assert building.periods[0] == pytest.approx(0.7, rel=1e-13)
    assert building.total_mass == pytest.approx(3.0e5, rel=1e-15)
    assert np.all(np.diff(building.periods) < 0)


def test_one_story_is_the_oscillator_of_its_period():
    building = uniform_building(1, 0.5, 2.0, 0.03)
    assert building.stiffness_matrix[0, 0] == pytest.approx(2.0 * (2 * np.pi / 0.5) ** 2, rel=1e-14)
    assert building.damping_matrix[0, 0] == pytest.approx(2 * 0.03 * (2 * np.pi / 0.5) * 2.0, rel=1e-13)


@pytest.mark.parametrize("model", ["modal", "rayleigh"])
def test_damping_gives_the_ratio_to_the_modes_it_names(model):
    building = uniform_building(4, 1.2, 1.0e6, 0.05, model)
    omega, shapes = building.modes
    ratios = np.diag(shapes.T @ building.damping_matrix @ shapes) / (2 * omega)
    named = ratios if model == "modal" else ratios[[0, -1]]
    assert named == pytest.approx(0.05, rel=1e-12)
    if model == "rayleigh":
        assert np.all(ratios[1:-1] < 0.05)


@pytest.mark.parametrize("stories", [1, 2, 5])
def test_state_space_steps_equal_the_modal_closed_form(stories):
    acceleration, dt = _record()
    building = uniform_building(stories, 0.4 * stories, 1.0e5, 0.04)
    history = linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix,
                             np.ones(stories), acceleration, dt)
    modal = modal_displacements(building, acceleration, dt)
    scale = np.abs(modal).max()
    assert np.abs(history.displacement - modal).max() < 1e-10 * scale


def test_absolute_acceleration_is_the_relative_one_plus_the_ground():
    dt = 0.002
    time = np.arange(4000) * dt
    acceleration = 3.0 * np.sin(2 * np.pi * 1.3 * time) + 1.5 * np.sin(2 * np.pi * 3.1 * time)
    building = uniform_building(2, 0.6, 1.0e5, 0.05)
    history = linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix,
                             np.ones(2), acceleration, dt)
    relative = np.gradient(history.velocity, dt, axis=0)
    inner = slice(10, -10)
    difference = history.absolute_acceleration[inner] - (relative[inner] + acceleration[inner, None])
    assert np.abs(difference).max() < 1e-3 * np.abs(history.absolute_acceleration).max()


@pytest.mark.parametrize("masses, stiffnesses, message", [
    ([1.0, 2.0], [1.0], "one floor mass per story stiffness"),
    ([1.0, -2.0], [1.0, 1.0], "floor masses [kg] must be positive"),
    ([1.0], [0.0], "story stiffnesses [N/m] must be positive"),
])
def test_a_building_refuses_what_is_not_one(masses, stiffnesses, message):
    with pytest.raises(StickslipError, match=message.replace("[", r"\[").replace("]", r"\]")):
        ShearBuilding(masses, stiffnesses)


def test_a_building_refuses_a_bad_damping():
    with pytest.raises(StickslipError, match="damping ratio 1.5"):
        uniform_building(2, 0.5, 1.0, 1.5)
    with pytest.raises(StickslipError, match="damping model 'viscous'"):
        uniform_building(2, 0.5, 1.0, 0.02, "viscous")
    with pytest.raises(StickslipError, match="number of stories 0"):
        uniform_building(0, 0.5, 1.0)
