"""The collection study: mean period, SLAMMER's conventions and the check, the scaling law, leave-one-event-out,
the prediction band, records left out and the fewest records for a verdict, and the study end to end (the .test/
configuration's pyslammer collection, and a folder of AT2 files with a config of its own)."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
import xarray as xr
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import REPO_ROOT, require_shared_records, snakemake
from stickslip.collections import RecordFilter, load_collection
from stickslip.collections.slammer_measures import database_tolerance, slammer_convention
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.plumbing.files import read_csv_rows
from stickslip.measures import mean_period
from stickslip.records.record import Record, RecordMeta
from stickslip.models.rigid.exact import SCALAR_NAMES, sweep_scalars
from stickslip.studies.collections.analysis import design_chart
from stickslip.studies.collections.measures import chunk_measures
from stickslip.collections.members import left_out, studied
from stickslip.studies.collections.relations import (leave_one_event_out_splits, loeo_errors, prediction_band,
                                                    relations_rows)
from stickslip.studies.collections.friction_design import claims_rows, coverage_rows, near_far_reason
from stickslip.studies.collections.measures_check import check_rows, summary
from stickslip.studies.collections.scaling_law import scaling_law_rows

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


def _study_row(record_id: str, pga: float, mu_max: float, optimum_status: str = "ok", status: str = "ok") -> dict:
    """A row of records.csv (the columns the analysis reads), as text."""
    moving = optimum_status == "ok"
    return {"id": record_id, "event": f"event {record_id[-1]}", "status": status, "reason": "",
            "optimum_status": optimum_status, "pga": str(pga), "rms_acceleration": str(pga / 3),
            "mu_max_continuous": str(mu_max) if moving else "",
            "mu_max_g_over_pga": str(mu_max * 9.81 / pga) if moving else "", "efficiency": "0.9" if moving else ""}


def test_records_left_out_are_named_and_a_verdict_needs_min_records():
    rows = [_study_row(f"r{k}", 2.0 + k, 0.05 + 0.02 * k) for k in range(4)]
    rows.append(_study_row("weak", 0.01, 0.0, "never slides: PGA 0.01 m/s2 is below mu*g = 0.0245 m/s2"))
    rows.append({**_study_row("gone", 1.0, 0.0, "not solved", status="missing"), "reason": "not here"})
    assert [row["id"] for row in studied(rows)] == ["r0", "r1", "r2", "r3"]
    assert [(row["id"], row["group"], row["reason"]) for row in left_out(rows)] == [
        ("weak", "never slides", rows[4]["optimum_status"]), ("gone", "not read", "missing: not here")]
    relations = relations_rows(rows, n_boot=50, seed=0, min_records=5)
    assert relations[0]["status"] == "too few records: 4 with a value of PGA, a fit needs at least 5"
    mu = np.linspace(0.02, 0.3, 15)
    energy = np.array([np.exp(-((mu - 0.05 - 0.02 * k) / 0.05) ** 2) for k in range(4)])
    cube = xr.Dataset({"energy_dissipated": (("record", "mu"), energy)}, coords={"mu": mu})
    coverage = coverage_rows(cube, np.array([0.2, 0.3, 0.4, 0.5]), [0.0, 3.0], 0.1, 0.95, 0.9, 0.8,
                             np.full(4, 0.9), min_records=5)
    assert {row["status"] for row in coverage} == {"too few records: 4, a verdict needs at least 5 "
                                                   "(collection_study.min_records)"}
    claims = claims_rows(relations, coverage, 4, 0.1)
    assert len(claims) == 3 and all(row["verdict"].startswith("not tested: too few records: 4") for row in claims)
    chart = design_chart(rows, relations, 9.81, min_records=5)
    assert chart["status"].startswith("no fit: too few records: 4") and "ratio_quantiles" not in chart
    assert chart["ratio_status"].startswith("too few records: 4") and len(chart["pga_points"]) == 4
    assert near_far_reason(rows, 20.0, 5) == "no record studied has a rupture distance"


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


def test_stickslip_optimum_gives_the_collection_study_s_mu_max_to_the_last_digit(test_workflow, run_cli):
    """One route to mu_max: the study's table and `stickslip optimum` on the same file and grid agree exactly."""
    config = yaml.safe_load((REPO_ROOT / ".test" / "config" / "config.yaml").read_text())
    grid = config["collection_study"]["mu"]
    rows = read_csv_rows(test_workflow / "collections" / "pyslammer" / "records.csv")
    samples = load_collection("pyslammer")
    for row in rows:
        path = samples.local_file(row["id"])
        code, out, err = run_cli("optimum", path, "--mu", f"{grid['start']}:{grid['stop']}:{grid['step']}",
                                 "--mass", str(config["block_mass"]), "--range-points", "0",
                                 "--json")  # the study's grid and block as they are, unrefined
        assert code == 0, err
        ours = json.loads(out)["records"][0]
        for name in ("mu_max", "mu_max_continuous", "energy_dissipated_max_continuous", "mu_low", "mu_high",
                     "largest_stroke", "efficiency"):
            assert ours[name] == float(row[name]), (row["id"], name)  # to the last digit


