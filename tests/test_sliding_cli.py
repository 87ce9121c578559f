"""Yield accelerations in ``stickslip solve`` and ``sweep`` and in :func:`stickslip.sweep`: values, cubes and errors."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import xarray as xr
from conftest import assert_one_error_line

from stickslip.errors import StickslipError
from stickslip.records.readers import read_record
from stickslip.models.rigid.response import SCALAR_ATTRS, SLOPE_SCALAR_ATTRS
from stickslip.models import solve
from stickslip.models import sweep
from stickslip.models.rigid import RIGID
from stickslip.sweeps import write_cube
from stickslip.constants import DEFAULT_BLOCK_MASS

RECORD = "SLAMMER_Cape_Mendocino_1992_PET-090.txt"
G = 9.81


@pytest.fixture(scope="module")
def record_path(paper_records_dir):
    return paper_records_dir / RECORD


@pytest.fixture(scope="module")
def record(record_path):
    return read_record(record_path)


# --- stickslip solve ----------------------------------------------------------------------------


def test_solve_ky_in_g_or_m_s2_matches_the_library(run_cli, record_path, record):
    code, out, err = run_cli("solve", record_path, "--ky", "0.1g", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert [name for name in printed if name in {*SCALAR_ATTRS, *SLOPE_SCALAR_ATTRS}] == [*SCALAR_ATTRS, *SLOPE_SCALAR_ATTRS]
    assert (printed["ky"], printed["direction"], printed["polarity"]) == (0.1, "down", "normal")
    assert printed["units"]["downslope_displacement"] == "m"
    expected = solve(record, ky=0.1).scalars()
    assert {name: printed[name] for name in expected} == pytest.approx(expected, rel=1e-15)
    assert printed["downslope_displacement"] == -printed["residual_displacement"] > 0.0
    _, in_m_s2, _ = run_cli("solve", record_path, "--ky", f"{0.1 * G}m/s2", "--json")
    assert json.loads(in_m_s2)["downslope_displacement"] == pytest.approx(printed["downslope_displacement"], rel=1e-12)


def test_solve_two_way_inverse_and_slammer_options_reach_the_library(run_cli, record_path):
    code, out, err = run_cli("solve", record_path, "--ky", "0.12g", "--direction", "both", "--thrust-angle", "15",
                             "--inverse", "--method", "slammer", "--g", "9.80665", "--json")
    assert code == 0, err
    expected = solve(read_record(record_path, g=9.80665), ky=0.12, direction="both", thrust_angle=15.0, inverse=True,
                     method="slammer", g=9.80665)  # one g: the record in g converted with it too
    assert json.loads(out)["downslope_displacement"] == expected.downslope_displacement
    assert json.loads(out)["body_force_work"] == pytest.approx(
        DEFAULT_BLOCK_MASS * -9.80665 * math.sin(math.radians(15.0)) * expected.residual_displacement, rel=1e-12)


def test_solve_table_names_the_sliding_and_its_units(run_cli, record_path):
    code, out, _ = run_cli("solve", record_path, "--ky", "0.1g", "--inverse")
    assert code == 0
    header, *rows = out.splitlines()
    assert "ky = 0.1 (k_y*g = 0.981 m/s2), one-way (downslope), inverse polarity" in header
    table = {line.split()[0]: line.split()[1:] for line in rows}
    assert table["downslope_displacement"][1] == "m" and table["body_force_work"][1] == "J"


def test_solve_ky_writes_its_parameters_to_the_netcdf(run_cli, record_path, tmp_path):
    target = tmp_path / "pet.nc"
    code, _, err = run_cli("solve", record_path, "--ky", "0.1g", "--direction", "both", "--thrust-angle", "5",
                           "--out", target)
    assert code == 0, err
    with xr.open_dataset(target, engine="netcdf4") as dataset:
        assert (dataset.attrs["ky"], dataset.attrs["direction"], dataset.attrs["thrust_angle"]) == (0.1, "both", 5.0)
        assert "mu" not in dataset.attrs
        assert dataset["body_force_work"].attrs["units"] == "J"
        residual = float(np.max(np.abs(dataset["balance_residual"])))
        assert residual < 1e-12 * float(dataset["energy_input"][-1])


@pytest.mark.parametrize(
    ("arguments", "name", "phrase"),
    [
        (("--ky", "0.1g", "--mu", "0.1"), "--mu", "not allowed with argument --ky"),
        (("--ky", "abc"), "--ky 'abc'", "expected a number in units of g (0.15, or 0.15g) or an acceleration with its unit"),
        (("--ky", "-0.1g"), "--ky", "must be a positive finite number"),
        (("--ky", "0"), "--ky", "must be a positive finite number"),
        (("--ky", "infg"), "--ky", "must be a positive finite number"),
        (("--mu", "0.1", "--direction", "both"), "--direction", "applies with --ky only"),
        (("--mu", "0.1", "--inverse", "--thrust-angle", "3"), "--thrust-angle", "applies to --direction both only"),
        (("--ky", "0.1g", "--thrust-angle", "3"), "--thrust-angle", "applies to --direction both only"),
        (("--ky", "0.1g", "--direction", "both", "--thrust-angle", "95"), "--thrust-angle", "from 0 to 90 degrees"),
        (("--ky", "0.1g", "--direction", "up"), "--direction", "invalid choice"),
        (("--ky", "0.1g", "--method", "newmark"), "newmark", "solves flat friction only"),
        (("--ky", "0.1g", "--method", "slammer", "--time-step", "0.001"), "--time-step", "applies to --method newmark only"),
        (("--direction", "both"), "--direction", "applies with --ky only"),
    ],
)
def test_solve_refuses_bad_sliding_options_in_one_line(run_cli, record_path, tmp_path, arguments, name, phrase):
    target = tmp_path / "kept.nc"
    target.write_bytes(b"an earlier result")
    code, stdout, stderr = run_cli("solve", record_path, *arguments, "--out", target)
    assert_one_error_line(code, stdout, stderr, name, phrase)
    assert target.read_bytes() == b"an earlier result"


def test_solve_above_the_record_s_peak_says_why_without_speaking_of_a_grid(run_cli, record_path, record):
    ky = 1.01 * float(record.acceleration.max()) / G  # above the largest downslope acceleration: one-way, no sliding
    code, out, err = run_cli("solve", record_path, "--ky", f"{ky:.6f}")
    assert code == 0 and "energy_dissipated                        0  J" in out
    assert f"the block never slides at ky = {ky:g}" in err and f"at ky = {ky:g}" in err.split(":", 3)[3]
    assert "grid" not in err


def test_flat_solve_reports_no_slope_scalars(run_cli, record_path):
    code, out, _ = run_cli("solve", record_path, "--mu", "0.1", "--inverse", "--json")
    assert code == 0
    printed = json.loads(out)
    assert not set(SLOPE_SCALAR_ATTRS) & set(printed) and set(SCALAR_ATTRS) <= set(printed)
    assert (printed["mu"], printed["polarity"]) == (0.1, "inverse")


# --- stickslip.sweep over k_y ---------------------------------------------------------------


@pytest.fixture(scope="module")
def ky_cube(record):
    return sweep([record], ky=[0.05, 0.1, 0.2], direction="both", thrust_angle=10.0, inverse=True, mass=2.0)


def test_ky_cube_has_a_ky_dimension_with_units_and_the_yield_acceleration(ky_cube):
    assert dict(ky_cube.sizes) == {"record": 1, "ky": 3}
    assert ky_cube.ky.attrs == {"units": "1", "long_name": "yield coefficient k_y (yield acceleration / g)"}
    np.testing.assert_array_equal(ky_cube.yield_acceleration.values, np.array([0.05, 0.1, 0.2]) * G)
    assert ky_cube.yield_acceleration.attrs["units"] == "m s-2"
    for name, variable in ky_cube.data_vars.items():
        assert variable.dims == ("record", "ky") and variable.attrs["long_name"], name
    assert ky_cube.downslope_displacement.attrs["units"] == "m"
    assert ky_cube.attrs["title"] == "stickslip yield-coefficient sweep"
    assert (ky_cube.attrs["direction"], ky_cube.attrs["thrust_angle"]) == ("both", 10.0)
    assert ky_cube.attrs["polarity"].startswith("inverse")


def test_ky_cube_values_equal_one_solve_per_case(ky_cube, record):
    for ky in ky_cube.ky.values:
        expected = solve(record, ky=float(ky), direction="both", thrust_angle=10.0, inverse=True, mass=2.0).scalars()
        case = ky_cube.sel(record="cape_mendocino", ky=ky)
        for name in ("energy_dissipated", "downslope_displacement", "body_force_work", "sliding_path"):
            assert float(case[name]) == pytest.approx(expected[name], rel=1e-12, abs=1e-15), name
    # Displacement falls as the block gets stronger.
    assert np.all(np.diff(ky_cube.downslope_displacement.values[0]) < 0.0)


def test_ky_cube_by_the_slammer_scheme_equals_its_solves(record):
    cube = sweep([record], ky=[0.1, 0.2], method="slammer", g=9.80665)
    for ky in (0.1, 0.2):
        expected = solve(record, ky=ky, method="slammer", g=9.80665).downslope_displacement
        assert float(cube.downslope_displacement.sel(ky=ky)[0]) == expected


def test_missing_cube_of_a_ky_sweep_has_the_same_layout(ky_cube, tmp_path):
    missing = RIGID.missing_cube("absent", "missing: not found", ky=[0.05, 0.1, 0.2], direction="both", thrust_angle=10.0,
                           inverse=True)
    assert set(missing.data_vars) == set(ky_cube.data_vars)
    assert dict(missing.sizes) == {"record": 1, "ky": 3}
    assert np.all(np.isnan(missing.downslope_displacement))
    write_cube(missing, tmp_path / "missing.nc")


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"ky": [0.2, 0.1]}, "yield coefficients ky: values must be strictly increasing"),
        ({"ky": [0.1], "mu": [0.1]}, "not both"),
        ({"mu": [0.1], "thrust_angle": 5.0}, "apply to a yield coefficient ky"),
        ({"ky": [0.1], "method": "newmark"}, "solves flat friction only"),
    ],
)
def test_bad_ky_sweeps_raise_one_clear_error(record, kwargs, message):
    with pytest.raises(StickslipError, match=message):
        sweep([record], **kwargs)


# --- stickslip sweep --ky ------------------------------------------------------------------------


def test_cli_ky_sweep_writes_the_cube_of_the_library(run_cli, record_path, record, tmp_path):
    out = tmp_path / "ky.nc"
    code, _, err = run_cli("sweep", record_path, "--ky", "0.05g:0.15g:0.05g", "--out", out)
    assert code == 0, err
    cube = xr.load_dataset(out)
    np.testing.assert_allclose(cube.ky.values, [0.05, 0.1, 0.15])
    assert cube.attrs["direction"] == "down" and cube.attrs["polarity"].startswith("normal")
    expected = sweep([record], ky=[0.05, 0.1, 0.15])
    np.testing.assert_array_equal(cube.downslope_displacement.values, expected.downslope_displacement.values)
    in_m_s2 = tmp_path / "ky_m_s2.nc"
    assert run_cli("sweep", record_path, "--ky-list", f"{0.05 * G}m/s2", f"{0.1 * G} m/s²", "--out", in_m_s2)[0] == 0
    np.testing.assert_allclose(xr.load_dataset(in_m_s2).ky.values, [0.05, 0.1], rtol=1e-15)


@pytest.mark.parametrize(
    ("arguments", "name", "phrase"),
    [
        (("--ky", "0.1g:0.05g:0.01g"), "--ky", "expected 0 < START <= STOP"),
        (("--ky", "-0.1g:0.2g:0.05g"), "--ky", "yield coefficients k_y must be positive, START is -0.1"),
        (("--ky", "0.1:0.2"), "--ky", "expected START:STOP:STEP, three numbers such as 0.02:0.4:0.02"),
        (("--ky", "0.01g:1e9g:1e-9g"), "--ky", "yield coefficients k_y; at most 1,000,000 are allowed"),
        (("--ky-list", "0.1g", "nope"), "--ky 'nope'", "expected a number in units of g"),
        (("--ky", "0.1g:0.2g:0.1g", "--mu", "0.1:0.2:0.1"), "--mu", "not allowed with argument --ky"),
        (("--mu", "0.1:0.2:0.1", "--direction", "down"), "--direction", "applies with --ky only"),
    ],
)
def test_cli_ky_sweep_refuses_bad_options_in_one_line(run_cli, tmp_path, arguments, name, phrase):
    code, stdout, stderr = run_cli("sweep", tmp_path / "any.AT2", *arguments, "--out", tmp_path / "c.nc")
    assert_one_error_line(code, stdout, stderr, name, phrase)
    assert list(tmp_path.iterdir()) == []
