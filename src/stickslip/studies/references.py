"""Stored reference tables: the CI check that our study tables do not drift.

``tests/references/paper/`` holds the tables the workflow wrote on the shared
paper records (``config/config.yaml``), and ``tests/references/test_config/``
those of the small ``.test/`` configuration (records that are always
available), when the references were last accepted.  The check runs the
workflow again and compares the tables by value: numeric cells to a relative
tolerance, text cells exactly, except ``status`` cells, whose explanation names
a machine's records folder and is compared by its first word (``ok``,
``missing:``, ``same`` …).

Regenerate after an intended change with ``make references`` and review the
diff before committing it.
"""

from __future__ import annotations

import math
from pathlib import Path

from stickslip.plumbing.files import read_csv_rows, write_csv_atomic

#: The tables (under ``results/tables``) kept as references; ``{timestep}`` is the time-step study's record.
REFERENCE_TABLES: tuple[str, ...] = (
    "table5_records.csv",
    "harmonic_energy.csv",
    "table4_readings.csv",
    "table6_results.csv",
    "table7_ranges.csv",
    "table7_q_intervals.csv",
    "table8_results.csv",
    "mass_check.csv",
    "timestep_{timestep}_summary.csv",
    "model_responses.csv",
    "table3_table4_model.csv",
    "errata.csv",
    "paper_fits.csv",
)

#: Relative tolerance for numeric cells (results are deterministic; this only
#: absorbs floating-point differences between machines and library builds).
RELATIVE_TOLERANCE = 1e-6
#: Absolute floor for numeric cells that should be zero (e.g. balance residuals) [cell units].
ABSOLUTE_TOLERANCE = 1e-9


def normalised_rows(rows: list[dict[str, str]]) -> list[dict[str, str]]:
    """Rows with each ``status`` cell cut to its first word (machine-independent)."""
    return [
        {key: (value.split(" ", 1)[0] if key == "status" else value) for key, value in row.items()}
        for row in rows
    ]


def write_reference(table: str | Path, reference: str | Path) -> Path:
    """Store ``table`` as the reference ``reference``, with normalised status cells."""
    rows = normalised_rows(read_csv_rows(table))
    return write_csv_atomic(reference, rows, fieldnames=list(rows[0]) if rows else [])


def _cells_differ(ours: str, theirs: str) -> bool:
    try:
        a, b = float(ours), float(theirs)
    except ValueError:
        return ours != theirs
    if math.isnan(a) or math.isnan(b):
        return not (math.isnan(a) and math.isnan(b))
    return not math.isclose(a, b, rel_tol=RELATIVE_TOLERANCE, abs_tol=ABSOLUTE_TOLERANCE)


def table_differences(table: str | Path, reference: str | Path) -> list[str]:
    """Every difference between ``table`` and the stored ``reference``, one line each (empty: they match)."""
    ours = normalised_rows(read_csv_rows(table))
    theirs = read_csv_rows(reference)
    name = Path(table).name
    if not ours or not theirs:
        return [f"{name}: {len(ours)} rows, reference has {len(theirs)}"] if len(ours) != len(theirs) else []
    if list(ours[0]) != list(theirs[0]):
        return [f"{name}: columns {list(ours[0])} differ from the reference's {list(theirs[0])}"]
    if len(ours) != len(theirs):
        return [f"{name}: {len(ours)} rows, reference has {len(theirs)}"]
    return [
        f"{name} row {index + 1} ({row.get('record', '')}) column {column}: {row[column]!r}, reference {ref[column]!r}"
        for index, (row, ref) in enumerate(zip(ours, theirs))
        for column in row
        if _cells_differ(row[column], ref[column])
    ]
