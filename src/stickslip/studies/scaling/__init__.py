"""Scaling: μ_max of records scaled to target PGAs, 0.60 g, 0.80 g and 1.00 g (the paper's Table 8, Figs. 24-25).

The paper scaled the Mendoza 1985 record, which no reachable source holds.
The workflow scales each record of ``scaling.records`` (default: every paper
record) instead, and says so: every row names its record, and the comparison
with the paper's Table 8 keeps the paper's Mendoza rows with status
``missing: …`` when Mendoza is not available.

Reads the gathered cubes of the paper's grid (unscaled) and of the scaled grid
(record, target PGA [m/s²], μ) and writes ``table8_results.csv``: for each
record, the unscaled record and each target: scale factor [1], PGA and RMS
acceleration [m/s²], E_df,max [J], μ_max [1] and whether μ_max is the first or last
μ of the grid (``mu_max_on_grid_edge``).  :func:`write_scaling_comparison`
writes ``table8_comparison.csv``.
"""

from __future__ import annotations

from pathlib import Path

import xarray as xr

from stickslip.analysis import mu_max_on_grid, mu_max_on_grid_edge
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, write_comparison
from stickslip.sweeps import available, missing_records, read_cube


def scaling_rows(unscaled: xr.Dataset, scaled: xr.Dataset) -> list[dict]:
    """One row per (record, scaling) of the scaled cube: the unscaled record first, then each target PGA."""
    missing = missing_records(scaled)
    scaled = available(scaled)
    rows = []
    for record_id in scaled.record.values:
        base = unscaled.sel(record=record_id)
        rows.append({"record": record_id, "scaling": "unscaled", "target_pga": "", "scale_factor": 1.0,
                     "pga": float(base.pga), "rms_acceleration": float(base.rms_acceleration),
                     "energy_dissipated_max": float(base.energy_dissipated.max("mu")),
                     "mu_max": float(mu_max_on_grid(base.energy_dissipated)),
                     "mu_max_on_grid_edge": mu_max_on_grid_edge(base.energy_dissipated), "status": "ok"})
        for target in scaled.target_pga.values:
            case = scaled.sel(record=record_id, target_pga=target)
            rows.append({"record": record_id, "scaling": f"PGA {target / scaled.attrs['gravity']:.2f} g",
                         "target_pga": float(target), "scale_factor": float(case.scale_factor),
                         "pga": float(case.pga), "rms_acceleration": float(case.rms_acceleration),
                         "energy_dissipated_max": float(case.energy_dissipated.max("mu")),
                         "mu_max": float(mu_max_on_grid(case.energy_dissipated)),
                         "mu_max_on_grid_edge": mu_max_on_grid_edge(case.energy_dissipated), "status": "ok"})
    rows += [{"record": record_id, "status": status} for record_id, status in missing.items()]
    return rows


def comparison(rows: list[dict[str, str]], tolerances: dict) -> list[dict]:
    """The paper's Table 8 rows (its record, keyed ``record xscale``) against ours when we have that record."""
    reference = paper_tables()["table8_scaling_mendoza"]
    record_id = reference["record"]
    paper = {f"{record_id} x{row['scale']:.2f}": row for row in reference["rows"]}
    ours_rows = [row for row in rows if row["record"] == record_id]
    status = ours_rows[0]["status"] if ours_rows else "missing: not in the scaling study's records (scaling.records)"
    columns = ["pga", "rms_acceleration", "energy_dissipated_max", "mu_max"]
    ours, missing = {}, {}
    if status == "ok":
        ours = {key: {column: float(row[column]) for column in columns}
                for key, row in zip(paper, ours_rows)}
    else:
        missing = dict.fromkeys(paper, status)
    return compare_cells("table8", ours, paper, columns, tolerances, missing=missing)


def write_scaling_table(unscaled_path, scaled_path, table_path) -> Path:
    """``table8_results.csv`` from the gathered unscaled (paper grid) and scaled cubes."""
    unscaled, scaled = read_cube(unscaled_path), read_cube(scaled_path)
    return write_csv_atomic(table_path, scaling_rows(unscaled, scaled))


def write_scaling_comparison(table_path, comparison_path, tolerances: dict) -> Path:
    """``table8_comparison.csv``: the paper's Table 8 against our rows for the same record."""
    return write_comparison(comparison_path, comparison(read_csv_rows(table_path), tolerances))
