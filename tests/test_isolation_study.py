"""The isolation study's steps on the two horizontal components of one station: a building on friction pendulums
against the same building on a fixed base.

Gilroy Array #6 (Coyote Lake 1979, components 230 and 320, 0.005 s) is one of the SLAMMER library's station pairs
and among the shared paper records: its pair goes through the pair job's step (a ``pairs.csv`` row and a record
store), the gathering and the tables; the bearing that never slides is the fixed-base building; the fixed base is
the single oscillator; the summary's statistics are checked by hand; without records the tables are empty and the
study says how to get them.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from conftest import read_shared_paper_record
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.errors import StickslipError
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.response_spectrum import relative_displacement
from stickslip.studies.isolation.index import isolation_section_html
from stickslip.solvers.structure.friction_linked import search_points
from stickslip.solvers.structure.linear_response import linear_history
from stickslip.solvers.structure.shear_building import uniform_building
from stickslip.studies.isolation.response import fixed_base_peaks, isolated_system
from stickslip.studies.isolation.sweep import (gather_isolation_study, study_settings, write_pair_chunk_cube,
                                               write_three_component_cube)
from stickslip.studies.isolation.tables import summary_rows, write_isolation_tables
from stickslip.sweeps import read_cube

G = 9.81
#: Two periods, one radius, a friction that slides and one no record can overcome (μg = 49 m/s²).
SETTINGS = {"periods": [0.3, 1.0], "radii": [2.0], "mu": [0.05, 5.0], "mass_ratio": 1.0, "damping_ratio": 0.02}
FILES = {"G06-230": "SLAMMER_Coyote_Lake_1979_G06-230.txt", "G06-320": "SLAMMER_Coyote_Lake_1979_G06-320.txt"}


@pytest.fixture(scope="module")
def pair_study(paper_records_dir, tmp_path_factory):
    """The pair job, an empty three-component job, the gathering and the tables, on Gilroy Array #6."""
    folder = tmp_path_factory.mktemp("isolation")
    records = {name: read_shared_paper_record(paper_records_dir, file) for name, file in FILES.items()}
    write_record_store([StoredRecord(name, record, "ok") for name, record in records.items()], folder / "store.nc")
    write_csv_atomic(folder / "pairs.csv", [{"pair": "Coyote Lake 1979/G06", "chunk": "000", "status": "ok",
                                             "first": "G06-230", "second": "G06-320", "first_component": "G06-230",
                                             "second_component": "G06-320", "rupture_distance": "3.1"}])
    for period in SETTINGS["periods"]:
        write_pair_chunk_cube(folder / "pairs.csv", [folder / "store.nc"], folder / f"pairs_{period}.nc", "000",
                              SETTINGS, period, G)
        write_three_component_cube(folder / f"three_{period}.nc", SETTINGS, period, G)
    cubes = [folder / f"{name}_{period}.nc" for name in ("pairs", "three") for period in SETTINGS["periods"]]
    gather_isolation_study(cubes, folder / "isolation.nc", len(SETTINGS["periods"]))
    paths = [folder / name for name in ("cases.csv", "summary.csv", "near_far.csv", "study.json")]
    write_isolation_tables(*paths, folder / "isolation.nc", SETTINGS, "slammer", 20.0, 5, "the sentence on how")
    return {"records": records, "cube": read_cube(folder / "isolation.nc"), "cases": read_csv_rows(paths[0]),
            "summary": read_csv_rows(paths[1]), "near_far": read_csv_rows(paths[2]),
            "document": json.loads(paths[3].read_text()), "folder": folder}


def test_a_bearing_that_never_slides_is_the_building_on_a_fixed_base(pair_study):
    """At μ = 5 the bearing holds throughout: the drift and the floor acceleration are the fixed base's (ratio 1 to
    1e-9) and the isolator does not move; at μ = 0.05 it slides and the drift falls."""
    cube = pair_study["cube"]
    held = cube.sel(mu=5.0)
    assert np.allclose(held.drift_ratio, 1.0, rtol=0, atol=1e-9)
    assert np.allclose(held.floor_acceleration_ratio, 1.0, rtol=0, atol=1e-9)
    assert np.all(held.peak_isolator_displacement.values == 0.0)
    sliding = cube.sel(mu=0.05)
    assert np.all(sliding.peak_isolator_displacement.values > 0.01)
    assert np.all(sliding.drift_ratio.values < 0.6)


