"""OpenSees as an independent oracle for the structures above and below a slider (tests/structure_opensees.py).

First the OpenSees models themselves are held to the linear structures they
become where friction drops out, each computed by stickslip's exact
first-order hold (:func:`~stickslip.solvers.structure.linear_response.linear_history`),
so that the harness is right before it judges a friction solver:

- a bearing that never slides (μ = 1000) carries the fixed-base building;
- a damper that never slides (μ = 1000) is its mass rigidly attached to its floor;
- a damper on a flat surface without friction (μ = 1e-9: OpenSees refuses μ = 0) leaves the bare building;
- without friction, a curved surface of radius R is a linear spring N/R under the base or the damper
  (``singleFPBearing``; to its departures of the order (u/R)², so under a tenth of the record).

In the first two the bearing's regularising spring kInit [N/m] is the only
departure and the difference falls as 1/kInit; what is left at the stiffest
bearing is the integrator's (HHT α = 0.7, 0.5 ms steps).  Measured on the
first 10 s of Northridge NWH-090 (500 samples of 0.02 s), buildings of 0.5 s
and 4e5 kg, base 1e5 kg, damper 2e4 kg on the top floor, largest difference
over the samples relative to the largest value:

| case | kInit [N/m] | floor displacement | floor acceleration |
| --- | --- | --- | --- |
| fixed-base building, 1 story | 1e10 / 1e12 | 3.6e-2 / 4.0e-4 | 3.3e-2 / 3.7e-4 |
| fixed-base building, 3 stories (modal) | 1e10 / 1e12 | 3.2e-2 / 3.6e-4 | 2.6e-2 / 3.3e-4 |
| mass attached, 1 story | 1e9 / 1e11 | 8.5e-4 / 6.0e-5 | 8.5e-4 / 5.9e-5 |
| mass attached, 3 stories (modal) | 1e9 / 1e11 | 1.4e-3 / 6.7e-5 | 1.7e-3 / 1.5e-4 |
| bare building (μ = 1e-9), 1 / 3 stories | 1e6 | 5.1e-5 / 5.0e-5 | 5.0e-5 / 1.4e-4 |
"""

from __future__ import annotations

import numpy as np
import pytest
from structure_opensees import at_samples, opensees_damper, opensees_isolated

from stickslip.records.process import integrate_linear_acceleration
from stickslip.solvers.structure.linear_response import linear_history
from stickslip.solvers.structure.shear_building import uniform_building

pytestmark = pytest.mark.oracle

G = 9.81
#: The superstructure's (or the structure's) mass [kg], the isolated building's base mass [kg], the damper's [kg].
STRUCTURE_MASS, BASE_MASS, DAMPER_MASS = 4.0e5, 1.0e5, 2.0e4
NEVER_SLIDES = 1e3
NO_FRICTION = 1e-9
STORIES = (1, 3)


@pytest.fixture(scope="module")
def ground(paper_records) -> tuple[np.ndarray, float]:
    """The first 10 s of Northridge NWH-090: (acceleration [m/s²], dt [s])."""
    record = paper_records["SLAMMER_Northridge_1994_NWH-090.txt"]
    return record.acceleration[:500], record.dt


def difference(values: np.ndarray, reference: np.ndarray) -> float:
    """The largest |values − reference| over the reference's largest |value|."""
    return float(np.max(np.abs(values - reference)) / np.max(np.abs(reference)))


def building(stories: int):
    """A uniform building of 0.5 s, 5 % modal damping (on 3 stories its dashpots include negative ones)."""
    return uniform_building(stories, 0.5, STRUCTURE_MASS, 0.05)


def linear(structure, mass_matrix, ground) -> object:
    acceleration, dt = ground
    return linear_history(mass_matrix, structure.damping_matrix, structure.stiffness_matrix,
                          np.ones(structure.stories), acceleration, dt)


@pytest.mark.slow
@pytest.mark.parametrize("stories", STORIES)
def test_a_bearing_that_never_slides_carries_the_fixed_base_building(ground, stories):
    structure = building(stories)
    fixed = linear(structure, structure.mass_matrix, ground)
    errors = []
    for stiffness in (1e10, 1e12):
        result = opensees_isolated(structure, BASE_MASS, NEVER_SLIDES, np.inf, stiffness, *ground, G)
        shear = -fixed.absolute_acceleration @ structure.floor_masses
        errors.append([difference(at_samples(result, "floor_displacement"), fixed.displacement),
                       difference(at_samples(result, "floor_acceleration"), fixed.absolute_acceleration),
                       difference(at_samples(result, "story_shear"), shear)])
    assert np.all(np.array(errors[1]) < 5e-4), errors
    assert np.all(np.array(errors[0]) > 50 * np.array(errors[1])), errors  # the spring's stretch, as 1/kInit


