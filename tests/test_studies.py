"""The paper's studies (Tables 4, 6, 7, 8 and the mass check) on the shared records."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest
from conftest import assert_one_error_line
import xarray as xr

from stickslip.config import load_config
from stickslip.reference import paper_tables
from stickslip.studies import STUDIES, study_module
from stickslip.studies.compare import compare_cells, relative_difference

AVAILABLE = ["cape_mendocino", "chichi_chy080n", "coyote_g06_230", "coyote_g06_320", "kobe_kjm090", "northridge_nwh090"]
MISSING = ["mendoza_1985", "parkfield_c02_360"]


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


@pytest.fixture(scope="module")
def config(paper_records_dir):
    config = load_config()
    config["records_dir"] = str(paper_records_dir)
    config["table6"]["fine_mu"] = {"start": 0.02, "stop": 0.30, "step": 0.001}
    config["table6"]["n_boot"] = 500
    return config


@pytest.fixture(scope="module")
def results(config, tmp_path_factory):
    out_dir = tmp_path_factory.mktemp("results")
    written = {name: study_module(name).run(config, out_dir) for name in ("table4", "table6", "table8", "mass")}
    return out_dir, written


def test_studies_are_registered():
    assert {"table4", "table6", "table8", "mass"} <= set(STUDIES)


def test_every_written_path_exists_without_partials(results):
    out_dir, written = results
    for paths in written.values():
        assert paths and all(path.is_file() and path.stat().st_size > 0 for path in paths)
    assert not list(out_dir.rglob("*.part"))


def test_table6_mu_max_matches_the_paper_for_five_of_six_records(results):
    out_dir, _ = results
    rows = {row["record"]: row for row in read_csv(out_dir / "tables" / "table6_results.csv")}
    paper = paper_tables()["table6_results"]["rows"]
    matches = [record for record in AVAILABLE if float(rows[record]["mu_max"]) == pytest.approx(paper[record]["mu_max"])]
    assert len(matches) >= 5, matches
    for record in AVAILABLE:
        ours = float(rows[record]["energy_dissipated_max"])
        assert abs(relative_difference(ours, paper[record]["energy_dissipated_max"])) <= 0.20, record


def test_table6_keeps_missing_records_with_how_to_obtain(results):
    out_dir, _ = results
    rows = {row["record"]: row for row in read_csv(out_dir / "tables" / "table6_results.csv")}
    assert list(rows) == load_config()["paper_records"]
    for record in MISSING:
        assert rows[record]["status"].startswith("missing:")
        assert "How to obtain" in rows[record]["status"]
    for record in AVAILABLE:
        assert rows[record]["status"] == "ok"


def test_table6_continuous_mu_max_lies_near_the_fine_grid_maximum(results):
    out_dir, _ = results
    for row in read_csv(out_dir / "tables" / "table6_results.csv"):
        if row["status"] != "ok":
            continue
        assert abs(float(row["mu_max_continuous"]) - float(row["mu_max_fine"])) <= 0.001
        assert float(row["energy_dissipated_max_continuous"]) >= float(row["energy_dissipated_max_fine"])
        assert float(row["energy_dissipated_max_fine"]) >= float(row["energy_dissipated_max"]) * (1 - 1e-12)


def test_table6_rms_column_is_flagged_and_the_text_value_agrees(results):
    out_dir, _ = results
    cells = read_csv(out_dir / "tables" / "table6_comparison.csv")
    rms = [c for c in cells if c["table"] == "table6" and c["column"] == "rms_acceleration" and c["row"] in AVAILABLE]
    assert sum(c["status"] == "beyond tolerance" for c in rms) >= 4
    assert all("typesetting error" in c["note"] for c in rms)
    text = [c for c in cells if c["table"] == "table6_text"]
    assert [c["row"] for c in text] == ["chichi_chy080n"]
    assert text[0]["status"] == "ok"
    assert {c["status"][:8] for c in cells if c["row"] in MISSING} == {"missing:"}


def test_table6_cubes_hold_the_paper_grid_and_the_fine_grid(results, config):
    out_dir, _ = results
    grid = xr.load_dataset(out_dir / "sweeps" / "paper_grid.nc")
    fine = xr.load_dataset(out_dir / "sweeps" / "paper_fine.nc")
    assert grid.record.values.tolist() == AVAILABLE
    np.testing.assert_allclose(grid.mu.values, config["mu_grid"])
    assert fine.sizes["mu"] == 281
    assert grid.attrs["block_mass"] == pytest.approx(5.10)


def test_table7_ranges_hold_mu_max_and_report_the_consistent_q(results, config):
    out_dir, _ = results
    ranges = {row["record"]: row for row in read_csv(out_dir / "tables" / "table7_ranges.csv")}
    results6 = {row["record"]: row for row in read_csv(out_dir / "tables" / "table6_results.csv")}
    for record in AVAILABLE:
        row = ranges[record]
        assert float(row["q"]) == config["table6"]["near_optimal_fraction"]
        assert float(row["mu_low"]) <= float(results6[record]["mu_max"]) <= float(row["mu_high"])
        assert float(row["q_reproducing_paper_above"]) >= 0.0
    fits = json.loads((out_dir / "fits.json").read_text())
    consistent = fits["q_reproducing_paper_table7"]
    assert consistent["exists"] == (consistent["above"] < consistent["at_most"])


def test_fits_relate_mu_max_to_pga_and_rms(results):
    out_dir, _ = results
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
    out_dir, _ = results
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


def test_table4_readings_and_best_choice(results):
    out_dir, _ = results
    rows = read_csv(out_dir / "tables" / "table4_readings.csv")
    assert len(rows) == 2 * 3 * 4
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
    out_dir, _ = results
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


def test_study_cli_runs_table4(run_cli, tmp_path):
    code, stdout, stderr = run_cli("study", "table4", "--out-dir", tmp_path)
    assert code == 0, stderr
    assert (tmp_path / "tables" / "table4_comparison.csv").is_file()
    assert str(tmp_path / "tables" / "table4_readings.csv") in stdout



def _write_config(tmp_path, edit):
    import yaml

    from stickslip.config import DEFAULT_CONFIG

    settings = yaml.safe_load(DEFAULT_CONFIG.read_text(encoding="utf-8"))
    edit(settings)
    path = tmp_path / "config.yaml"
    path.write_text(yaml.safe_dump(settings), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("edit", "phrase"),
    [
        (lambda c: c.pop("table6"), "'table6' is a required property"),
        (lambda c: c.update(block_mass=-5.1), "at block_mass: -5.1 is less than or equal to the minimum of 0"),
        (lambda c: c["table4"].pop("dt"), "at table4: 'dt' is a required property"),
    ],
)
def test_study_cli_refuses_a_config_that_breaks_the_schema(run_cli, tmp_path, edit, phrase):
    config_path = _write_config(tmp_path, edit)
    out_dir = tmp_path / "results"
    code, out, err = run_cli("study", "table4", "--config", config_path, "--out-dir", out_dir)
    assert_one_error_line(code, out, err, config_path, phrase)
    assert not out_dir.exists()


def test_study_cli_refuses_invalid_yaml_in_one_line(run_cli, tmp_path):
    config_path = tmp_path / "broken.yaml"
    config_path.write_text("gravity: [1, 2\nblock_mass: 3\n", encoding="utf-8")
    code, out, err = run_cli("study", "table4", "--config", config_path, "--out-dir", tmp_path / "results")
    assert_one_error_line(code, out, err, config_path, "not valid YAML: expected ',' or ']', but got ':' at line 2, column 11")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["broken.yaml"]


def test_records_dir_from_the_environment_is_relative_to_the_current_directory(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("STICKSLIP_RECORDS_DIR", "my_records")
    assert load_config()["records_dir"] == str(tmp_path.resolve() / "my_records")


def test_records_dir_in_the_config_file_is_relative_to_the_project_root(tmp_path, monkeypatch):
    monkeypatch.delenv("STICKSLIP_RECORDS_DIR", raising=False)
    project = tmp_path / "project"
    (project / "config").mkdir(parents=True)
    config_path = _write_config(project / "config", lambda c: c.update(records_dir="my_records"))
    monkeypatch.chdir(tmp_path)
    assert load_config(config_path)["records_dir"] == str(project.resolve() / "my_records")


@pytest.mark.parametrize(
    ("make_out_dir", "phrase"),
    [
        (lambda tmp: tmp / "blocker", "cannot write the results: it is a file, not a folder"),
        (lambda tmp: tmp / "blocker" / "results", "blocker is a file, not a folder"),
        (lambda tmp: tmp / "with_tables_file", "with_tables_file/tables: cannot write the results: it is a file, not a folder"),
    ],
)
def test_study_cli_refuses_a_bad_out_dir_before_any_work(run_cli, tmp_path, monkeypatch, make_out_dir, phrase):
    import stickslip.studies.table4

    def no_work(*args, **kwargs):
        raise AssertionError("the study ran before the results folder was checked")

    monkeypatch.setattr(stickslip.studies.table4, "run", no_work)
    (tmp_path / "blocker").write_text("kept")
    (tmp_path / "with_tables_file").mkdir()
    (tmp_path / "with_tables_file" / "tables").write_text("kept")
    out_dir = make_out_dir(tmp_path)
    code, out, err = run_cli("study", "table4", "--out-dir", out_dir)
    assert_one_error_line(code, out, err, out_dir, phrase)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocker", "with_tables_file"]
    assert [p.name for p in (tmp_path / "with_tables_file").iterdir()] == ["tables"]
