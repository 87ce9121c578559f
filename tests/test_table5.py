"""The records table (the paper's Table 5), as the workflow writes it from the shared records' measures."""

from __future__ import annotations

import csv
import json

import pytest
from conftest import project_config

from stickslip.reference import paper_tables
from stickslip.studies.measures import records_table as measures_table

AVAILABLE = ["cape_mendocino", "chichi_chy080n", "coyote_g06_230", "coyote_g06_320", "kobe_kjm090", "northridge_nwh090"]
MISSING = ["mendoza_1985", "parkfield_c02_360"]


@pytest.fixture
def config():
    return project_config()


def read_rows(path) -> list[dict[str, str]]:
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


@pytest.fixture
def table(paper_workflow):
    return read_rows(paper_workflow / "tables" / "table5_records.csv")


def test_rows_are_the_papers_eight_records_in_order(table, config):
    assert [row["record"] for row in table] == config["paper_records"]
    assert list(table[0]) == measures_table.columns()


@pytest.mark.parametrize("record_id", AVAILABLE)
def test_available_records_match_the_paper(table, record_id):
    row = next(row for row in table if row["record"] == record_id)
    paper = paper_tables()["table5_records"]["rows"][record_id]
    assert row["status"] == "ok"
    assert float(row["paper_arias_intensity"]) == paper["arias_intensity"]
    assert float(row["arias_intensity"]) == pytest.approx(paper["arias_intensity"], rel=0.01)
    assert abs(float(row["rel_diff_arias_intensity"])) < 0.01
    assert float(row["significant_duration"]) == pytest.approx(paper["significant_duration"], abs=0.15)
    assert float(row["rel_diff_pga"]) == pytest.approx(float(row["pga"]) / paper["pga"] - 1, rel=1e-9)
    assert float(row["dt"]) == paper["dt"]
    assert row["source_file"] and row["mw"] == str(paper["mw"])


@pytest.mark.parametrize("record_id", MISSING)
def test_missing_records_keep_their_row_and_say_how_to_obtain_them(table, record_id):
    row = next(row for row in table if row["record"] == record_id)
    assert row["status"].startswith("missing: ")
    assert f"{record_id}.AT2" in row["status"]  # the file name to put in the records folder
    assert row["arias_intensity"] == "" and row["pga"] == ""
    assert float(row["paper_pga"]) == paper_tables()["table5_records"]["rows"][record_id]["pga"]


def test_a_failing_run_keeps_the_previous_table(paper_workflow, tmp_path):
    target = tmp_path / "table5_records.csv"
    target.write_text("previous table\n", encoding="utf-8")
    broken = tmp_path / "broken.json"
    broken.write_text("{not json", encoding="utf-8")
    measures = [paper_workflow.parent / "results" / "measures" / "cape_mendocino.json", broken]
    with pytest.raises(json.JSONDecodeError):
        measures_table.write_records_table(measures, target, tmp_path / "comparison.csv", {"default": 0.05})
    assert target.read_text(encoding="utf-8") == "previous table\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["broken.json", "table5_records.csv"]


def test_comparison_flags_cells_cell_by_cell(paper_workflow):
    cells = read_rows(paper_workflow / "tables" / "table5_comparison.csv")
    by_key = {(cell["row"], cell["column"]): cell for cell in cells}
    for record_id in AVAILABLE:
        arias = by_key[(record_id, "arias_intensity")]
        assert arias["status"] == "ok" and abs(float(arias["relative_difference"])) <= 0.01
    kobe_duration = by_key[("kobe_kjm090", "duration")]
    assert kobe_duration["status"] == "beyond tolerance"  # 44.62 s trimmed window against 149.98 s
    assert "trimmed" in kobe_duration["note"]
    assert by_key[("mendoza_1985", "pga")]["status"].startswith("missing:")
