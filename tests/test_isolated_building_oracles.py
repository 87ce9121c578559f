"""The isolated building against what is known without it: the fixed-base building's modal closed form, the friction
pendulum as the superstructure turns rigid, its own energy ledger, and its sweep against its solves."""

from __future__ import annotations

import numpy as np
import pytest

import stickslip
from stickslip.records.record import Record, RecordMeta
from stickslip.solvers.structure.linear_response import modal_displacements
from stickslip.solvers.structure.shear_building import uniform_building


@pytest.fixture(scope="module")
def pulse() -> Record:
    """A decaying two-tone motion with a 0.5 g peak, 8 s sampled every 0.005 s."""
    time = np.arange(0.0, 8.0, 0.005)
    wave = (np.sin(2 * np.pi * 0.8 * time) + 0.5 * np.sin(2 * np.pi * 2.3 * time)) * np.exp(-0.35 * time)
    return Record(0.5 * 9.81 * wave / np.max(np.abs(wave)), 0.005, RecordMeta(record_id="pulse"))


@pytest.mark.parametrize("stories, damping_model", [(1, "modal"), (3, "modal"), (4, "rayleigh")])
def test_an_isolator_that_never_slides_carries_the_fixed_base_building(pulse, stories, damping_model):
    result = stickslip.solve(pulse, model="isolated", superstructure_period=0.6, stories=stories,
                             damping_model=damping_model, superstructure_damping=0.05, radius=2.0, mu=20.0,
                             mass=5e5)
    assert result.never_slides is not None and result.scalars()["peak_isolator_displacement"] == 0.0
    building = uniform_building(stories, 0.6, 5e5 * 4 / 5, 0.05, damping_model)
    drifts = result.histories()["story_drift"]
    if damping_model == "modal":
        floors = modal_displacements(building, pulse.acceleration, pulse.dt)
        expected = np.diff(np.hstack([np.zeros((floors.shape[0], 1)), floors]), axis=1)
        assert np.max(np.abs(drifts - expected)) < 1e-10 * np.max(np.abs(expected))
    assert result.extras()["peak_story_drifts"] == pytest.approx(np.abs(drifts).max(axis=0), rel=2e-2)
    assert result.scalars()["peak_drift"] == max(result.extras()["peak_story_drifts"])


def test_a_rigid_superstructure_is_the_friction_pendulum_to_first_order_in_its_period(pulse):
    pendulum = stickslip.solve(pulse, model="pendulum", radius=2.0, mu=0.05, mass=1000.0).scalars()
    errors = []
    for period in (0.04, 0.02, 0.01, 0.005):
        isolated = stickslip.solve(pulse, model="isolated", superstructure_period=period, radius=2.0, mu=0.05,
                                   mass=1000.0).scalars()
        errors.append((abs(isolated["peak_isolator_displacement"] / pendulum["peak_relative_displacement"] - 1),
                       abs(isolated["energy_dissipated"] / pendulum["energy_dissipated"] - 1)))
    errors = np.array(errors)
    assert np.all(errors[-1] < 5e-3)
    rates = errors[:-1] / errors[1:]  # the error over the next period's, as the period halves
    assert np.all(rates > 1.5), errors


def test_the_ledger_closes_on_a_real_record(paper_records):
    record = paper_records["CHY080-N.AT2"]
    result = stickslip.solve(record, model="isolated", superstructure_period=0.5, stories=3, radius=2.0, mu=0.06,
                             mass=2e6)
    scalars = result.scalars()
    ledger = result.energy_ledger()
    assert scalars["n_slip_episodes"] > 10 and scalars["energy_dissipated"] > 0.5 * scalars["energy_input"]
    assert scalars["balance_residual"] < 1e-10 * np.max(ledger["energy_input"])
    closed = (ledger["kinetic_energy"] + ledger["strain_energy"] + ledger["viscous_energy"]
              + ledger["potential_energy"] + ledger["energy_dissipated"] - ledger["energy_input"])
    assert np.max(np.abs(closed - ledger["balance_residual"])) < 1e-12 * np.max(ledger["energy_input"])


def test_the_sweep_holds_the_solves_of_its_cases(pulse):
    mus = [0.02, 0.05, 0.1]
    cube = stickslip.sweep([pulse], model="isolated", superstructure_period=0.5, stories=2, radius=2.0, mu=mus)
    for index, mu in enumerate(mus):
        solved = stickslip.solve(pulse, model="isolated", superstructure_period=0.5, stories=2, radius=2.0,
                                 mu=mu).scalars()
        for name in ("peak_isolator_displacement", "peak_drift", "peak_floor_acceleration", "base_shear_coefficient",
                     "energy_dissipated"):
            assert float(cube[name].isel(record=0, mu=index)) == pytest.approx(solved[name], rel=1e-12), name
        assert float(cube["residual_isolator_displacement"].isel(record=0, mu=index)) == pytest.approx(
            solved["residual_isolator_displacement"], rel=1e-12, abs=1e-15)
    assert "peak_relative_displacement" not in cube, "the isolator's stroke is in the cube once, under its own name"
