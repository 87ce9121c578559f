"""The friction tuned mass damper against what is known without it.

Each limit is a linear structure solved by the first-order hold of
``linear_history``, independently of the friction-linked solver: without
friction on a flat surface the damper leaves the bare building (and stays
where it was in space); held (μ → ∞) it is its mass attached to its floor;
without friction on a curved surface it is a linear tuned mass damper, a
spring N/R_d to its floor.  Then the ledger, the sweep against the solves,
the references and reductions, and when the damper leaves rest.
"""

import math

import numpy as np
import pytest

import stickslip
from stickslip.models.friction_tmd.case import DamperCase
from stickslip.models.friction_tmd.references import RESPONSES, reductions
from stickslip.models.friction_tmd.solve import solve_motion
from stickslip.models.parameters import HELD
from stickslip.records.process import integrate_linear_acceleration
from stickslip.records.record import Record, RecordMeta
from stickslip.solvers.structure.linear_response import linear_history

G = 9.81
MASS = 2.0e5


def damper(mu=0.1, stories=1, radius=math.inf, story=None, mass_ratio=0.05, period=1.0):
    return DamperCase(mu, period, stories, 0.02, "modal", mass_ratio, radius, story or stories, MASS, G)


@pytest.fixture(scope="module")
def record() -> Record:
    rng = np.random.default_rng(3)
    return Record(np.convolve(rng.normal(0.0, 3.0, 1500), np.ones(5) / 5, mode="same"), 0.01,
                  RecordMeta(record_id="noise"))


def difference(values, reference) -> float:
    return float(np.max(np.abs(np.asarray(values) - reference)) / np.max(np.abs(reference)))


def solved(case, record):
    return solve_motion(record, case, "exact")


@pytest.mark.parametrize("stories, story", [(1, 1), (3, 3), (3, 2)])
def test_without_friction_on_a_flat_surface_the_building_is_bare(record, stories, story):
    case = damper(0.0, stories, story=story)
    response = solved(case, record)
    building = case.building
    bare = linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix,
                          np.ones(stories), record.acceleration, record.dt)
    assert difference(response.history["floor_displacement"], bare.displacement) < 1e-10
    assert difference(response.history["floor_acceleration"], bare.absolute_acceleration) < 1e-10
    _, ground = integrate_linear_acceleration(record.acceleration, record.dt)
    history = response.history
    damper_displacement = history["relative_displacement"] + history["floor_displacement"][:, story - 1]
    assert difference(damper_displacement, -ground) < 1e-10  # nothing pushes it: it stays where it was
    scalars = response.scalars()
    assert scalars["energy_dissipated"] == 0.0
    for name in RESPONSES:
        assert scalars[f"{name}_reduction"] == pytest.approx(0.0, abs=1e-10), name


@pytest.mark.parametrize("stories, story, radius", [(1, 1, math.inf), (3, 3, 2.0), (3, 2, math.inf)])
def test_held_the_damper_is_its_mass_attached(record, stories, story, radius):
    case = damper(HELD, stories, radius, story)
    response = solved(case, record)
    building = case.building
    attached = linear_history(case.attached_mass_matrix, building.damping_matrix, building.stiffness_matrix,
                              np.ones(stories), record.acceleration, record.dt)
    assert difference(response.history["floor_displacement"], attached.displacement) < 1e-10
    assert difference(response.history["floor_acceleration"], attached.absolute_acceleration) < 1e-10
    assert np.max(np.abs(response.history["relative_displacement"])) < 1e-10 * np.max(np.abs(attached.displacement))
    scalars = response.scalars()
    assert (scalars["n_slip_episodes"], scalars["energy_dissipated"]) == (0, 0.0)
    for name in RESPONSES:
        assert scalars[f"{name}_reduction_attached"] == pytest.approx(0.0, abs=1e-10), name
        assert response.references["attached_mass"][name] == pytest.approx(scalars[name], rel=1e-10)
    assert response.never_slides.startswith(f"holding the damper on floor {story} needs at most")


