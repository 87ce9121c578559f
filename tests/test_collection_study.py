"""The collection study: mean period, SLAMMER's conventions and the check, the scaling law, leave-one-event-out,
the prediction band, and the study end to end (the .test/ configuration's pyslammer collection)."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import require_shared_records
from stickslip.collections import RecordFilter, load_collection
from stickslip.collections.slammer_measures import database_tolerance, slammer_convention
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.io import read_csv_rows
from stickslip.measures import mean_period
from stickslip.records.record import Record, RecordMeta
from stickslip.solvers.exact import SCALAR_NAMES, sweep_scalars
from stickslip.studies.collection_measures import chunk_measures
from stickslip.studies.collection_relations import (leave_one_event_out_splits, loeo_errors, prediction_band,
                                                    relations_rows)
from stickslip.studies.measures_check import check_rows, summary
from stickslip.studies.scaling_law import scaling_law_rows

ENERGY = SCALAR_NAMES.index("energy_dissipated")


def test_mean_period_of_a_sine_is_its_period():
    dt = 0.005
    time = np.arange(0, 40, dt)
    assert mean_period(np.sin(2 * np.pi * 2.0 * time), dt) == pytest.approx(0.5, rel=0.02)
    assert mean_period(np.sin(2 * np.pi * 0.5 * time) + 0.0 * time, dt) == pytest.approx(2.0, rel=0.02)


def test_mean_period_is_nan_without_a_frequency_in_the_band():
    assert np.isnan(mean_period(np.array([0.1, -0.1, 0.2]), 0.01))


def test_slammer_convention_counts_whole_samples_and_uses_its_constant():
    g = 9.81
    in_g = np.array([0.0, 0.1, -0.2, 0.4, -0.1, 0.05, 0.0])
    values = slammer_convention(in_g * g, 0.02, g)
    in_m = in_g * 9.80665
    assert values["pga"] == pytest.approx(0.4)
    assert values["arias_intensity"] == pytest.approx(0.1603 * 0.02 * np.sum(in_m ** 2))
    cumulative = np.cumsum(in_m ** 2)
    inside = (cumulative >= 0.05 * cumulative[-1]) & (cumulative <= 0.95 * cumulative[-1])
    assert values["dobry_duration"] == pytest.approx(0.02 * inside.sum()) and inside.sum() == 2  # samples 2 and 3
    assert database_tolerance("dobry_duration") == pytest.approx(0.05)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.floats(-3.0, 3.0), min_size=20, max_size=300), st.sampled_from([0.5, 2.0, 3.0]))
def test_scaling_law_energy_scales_with_the_square(values, factor):
    acceleration = np.asarray(values) * 9.81
    mu = np.array([0.02, 0.05, 0.1, 0.2])
    energy = sweep_scalars([acceleration], [0.01], mu, 9.81)[0, :, ENERGY]
    scaled = sweep_scalars([factor * acceleration], [0.01], factor * mu, 9.81)[0, :, ENERGY]
    np.testing.assert_allclose(scaled, factor ** 2 * energy, rtol=1e-12, atol=1e-12 * max(1.0, energy.max()))


def test_scaling_law_rows_show_mu_max_proportional_to_pga(tmp_path):
    rng = np.random.default_rng(3)
    time = np.arange(0, 20, 0.01)
    acceleration = 3.0 * np.sin(2 * np.pi * 1.3 * time) * np.exp(-0.1 * time) + rng.normal(0, 0.5, time.size)
    record = Record(acceleration, 0.01, RecordMeta(record_id="synthetic"))
    store = write_record_store([StoredRecord("synthetic", record, "ok")], tmp_path / "store.nc")
    rows = scaling_law_rows(store, {"start": 0.005, "stop": 0.6, "step": 0.005}, [0.5, 2.0], 9.81)
    for row in rows:
        assert row["max_relative_energy_difference"] < 1e-12
        assert row["mu_max_ratio"] == pytest.approx(1.0, abs=1e-4)


def test_leave_one_event_out_leaves_each_event_out_whole():
    events = ["a", "b", "a", "c", "b", "a"]
    splits = leave_one_event_out_splits(events)
    assert len(splits) == 3
    tested = np.concatenate([test for _, test in splits])
    assert sorted(tested.tolist()) == list(range(6))
    for train, test in splits:
        assert len({events[i] for i in test}) == 1
        assert not {events[i] for i in test} & {events[i] for i in train}


def test_leave_one_event_out_errors_vanish_on_a_line_and_not_for_the_mean():
    x = np.arange(12.0)
    y = 0.02 * x + 0.01
    events = np.repeat(["a", "b", "c", "d"], 3)
    line, mean = loeo_errors(x, y, events)
    np.testing.assert_allclose(line, 0.0, atol=1e-12)
    assert np.all(np.abs(mean) > 0)


def test_prediction_band_holds_about_95_percent_of_new_points():
    rng = np.random.default_rng(0)
    x = rng.uniform(0, 10, 200)
    y = 0.01 * x + rng.normal(0, 0.02, x.size)
    new_x = rng.uniform(0, 10, 4000)
    new_y = 0.01 * new_x + rng.normal(0, 0.02, new_x.size)
    band = prediction_band(x, y, new_x)
    inside = (new_y >= np.array(band["low"])) & (new_y <= np.array(band["high"]))
    assert 0.93 < inside.mean() < 0.97


def test_relations_need_enough_records():
    rows = [{"status": "ok", "optimum_status": "ok", "event": "e", "mu_max_continuous": "0.1", "pga": "3"}
            for _ in range(2)]
    relation = relations_rows(rows, n_boot=100, seed=0, min_records=5)[0]
    assert relation["predictor"] == "pga" and relation["status"].startswith("too few records: 2")


def test_measures_match_the_slammer_database_on_the_shared_near_fault_records(tmp_path):
    folder = require_shared_records() / "slammer"
    library = load_collection("slammer", folder).select(RecordFilter(max_rupture_distance=20.0))
    ids = library.local_ids()
    assert len(ids) == 521
    store = write_record_store([StoredRecord(i, library.read(i), "ok") for i in ids], tmp_path / "store.nc")
    measured = {row["record"]: row for row in chunk_measures(store, 9.81)}
    rows = [{**library.table.loc[i].to_dict(), **measured[i]} for i in ids]
    table = check_rows(rows)
    result = summary(table, 0.99)
    assert result["checked"] == 4 * 521 and result["passes"]
    assert result["pass_rate"] >= 0.99
    for row in table:  # every value within the database's rounding of its measure
        assert row["status"] == "within tolerance", row
        assert abs(row["ours_rounded"] - row["published"]) <= 1.5 * 10 ** -{"pga": 3, "arias_intensity": 3,
                                                                           "dobry_duration": 1,
                                                                           "mean_period": 2}[row["measure"]]
    own_pga = [abs(row["own_definition_relative_difference"]) for row in table if row["measure"] == "pga"]
    assert max(own_pga) < 0.01  # our g = 9.81 and SLAMMER's file values differ by the database's rounding only


def test_the_small_collection_study_end_to_end(test_workflow):
    folder = test_workflow / "collections" / "pyslammer"
    rows = read_csv_rows(folder / "records.csv")
    assert len(rows) == 18 and all(row["status"] == "ok" for row in rows)
    for row in rows:
        assert 0 < float(row["mu_max_continuous"]) < float(row["pga"]) / 9.81
        assert float(row["mu_low"]) <= float(row["mu_max"]) <= float(row["mu_high"])
        assert 0 <= float(row["efficiency"]) <= 1 + 1e-12
    claims = read_csv_rows(folder / "claims.csv")
    assert [row["verdict"] != "" for row in claims] == [True, True, True]
    check = json.loads((folder / "measures_check.json").read_text())
    assert check["checked"] == 4 * 18 and check["passes"]
    near_far = read_csv_rows(folder / "near_far.csv")
    assert near_far and near_far[0]["n_far"] == "3"
    law = read_csv_rows(folder / "scaling_law.csv")
    assert max(float(row["max_relative_energy_difference"]) for row in law) < 1e-12
    index = (test_workflow.parent / "reports" / "index.html").read_text()
    assert "Beyond the paper: the pyslammer collection study" in index and "18 records" in index
    assert (test_workflow.parent / "reports" / "figures" / "collection" / "design_chart.png").stat().st_size > 10_000
