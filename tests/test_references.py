"""CI check: the studies reproduce the stored reference tables in tests/references/.

Each study runs on the shared paper records into a temporary folder and every
table is compared by value with its stored reference (see
``stickslip.studies.references``).  After an intended change, regenerate the
references with ``make references`` and review the diff.
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from stickslip.config import load_config
from stickslip.studies import study_module
from stickslip.studies.references import REFERENCE_TABLES, table_differences, write_reference

REFERENCES = Path(__file__).resolve().parent / "references"


@pytest.fixture(scope="module")
def results(paper_records_dir, tmp_path_factory):
    """Every study's tables, computed now on the shared records."""
    config = load_config()
    config["records_dir"] = str(paper_records_dir)
    out_dir = tmp_path_factory.mktemp("results")
    for study in REFERENCE_TABLES:
        study_module(study).run(config, out_dir)
    return out_dir / "tables"


@pytest.mark.parametrize(
    "table", [name for tables in REFERENCE_TABLES.values() for name in tables]
)
def test_table_matches_its_stored_reference(results, table):
    assert (REFERENCES / table).is_file(), f"no stored reference for {table}; run 'make references'"
    assert table_differences(results / table, REFERENCES / table) == []


def test_a_changed_value_is_reported(results, tmp_path):
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


def test_a_missing_row_is_reported(results, tmp_path):
    reference = tmp_path / "table5_records.csv"
    lines = (results / "table5_records.csv").read_text(encoding="utf-8").splitlines()
    reference.write_text("\n".join(lines[:-1]) + "\n", encoding="utf-8")
    assert table_differences(results / "table5_records.csv", reference) == [
        "table5_records.csv: 8 rows, reference has 7"
    ]
