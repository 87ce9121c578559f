"""The friction pendulum's velocity law μ(v) in every sweep: the grid's μ is μ_fast, its ratio and rate held."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest
from conftest import assert_one_error_line

import stickslip
from stickslip.errors import StickslipError, StickslipWarning
from stickslip.models import design_of
from stickslip.models.pendulum.chart import chart_statistics, design_chart
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record, RecordMeta
from stickslip.reports.isolator_plots import friction_axis_label

G = 9.80665
LAW = {"mu_slow_ratio": 0.5, "rate": 20.0}
GRID = [0.04, 0.08, 0.12]
#: How the command line reads the record file of :func:`record_file`.
FILE = ("--format", "slammer_1col", "--dt", "0.01", "--units", "m/s2")


def wave(seconds: float, peak_g: float, frequency: float, component: str) -> Record:
    """A decaying two-tone motion sampled every 0.01 s, peak ``peak_g`` g."""
    time = np.arange(0.0, seconds, 0.01)
    values = (np.sin(2 * np.pi * frequency * time) + 0.4 * np.sin(2 * np.pi * 3.7 * time)) * np.exp(-0.3 * time)
    return Record(peak_g * G * values / np.max(np.abs(values)), 0.01,
                  RecordMeta(record_id=f"wave-{component}", station="Z", component=component))


@pytest.fixture(scope="module")
def record() -> Record:
    return wave(8.0, 0.5, 1.1, "000")


@pytest.fixture(scope="module")
def cube(record):
    return stickslip.sweep([record], model="pendulum", mu=GRID, radius=2.0, **LAW)


def test_a_sweep_solves_each_mu_fast_with_the_ratio_and_the_rate_held(record, cube):
    for index, mu_fast in enumerate(GRID):
        alone = stickslip.solve(record, model="pendulum", mu_slow=0.5 * mu_fast, mu_fast=mu_fast, rate=20.0,
                                radius=2.0).scalars()
        assert float(cube["energy_dissipated"][0, index]) == pytest.approx(alone["energy_dissipated"], rel=1e-9)
        assert float(cube["peak_relative_displacement"][0, index]) == pytest.approx(
            alone["peak_relative_displacement"], rel=1e-9)
    coulomb = stickslip.sweep([record], model="pendulum", mu=GRID, radius=2.0)
    assert not np.allclose(cube["energy_dissipated"].values, coulomb["energy_dissipated"].values, rtol=1e-3)


def test_the_cube_records_the_law_and_its_design_answer_reads_it_back(cube):
    assert cube.attrs["friction_law"] == "velocity_dependent"
    assert (cube.attrs["mu_slow_ratio"], cube.attrs["rate"], cube.attrs["rate_units"]) == (0.5, 20.0, "s m-1")
    assert "mu is mu_fast, mu_slow = 0.5 mu_fast, rate 20 s/m" in cube.attrs["friction_law_description"]
    np.testing.assert_allclose(cube["mu_slow"].values, 0.5 * np.asarray(GRID))
    law = design_of(cube).case.at("mu", 0.1).friction
    assert (law.mu_slow, law.mu_fast, law.rate) == pytest.approx((0.05, 0.1, 20.0))
    plain = stickslip.sweep([wave(4.0, 0.5, 1.1, "000")], model="pendulum", mu=GRID, radius=2.0)
    assert plain.attrs["friction_law"] == "coulomb" and "mu_slow" not in plain.coords


def test_a_pair_sweep_holds_the_law_too():
    pair = RecordPair(wave(3.0, 0.5, 1.1, "000"), wave(3.0, 0.4, 0.8, "090"))
    swept = stickslip.sweep([pair], model="pendulum", mu=[0.05, 0.1], radius=2.0, **LAW)
    alone = stickslip.solve(pair, model="pendulum", mu_slow=0.05, mu_fast=0.1, rate=20.0, radius=2.0).scalars()
    assert float(swept["energy_dissipated"][0, 1]) == pytest.approx(alone["energy_dissipated"], rel=1e-9)


def test_the_design_chart_sweeps_the_law_and_names_its_axis(record, cube):
    chart = design_chart([record], [2.0, 3.0], GRID, **LAW)
    np.testing.assert_allclose(chart["peak_relative_displacement"].sel(radius=2.0).values[0],
                               cube["peak_relative_displacement"].values[0], rtol=1e-9)
    statistics = chart_statistics(chart)
    assert friction_axis_label(statistics.attrs) == "friction ratio μ_fast [-] (μ_slow = 0.5 μ_fast, a = 20 s/m)"
    assert friction_axis_label({"friction_law": "coulomb"}) == "friction ratio μ [-]"


@pytest.fixture(scope="module")
def record_file(tmp_path_factory, record):
    path = tmp_path_factory.mktemp("law") / "wave.txt"
    path.write_text("\n".join(f"{value:.8e}" for value in record.acceleration) + "\n")
    return path


def optimum_json(run_cli, path, *law: str) -> dict:
    code, out, err = run_cli("optimum", path, *FILE,
                             "--radius", "2", "--mu", "0.04,0.08,0.12", "--range-points", "1", "--reference-mu",
                             "0.08", *law, "--json")
    assert code == 0, err
    return json.loads(out)


def test_optimum_answers_for_the_law_and_says_it(run_cli, record_file, record):
    law = optimum_json(run_cli, record_file, "--mu-slow-ratio", "0.5", "--rate", "20")
    coulomb = optimum_json(run_cli, record_file)
    assert (law["settings"]["friction_law"], law["settings"]["mu_slow_ratio"], law["settings"]["rate"]) == (
        "velocity_dependent", 0.5, 20.0)
    assert law["units"]["rate"] == "s m-1" and coulomb["settings"]["friction_law"] == "coulomb"
    expected = stickslip.solve(record, model="pendulum", mu_slow=0.04, mu_fast=0.08, rate=20.0, radius=2.0)
    assert law["records"][0]["energy_dissipated_reference"] == pytest.approx(
        expected.scalars()["energy_dissipated"], rel=1e-9)
    assert law["records"][0]["energy_dissipated_reference"] != pytest.approx(
        coulomb["records"][0]["energy_dissipated_reference"], rel=1e-3)
    code, out, err = run_cli("optimum", record_file, *FILE,
                             "--radius", "2", "--mu", "0.04,0.08,0.12", "--mu-slow-ratio", "0.5", "--rate", "20")
    assert code == 0 and err == ""
    assert ("velocity-dependent friction (Constantinou, Mokha & Reinhorn 1990): mu is mu_fast, mu_slow = 0.5 "
            "mu_fast, rate 20 s/m") in out.splitlines()[0]


@pytest.mark.parametrize("command", ["sweep", "optimum", "report"])
@pytest.mark.parametrize(("given", "name"), [(("--mu-slow", "0.05", "--mu-fast", "0.1"), "--mu-slow"),
                                             (("--mu-fast", "0.1"), "--mu-fast")])
def test_a_sweep_refuses_mu_slow_and_mu_fast_naming_the_ratio(run_cli, record_file, tmp_path, command, given, name):
    out = tmp_path / ("page.html" if command == "report" else "cube.nc")
    assert_one_error_line(*run_cli(command, record_file, *FILE, "--radius", "2",
                                   *given, "--rate", "20", *(() if command == "optimum" else ("--out", out))),
                          name, "a sweep's friction grid --mu is the velocity law's mu_fast")
    assert not out.exists()


def test_a_sweep_without_its_grid_is_one_line(run_cli, record_file, record, tmp_path):
    assert_one_error_line(*run_cli("sweep", record_file, *FILE, "--radius", "2", "--mu-slow-ratio", "0.5", "--rate",
                                   "20", "--out", tmp_path / "cube.nc"), "--mu", "give a friction ratio --mu")
    with pytest.raises(StickslipError, match="takes the values of one swept coefficient, mu=; got none"):
        stickslip.sweep([record], model="pendulum", mu_slow=0.05, mu_fast=0.1, rate=20.0)


def test_solve_records_the_law_given_by_its_ratio(run_cli, record_file):
    code, out, err = run_cli("solve", record_file, *FILE, "--radius", "2",
                             "--mu", "0.1", "--mu-slow-ratio", "0.5", "--rate", "20", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert (printed["mu_slow"], printed["mu_fast"], printed["rate"]) == (0.05, 0.1, 20.0)
    assert "mu" not in printed


@pytest.mark.parametrize(("law", "phrase"), [
    ({"mu_slow": 0.1, "mu_fast": 0.05, "rate": 20.0}, "mu_slow=0.1 above mu_fast 0.05: friction that weakens"),
    ({"mu": 0.05, "mu_slow_ratio": 2.0, "rate": 20.0}, "mu_slow_ratio=2: friction that weakens with speed"),
    ({"mu_slow": 0.05, "mu_fast": 0.1, "rate": 0.77}, "rate=0.77 s/m is outside the 10 to 100 s/m"),
    ({"mu_slow": 0.05, "mu_fast": 0.1, "rate": 500.0}, "rate=500 s/m is outside the 10 to 100 s/m"),
])
def test_an_unusual_law_is_a_warning(law, phrase):
    with pytest.warns(StickslipWarning) as caught:
        stickslip.models.MODELS["pendulum"].case(stickslip.models.MODELS["pendulum"].checked({"radius": 2.0, **law}))
    assert [str(warning.message) for warning in caught if phrase in str(warning.message)]


def test_a_usual_law_and_coulomb_friction_get_no_warning():
    entry = stickslip.models.MODELS["pendulum"]
    with warnings.catch_warnings():
        warnings.simplefilter("error", StickslipWarning)
        cases = [entry.case(entry.checked({"radius": 2.0, **law}))
                 for law in ({"mu_slow": 0.05, "mu_fast": 0.1, "rate": 10.0},
                             {"mu_slow": 0.05, "mu_fast": 0.1, "rate": 100.0},
                             {"mu": 0.05, "mu_slow_ratio": 1.0, "rate": 500.0}, {"mu": 0.05})]
    assert [case.friction.rate for case in cases] == [10.0, 100.0, 0.0, 0.0]  # a ratio of 1 is Coulomb friction


def test_the_command_line_warns_once_in_one_line(run_cli, record_file, tmp_path):
    code, out, err = run_cli("sweep", record_file, *FILE, "--radius", "2",
                             "--mu", "0.04,0.08", "--mu-slow-ratio", "1.5", "--rate", "0.77",
                             "--out", tmp_path / "cube.nc")
    assert code == 0
    assert err.splitlines() == [
        "stickslip: warning: --mu-slow-ratio 1.5: friction that weakens with speed, unusual for PTFE-type liners on "
        "polished stainless steel, whose friction grows with speed (mu_slow < mu_fast; Mokha, Constantinou & "
        "Reinhorn 1990)",
        "stickslip: warning: --rate 0.77 s/m is outside the 10 to 100 s/m that tests of sliding bearings report "
        "(Constantinou, Mokha & Reinhorn 1990); check that it is in s/m (1 s/in = 39.37 s/m)"]
