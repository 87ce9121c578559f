"""The paper's studies (Tables 4 to 8 and the mass check), run by the workflow on the shared records."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr
from conftest import CONFIG_SCHEMA, PROJECT_CONFIG, project_config

from stickslip.plumbing.config import check_config_semantics, load_config
from stickslip.errors import StickslipError
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, relative_difference

AVAILABLE = ["cape_mendocino", "chichi_chy080n", "coyote_g06_230", "coyote_g06_320", "kobe_kjm090", "northridge_nwh090"]
MISSING = ["mendoza_1985", "parkfield_c02_360"]


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


@pytest.fixture(scope="module")
def config():
    return project_config()


@pytest.fixture(scope="module")
def results(paper_workflow):
    """The workflow's results folder on the shared paper records."""
    return paper_workflow


def test_table6_mu_max_matches_the_paper_for_five_of_six_records(results):
    out_dir = results
    rows = {row["record"]: row for row in read_csv(out_dir / "tables" / "table6_results.csv")}
    paper = paper_tables()["table6_results"]["rows"]
    matches = [record for record in AVAILABLE if float(rows[record]["mu_max"]) == pytest.approx(paper[record]["mu_max"])]
    assert len(matches) >= 5, matches
    for record in AVAILABLE:
        ours = float(rows[record]["energy_dissipated_max"])
        assert abs(relative_difference(ours, paper[record]["energy_dissipated_max"])) <= 0.20, record


def test_table6_keeps_missing_records_with_how_to_obtain(results):
    out_dir = results
    rows = {row["record"]: row for row in read_csv(out_dir / "tables" / "table6_results.csv")}
    assert list(rows) == project_config()["paper_records"]
    for record in MISSING:
        assert rows[record]["status"].startswith("missing:")
        assert "How to obtain" in rows[record]["status"]
    for record in AVAILABLE:
        assert rows[record]["status"] == "ok"


def test_table6_continuous_mu_max_lies_near_the_fine_grid_maximum(results):
    out_dir = results
    for row in read_csv(out_dir / "tables" / "table6_results.csv"):
        if row["status"] != "ok":
            continue
        assert abs(float(row["mu_max_continuous"]) - float(row["mu_max_fine"])) <= 0.001
        assert float(row["energy_dissipated_max_continuous"]) >= float(row["energy_dissipated_max_fine"])
        assert float(row["energy_dissipated_max_fine"]) >= float(row["energy_dissipated_max"]) * (1 - 1e-12)


def test_table6_rms_column_is_a_paper_erratum_and_the_text_value_agrees(results):
    out_dir = results
    cells = read_csv(out_dir / "tables" / "table6_comparison.csv")
    rms = [c for c in cells if c["table"] == "table6" and c["column"] == "rms_acceleration" and c["row"] in AVAILABLE]
    # every printed RMS cell, Kobe's too (within 5 % of ours by chance), is explained by erratum E1
    assert len(rms) == 6 and all(c["status"].startswith("paper erratum: E1") for c in rms)
    assert all("typesetting error" in c["note"] for c in rms)
    text = [c for c in cells if c["table"] == "table6_text"]
    assert [c["row"] for c in text] == ["chichi_chy080n"]
    assert text[0]["status"] == "ok"
    assert {c["status"][:8] for c in cells if c["row"] in MISSING} == {"missing:"}


def test_table6_cubes_hold_the_paper_grid_and_the_fine_grid(results, config):
    out_dir = results
    grid = xr.load_dataset(out_dir / "sweeps" / "paper.nc")
    fine = xr.load_dataset(out_dir / "sweeps" / "fine.nc")
    assert grid.record.values.tolist() == config["paper_records"]
    assert [str(s).split(":")[0] for s in grid.status.values] == [
        "missing" if record in MISSING else "ok" for record in config["paper_records"]]
    np.testing.assert_allclose(grid.mu.values, config["mu_grid"])
    assert fine.sizes["mu"] == 391
    assert np.isnan(fine.mu_max_continuous.sel(record="mendoza_1985"))
    assert grid.attrs["block_mass"] == pytest.approx(5.10)


def test_table7_ranges_hold_mu_max_and_report_the_consistent_q(results, config):
    out_dir = results
    ranges = {row["record"]: row for row in read_csv(out_dir / "tables" / "table7_ranges.csv")}
    results6 = {row["record"]: row for row in read_csv(out_dir / "tables" / "table6_results.csv")}
    for record in AVAILABLE:
        row = ranges[record]
        assert float(row["q"]) == config["mu_max"]["near_optimal_fraction"]
        assert float(row["mu_low"]) <= float(results6[record]["mu_max"]) <= float(row["mu_high"])
    q_rows = {row["record"]: row for row in read_csv(out_dir / "tables" / "table7_q_intervals.csv")}
    assert all(float(q_rows[record]["q_above"]) >= 0.0 for record in AVAILABLE)
    overall = q_rows["all records"]
    fits_all = float(overall["q_above"]) < float(overall["q_at_most"])
    assert overall["status"] == ("one q fits all" if fits_all else "no single q fits all")