def test_the_fixed_base_is_the_single_oscillator_at_the_same_instants_as_the_isolated_building(pair_study):
    """The held bearing's peaks are the oscillator's, taken at the samples and the scheme's search points between
    them (the first-order hold on the record resampled there, to 1e-9); at the samples alone a little less."""
    record = pair_study["records"]["G06-230"]
    for period in (0.3, 1.0):
        system, _ = isolated_system(period, 1.0, 0.02, math.inf, G)
        points = search_points(np.stack(system.phase_matrices()), record.dt)
        fine = np.interp(np.arange((record.npts - 1) * points + 1) / points, np.arange(record.npts),
                         record.acceleration)
        building = uniform_building(1, period, 1.0, 0.02)
        history = linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix, np.ones(1),
                                 fine, record.dt / points)
        peaks = fixed_base_peaks([record], period, 1.0, 0.02, G)
        assert peaks.drift[0] == pytest.approx(np.abs(history.displacement).max(), rel=1e-9)
        assert peaks.floor_acceleration[0] == pytest.approx(np.abs(history.absolute_acceleration).max(), rel=1e-9)
        at_samples = np.abs(relative_displacement(record.acceleration, record.dt, period, 0.02)).max()
        assert at_samples <= peaks.drift[0] <= at_samples * (1 + 2e-3)


def test_the_cube_carries_each_component_its_units_and_the_fixed_base(pair_study):
    cube = pair_study["cube"]
    assert dict(cube.sizes) == {"record": 2, "period": 2, "radius": 1, "mu": 2}
    assert list(cube.record.values) == ["G06-230", "G06-320"]
    assert set(cube.library.values) == {"slammer"} and set(cube.station.values) == {"Coyote Lake 1979/G06"}
    assert cube.rupture_distance.values.tolist() == [3.1, 3.1]
    units = {name: cube[name].attrs["units"] for name in cube.data_vars}
    assert units == {"peak_drift": "m", "peak_floor_acceleration": "m s-2", "peak_isolator_displacement": "m",
                     "drift_ratio": "1", "floor_acceleration_ratio": "1", "fixed_base_peak_drift": "m",
                     "fixed_base_peak_floor_acceleration": "m s-2"}
    assert cube.period.attrs["units"] == "s" and cube.radius.attrs["units"] == "m" and cube.mu.attrs["units"] == "1"
    ratio = cube.peak_drift / cube.fixed_base_peak_drift
    assert np.allclose(cube.drift_ratio, ratio, rtol=1e-15)


def test_the_summary_is_the_median_and_the_16_84_band_over_the_records(pair_study):
    cases = pair_study["cases"]
    assert len(cases) == 2 * 2 * 1 * 2
    for row in pair_study["summary"]:
        values = [float(case[row["quantity"]]) for case in cases
                  if (case["period"], case["radius"], case["mu"]) == (row["period"], row["radius"], row["mu"])]
        assert row["library"] == "slammer" and int(row["records"]) == 2
        # two values: the median their mean, the percentiles linear between them
        low, high = sorted(values)
        assert float(row["median"]) == pytest.approx((low + high) / 2, rel=1e-12)
        assert float(row["p16"]) == pytest.approx(low + 0.16 * (high - low), rel=1e-12)
        assert float(row["p84"]) == pytest.approx(low + 0.84 * (high - low), rel=1e-12)


