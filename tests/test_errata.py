"""The paper's errata, each found by a computed check (stickslip.studies.errata)."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr

from stickslip.reference import paper_tables
from stickslip.models import solve
from stickslip.solvers.harmonic import harmonic_record
from stickslip.studies import errata
from stickslip.studies.compare import compare_cells


def test_e1_table6_rms_column_is_table4_model_column():
    row = errata.table6_rms_repeats_table4()
    assert row["status"] == "confirmed" and row["value"] == 0.0
    assert row["explains"] == "table6.rms_acceleration"
    assert row["finding"].startswith("8 of 8 cells equal")


@pytest.fixture(scope="module")
def harmonic_response(tmp_path_factory):
    response = solve(harmonic_record(0.030, 2.0, 3.0, 0.001), mu=0.10, mass=5.10)
    path = tmp_path_factory.mktemp("e2") / "harmonic_model.nc"
    dataset = response.to_xarray()
    dataset.attrs["status"] = "ok"
    dataset.to_netcdf(path)
    return response, path


def test_e2_balance_closes_with_the_square_and_not_as_printed(harmonic_response):
    response, path = harmonic_response
    row = errata.balance_closure(path, "harmonic_model")
    assert row["status"] == "confirmed"
    assert row["compared_with"] < 1e-9  # ½·m·u̇²: round-off of the exact solver
    assert row["value"] > 0.05  # ½·m·u̇ as printed misses by a fraction of E_I
    # the same residual computed independently from the response
    kinetic = 0.5 * response.mass * response.absolute_velocity
    residual = kinetic - kinetic[0] + response.energy_dissipated_history - response.energy_input_history
    assert row["value"] == pytest.approx(np.max(np.abs(residual)) / np.max(np.abs(response.energy_input_history)))


def test_e2_of_a_missing_record_is_not_computed(tmp_path):
    path = tmp_path / "seismic_model.nc"
    xr.Dataset(attrs={"status": "missing: record x not found"}).to_netcdf(path)
    row = errata.balance_closure(path, "seismic_model")
    assert row["status"].startswith("missing") and row["finding"] == "not computed"


def test_e3_table8_rms_follows_its_scale_factors_and_contradicts_table6():
    row = errata.table8_rms_consistency()
    table8 = paper_tables()["table8_scaling_mendoza"]["rows"]
    assert row["compared_with"] < 0.005  # RMS / scale factor is one number to printing precision
    assert row["value"] == pytest.approx(table8[0]["rms_acceleration"] / 1.800 - 1)
    assert row["status"] == "confirmed"


def _readings(tmp_path, energies):
    """A table4_readings.csv whose relative differences are given per (amplitude, frequency)."""
    rows = []
    for (amplitude, frequency), difference in energies.items():
        rows.append({"reading": f"amplitude {amplitude * 1e3:g} mm, ramp 0 cycles", "displacement_amplitude": amplitude,
                     "ramp_cycles": 0.0, "row": f"{frequency} Hz", "frequency": frequency, "duration": 5.0,
                     "mu": 0.1, "energy_dissipated": 1.0, "paper_energy_dissipated": 1.0,
                     "relative_difference": difference, "reading_rms_relative_difference": 0.0})
    for row in rows:
        mine = [r["relative_difference"] for r in rows if r["displacement_amplitude"] == row["displacement_amplitude"]]
        row["reading_rms_relative_difference"] = float(np.sqrt(np.mean(np.square(mine))))
    path = tmp_path / "table4_readings.csv"
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return path


def test_e4_no_single_reading_is_unresolved_and_one_reading_is_not_an_erratum(tmp_path):
    split = _readings(tmp_path, {(0.030, 2.0): 1.5, (0.015, 2.0): 0.05, (0.030, 1.0): 0.02, (0.015, 1.0): -1.0})
    row = errata.harmonic_readings(split, 9.81)
    assert row["status"] == "unresolved" and "No single reading" in row["finding"]
    assert "f_f = 1.66 (f_f >= 1" in row["finding"]  # 15 mm at 1 Hz: μ·g/(u_g0·ω²) with μ = 0.1
    one = _readings(tmp_path, {(0.030, 2.0): 0.03, (0.015, 2.0): -0.6, (0.030, 1.0): 0.02, (0.015, 1.0): -1.0})
    row = errata.harmonic_readings(one, 9.81)
    assert row["status"] == "not confirmed" and "The 30 mm amplitude fits every frequency" in row["finding"]
    assert row["value"] < row["compared_with"]


def test_confirmed_errata_mark_comparison_cells_but_not_missing_records():
    rows = [{"check": "E1", "status": "confirmed", "explains": "table6.rms_acceleration"},
            {"check": "E4", "status": "unresolved", "explains": "table4.energy_dissipated"}]
    marks = errata.confirmed_errata(rows)
    assert list(marks) == ["table6.rms_acceleration"] and marks["table6.rms_acceleration"].startswith("paper erratum: E1")
    paper = {"a": {"rms_acceleration": 1.923, "pga": 6.49}, "b": {"rms_acceleration": 1.8, "pga": 4.68}}
    ours = {"a": {"rms_acceleration": 1.156, "pga": 6.5}}
    cells = compare_cells("table6", ours, paper, ["pga", "rms_acceleration"], {"default": 0.05},
                          missing={"b": "missing: record b not found"}, errata=marks)
    status = {(c["row"], c["column"]): c["status"] for c in cells}
    assert status["a", "pga"] == "ok"
    assert status["a", "rms_acceleration"].startswith("paper erratum: E1")
    assert status["b", "rms_acceleration"].startswith("missing")