def write_at2(path, event: str, station: str, acceleration_g: np.ndarray, dt: float) -> None:
    """A PEER NGA-West2 AT2 file of ``acceleration_g`` [g] at step ``dt`` [s]."""
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", f"{event}, 1/1/2001, {station}, H1",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS= {acceleration_g.size:6d}, DT= {dt:.4f} SEC,"]
    lines += ["".join(f"{value:15.7E}" for value in acceleration_g[start:start + 5])
              for start in range(0, acceleration_g.size, 5)]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")


def synthetic_motion(pga_g: float, frequency: float, seed: int, dt: float = 0.01) -> np.ndarray:
    """A decaying, noisy sine of 20 s [g] scaled to ``pga_g``."""
    time = np.arange(0.0, 20.0, dt)
    motion = np.sin(2 * np.pi * frequency * time) * time * np.exp(-0.15 * time)
    motion += np.random.default_rng(seed).normal(0.0, 0.2, time.size)
    return motion * pga_g / np.abs(motion).max()


#: The generated records of the folder study: file stem -> (event, PGA [g], frequency [Hz]).
GENERATED = {"SYN1": ("Synthetic A", 0.25, 1.0), "SYN2": ("Synthetic A", 0.3, 1.7), "SYN3": ("Synthetic B", 0.5, 1.3),
             "SYN4": ("Synthetic B", 0.55, 2.1), "SYN5": ("Synthetic C", 0.8, 0.9)}


