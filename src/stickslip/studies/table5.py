"""Study ``table5``: the paper's eight records and their intensity measures beside the paper's Table 5.

Writes ``tables/table5_records.csv`` (one row per record, in the paper's order,
``config["paper_records"]``).  Each row holds the record's description, the
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

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordNotFoundError
from stickslip.io import write_csv_atomic
from stickslip.measures import intensity_measures
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, relative_difference, write_comparison
from stickslip.studies.records import load_study_record, study_manifest

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


def record_row(record_id: str, config: dict, manifest: dict, paper_rows: dict) -> dict:
    """One CSV row for ``record_id``: description, measures beside the paper's, and status."""
    entry = manifest.get(record_id)
    paper = paper_rows.get(record_id, {})
    row = {
        "record": record_id,
        "event": entry.event if entry else paper.get("event", ""),
        "station": entry.station if entry else paper.get("station", ""),
        "component": entry.component if entry else paper.get("component", ""),
        "mw": entry.mw if entry and entry.mw is not None else paper.get("mw", ""),
    }
    for measure, paper_key in PAPER_COLUMN.items():
        row[f"paper_{measure}"] = paper.get(paper_key, "")
    try:
        record = load_study_record(config, record_id, manifest)
    except RecordNotFoundError as error:
        row["status"] = f"missing: {entry.obtain if entry and entry.obtain else error}"
        return row
    values = intensity_measures(record, g=config.get("gravity", STANDARD_GRAVITY)).as_dict()
    row["source_file"] = Path(record.meta.source).name
    for measure in MEASURE_COLUMNS:
        row[measure] = values[measure]
        if measure in PAPER_COLUMN and paper.get(PAPER_COLUMN[measure]):
            row[f"rel_diff_{measure}"] = relative_difference(values[measure], paper[PAPER_COLUMN[measure]])
    row["status"] = "ok"
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


def run(config: dict, out_dir: Path) -> list[Path]:
    """Write ``tables/table5_records.csv`` and ``tables/table5_comparison.csv`` under ``out_dir``; return their paths."""
    manifest = study_manifest(config)
    paper_rows = paper_tables()["table5_records"]["rows"]
    rows = [record_row(record_id, config, manifest, paper_rows) for record_id in config["paper_records"]]
    tables = Path(out_dir) / "tables"
    return [
        write_csv_atomic(tables / TABLE_NAME, rows, fieldnames=columns()),
        write_comparison(tables / "table5_comparison.csv", comparison_cells(rows, paper_rows, config["comparison_tolerance"])),
    ]
