"""CI check: the workflow reproduces the stored reference tables in tests/references/.

The whole workflow runs on the shared paper records (``config/config.yaml``)
and on the small ``.test/`` configuration, each in a temporary folder, and
every table is compared by value with its stored reference (see
``stickslip.studies.references``).  After an intended change, regenerate the
references with ``make references`` and review the diff.
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
import yaml

from conftest import REPO_ROOT
from stickslip.studies.references import REFERENCE_TABLES, table_differences, write_reference

REFERENCES = Path(__file__).resolve().parent / "references"


def table_names(configfile: Path) -> list[str]:
    record = yaml.safe_load(configfile.read_text(encoding="utf-8"))["timestep_study"]["record"]
    return [name.format(timestep=record) for name in REFERENCE_TABLES]


@pytest.mark.parametrize("table", table_names(REPO_ROOT / "config" / "config.yaml"))
def test_paper_table_matches_its_stored_reference(paper_workflow, table):
    reference = REFERENCES / "paper" / table
    assert reference.is_file(), f"no stored reference for {table}; run 'make references'"
    assert table_differences(paper_workflow / "tables" / table, reference) == []


@pytest.mark.parametrize("table", table_names(REPO_ROOT / ".test" / "config" / "config.yaml"))
def test_test_config_table_matches_its_stored_reference(test_workflow, table):
    reference = REFERENCES / "test_config" / table
    assert reference.is_file(), f"no stored reference for {table}; run 'make references'"
    assert table_differences(test_workflow / "tables" / table, reference) == []


def test_a_changed_value_is_reported(paper_workflow, tmp_path):
    results = paper_workflow / "tables"
    reference = write_reference(results / "table6_results.csv", tmp_path / "table6_results.csv")
    with open(reference, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    rows[0]["mu_max"] = str(float(rows[0]["mu_max"]) * (1 + 1e-4))
    with open(reference, "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    differences = table_differences(results / "table6_results.csv", reference)
    assert len(differences) == 1
    assert "row 1 (cape_mendocino) column mu_max" in differences[0]


def test_a_missing_row_is_reported(paper_workflow, tmp_path):
    results = paper_workflow / "tables"
    reference = tmp_path / "table5_records.csv"
    lines = (results / "table5_records.csv").read_text(encoding="utf-8").splitlines()
    reference.write_text("\n".join(lines[:-1]) + "\n", encoding="utf-8")
    assert table_differences(results / "table5_records.csv", reference) == [
        "table5_records.csv: 8 rows, reference has 7"
    ]