@pytest.mark.slow
@pytest.mark.parametrize("stories", STORIES)
def test_a_damper_that_never_slides_is_its_mass_attached(ground, stories):
    structure = building(stories)
    attached = structure.mass_matrix.copy()
    attached[-1, -1] += DAMPER_MASS
    reference = linear(structure, attached, ground)
    errors = []
    for stiffness in (1e9, 1e11):
        result = opensees_damper(structure, DAMPER_MASS, stories, NEVER_SLIDES, np.inf, stiffness, *ground, G)
        errors.append([difference(at_samples(result, "floor_displacement"), reference.displacement),
                       difference(at_samples(result, "floor_acceleration"), reference.absolute_acceleration),
                       difference(at_samples(result, "story_shear"),
                                  -reference.absolute_acceleration @ np.diag(attached))])
        assert np.max(np.abs(result["slip"])) < 10 * NEVER_SLIDES * DAMPER_MASS * G / stiffness
    assert np.all(np.array(errors[1]) < 2e-4), errors
    assert np.all(np.array(errors[0]) > 5 * np.array(errors[1])), errors


@pytest.mark.slow
@pytest.mark.parametrize("stories", STORIES)
def test_a_damper_without_friction_leaves_the_bare_building(ground, stories):
    structure = building(stories)
    bare = linear(structure, structure.mass_matrix, ground)
    result = opensees_damper(structure, DAMPER_MASS, stories, NO_FRICTION, np.inf, 1e6, *ground, G)
    assert difference(at_samples(result, "floor_displacement"), bare.displacement) < 1e-4
    assert difference(at_samples(result, "floor_acceleration"), bare.absolute_acceleration) < 2e-4
    assert abs(result["energy_dissipated"]) < 1e-3  # J: μ·N·(path) = 1e-9 · 2e5 N · a few m
    # nothing pushes the damper: it stays where it was in space, at −u_g relative to the ground
    _, ground_displacement = integrate_linear_acceleration(*ground)
    damper = at_samples(result, "slip") + at_samples(result, "floor_displacement")[:, -1]
    assert difference(damper, -ground_displacement) < 1e-4


@pytest.mark.slow
@pytest.mark.parametrize("stories", STORIES)
def test_without_friction_a_curved_surface_is_a_linear_spring_of_n_over_r(ground, stories):
    """On a surface of radius R without friction the bearing is a spring N/R [N/m]: the isolated building is a
    linear structure on it, the damper a linear tuned mass damper.  OpenSees's singleFPBearing departs from that
    by terms of the order (u/R)²: under 10 % of the record (u/R about 0.03) by 1.6e-4 (the base's displacement)
    and 1.2e-3 (the damper's stroke), measured; under the whole record (u/R about 0.2 and 0.35) by 1.6e-2 and 0.11."""
    acceleration, dt = 0.1 * ground[0], ground[1]
    structure = building(stories)
    n = stories
    # the isolated building: x = (u_b, u_1 … u_n), the stories on the base, the bearing N/R at the base
    floors_on_base = np.hstack([-np.ones((n, 1)), np.eye(n)])
    stiffness = floors_on_base.T @ structure.stiffness_matrix @ floors_on_base
    stiffness[0, 0] += (BASE_MASS + STRUCTURE_MASS) * G / 2.0
    isolated = linear_history(np.diag(np.r_[BASE_MASS, structure.floor_masses]),
                              floors_on_base.T @ structure.damping_matrix @ floors_on_base, stiffness,
                              np.ones(n + 1), acceleration, dt)
    result = opensees_isolated(structure, BASE_MASS, NO_FRICTION, 2.0, 1e6, acceleration, dt, G)
    assert difference(at_samples(result, "slip"), isolated.displacement[:, 0]) < 3e-4
    assert difference(at_samples(result, "floor_displacement"), isolated.displacement[:, 1:]) < 3e-4
    assert difference(at_samples(result, "floor_acceleration"), isolated.absolute_acceleration[:, 1:]) < 6e-4
    # the damper: x = (u_1 … u_n, u_d), the spring m_d g/R_d between the top floor and the damper
    slip = np.r_[np.zeros(n - 1), -1.0, 1.0]
    stiffness, damping = np.zeros((n + 1, n + 1)), np.zeros((n + 1, n + 1))
    stiffness[:n, :n], damping[:n, :n] = structure.stiffness_matrix, structure.damping_matrix
    stiffness += DAMPER_MASS * G / 1.0 * np.outer(slip, slip)
    tuned = linear_history(np.diag(np.r_[structure.floor_masses, DAMPER_MASS]), damping, stiffness,
                           np.ones(n + 1), acceleration, dt)
    result = opensees_damper(structure, DAMPER_MASS, n, NO_FRICTION, 1.0, 1e6, acceleration, dt, G)
    assert difference(at_samples(result, "slip"), tuned.displacement @ slip) < 2e-3
    assert difference(at_samples(result, "floor_displacement"), tuned.displacement[:, :n]) < 2e-4
    assert difference(at_samples(result, "floor_acceleration"), tuned.absolute_acceleration[:, :n]) < 3e-4
