"""The isolated building on the command line: solve --json with the designer's answers, optimum by drift, sweep into a
cube, and one line with exit code 2 for what it cannot take (its pairs and verticals:
tests/test_structures_in_the_plane_models.py)."""

from __future__ import annotations

import json

import numpy as np
import pytest

import stickslip

KEYS = ("peak_isolator_displacement", "residual_isolator_displacement", "peak_drift", "peak_story_drifts",
        "peak_floor_acceleration", "peak_floor_accelerations", "base_shear_coefficient",
        "superstructure_shear_coefficient", "energy_dissipated", "energy_input", "viscous_energy", "kinetic_energy",
        "strain_energy", "potential_energy", "balance_residual")


@pytest.fixture
def wave_file(tmp_path):
    """A decaying 0.9 Hz wave with a 0.4 g peak, 10 s every 0.01 s, as a two-column text file in m/s²."""
    time = np.arange(0.0, 10.0, 0.01)
    acceleration = 0.4 * 9.81 * np.sin(2 * np.pi * 0.9 * time) * np.exp(-0.25 * time)
    path = tmp_path / "wave.txt"
    path.write_text("\n".join(f"{t:.2f} {a:.12e}" for t, a in zip(time, acceleration)) + "\n")
    return path


BUILDING = ("--model", "isolated", "--superstructure-period", "0.5", "--stories", "2", "--radius", "2")


def test_solve_json_gives_the_designers_answers(run_cli, wave_file):
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", *BUILDING, "--mu", "0.06", "--mass", "2e6",
                             "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert set(KEYS) <= printed.keys()
    assert (printed["model"], printed["stories"], printed["mass_ratio"], printed["damping_model"]) == (
        "isolated", 2, 4.0, "modal")
    assert len(printed["peak_story_drifts"]) == 2 and printed["peak_drift"] == max(printed["peak_story_drifts"])
    assert (printed["units"]["peak_isolator_displacement"], printed["units"]["energy_dissipated"]) == ("m", "J")
    expected = stickslip.solve(stickslip.read_record(wave_file, units="m/s2"), model="isolated",
                               superstructure_period=0.5, stories=2, radius=2.0, mu=0.06, mass=2e6).scalars()
    assert printed["peak_isolator_displacement"] == pytest.approx(expected["peak_isolator_displacement"], rel=1e-12)
    assert printed["energy_dissipated"] == pytest.approx(expected["energy_dissipated"], rel=1e-12)


def test_optimum_by_drift_answers_the_mu_of_the_smallest_drift(run_cli, wave_file):
    code, out, err = run_cli("optimum", wave_file, "--units", "m/s2", *BUILDING, "--mu", "0.02:0.2:0.02",
                             "--objective", "drift", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert printed["settings"]["objective"] == "drift"
    record = printed["records"][0]
    motion = stickslip.read_record(wave_file, units="m/s2")

    def drift(mu):
        return stickslip.solve(motion, model="isolated", superstructure_period=0.5, stories=2, radius=2.0,
                               mu=mu).scalars()["peak_drift"]

    on_grid = [drift(mu) for mu in np.arange(0.02, 0.2001, 0.02)]
    assert drift(record["mu_max"]) <= min(on_grid)
    assert record["peak_drift_at_mu_max"] == pytest.approx(drift(record["mu_max"]), rel=1e-12)


def test_optimum_by_displacement_reads_the_isolators_displacement(run_cli, wave_file):
    code, out, err = run_cli("optimum", wave_file, "--units", "m/s2", *BUILDING, "--mu", "0.02:0.2:0.02",
                             "--objective", "displacement", "--json")
    assert code == 0, err
    record = json.loads(out)["records"][0]
    stroke = stickslip.solve(stickslip.read_record(wave_file, units="m/s2"), model="isolated",
                             superstructure_period=0.5, stories=2, radius=2.0, mu=0.2).scalars()
    assert record["mu_max"] >= 0.2 and record["peak_relative_displacement_at_mu_max"] <= stroke[
        "peak_isolator_displacement"]
    assert stickslip.models.registry.MODELS["isolated"].strokes[0] == "peak_isolator_displacement"


@pytest.mark.parametrize("options, message", [
    (("--stories", "1.5"), "number of stories (--stories) must be a whole number of at least 1, got 1.5"),
    (("--superstructure-period", "-0.5"), "--superstructure-period -0.5: superstructure period [s] "
                                          "(--superstructure-period) must be a positive finite number"),
    (("--mass-ratio", "0"), "--mass-ratio 0: mass ratio m_s/m_b (--mass-ratio) must be a positive finite number"),
    (("--radius", "-2"), "radius of the isolator's surface [m] (--radius) must be positive (inf for a flat slider), "
                         "got -2"),
])
def test_a_bad_option_is_one_line_and_exit_code_2(run_cli, wave_file, options, message):
    given = dict(zip(BUILDING[::2], BUILDING[1::2]))
    given.update(dict(zip(options[::2], options[1::2])))
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", *[part for item in given.items() for part in item],
                             "--mu", "0.06")
    assert (code, out) == (2, "")
    lines = err.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], err


def test_a_missing_period_is_refused_in_one_line(run_cli, wave_file):
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", "--model", "isolated", "--mu", "0.06")
    assert (code, out, err.strip()) == (2, "", "stickslip: error: the isolated model needs a friction ratio --mu and "
                                               "the superstructure's fixed-base period --superstructure-period [s]")