def test_the_own_folder_study_end_to_end_from_the_users_config(tmp_path, run_cli):
    """docs/collections.md: a folder of AT2 files (shared and generated, one too weak to slide) and a config of its own."""
    shared = require_shared_records()
    folder = tmp_path / "my_at2_files"
    folder.mkdir()
    for path in [*(shared / "formats").glob("*.AT2"), shared / "paper" / "CHY080-N.AT2"]:
        shutil.copy(path, folder / path.name)
    for index, (stem, (event, pga, frequency)) in enumerate(GENERATED.items()):
        write_at2(folder / f"{stem}.AT2", event, f"STA{index}", synthetic_motion(pga, frequency, index), 0.01)
    weak = synthetic_motion(0.001, 2.0, 9)  # below mu*g at the grid's smallest mu, 0.01: it never slides
    write_at2(folder / "WEAK.AT2", "Synthetic D", "FAR", weak, 0.01)
    headless = synthetic_motion(0.4, 1.2, 11, dt=0.02)  # one column, no time step: the folder's dt serves it
    (folder / "headless.txt").write_text("\n".join(f"{value:.7f}" for value in headless) + "\n", encoding="ascii")
    (folder / "BROKEN.AT2").write_text("PEER NGA STRONG MOTION DATABASE RECORD\nno header\n", encoding="ascii")
    (folder / "README.txt").write_text("My AT2 files\n============\nFrom PEER and made up.\n", encoding="utf-8")
    (folder / "notes.md").write_text("# notes\n\nSYN5 is the strongest.\n", encoding="utf-8")
    configfile = tmp_path / "my.yaml"  # only what differs from config/config.yaml
    configfile.write_text(yaml.safe_dump({
        "collection_study": {"collection": "folder", "folder": str(folder), "dt": 0.02,
                             "mu": {"start": 0.01, "stop": 1.0, "step": 0.01}},
        "relations": {"n_boot": 200}}), encoding="utf-8")
    workdir = tmp_path / "work"
    workdir.mkdir()
    result = snakemake(workdir, configfile, "reports/html/collection_study.html")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]

    study = workdir / "results" / "collections" / "folder"
    rows = {row["id"]: row for row in read_csv_rows(study / "records.csv")}
    assert len(rows) == 3 + len(GENERATED) + 2  # README.txt and notes.md are no records: skipped
    assert rows["broken"]["status"] == "rejected" and "BROKEN.AT2: PEER AT2 header has no" in rows["broken"]["reason"]
    assert read_csv_rows(study / "skipped.csv") == [{"file": "README.txt", "reason": "text without rows of numbers"},
                                                    {"file": "notes.md", "reason": "text without rows of numbers"}]
    readable = {record_id: row for record_id, row in rows.items() if record_id != "broken"}
    assert all(row["status"] == "ok" for row in readable.values())
    assert rows["headless"]["format"] == "slammer_1col" and float(rows["headless"]["dt"]) == 0.02
    assert rows["weak"]["optimum_status"].startswith("never slides: E_df = 0 at every mu of the grid; its PGA")
    assert rows["weak"]["mu_max_continuous"] == rows["weak"]["efficiency"] == ""
    assert float(rows["weak"]["energy_dissipated_max"]) == 0.0
    sliding = [row for record_id, row in readable.items() if record_id != "weak"]
    for row in sliding:  # one route to mu_max: `stickslip optimum` on the same file and grid, to the last digit
        step = ["--dt", "0.02"] if row["id"] == "headless" else []  # the folder's dt serves the headless file
        code, out, err = run_cli("optimum", folder / row["file"], "--mu", "0.01:1:0.01", "--range-points", "0", *step,
                                 "--json")
        assert code == 0, err
        assert json.loads(out)["records"][0]["mu_max_continuous"] == float(row["mu_max_continuous"]), row["id"]
    assert all(row["optimum_status"] == "ok" for row in sliding)
    for row in sliding:
        assert 0 < float(row["mu_max_continuous"]) < float(row["pga"]) / 9.81
        assert 0 < float(row["efficiency"]) <= 1 + 1e-12
    relations = {row["predictor"]: row for row in read_csv_rows(study / "relations.csv")}
    assert relations["pga"]["status"] == "ok" and relations["pga"]["n"] == str(len(sliding))
    assert relations["mw"]["status"] == "no record has a value of moment magnitude Mw"
    claims = read_csv_rows(study / "claims.csv")
    assert len(claims) == 3 and not any(row["verdict"].startswith("not tested") for row in claims)
    bands = {row["pga_band"]: row for row in read_csv_rows(study / "coverage.csv")}
    assert bands["all records"]["n"] == str(len(sliding)) and bands["all records"]["status"] == "ok"
    for label, band in bands.items():  # min_records is 5: no band of these records has a verdict
        if label != "all records":
            assert band["status"] in ("no records in this band", f"too few records: {band['n']}, a verdict needs "
                                      "at least 5 (collection_study.min_records)")
    assert read_csv_rows(study / "near_far.csv") == []
    figures = workdir / "reports" / "figures" / "collection"
    assert (figures / "measures_check.png").stat().st_size > 5_000  # "Not drawn": no published measures

    page = (workdir / "reports" / "html" / "collection_study.html").read_text(encoding="utf-8")
    assert "<title>Beyond the paper: friction energy over a record collection</title>" in page
    assert "hl-ipython3" not in page and "from stickslip" not in page  # no code cells
    assert ("1 record never slid at any μ of the grid</b>, left out of every fit: weak (never slides: E_df = 0 at "
            "every mu") in page
    assert f"<b>{len(sliding)} of {len(rows)} record files studied</b>" in page
    assert "<b>1 record could not be read</b>, left out of every fit: broken (rejected: " in page
    assert ("2 other files of the folder, not record files, skipped: README.txt (text without rows of numbers); "
            "notes.md (text without rows of numbers).") in page
    assert (figures / "energy_curves.png").stat().st_size > 20_000  # every record's E_df(mu), drawn for a few records
    assert all(f"<td style=\"text-align:left\">{record_id}</td>" in page for record_id in rows)  # per-record table
    assert "Not compared: no record studied has a rupture distance." in page
    assert "this collection publishes no intensity measures" in page