def test_the_study_document_names_the_best_pendulum_per_period_and_what_is_missing(pair_study):
    document = pair_study["document"]
    assert document["available"] is True and document["components"] == {"slammer": 2, "three_component": 0}
    assert document["pairs_status"] == "ok" and document["three_component_status"] == "the sentence on how"
    assert document["pooled"] == "slammer"
    assert [(cell["period"], cell["mu"]) for cell in document["best"]] == [(0.3, 0.05), (1.0, 0.05)]
    drift = {(row["period"], row["mu"]): float(row["median"]) for row in pair_study["summary"]
             if row["quantity"] == "drift_ratio"}
    assert document["best"][0]["drift_ratio_median"] == pytest.approx(drift["0.3", "0.05"], rel=1e-12)
    assert document["far_field_status"].startswith("Near-fault against far-field is not compared: too few "
                                                   "components: 2 within 20 km of the rupture and 0 farther")
    assert "STICKSLIP_SLAMMER_DIR" in document["far_field_status"]  # near-fault records alone: how to add the rest
    assert pair_study["near_far"] == [] and document["near_far"]["compared"] is False
    assert document["near_far"]["components"] == {"near": 2, "far": 0, "unknown": 0}
    largest = max(pair_study["cases"], key=lambda row: float(row["peak_isolator_displacement"]))
    assert document["largest_isolator_displacement"]["peak_isolator_displacement"] == pytest.approx(
        float(largest["peak_isolator_displacement"]), rel=1e-12)
    assert document["largest_isolator_displacement"]["component"] == largest["component"]
    assert "rupture_distance" not in document["largest_isolator_displacement"]
    no_plane = pair_study["folder"] / "vertical_summary.csv"  # the in-plane part's, without its records
    no_plane.write_text("period,radius,mu,quantity,stations,median,p16,p84\n", encoding="utf-8")
    html = isolation_section_html(pair_study["folder"] / "study.json", no_plane, "reports/html/isolation_study.html",
                                  "reports")
    assert "T = 0.3 s: R = 2 m, μ = 0.05: drift ratio" in html and 'href="html/isolation_study.html"' in html


def test_without_records_the_tables_are_empty_and_the_study_says_how_to_get_them(tmp_path):
    for period in SETTINGS["periods"]:
        write_three_component_cube(tmp_path / f"three_{period}.nc", SETTINGS, period, G)
    gather_isolation_study([tmp_path / f"three_{period}.nc" for period in SETTINGS["periods"]],
                           tmp_path / "isolation.nc", len(SETTINGS["periods"]))
    paths = [tmp_path / name for name in ("cases.csv", "summary.csv", "near_far.csv", "study.json")]
    write_isolation_tables(*paths, tmp_path / "isolation.nc", SETTINGS, "pyslammer", 20.0, 5,
                           "The three-component records were not available (no folder configured): copy them.")
    assert paths[0].read_text().splitlines() == [",".join(["library", "station", "component", "record",
                                                           "rupture_distance", "period", "radius", "mu", "peak_drift",
                                                           "peak_floor_acceleration", "peak_isolator_displacement",
                                                           "drift_ratio", "floor_acceleration_ratio",
                                                           "fixed_base_peak_drift",
                                                           "fixed_base_peak_floor_acceleration"])]
    assert len(paths[1].read_text().splitlines()) == 1
    assert len(paths[2].read_text().splitlines()) == 1
    document = json.loads(paths[3].read_text())
    assert document["available"] is False and document["best"] == []
    assert document["pairs_status"].startswith("The SLAMMER library's station pairs were not available (the "
                                               "collection study ran on the pyslammer collection")
    assert "STICKSLIP_SLAMMER_DIR" in document["pairs_status"]
    no_plane = tmp_path / "vertical_summary.csv"
    no_plane.write_text("period,radius,mu,quantity,stations,median,p16,p84\n", encoding="utf-8")
    html = isolation_section_html(paths[3], no_plane, None, tmp_path)
    assert "No record: The SLAMMER library&#x27;s station pairs were not available" in html
    assert "The three-component records were not available" in html


def test_a_grid_out_of_order_is_one_line_naming_its_key():
    with pytest.raises(StickslipError, match=r"^isolation_study.periods: values must be strictly increasing"):
        study_settings({**SETTINGS, "periods": [1.0, 0.3]})
    with pytest.raises(StickslipError, match=r"^isolation_study.mu: every value must be a positive finite number"):
        study_settings({**SETTINGS, "mu": [0.0, 0.05]})


def test_the_summary_pools_the_libraries_when_there_are_two():
    rows = [{"library": library, "record": name, "period": "0.5", "radius": "2", "mu": "0.06", "drift_ratio": value,
             "floor_acceleration_ratio": value, "peak_isolator_displacement": value}
            for library, name, value in (("slammer", "A", 0.2), ("slammer", "B", 0.4),
                                         ("three_component", "C", 0.9))]
    summary = {(row["library"], row["quantity"]): row for row in summary_rows(rows)}
    assert summary["all", "drift_ratio"]["records"] == 3 and summary["all", "drift_ratio"]["median"] == 0.4
    assert summary["three_component", "drift_ratio"]["p84"] == 0.9
    assert math.isclose(summary["slammer", "drift_ratio"]["median"], 0.3)
