"""The friction tuned mass damper against what is known without it: the bare building, the mass attached."""

import math

import numpy as np
import pytest

from stickslip.models.friction_tmd.case import DamperCase
from stickslip.models.friction_tmd.references import (RESPONSES, attached_history, bare_history, reductions,
                                                      reference_answers, structure_answers)
from stickslip.solvers.structure.linear_response import modal_displacements

G = 9.81


def damper(mu=0.1, stories=1, radius=math.inf, story=None, mass_ratio=0.05, period=1.0):
    return DamperCase(mu, period, stories, 0.02, "modal", mass_ratio, radius, story or stories, 2.0e5, G)


def _record(samples=1500, dt=0.01, seed=3):
    rng = np.random.default_rng(seed)
    return np.convolve(rng.normal(0.0, 2.0, samples), np.ones(5) / 5, mode="same"), dt


@pytest.mark.parametrize("stories", [1, 3])
def test_the_bare_building_is_the_modal_closed_form(stories):
    acceleration, dt = _record()
    case = damper(stories=stories)
    modal = modal_displacements(case.building, acceleration, dt)
    answers = reference_answers(case, acceleration, dt)["bare_structure"]
    drifts = np.max(np.abs(np.diff(modal, axis=1, prepend=0.0)), axis=0)
    assert answers["peak_story_drifts"] == pytest.approx(drifts, rel=1e-10)
    assert answers["peak_structure_displacement"] == pytest.approx(np.max(np.abs(modal)), rel=1e-10)
    assert answers["peak_drift"] == max(answers["peak_story_drifts"])


@pytest.mark.parametrize("history", [bare_history, attached_history])
def test_the_base_shear_is_the_inertia_of_the_floors(history):
    """V_b = 1ᵀ(K_b x + C_b ẋ) is the ground's force on the building: −Σ m_i ü_i,abs, the attached mass included."""
    acceleration, dt = _record()
    case = damper(stories=3, story=2, mass_ratio=0.1)
    solved = history(case, acceleration, dt)
    masses = np.diag(case.attached_mass_matrix if history is attached_history else case.building.mass_matrix)
    inertia = np.max(np.abs(solved.absolute_acceleration @ masses)) / (case.building.total_mass * G)
    answers = structure_answers(case.building, *solved, G)
    assert answers["base_shear_coefficient"] == pytest.approx(inertia, rel=1e-10)
    assert answers["peak_floor_accelerations"] == pytest.approx(np.max(np.abs(solved.absolute_acceleration), axis=0))


def test_a_vanishing_attached_mass_is_the_bare_building():
    acceleration, dt = _record()
    answers = reference_answers(damper(stories=2, mass_ratio=1e-14), acceleration, dt)
    for name in RESPONSES:
        assert answers["attached_mass"][name] == pytest.approx(answers["bare_structure"][name], rel=1e-10)


def test_reductions_are_against_each_reference():
    references = {"bare_structure": {name: 2.0 for name in RESPONSES},
                  "attached_mass": {name: 4.0 for name in RESPONSES}}
    found = reductions({name: 1.0 for name in RESPONSES}, references)
    assert found == {**{f"{name}_reduction": 0.5 for name in RESPONSES},
                     **{f"{name}_reduction_attached": 0.75 for name in RESPONSES}}
    still = reductions({name: 0.0 for name in RESPONSES},
                       {key: {name: 0.0 for name in RESPONSES} for key in references})
    assert all(math.isnan(value) for value in still.values())


def test_the_damper_leaves_rest_where_its_floor_needs_more_than_mu_g():
    acceleration, dt = _record()
    case = damper(stories=2, story=2)
    motion = type("Motion", (), {"acceleration": acceleration, "dt": dt})()
    peak = np.max(np.abs(attached_history(case, acceleration, dt).absolute_acceleration[:, 1]))
    assert case.at("mu", 0.99 * peak / G).slides(motion)
    assert not case.at("mu", 1.01 * peak / G).slides(motion)
    assert f"{peak:.4g} m/s2" in case.at("mu", 1.01 * peak / G).still_reason(motion)
