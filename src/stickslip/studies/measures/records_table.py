"""The records table: the paper's eight records and their intensity measures beside the paper's Table 5.

Built from the measures stage's files (``results/measures/{id}.json``, see
:mod:`stickslip.studies.measures.record_measures`); no record file is opened here.
Writes ``table5_records.csv`` (one row per record, in the paper's order).  Each row holds the record's description, the
file it was read from, our measures (SI: s, m/s, m/s²), the paper's printed
value beside each comparable measure (``paper_…``, from
:func:`stickslip.reference.paper_tables`) and the relative difference
``rel_diff_… = (ours − paper) / |paper|``.  A record that no source can provide
keeps its row, with ``status`` = ``"missing: <how to obtain it>"`` and empty
measures.  ``tables/table5_comparison.csv`` holds the same comparison cell by
cell, flagged against the config's ``comparison_tolerance`` (see
:mod:`stickslip.studies.compare`).
"""

from __future__ import annotations

from pathlib import Path

from stickslip.plumbing.files import write_csv_atomic
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, relative_difference, write_comparison
from stickslip.studies.measures.record_measures import read_record_measures

#: Output file name.
TABLE_NAME = "table5_records.csv"

#: Our measures, in column order; each is followed by the paper's value and the relative difference
#: when the paper's Table 5 prints it (the whole-sample t_e is compared with the paper's t_e).
MEASURE_COLUMNS = (
    "npts",
    "duration",
    "t5",
    "t95",
    "significant_duration",
    "significant_duration_samples",
    "dt",
    "arias_intensity",
    "pga",
    "pgv",
    "rms_acceleration",
)

#: Our measure -> the key of the paper's Table 5 column it is comparable with.
PAPER_COLUMN = {
    "duration": "duration",
    "significant_duration": "significant_duration",
    "significant_duration_samples": "significant_duration",
    "dt": "dt",
    "arias_intensity": "arias_intensity",
    "pga": "pga",
}

DESCRIPTION_COLUMNS = ("record", "event", "station", "component", "mw", "source_file")

#: Why whole columns differ from the paper (written beside their cells in the comparison).
COLUMN_NOTES = {
    "duration": "most files are SLAMMER windows trimmed from the PEER records (docs/records.md)",
    "pga": "NGA-West1 processing here; the paper's values fit NGA-West2 (docs/records.md)",
}


def columns() -> list[str]:
    """The CSV header, in order."""
    names = list(DESCRIPTION_COLUMNS)
    for measure in MEASURE_COLUMNS:
        names.append(measure)
        if measure in PAPER_COLUMN:
            names += [f"paper_{measure}", f"rel_diff_{measure}"]
    return names + ["status"]


def record_row(document: dict, paper_rows: dict) -> dict:
    """One CSV row from a measures document: description, measures beside the paper's, and status."""
    record_id = document["record"]
    paper = paper_rows.get(record_id, {})
    row = {"record": record_id}
    for column in ("event", "station", "component", "mw"):
        row[column] = document.get(column) or paper.get(column, "")
    for measure, paper_key in PAPER_COLUMN.items():
        row[f"paper_{measure}"] = paper.get(paper_key, "")
    row["status"] = document["status"]
    if document["status"] != "ok":
        return row
    values = document["measures"]
    row["source_file"] = document["source_file"]
    for measure in MEASURE_COLUMNS:
        row[measure] = values[measure]
        if measure in PAPER_COLUMN and paper.get(PAPER_COLUMN[measure]):
            row[f"rel_diff_{measure}"] = relative_difference(values[measure], paper[PAPER_COLUMN[measure]])
    return row


def comparison_cells(rows: list[dict], paper_rows: dict, tolerances: dict) -> list[dict]:
    """The rows' comparable measures against the paper's Table 5, cell by cell."""
    ours = {row["record"]: {m: row[m] for m in PAPER_COLUMN if m in row} for row in rows}
    paper = {
        record_id: {measure: paper_rows[record_id][key] for measure, key in PAPER_COLUMN.items()}
        for record_id in (row["record"] for row in rows)
        if record_id in paper_rows
    }
    missing = {row["record"]: row["status"] for row in rows if row["status"] != "ok"}
    return compare_cells("table5", ours, paper, list(PAPER_COLUMN), tolerances, missing=missing, notes=COLUMN_NOTES)


def write_records_table(measures_paths: list[str | Path], table_path: str | Path, comparison_path: str | Path,
                        tolerances: dict) -> list[Path]:
    """Write the records table and its cell-by-cell comparison from the measures files, in their order."""
    paper_rows = paper_tables()["table5_records"]["rows"]
    rows = [record_row(read_record_measures(path), paper_rows) for path in measures_paths]
    return [
        write_csv_atomic(table_path, rows, fieldnames=columns()),
        write_comparison(comparison_path, comparison_cells(rows, paper_rows, tolerances)),
    ]