@pytest.mark.parametrize("stories", [1, 3])
def test_without_friction_on_a_curved_surface_it_is_a_linear_tuned_mass_damper(record, stories):
    case = damper(0.0, stories, radius=1.5)
    response = solved(case, record)
    d = case.slip_vector
    tuned = linear_history(case.mass_matrix, case.damping_matrix,
                           case.stiffness_matrix + case.normal_force / 1.5 * np.outer(d, d),
                           np.ones(stories + 1), record.acceleration, record.dt)
    assert difference(response.history["floor_displacement"], tuned.displacement[:, :stories]) < 1e-10
    assert difference(response.history["relative_displacement"], tuned.displacement @ d) < 1e-10
    assert difference(response.history["floor_acceleration"], tuned.absolute_acceleration[:, :stories]) < 1e-10


@pytest.mark.parametrize("stories, radius", [(1, math.inf), (3, 2.0)])
def test_the_ledger_closes_to_round_off(paper_records, stories, radius):
    northridge = paper_records["SLAMMER_Northridge_1994_NWH-090.txt"]
    for mu in (0.02, 0.1, 0.3):
        response = stickslip.solve(northridge, model="friction-tmd", structure_period=1.0, stories=stories,
                                   radius=radius, mu=mu, mass=MASS)
        scalars = response.scalars()
        assert scalars["n_slip_episodes"] > 0 and scalars["energy_dissipated"] > 0
        assert scalars["balance_residual"] < 1e-11 * scalars["energy_input"], (mu, scalars)
        ledger = response.energy_ledger()
        assert list(ledger) == ["energy_input", "energy_dissipated", "kinetic_energy", "strain_energy",
                                "viscous_energy", "potential_energy", "balance_residual"]
        closing = (ledger["kinetic_energy"] - ledger["kinetic_energy"][0] + ledger["strain_energy"]
                   + ledger["viscous_energy"] + ledger["potential_energy"] + ledger["energy_dissipated"]
                   - ledger["energy_input"])
        np.testing.assert_allclose(closing, ledger["balance_residual"], rtol=0, atol=1e-9 * scalars["energy_input"])
        if math.isinf(radius):
            assert np.all(ledger["potential_energy"] == 0.0)


def test_a_sweep_holds_the_solves_of_its_cases(record):
    mus = [0.02, 0.1, 0.4]
    parameters = {"structure_period": 0.8, "stories": 2, "radius": 3.0, "mass_ratio": 0.08}
    cube = stickslip.sweep([record], model="friction-tmd", mu=mus, **parameters)
    assert cube.attrs["model"] == "friction-tmd" and float(cube.attrs["radius"]) == 3.0
    for index, mu in enumerate(mus):
        scalars = stickslip.solve(record, model="friction-tmd", mu=mu, **parameters).scalars()
        for name in ("energy_dissipated", "peak_damper_stroke", "residual_damper_stroke", "peak_drift",
                     "peak_floor_acceleration", "base_shear_coefficient", "peak_drift_reduction",
                     "base_shear_coefficient_reduction_attached", "n_slip_episodes"):
            assert float(cube[name].values[0, index]) == pytest.approx(scalars[name], rel=1e-10, abs=1e-14), name


def test_reductions_are_against_each_reference():
    references = {"bare_structure": {name: 2.0 for name in RESPONSES},
                  "attached_mass": {name: 4.0 for name in RESPONSES}}
    found = reductions({name: 1.0 for name in RESPONSES}, references)
    assert found == {**{f"{name}_reduction": 0.5 for name in RESPONSES},
                     **{f"{name}_reduction_attached": 0.75 for name in RESPONSES}}
    still = reductions({name: 0.0 for name in RESPONSES},
                       {key: {name: 0.0 for name in RESPONSES} for key in references})
    assert all(np.isnan(value) for value in still.values())


def test_the_damper_leaves_rest_where_holding_it_needs_more_than_mu_n(record):
    case = damper(stories=2)
    ratio = case.holding_ratio(record)
    assert case.at("mu", 0.99 * ratio).slides(record)
    assert not case.at("mu", 1.01 * ratio).slides(record)
    assert solved(case.at("mu", 0.99 * ratio), record).scalars()["n_slip_episodes"] > 0
    still = solved(case.at("mu", 1.01 * ratio), record)
    assert still.scalars()["n_slip_episodes"] == 0
    assert f"needs at most {ratio:.4g} times its weight" in still.never_slides


def test_the_damper_refuses_a_floor_the_building_has_not(record):
    with pytest.raises(stickslip.StickslipError, match=r"damper story 4: the building has 3 stories \(floors 1 to 3\)"):
        stickslip.solve(record, model="friction-tmd", structure_period=1.0, mu=0.1, stories=3, damper_story=4)