def test_fits_relate_mu_max_to_pga_and_rms(results):
    import json

    out_dir = results
    fits = json.loads((out_dir / "fits.json").read_text())
    rows = {row["record"]: row for row in read_csv(out_dir / "tables" / "table6_results.csv")}
    pga_fit = fits["mu_max_vs_pga"]
    assert [p["label"] for p in pga_fit["points"]] == AVAILABLE
    x = np.array([float(rows[r]["pga"]) for r in AVAILABLE])
    y = np.array([float(rows[r]["mu_max"]) for r in AVAILABLE])
    slope, intercept = np.polyfit(x, y, 1)
    assert pga_fit["linear_fit"]["slope"] == pytest.approx(slope)
    assert pga_fit["linear_fit"]["intercept"] == pytest.approx(intercept)
    assert pga_fit["pearson_r"] == pytest.approx(np.corrcoef(x, y)[0, 1])
    assert -1.0 <= fits["mu_max_vs_rms_acceleration"]["spearman_rho"] <= 1.0


def test_table8_scales_each_record_to_the_targets(results, config):
    out_dir = results
    rows = read_csv(out_dir / "tables" / "table8_results.csv")
    scaled = [row for row in rows if row["status"] == "ok" and row["scaling"] != "unscaled"]
    assert len(scaled) == 3 * len(AVAILABLE)
    for row in scaled:
        assert float(row["pga"]) == pytest.approx(float(row["target_pga"]), rel=1e-12)
    targets = sorted({float(row["target_pga"]) for row in scaled})
    assert targets == pytest.approx([0.6 * 9.81, 0.8 * 9.81, 1.0 * 9.81])
    assert {row["record"] for row in rows if row["status"].startswith("missing")} == set(MISSING)
    cells = read_csv(out_dir / "tables" / "table8_comparison.csv")
    assert len(cells) == 16 and all(c["status"].startswith("missing:") for c in cells)
    assert all("mendoza" in c["row"] for c in cells)


def test_table4_readings_and_best_choice(results):
    out_dir = results
    rows = read_csv(out_dir / "tables" / "table4_readings.csv")
    assert len(rows) == 2 * 3 * 4 and {r["row"] for r in rows} == {f"Harmonic {k}" for k in range(1, 5)}
    by_key = {(float(r["displacement_amplitude"]), float(r["ramp_cycles"]), r["row"]): float(r["energy_dissipated"]) for r in rows}
    # 15 mm at 1 Hz: f_f = μg/(u_g0·ω²) ≈ 1.66 > 1, so the block never slides (Eq. 3).
    assert by_key[(0.015, 0.0, "Harmonic 3")] == 0.0
    assert by_key[(0.030, 0.0, "Harmonic 3")] > 0.0
    # A longer record dissipates more.
    assert by_key[(0.030, 0.0, "Harmonic 2")] > by_key[(0.030, 0.0, "Harmonic 1")]
    best = min(rows, key=lambda r: float(r["reading_rms_relative_difference"]))["reading"]
    cells = read_csv(out_dir / "tables" / "table4_comparison.csv")
    assert len(cells) == 4 and all(best in c["note"] for c in cells)


def test_mass_does_not_change_energy_per_unit_mass(results):
    out_dir = results
    (row,) = read_csv(out_dir / "tables" / "mass_check.csv")
    assert row["status"] == "same"
    assert float(row["max_relative_spread"]) <= 1e-12
    cube = xr.load_dataset(out_dir / "sweeps" / "mass.nc")
    assert cube.mass.values.tolist() == [1.0, 5.1, 50.0]
    assert float(cube.energy_dissipated.sel(mass=50.0).max()) == pytest.approx(
        50.0 / 5.1 * float(cube.energy_dissipated.sel(mass=5.1).max()), rel=1e-12)


def test_compare_cells_flags_beyond_tolerance_and_missing():
    cells = compare_cells(
        "t", {"a": {"x": 1.04}, "b": {"x": 2.5}}, {"a": {"x": 1.0}, "b": {"x": 2.0}, "c": {"x": 3.0}},
        ["x"], {"default": 0.05}, missing={"c": "missing: ask INPRES"},
    )
    assert [c["status"] for c in cells] == ["ok", "beyond tolerance", "missing: ask INPRES"]
    assert cells[1]["relative_difference"] == pytest.approx(0.25)


def _config(edit):
    settings = project_config()
    edit(settings)
    return settings


