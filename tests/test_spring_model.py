"""A block on a linear spring with Coulomb friction, a model that is its module and one registry line.

Free vibration from an initial velocity: each half cycle turns 2μg/ω² nearer
the middle than the last (4μg/ω² a cycle) and the block stays at the first
turn within μg/ω²; the model flows through solve, sweep, the command line's
solve, sweep and optimum, and the record report.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import stickslip
from stickslip.records.record import Record, RecordMeta

G = 9.81


def free_vibration(mu: float, period: float, turns: int):
    """A base at rest sampled so that the block's turns fall on samples, and its initial velocity [m/s].

    From u = 0 with u̇ = v0 the block swings about −μg/ω² until the phase
    reaches 0: after atan2(v0/ω, μg/ω²)/ω, chosen as 0.49 of a half period,
    so that with 100 samples a half period every turn is a sample.
    """
    omega = 2 * math.pi / period
    stick = mu * G / omega**2
    initial_velocity = omega * stick * math.tan(0.49 * math.pi)
    dt = math.pi / omega / 100
    rest = Record(np.zeros(49 + 100 * turns + 1), dt, RecordMeta(record_id="rest"))
    return rest, initial_velocity, stick


def test_free_vibration_loses_four_mu_g_over_omega_squared_a_cycle_and_stops_within_mu_g_over_omega_squared():
    mu, period = 0.05, 1.0
    rest, initial_velocity, stick = free_vibration(mu, period, turns=20)
    response = stickslip.solve(rest, mu=mu, period=period, initial_velocity=initial_velocity)
    assert response.model == "spring"
    first = -stick + math.hypot(stick, initial_velocity * period / (2 * math.pi))
    expected = [first]
    while abs(expected[-1]) > stick:  # a turn beyond mu g / omega^2 swings back, 2 mu g / omega^2 shorter
        expected.append(-math.copysign(abs(expected[-1]) - 2 * stick, expected[-1]))
    assert len(expected) == 16
    turns = response.history["relative_displacement"][49::100]
    np.testing.assert_allclose(turns[:len(expected)], expected, rtol=0, atol=1e-9)
    np.testing.assert_allclose(turns[len(expected):], expected[-1], rtol=0, atol=1e-9)
    cycles = np.abs(turns[:len(expected) - 2]) - np.abs(turns[2:len(expected)])
    np.testing.assert_allclose(cycles, 4 * stick, rtol=0, atol=1e-9)
    scalars = response.scalars()
    assert scalars["residual_displacement"] == pytest.approx(expected[-1], abs=1e-9)
    assert scalars["peak_relative_displacement"] == pytest.approx(first, abs=1e-9)
    assert scalars["balance_residual"] < 1e-12 * 0.5 * response.block.mass * initial_velocity**2


@pytest.fixture(scope="module")
def wave() -> Record:
    time = np.arange(0.0, 10.0, 0.01)
    return Record(4.0 * np.sin(2 * np.pi * 0.7 * time) * np.exp(-0.3 * time), 0.01,
                  RecordMeta(record_id="wave", source="wave.txt"))


def test_a_sweep_holds_the_solves_of_its_cases(wave):
    mu = [0.05, 0.1, 0.2]
    cube = stickslip.sweep([wave], mu=mu, period=1.5)
    assert cube.attrs["model"] == "spring" and float(cube.attrs["period"]) == 1.5
    for index, value in enumerate(mu):
        solved = stickslip.solve(wave, mu=value, period=1.5).scalars()
        for name in ("energy_dissipated", "peak_relative_displacement", "restoring_work"):
            assert float(cube[name].values[0, index]) == pytest.approx(solved[name], rel=1e-12), name


def test_the_dataset_keeps_the_energy_histories_beside_their_end_values(wave):
    response = stickslip.solve(wave, mu=0.1, period=1.5, mass=2.0)
    dataset = response.to_xarray()
    scalars = response.scalars()
    for name in ("energy_dissipated", "energy_input", "restoring_work", "balance_residual"):
        assert dataset[name].dims == ("time",), name
        assert dataset[name].attrs["units"] == "J"
    np.testing.assert_array_equal(dataset["energy_dissipated"].values, 2.0 * response.history["energy_dissipated"])
    assert float(dataset["energy_dissipated"][-1]) == scalars["energy_dissipated"]
    assert float(np.max(np.abs(dataset["balance_residual"]))) == scalars["balance_residual"]
    assert float(dataset["peak_relative_displacement"]) == scalars["peak_relative_displacement"]
    assert dataset.attrs["period"] == 1.5 and dataset.attrs["model"] == "spring"
    assert dataset.attrs["Conventions"].startswith("CF-")


@pytest.fixture
def wave_file(tmp_path, wave):
    path = tmp_path / "wave.txt"
    time = np.arange(wave.npts) * wave.dt
    path.write_text("\n".join(f"{t:.2f} {a:.12e}" for t, a in zip(time, wave.acceleration)) + "\n")
    return path


def test_the_command_line_solves_sweeps_and_designs_the_spring(run_cli, wave_file, tmp_path):
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", "--mu", "0.1", "--period", "1.5", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert (printed["model"], printed["period"], printed["units"]["period"]) == ("spring", 1.5, "s")
    expected = stickslip.solve(stickslip.read_record(wave_file, units="m/s2"), mu=0.1, period=1.5).scalars()
    assert printed["energy_dissipated"] == pytest.approx(expected["energy_dissipated"], rel=1e-12)
    cube_path = tmp_path / "spring.nc"
    code, out, err = run_cli("sweep", wave_file, "--units", "m/s2", "--mu", "0.05:0.3:0.05", "--period", "1.5",
                             "--out", cube_path)
    assert code == 0, err
    import xarray as xr

    with xr.open_dataset(cube_path) as cube:
        assert cube.attrs["model"] == "spring" and cube.sizes["mu"] == 6
    code, out, err = run_cli("optimum", wave_file, "--units", "m/s2", "--mu", "0.05:0.3:0.05", "--period", "1.5")
    assert code == 0, err
    assert "on a spring T = 1.5 s" in out and "mu_max" in out


def test_a_spring_without_its_period_is_one_line(run_cli, wave_file):
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", "--initial-velocity", "0.2", "--mu", "0.1")
    assert (code, out) == (2, "")
    assert err.strip() == "stickslip: error: the spring model needs a friction ratio --mu and a natural period --period [s]"


def test_the_record_report_of_the_spring_is_its_design_answer_and_its_response(run_cli, wave_file, tmp_path):
    page = tmp_path / "spring.html"
    code, out, err = run_cli("report", wave_file, "--units", "m/s2", "--period", "1.5", "--mu", "0.05:0.3:0.05",
                             "--out", page)
    assert code == 0, err
    text = page.read_text()
    assert "the spring model, on a spring T = 1.5 s" in text
    assert "energy stored in the spring at the end" in text  # the response's table, in the model's words
    assert "Not drawn: the spring model draws no design chart (--model pendulum, isolated, friction-tmd draw one)" in text


@pytest.mark.parametrize("option", ["--chart-levels", "--chart-values"])
def test_the_record_report_refuses_a_design_chart_s_option_for_the_spring(run_cli, wave_file, tmp_path, option):
    page = tmp_path / "spring.html"
    code, out, err = run_cli("report", wave_file, "--units", "m/s2", "--period", "1.5", "--mu", "0.05:0.3:0.05",
                             option, "1,2", "--out", page)
    assert (code, out) == (2, "") and not page.exists()
    assert err.strip().startswith(f"stickslip: error: {option}: the spring model draws no design chart; ")
    assert "isolated" in err and "pendulum" in err
