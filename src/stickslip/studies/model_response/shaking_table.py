"""Our model of the shaking-table cases beside the paper's model and test columns (Tables 3 and 4).

Reads ``model_responses.csv`` (:mod:`stickslip.studies.model_response.cases`): the
harmonic case (u_g0 = 30 mm, 2 Hz, 5 s, μ = 0.10) and the seismic case (Kobe
KJMA 090 × 0.65, μ = 0.10), and writes

``table3_table4_model.csv``
    One row per printed row of Table 3 (residual displacement [m]) and per
    seismic row of Table 4 (E_df [J]): its number in the printed table,
    interface, record, our value, the
    paper's model and test values, and our relative difference from each.
``table3_comparison.csv``, ``table4_records_comparison.csv``
    The same against the paper's model column, cell by cell
    (:func:`stickslip.studies.compare.compare_cells`); a Mendoza row has the
    status ``missing: …`` (we have no Mendoza record).

Residual displacements are compared in magnitude (the paper prints no sign).
"""

from __future__ import annotations

from pathlib import Path

from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, relative_difference, write_comparison

#: The paper's row names -> our case in model_responses.csv.
CASE_OF_ROW = {"Harmonic": "harmonic_model", "Harmonic 1": "harmonic_model", "Kobe": "seismic_model"}

#: Status of a row whose record we do not have.
MENDOZA_MISSING = "missing: Mendoza 1985 is in no reachable source (records/SOURCES.md); the paper gives no file"


def _ours(cases: dict[str, dict[str, str]], row_name: str, column: str, magnitude: bool) -> tuple[float | None, str]:
    """Our value of ``column`` for the paper's row ``row_name`` and the case's status."""
    case = cases.get(CASE_OF_ROW.get(row_name, ""))
    if case is None:
        return None, MENDOZA_MISSING
    if case["status"] != "ok":
        return None, case["status"]
    value = float(case[column])
    return (abs(value) if magnitude else value), "ok"


def model_rows(cases: dict[str, dict[str, str]]) -> list[dict]:
    """Table 3 rows and the seismic rows of Table 4, ours beside the paper's model and test values."""
    reference = paper_tables()
    printed = [("table3", number, row, "residual_displacement", "m", True)
               for number, row in enumerate(reference["table3_residual_displacements"]["rows"], 1)]
    printed += [("table4", number, row, "energy_dissipated", "J", False)
                for number, row in enumerate(reference["table4_rows"]["rows"], 1)
                if not row["name"].startswith("Harmonic")]
    rows = []
    for table, number, row, column, units, magnitude in printed:
        ours, status = _ours(cases, row["name"], column, magnitude)
        model, test = row[column], row[f"{column}_test"]
        rows.append({"table": table, "printed_row": number, "interface": row["interface"], "row": row["name"],
                     "quantity": column,
                     "units": units, "ours": ours, "paper_model": model, "paper_test": test,
                     "difference_from_model": relative_difference(ours, model),
                     "difference_from_test": relative_difference(ours, test),
                     "paper_model_from_test": relative_difference(model, test), "status": status})
    return rows


def comparisons(rows: list[dict], tolerances: dict) -> dict[str, list[dict]]:
    """Cell-by-cell comparisons of our model with the paper's model column, per table."""
    out = {}
    for table in ("table3", "table4"):
        mine = [row for row in rows if row["table"] == table]
        keys = [f"{row['row']} (interface {row['interface']}, printed row {row['printed_row']})" for row in mine]
        ours = {key: {row["quantity"]: row["ours"]} for key, row in zip(keys, mine) if row["status"] == "ok"}
        paper = {key: {row["quantity"]: row["paper_model"]} for key, row in zip(keys, mine)}
        missing = {key: row["status"] for key, row in zip(keys, mine) if row["status"] != "ok"}
        notes = {f"{key}.{row['quantity']}": f"paper's test value {row['paper_test']:g} {row['units']}"
                 for key, row in zip(keys, mine)}
        quantity = mine[0]["quantity"]
        out[table] = compare_cells(table, ours, paper, [quantity], tolerances, missing=missing, notes=notes)
    return out


def write_shaking_table_comparison(cases_path, model_path, table3_path, table4_path, tolerances: dict) -> list[Path]:
    """``table3_table4_model.csv`` and the two comparison tables from ``model_responses.csv``."""
    cases = {row["case"]: row for row in read_csv_rows(cases_path)}
    rows = model_rows(cases)
    tables = comparisons(rows, tolerances)
    return [write_csv_atomic(model_path, rows), write_comparison(table3_path, tables["table3"]),
            write_comparison(table4_path, tables["table4"])]