@pytest.mark.parametrize(
    ("edit", "phrase"),
    [
        (lambda c: c.update(mu_grid=[0.1, 0.05, 0.2]), "mu_grid: values must be strictly increasing"),
        (lambda c: c["fine_mu"].update(start=0.5), "fine_mu: expected 0 < START <= STOP, got START 0.5 and STOP 0.4"),
        (lambda c: c["fine_mu"].update(step=1.0), "fine_mu: values from START 0.01 to STOP 0.4 by STEP 1 number 1; at least 2 are needed"),
        (lambda c: c["collection_study"]["pga_bands_g"].reverse(), "collection_study.pga_bands_g: values must be"),
        (lambda c: c.update(paper_records=["cape_mendocino", "nowhere"]), "paper_records: unknown record id(s) 'nowhere'"),
        (lambda c: c.update(report_records=["nowhere"]), "report_records: unknown record id(s) 'nowhere'"),
        (lambda c: c["mass_study"].update(records=["nowhere"]), "mass_study.records: unknown record id(s) 'nowhere'"),
        (lambda c: c["timestep_study"].update(time_steps=[0.001, 0.0015]),
         "timestep_study.time_steps: 0.0015 is not a distinct whole multiple of the smallest"),
        (lambda c: c["jibson2007"].update(critical_accelerations_g=[0.1, 0.05]),
         "jibson2007.critical_accelerations_g: values must be strictly increasing"),
        (lambda c: c["estimates"].update(ky=[0.05, 0.15]),
         "estimates.ky: 0.15 not among jibson2007.critical_accelerations_g (0.02, 0.05, 0.1, 0.2, 0.3, 0.4), whose "
         "rigid D_n the study reuses"),
        (lambda c: c["estimates"].update(site_periods=[0.5, 0.1]), "estimates.site_periods: values must be strictly"),
    ],
)
def test_semantic_config_errors_name_the_key(edit, phrase):
    from stickslip.records.manifest import load_manifest

    with pytest.raises(StickslipError) as error:
        check_config_semantics(_config(edit), load_manifest())
    assert phrase in str(error.value)


def test_the_default_config_is_consistent():
    from stickslip.records.manifest import load_manifest

    config, manifest = project_config(), load_manifest()
    check_config_semantics(config, manifest)  # raises StickslipError on any inconsistency
    assert set(config["paper_records"]) <= set(manifest)


@pytest.mark.parametrize(
    ("edit", "phrase"),
    [
        (lambda c: c.pop("mu_max"), "'mu_max' is a required property"),
        (lambda c: c.update(block_mass=-5.1), "at block_mass: -5.1 is less than or equal to the minimum of 0"),
        (lambda c: c["harmonic"].pop("dt"), "at harmonic: 'dt' is a required property"),
    ],
)
def test_a_config_that_breaks_the_schema_is_refused_in_one_line(tmp_path, edit, phrase):
    import yaml

    settings = yaml.safe_load(PROJECT_CONFIG.read_text(encoding="utf-8"))
    edit(settings)
    path = tmp_path / "config.yaml"
    path.write_text(yaml.safe_dump(settings), encoding="utf-8")
    with pytest.raises(StickslipError) as error:
        load_config(path, CONFIG_SCHEMA)
    assert str(path) in str(error.value) and phrase in str(error.value)


def test_invalid_yaml_gives_the_line_and_column(tmp_path):
    config_path = tmp_path / "broken.yaml"
    config_path.write_text("gravity: [1, 2\nblock_mass: 3\n", encoding="utf-8")
    with pytest.raises(StickslipError) as error:
        load_config(config_path)
    assert "not valid YAML: expected ',' or ']', but got ':' at line 2, column 11" in str(error.value)


def test_records_dir_from_the_environment_is_relative_to_the_current_directory(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("STICKSLIP_RECORDS_DIR", "my_records")
    assert project_config()["records_dir"] == str(tmp_path.resolve() / "my_records")


def test_errata_are_rows_of_a_computed_table(results):
    rows = {row["check"]: row for row in read_csv(results / "tables" / "errata.csv")}
    assert list(rows) == ["E1", "E2 harmonic_model", "E2 seismic_model", "E3", "E4"]
    assert [rows[k]["status"] for k in ("E1", "E2 harmonic_model", "E2 seismic_model", "E3")] == ["confirmed"] * 4
    assert float(rows["E2 seismic_model"]["compared_with"]) < 1e-9 < 0.1 < float(rows["E2 seismic_model"]["value"])
    assert rows["E4"]["status"] == "unresolved"  # 2 Hz rows fit a 15 mm amplitude, 1 Hz rows need 30 mm


def test_tables3_and_4_have_the_kobe_rows_beside_the_paper_model_and_test(results):
    rows = read_csv(results / "tables" / "table3_table4_model.csv")
    kobe = [row for row in rows if row["row"] == "Kobe"]
    assert [(row["table"], row["interface"]) for row in kobe] == [
        ("table3", "II"), ("table3", "IV"), ("table4", "II"), ("table4", "II"), ("table4", "IV"), ("table4", "IV")]
    assert all(row["status"] == "ok" and float(row["ours"]) > 0 for row in kobe)
    energy = {float(row["ours"]) for row in kobe if row["table"] == "table4"}
    assert len(energy) == 1 and 1.5 < energy.pop() < 2.5  # one model value [J] beside the paper's four
    assert all(row["status"].startswith("missing") for row in rows if row["row"] == "Mendoza")
