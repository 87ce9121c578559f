"""Cell-by-cell comparison of our tables with the paper's printed values.

A comparison table is long: one row per (table row, column) cell, with our
value, the paper's (from :func:`stickslip.reference.paper_tables`, never typed
here), the relative difference (ours − paper) / |paper| and a status:
``ok`` within the column's tolerance, ``beyond tolerance``, ``missing: …``
when we have no value (with how to obtain the record), ``paper erratum: …``
when a confirmed erratum of the paper (:mod:`stickslip.studies.errata`)
explains the printed value, or ``no paper value``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path

from stickslip.errors import StickslipError
from stickslip.plumbing.files import write_csv_atomic

#: Columns of a comparison CSV, in order.
COMPARISON_FIELDS = ["table", "row", "column", "ours", "paper", "relative_difference", "tolerance", "status", "note"]


def relative_difference(ours: float, paper: float) -> float:
    """(ours − paper) / |paper| [1]; NaN when either is missing or the paper's value is 0."""
    if ours is None or paper is None or paper == 0 or math.isnan(ours) or math.isnan(paper):
        return float("nan")
    return (ours - paper) / abs(paper)


def tolerance_for(tolerances: Mapping[str, float], table: str, column: str) -> float:
    """The relative tolerance of ``column`` in ``table`` from the config's ``comparison_tolerance``.

    Looked up as ``tolerances[table][column]``, then ``tolerances[column]``,
    then ``tolerances["default"]``.
    """
    per_table = tolerances.get(table, {})
    for source in (per_table, tolerances):
        if isinstance(source, Mapping) and isinstance(source.get(column), (int, float)):
            return float(source[column])
    if "default" not in tolerances:
        raise StickslipError(f"comparison_tolerance: no tolerance for {table}.{column} and no default")
    return float(tolerances["default"])


def compare_cells(
    table: str,
    ours: Mapping[str, Mapping[str, float]],
    paper: Mapping[str, Mapping[str, float]],
    columns: Sequence[str],
    tolerances: Mapping[str, float],
    missing: Mapping[str, str] | None = None,
    notes: Mapping[str, str] | None = None,
    errata: Mapping[str, str] | None = None,
) -> list[dict]:
    """Compare every cell of ``columns`` for every row of the paper's table.

    Parameters
    ----------
    table:
        Table name (``table6`` …), written in each row.
    ours, paper:
        Row key -> column -> value.  Rows are taken in the paper's order, then
        our extra rows.
    columns:
        The columns to compare.
    tolerances:
        The config's ``comparison_tolerance`` mapping (see :func:`tolerance_for`).
    missing:
        Row key -> status text (``"missing: how to obtain"``) for rows we could not compute.
    notes:
        Column (or ``"row.column"``) -> an explanation written beside its cells.
    errata:
        ``"table.column"`` -> the status of its cells that a confirmed erratum
        explains (:func:`stickslip.studies.errata.confirmed_errata`); a missing
        record's status takes precedence.

    A cell is ``ok`` when |relative difference| ≤ tolerance; where the paper
    prints 0 the absolute difference is held to the tolerance instead.
    """
    missing = missing or {}
    notes = notes or {}
    errata = errata or {}
    cells = []
    for row in list(paper) + [key for key in ours if key not in paper]:
        for column in columns:
            ours_value = ours.get(row, {}).get(column)
            paper_value = paper.get(row, {}).get(column)
            tolerance = tolerance_for(tolerances, table, column)
            difference = relative_difference(ours_value, paper_value)
            if row in missing:
                status = missing[row]
            elif f"{table}.{column}" in errata:
                status = errata[f"{table}.{column}"]
            elif paper_value is None:
                status = "no paper value"
            elif ours_value is None or math.isnan(ours_value):
                status = "missing: not computed"
            elif abs(difference if not math.isnan(difference) else ours_value - paper_value) <= tolerance:
                status = "ok"
            else:
                status = "beyond tolerance"
            cells.append({
                "table": table,
                "row": row,
                "column": column,
                "ours": ours_value,
                "paper": paper_value,
                "relative_difference": difference,
                "tolerance": tolerance,
                "status": status,
                "note": notes.get(f"{row}.{column}", notes.get(column, "")),
            })
    return cells


def write_comparison(path: str | Path, cells: list[dict]) -> Path:
    """Write comparison cells (from :func:`compare_cells`) to a CSV file, atomically."""
    return write_csv_atomic(path, cells, COMPARISON_FIELDS)
