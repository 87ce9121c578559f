"""The ``timestep`` study (the paper's §5.2.1): files, layout and what they show."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr
from conftest import project_config

from stickslip.studies.timestep import write_timestep_study


@pytest.fixture(scope="module")
def study_output(paper_workflow):
    config = project_config()
    paths = [paper_workflow / "sweeps" / "timestep_coyote_g06_230.nc",
             paper_workflow / "tables" / "timestep_coyote_g06_230_summary.csv"]
    with open(paths[1], newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    return config, paths, rows


def summary(rows, method, time_step, mu):
    (row,) = [
        r for r in rows
        if r["method"] == method and float(r["time_step"]) == time_step and float(r["mu"]) == mu
    ]
    return {key: float(value) for key, value in row.items() if key not in ("record", "method", "status")}


def test_study_is_configured():
    settings = project_config()["timestep_study"]
    assert settings["record"] == "coyote_g06_230"
    assert settings["mus"] == [0.05, 0.125, 0.2]
    assert settings["time_steps"] == [0.001, 0.005]


def test_netcdf_layout(study_output):
    config, paths, _ = study_output
    assert [p.name for p in paths] == ["timestep_coyote_g06_230.nc", "timestep_coyote_g06_230_summary.csv"]
    with xr.open_dataset(paths[0]) as data:
        assert list(data["block_acceleration"].dims) == ["solver", "time_step", "mu", "time"]
        assert list(data["solver"].values) == ["exact", "newmark", "newmark_literal"]
        np.testing.assert_allclose(data["time"].values[:3], [0.0, 0.001, 0.002])
        coarse = data["block_acceleration"].sel(solver="newmark", time_step=0.005, mu=0.125).values
        assert np.isnan(coarse[1:5]).all() and np.isfinite(coarse[::5]).all()
        assert data.attrs["record_id"] == "coyote_g06_230"
        assert data["energy_dissipated"].attrs["units"] == "J"


def test_newmark_agrees_with_exact_at_both_steps(study_output):
    _, _, rows = study_output
    for time_step in (0.001, 0.005):
        for mu in (0.05, 0.125, 0.2):
            ours, reference = summary(rows, "newmark", time_step, mu), summary(rows, "exact", time_step, mu)
            assert ours["energy_dissipated"] == pytest.approx(reference["energy_dissipated"], rel=1e-3)
            assert ours["n_slip_episodes"] == reference["n_slip_episodes"]


def test_converging_newmark_does_not_stutter_in_stick(study_output):
    """Our default reading holds the block on the base: no stick-phase stuttering at 0.005 s."""
    _, _, rows = study_output
    for mu in (0.05, 0.125, 0.2):
        assert summary(rows, "newmark", 0.005, mu)["stick_stutter_rms"] == 0.0


def test_literal_reading_stutters_more_at_the_coarse_step_and_higher_mu(study_output):
    """Measured: stick RMS of ü − ü_g = 0.0072 and 0.053 m/s² at 0.005 s (mu = 0.125, 0.2), ~1e-6 at 0.001 s."""
    _, _, rows = study_output
    coarse = [summary(rows, "newmark_literal", 0.005, mu)["stick_stutter_rms"] for mu in (0.125, 0.2)]
    fine = [summary(rows, "newmark_literal", 0.001, mu)["stick_stutter_rms"] for mu in (0.125, 0.2)]
    assert coarse[1] > coarse[0] > 100 * max(fine)


def test_a_missing_record_gives_its_status_not_an_error(tmp_path):
    from stickslip.records.netcdf import write_missing_record

    record = write_missing_record("mendoza_1985", "record mendoza_1985 not found. How to obtain it: ask",
                                  tmp_path / "mendoza_1985.nc")
    cube_path, summary_path = write_timestep_study(record, tmp_path / "cube.nc", tmp_path / "summary.csv",
                                                   [0.1], [0.005], 5.1, 9.81)
    with open(summary_path, newline="", encoding="utf-8") as handle:
        (row,) = list(csv.DictReader(handle))
    assert row["record"] == "mendoza_1985" and row["status"].startswith("missing: record mendoza_1985 not found")
    with xr.open_dataset(cube_path) as data:
        assert data.attrs["status"] == row["status"] and not data.data_vars