def test_the_page_s_tables_speak_words_with_units_and_fit_its_width():
    """The collection page's tables: a heading in words with its units, an interval beside its value, ten columns at
    most, and no variable name, no unit "1", no exponent form, no minus zero in a cell."""
    import re

    from stickslip.studies.collections import tables as collection_tables

    scatter = np.random.default_rng(7).uniform(-1.0, 1.0, (2, 8))
    rows = [_study_row(f"r{k}", 2.0 + k, 0.05 + 0.01 * k + 0.02 * scatter[0, k]) for k in range(8)]
    for k, row in enumerate(rows):  # an RMS acceleration of its own, not a multiple of the PGA
        row["rms_acceleration"] = str(1.0 + 0.4 * scatter[1, k])
    relations = relations_rows(rows, n_boot=50, seed=0, min_records=5)
    mu = np.linspace(0.02, 0.3, 15)
    energy = np.array([np.exp(-((mu - 0.05 - 0.02 * k) / 0.05) ** 2) for k in range(8)])
    cube = xr.Dataset({"energy_dissipated": (("record", "mu"), energy)}, coords={"mu": mu})
    coverage = [{key: str(value) for key, value in row.items()} for row in  # as the page reads coverage.csv
                coverage_rows(cube, np.linspace(0.2, 0.9, 8), [0.0, 0.5, 3.0], 0.1, 0.95, 0.9, 0.8, np.full(8, 0.9),
                              min_records=5)]
    law = [{"record": "r0", "factor": "0.5", "max_relative_energy_difference": "0.0", "mu_max": "0.0562706",
            "mu_max_scaled": "0.0281354", "mu_max_ratio": "0.999995"}]
    near_far = [{"quantity": "pga", "units": "m s-2", "n_near": "6", "n_far": "9", "median_near": "3.5",
                 "median_far": "1.25", "mann_whitney_p_value": "0.0123"}]
    beyond = [{"record": "r1", "measure": "pga", "published": 0.25, "ours_slammer_convention": 0.2512,
               "explanation": "rounded up"}]
    tables = {"relations": collection_tables.relations_table(relations),
              "coverage": collection_tables.coverage_table(coverage),
              "scaling": collection_tables.scaling_law_table(law),
              "near_far": collection_tables.near_far_table(near_far),
              "beyond": collection_tables.beyond_table(beyond)}
    for name, (table_rows, columns) in tables.items():
        assert table_rows and len(columns) <= 10, name
        for key, heading in columns:
            assert not re.search(r"[a-z]+_[a-z]+", heading) and "[1]" not in heading, (name, heading)
        for row in table_rows:
            for value in row.values():
                text = str(value)
                assert not re.search(r"e\+0|(?<![\d.])-0(\.0+)?(?![\d.])", text), (name, text)
    relation_rows, columns = tables["relations"]
    pga = next(row for row in relations if row["predictor"] == "pga")
    assert relation_rows[0]["predictor"] == "PGA" and relation_rows[0]["units"] == "m/s2"
    assert relation_rows[0]["pearson"] == (f"{pga['pearson_r']:.3g} [{pga['pearson_r_low']:.3g}, "
                                           f"{pga['pearson_r_high']:.3g}]")
    band = tables["coverage"][0][0]
    assert band["band"] == "all records" and band["records"] == 8
    assert band["reference"].endswith("median efficiency 0.9")
    assert tables["coverage"][1][0] == ("band", "PGA band") and ("reference", "μ = 0.1") in tables["coverage"][1]
    assert tables["near_far"][0][0]["units"] == "m/s2" and tables["beyond"][0][0]["measure"] == "PGA [g]"


def test_counts_of_records_have_whole_ticks():
    from stickslip.studies.collections.plots import plot_ratio_and_efficiency

    rows = [_study_row(f"r{k}", 2.0 + k, 0.05 + 0.01 * k) for k in range(3)]  # one or two records per bar
    figure = plot_ratio_and_efficiency(rows, 0.1)
    for ax in figure.axes:
        ticks = ax.get_yticks()
        assert ticks.size >= 2 and all(float(tick).is_integer() for tick in ticks), ticks
