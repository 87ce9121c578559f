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

Then OpenSees judges our exact solver (``stickslip.solve`` of the models
``isolated`` and ``friction-tmd``, T = 0.5 s and 1.0 s, ζ = 0.02) as kInit
grows, the bearing's stretch at the friction force u_y = μN/kInit from 1e-4
to 1e-6 m: the peak slip (the isolator's displacement, the damper's stroke),
the peak story drift and floor acceleration (OpenSees's over its steps, ours
over the samples, search points and events) and E_df.  Measured (12 OpenSees
runs in 15 s), relative differences at u_y = 1e-4 / 1e-5 / 1e-6 m:

| case | peak slip | peak drift | peak floor acceleration | E_df |
| --- | --- | --- | --- | --- |
| isolated, 1 story, flat, μ = 0.06 | −1.1e-1 / −1.6e-2 / −1.6e-3 | 5.1e-3 / −5.0e-3 / −1.5e-3 | 4.8e-3 / −5.3e-3 / −1.8e-3 | 1.3e-2 / 2.8e-3 / 5.1e-4 |
| isolated, 2 stories, flat, μ = 0.1 | 3.9e-2 / 4.9e-3 / 1.7e-4 | −1.9e-2 / −2.2e-3 / 1.4e-4 | 1.9e-2 / 2.4e-3 / 4.9e-4 | 1.2e-2 / 1.8e-3 / 1.1e-4 |
| damper, 1 story, flat, μ = 0.1 | −5.1e-2 / −1.9e-2 / −7.3e-3 | −8.9e-4 / −2.5e-4 / −7.4e-5 | −8.5e-4 / −2.0e-4 / −3.0e-5 | 1.5e-2 / 4.9e-3 / 1.5e-3 |
| damper, 3 stories, R_d = 4 m, μ = 0.05 | 4.1e-3 / 1.7e-3 / −1.8e-4 | −4.0e-7 / −3.3e-5 / −4.5e-5 | 3.9e-4 / 4.4e-4 / 1.8e-4 | 7.2e-3 / 3.7e-3 / 2.4e-3 |

OpenSees dissipates more (its regularised stick chatters), as in the other
oracles.  A ``singleFPBearing`` under the isolated building (R = 2 and 4 m,
μ = 0.06) failed to converge in OpenSees on this record (HHT α = 0.7,
KrylovNewton, 0.5 ms and then 0.05 ms steps: "domain failed in update" from
5 s on, the bearing's inner iteration on its normal force), so the isolated
building is judged on flat sliders here; the curved bearing is judged under
the damper, and without friction under the building above.
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
#: The largest relative difference allowed at the stiffest bearing (measured in the module docstring).
TOLERANCE = 0.01


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


#: The cases judged against our exact solver: (name, model, its parameters, stories); the buildings as above.
CASES = (
    ("isolated, 1 story, flat, mu = 0.06", "isolated",
     {"superstructure_period": 0.5, "mass_ratio": STRUCTURE_MASS / BASE_MASS, "mu": 0.06}),
    ("isolated, 2 stories, flat, mu = 0.1", "isolated",
     {"superstructure_period": 0.5, "stories": 2, "mass_ratio": STRUCTURE_MASS / BASE_MASS, "mu": 0.1}),
    ("damper, 1 story, flat, mu = 0.1", "friction-tmd",
     {"structure_period": 1.0, "mass_ratio": DAMPER_MASS / STRUCTURE_MASS, "mu": 0.1}),
    ("damper, 3 stories, R_d = 4 m, mu = 0.05", "friction-tmd",
     {"structure_period": 1.0, "stories": 3, "mass_ratio": DAMPER_MASS / STRUCTURE_MASS, "radius": 4.0, "mu": 0.05}),
)
#: The bearing's elastic stretch at the friction force, μN/kInit [m], softest to stiffest.
YIELD_DISPLACEMENTS = (1e-4, 1e-5, 1e-6)
MEASURES = ("peak_slip", "peak_drift", "peak_floor_acceleration", "energy_dissipated")


@pytest.fixture(scope="module")
def convergence(ground) -> list[dict]:
    """One row per case: our answers and OpenSees's relative differences at each yield displacement."""
    import stickslip
    from stickslip.records.record import Record

    acceleration, dt = ground
    rows = []
    for name, model, parameters in CASES:
        stories = parameters.get("stories", 1)
        isolated = model == "isolated"
        total = STRUCTURE_MASS + BASE_MASS if isolated else STRUCTURE_MASS
        scalars = stickslip.solve(Record(acceleration, dt), model=model, mass=total, g=G, **parameters).scalars()
        ours = {"peak_slip": scalars["peak_isolator_displacement" if isolated else "peak_damper_stroke"],
                **{measure: scalars[measure] for measure in MEASURES[1:]}}
        period = parameters["superstructure_period" if isolated else "structure_period"]
        structure = uniform_building(stories, period, STRUCTURE_MASS, 0.02)
        radius = parameters.get("radius", np.inf)
        normal = (total if isolated else DAMPER_MASS) * G
        errors = []
        for yield_displacement in YIELD_DISPLACEMENTS:
            stiffness = parameters["mu"] * normal / yield_displacement
            if isolated:
                result = opensees_isolated(structure, BASE_MASS, parameters["mu"], radius, stiffness, acceleration, dt,
                                           G)
                drifts = np.diff(result["floor_displacement"], axis=1, prepend=result["slip"][:, None])
            else:
                result = opensees_damper(structure, DAMPER_MASS, stories, parameters["mu"], radius, stiffness,
                                         acceleration, dt, G)
                drifts = np.diff(result["floor_displacement"], axis=1, prepend=0.0)
            theirs = {"peak_slip": np.max(np.abs(result["slip"])), "peak_drift": np.max(np.abs(drifts)),
                      "peak_floor_acceleration": np.max(np.abs(result["floor_acceleration"])),
                      "energy_dissipated": result["energy_dissipated"]}
            errors.append({measure: theirs[measure] / ours[measure] - 1 for measure in MEASURES})
        rows.append({"case": name, "ours": ours, "errors": errors})
    print("\n| case | u_y [m] | " + " | ".join(f"rel. diff {measure}" for measure in MEASURES) + " |")
    print("| --- | --- |" + " --- |" * len(MEASURES))
    for row in rows:
        for yield_displacement, errors in zip(YIELD_DISPLACEMENTS, row["errors"]):
            print(f"| {row['case']} | {yield_displacement:.0e} | "
                  + " | ".join(f"{errors[measure]:+.1e}" for measure in MEASURES) + " |")
    return rows


@pytest.mark.slow
def test_opensees_converges_to_the_exact_structures_as_the_bearing_stiffens(convergence):
    for row in convergence:
        stiffest = row["errors"][-1]
        for measure in MEASURES:
            assert abs(stiffest[measure]) < TOLERANCE, (row["case"], measure, stiffest[measure])
    for measure in MEASURES:
        worst = [max(abs(row["errors"][index][measure]) for row in convergence)
                 for index in range(len(YIELD_DISPLACEMENTS))]
        assert worst[-1] < worst[0] / 3, (measure, worst)
