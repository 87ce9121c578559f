"""The friction pendulum as a model: chosen by its parameters and the vertical, solved and swept through the one
route, the vertical's sense read from its label, and the command line's options."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from conftest import assert_one_error_line

import stickslip
from stickslip.errors import StickslipError
from stickslip.models.pendulum.exact import pendulum_history
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical

G = 9.81


@pytest.fixture(scope="module")
def horizontal():
    time = np.arange(0.0, 12.0, 0.01)
    return Record(3.5 * np.sin(2 * np.pi * 0.8 * time) * np.exp(-0.25 * time), 0.01,
                  RecordMeta(record_id="wave-000", component="000", source="wave-000.txt"))


def vertical_record(values, component: str, source: str) -> Record:
    return Record(np.asarray(values, dtype=float), 0.01, RecordMeta(record_id=source, component=component,
                                                                    source=source))


@pytest.fixture(scope="module")
def upward(horizontal):
    time = np.arange(horizontal.npts) * 0.01
    return vertical_record(12.0 * np.sin(2 * np.pi * 3.0 * time) * np.exp(-0.5 * time), "UP", "wave-UP.txt")


def test_the_parameters_and_the_vertical_choose_the_model(horizontal, upward):
    assert stickslip.solve(horizontal, mu=0.05).model == "rigid"
    assert stickslip.solve(horizontal, mu=0.05, radius=2.0).model == "pendulum"
    assert stickslip.solve(horizontal, mu_slow=0.03, mu_fast=0.06, rate=20.0).model == "pendulum"
    assert stickslip.solve(WithVertical.of(horizontal, upward), mu=0.05).model == "pendulum"
    with pytest.raises(StickslipError, match="the rigid model takes no vertical ground motion"):
        stickslip.solve(WithVertical.of(horizontal, upward), model="rigid", mu=0.05)


def test_a_flat_surface_is_the_rigid_block_and_a_solve_is_its_kernel_for_the_mass(horizontal):
    flat = stickslip.solve(horizontal, model="pendulum", mu=0.05, mass=2.0).scalars()
    rigid = stickslip.solve(horizontal, mu=0.05, mass=2.0).scalars()
    for name in ("energy_dissipated", "energy_input", "residual_displacement", "peak_relative_displacement"):
        assert flat[name] == pytest.approx(rigid[name], rel=1e-12, abs=1e-14)
    kernel = pendulum_history(horizontal.acceleration, horizontal.dt, 0.05, 2.0, G)["scalars"]
    solved = stickslip.solve(horizontal, mu=0.05, radius=2.0, mass=2.0)
    assert solved.solved_by == "closed form"
    assert solved.scalars()["energy_dissipated"] == pytest.approx(2.0 * kernel["energy_dissipated"], rel=1e-15)
    assert solved.scalars()["balance_residual"] < 1e-12 * solved.scalars()["energy_input"]


@pytest.mark.parametrize("radius", [math.inf, 2.0])
def test_a_sweep_holds_the_solves_of_its_cases(horizontal, upward, radius):
    motion = WithVertical.of(horizontal, upward)
    mu = [0.03, 0.06, 0.1]
    cube = stickslip.sweep([motion], model="pendulum", mu=mu, radius=radius)
    for index, value in enumerate(mu):
        solved = stickslip.solve(motion, mu=value, radius=radius).scalars()
        for name in ("energy_dissipated", "peak_relative_displacement", "peak_base_shear", "liftoff_time"):
            assert float(cube[name].values[0, index]) == pytest.approx(solved[name], rel=1e-9, abs=1e-12), name
    assert cube.attrs["model"] == "pendulum" and float(cube.attrs["radius"]) == radius


def test_the_vertical_s_sense_is_read_from_its_label_and_a_down_file_is_turned(horizontal, upward):
    downward = vertical_record(-upward.acceleration, "DWN", "wave-DWN.txt")
    up, down = WithVertical.of(horizontal, upward), WithVertical.of(horizontal, downward)
    assert up.sense == "positive up (UP in its component)"
    assert down.sense == "positive down (DWN in its component), turned positive up"
    np.testing.assert_array_equal(down.vertical.acceleration, upward.acceleration)
    assert (stickslip.solve(down, mu=0.05, radius=2.0).scalars()
            == stickslip.solve(up, mu=0.05, radius=2.0).scalars())
    untold = vertical_record(upward.acceleration, "V", "wave-V1.txt")
    with pytest.raises(StickslipError, match=r"wave-V1.*do not say which way its positive axis points"):
        WithVertical.of(horizontal, untold)
    assert WithVertical.of(horizontal, untold, "up").sense == "positive up (as given)"


def test_an_upward_acceleration_of_more_than_g_lifts_the_slider_off(horizontal):
    time = np.arange(horizontal.npts) * 0.01
    lifting = vertical_record(np.where((time > 2.0) & (time < 2.5), -1.5 * G, 0.0), "UP", "wave-UP.txt")
    response = stickslip.solve(WithVertical.of(horizontal, lifting), mu=0.05)
    assert response.scalars()["liftoff_time"] == pytest.approx(0.5 - 2 * 0.01 / 2.5, rel=0.02)
    assert response.liftoff.shape == (1, 2) and 2.0 < response.liftoff[0, 0] < response.liftoff[0, 1] < 2.5
    assert any(line.startswith("lifted off (g + a_v <= 0) 1 time(s): ") for line in response.notes())


@pytest.fixture
def files(tmp_path, horizontal, upward):
    paths = {}
    for name, record in (("wave-000.txt", horizontal), ("wave-UP.txt", upward),
                         ("wave-V1.txt", vertical_record(upward.acceleration, "V", "wave-V1.txt"))):
        path = tmp_path / name
        time = np.arange(record.npts) * record.dt
        path.write_text("\n".join(f"{t:.2f} {a:.9e}" for t, a in zip(time, record.acceleration)) + "\n")
        paths[name] = path
    return paths


def test_the_command_line_solves_a_pendulum_with_its_vertical(run_cli, files):
    code, out, err = run_cli("solve", files["wave-000.txt"], "--mu", "0.05", "--radius", "2", "--vertical",
                             files["wave-UP.txt"], "--units", "m/s2", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert (printed["model"], printed["radius"], printed["mu"]) == ("pendulum", 2.0, 0.05)
    assert printed["vertical_sense"] == "positive up (UP in its file name)"
    assert printed["units"]["radius"] == "m" and printed["units"]["liftoff_time"] == "s"
    expected = stickslip.solve(WithVertical.of(stickslip.read_record(files["wave-000.txt"], units="m/s2"),
                                               stickslip.read_record(files["wave-UP.txt"], units="m/s2")),
                               mu=0.05, radius=2.0).scalars()
    assert printed["energy_dissipated"] == pytest.approx(expected["energy_dissipated"], rel=1e-12)


@pytest.mark.parametrize(("arguments", "name", "phrase"), [
    (("--mu", "0.05", "--mu-slow", "0.03"), "--mu-slow", "not allowed with argument --mu"),
    (("--rate", "3", "--mu", "0.05"), "--rate", "applies to the velocity law: give --mu-slow-ratio with --mu"),
    (("--mu", "0.05", "--radius", "-1"), "--radius -1", "must be positive (inf for a flat surface)"),
    (("--mu", "0.05", "--vertical-positive", "up"), "--vertical-positive", "applies with --vertical only"),
    (("--mu", "0.05", "--radius", "2", "--thrust-angle", "5"), "--thrust-angle", "--thrust-angle is the rigid model's"),
])
def test_a_pendulum_mistake_is_one_line(run_cli, files, arguments, name, phrase):
    assert_one_error_line(*run_cli("solve", files["wave-000.txt"], "--units", "m/s2", *arguments), name, phrase)


def test_a_vertical_that_does_not_tell_its_sense_needs_it_given(run_cli, files):
    arguments = ("solve", files["wave-000.txt"], "--units", "m/s2", "--mu", "0.05", "--vertical", files["wave-V1.txt"])
    assert_one_error_line(*run_cli(*arguments), "wave-V1", "--vertical-positive")
    code, out, err = run_cli(*arguments, "--vertical-positive", "down")
    assert code == 0, err
    assert "with its vertical read positive down (as given), turned positive up" in out


def test_the_isolator_s_design_answer_gives_the_base_shear_and_the_statistics_over_records(run_cli, files, tmp_path):
    second = tmp_path / "pulse-000.txt"
    time = np.arange(0.0, 12.0, 0.01)
    second.write_text("\n".join(f"{t:.2f} {a:.9e}" for t, a in
                                zip(time, 5.0 * np.exp(-((time - 3.0) / 0.6) ** 2) * np.sin(2 * np.pi * 0.5 * time)))
                      + "\n")
    code, out, err = run_cli("optimum", files["wave-000.txt"], second, "--units", "m/s2", "--radius", "2",
                             "--mu", "0.02:0.2:0.02", "--json")
    assert code == 0, err
    printed = json.loads(out)
    mu = printed["statistics"]["mu"]
    assert printed["statistics"]["percentiles"] == [50.0, 84.0] and printed["units"]["peak_base_shear"] == "1"
    records = [stickslip.read_record(path, units="m/s2") for path in (files["wave-000.txt"], second)]
    solved = {name: np.array([[stickslip.solve(record, mu=value, radius=2.0).scalars()[name] for value in mu]
                              for record in records])
              for name in ("energy_dissipated", "peak_relative_displacement", "residual_displacement",
                           "peak_base_shear")}
    solved["residual_magnitude"] = np.abs(solved.pop("residual_displacement"))
    for name, values in solved.items():
        np.testing.assert_allclose(printed["statistics"][name], np.percentile(values, [50, 84], axis=0),
                                   rtol=1e-9, err_msg=name)
    for row, record in zip(printed["records"], records):
        at_best = stickslip.solve(record, mu=row["mu_max"], radius=2.0).scalars()
        assert row["peak_base_shear_at_mu_max"] == pytest.approx(at_best["peak_base_shear"], rel=1e-9)
        assert row["largest_peak_base_shear"] >= row["peak_base_shear_at_mu_max"]
    code, out, err = run_cli("optimum", files["wave-000.txt"], second, "--units", "m/s2", "--radius", "2",
                             "--mu", "0.02:0.2:0.02")
    assert code == 0, err
    assert "over the 2 records, at each mu: p50 the median, p84 the 84th percentile" in out
    assert "V/W: peak base shear coefficient" in out


def test_the_report_of_a_pendulum_with_its_vertical_gives_its_base_shear_and_its_design_chart(run_cli, files,
                                                                                              tmp_path):
    page = tmp_path / "pendulum.html"
    code, out, err = run_cli("report", files["wave-000.txt"], "--units", "m/s2", "--radius", "2", "--vertical",
                             files["wave-UP.txt"], "--mu", "0.02:0.2:0.02", "--chart-radii", "1,2,3", "--out", page)
    assert code == 0, err
    text = page.read_text()
    assert "With its vertical component, <code>wave-UP.txt</code>, read positive up (UP in its file name)" in text
    assert "V/W at the grid's μ_max" in text and "the pendulum model, friction pendulum R = 2 m" in text
    assert "wave-000: design chart over the friction ratio and the model's other design parameter" in text
    assert "Not drawn" not in text
    code, out, err = run_cli("report", files["wave-000.txt"], "--units", "m/s2", "--radius", "2",
                             "--chart-radii", "2,1", "--out", tmp_path / "refused.html")
    assert_one_error_line(code, out, err, "--chart-radii", "increasing")
