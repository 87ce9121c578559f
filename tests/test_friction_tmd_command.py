"""The friction tuned mass damper through the command line: solve, sweep, optimum by each objective, report."""

import json

import numpy as np
import pytest
import xarray as xr

import stickslip
from conftest import assert_one_error_line

BUILDING = ("--model", "friction-tmd", "--structure-period", "1.0")


@pytest.fixture(scope="module")
def wave_file(tmp_path_factory):
    time = np.arange(0.0, 10.0, 0.01)
    acceleration = 4.0 * np.sin(2 * np.pi * 0.9 * time) * np.exp(-0.3 * time)
    path = tmp_path_factory.mktemp("damper") / "wave.txt"
    path.write_text("\n".join(f"{t:.2f} {a:.12e}" for t, a in zip(time, acceleration)) + "\n")
    return path


def test_solve_json_gives_the_building_the_damper_and_both_references(run_cli, wave_file):
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", *BUILDING, "--stories", "3", "--mu", "0.1",
                             "--mass-ratio", "0.08", "--radius", "2", "--mass", "3e5", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert (printed["model"], printed["stories"], printed["damper_story"], printed["radius"]) == ("friction-tmd", 3, 3,
                                                                                                 2.0)
    record = stickslip.read_record(wave_file, units="m/s2")
    expected = stickslip.solve(record, model="friction-tmd", structure_period=1.0, stories=3, mu=0.1, mass_ratio=0.08,
                               radius=2.0, mass=3e5)
    for name, value in expected.scalars().items():
        assert printed[name] == pytest.approx(value, rel=1e-12, abs=1e-15), name
    assert len(printed["peak_story_drifts"]) == len(printed["peak_floor_accelerations"]) == 3
    assert printed["peak_drift"] == max(printed["peak_story_drifts"])
    for reference in ("bare_structure", "attached_mass"):
        assert printed["peak_drift_reduction" + ("" if reference == "bare_structure" else "_attached")] == (
            pytest.approx(1 - printed["peak_drift"] / printed[reference]["peak_drift"], rel=1e-12))
    assert printed["units"]["peak_damper_stroke"] == "m" and printed["units"]["energy_dissipated"] == "J"


def test_a_flat_damper_on_a_floor_it_lacks_is_one_line(run_cli, wave_file):
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", *BUILDING, "--stories", "2", "--damper-story", "3",
                             "--mu", "0.1")
    assert_one_error_line(code, out, err, "damper story", "damper story 3: the building has 2 stories (floors 1 to 2)")
    code, out, err = run_cli("solve", wave_file, "--units", "m/s2", *BUILDING, "--radius", "-1", "--mu", "0.1")
    assert_one_error_line(code, out, err, "--radius", "radius of the damper's surface R_d [m] must be positive")


@pytest.mark.parametrize("objective, curve", [("energy", "energy_dissipated"), ("drift", "peak_drift"),
                                              ("floor-acceleration", "peak_floor_acceleration"),
                                              ("base-shear", "base_shear_coefficient"),
                                              ("displacement", "peak_damper_stroke")])
def test_optimum_answers_the_objective_named_from_the_damper_s_own_curves(run_cli, wave_file, tmp_path, objective,
                                                                          curve):
    cube_path = tmp_path / "damper.nc"
    code, out, err = run_cli("optimum", wave_file, "--units", "m/s2", *BUILDING, "--mu", "0.02:0.3:0.02",
                             "--objective", objective, "--range-points", "1", "--out", cube_path)
    assert code == 0, err
    with xr.open_dataset(cube_path) as cube:  # the grid as extended and refined for the answer
        assert cube.attrs["objective"] == objective and "peak_relative_displacement" not in cube
        values, mu = cube[curve].values[0], cube["mu"].values
        best = np.argmax(values) if objective == "energy" else np.argmin(values)
        assert float(cube["mu_max"].values[0]) == pytest.approx(mu[best], abs=1e-12)
        if objective == "displacement":
            assert float(cube["peak_relative_displacement_at_mu_max"].values[0]) == pytest.approx(np.min(values))


def test_the_record_report_of_the_damper(run_cli, wave_file, tmp_path):
    page = tmp_path / "damper.html"
    code, out, err = run_cli("report", wave_file, "--units", "m/s2", *BUILDING, "--mu", "0.02:0.3:0.02",
                             "--out", page)
    assert code == 0, err
    text = page.read_text()
    assert "the friction-tmd model, on floor 1 of a 1-story building T = 1 s" in text
    assert "damper displacement relative to its floor" in text
