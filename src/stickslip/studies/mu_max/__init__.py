"""μ_max of each record on the paper's grid, on a fine grid and continuous (the paper's Tables 6 and 7, Fig. 21).

Reads the gathered cubes of the sweep stage: the paper's grid
(``results/sweeps/paper.nc``) and the fine grid (``results/sweeps/fine.nc``,
which holds the continuous μ_max of each record).  :func:`write_mu_max_tables`
writes

- ``table6_results.csv``: PGA [m/s²], RMS acceleration over the significant
  duration [m/s²], E_df,max [J] and μ_max on the paper's grid, on the fine grid
  and continuous (the fine cube's results, stored by its sweep through
  :func:`stickslip.with_optimum`, the one μ_max route), and whether μ_max
  is the first or last μ of its grid (``mu_max_on_grid_edge``,
  ``mu_max_fine_on_grid_edge``: then it only bounds the true maximum);
- ``table7_ranges.csv``: the near-optimal range {μ : E_df ≥ q·E_df,max} on both grids.

Each quantity is the one :mod:`stickslip.optimum` defines for every sweep
(:func:`stickslip.optimum.grid_results`), so a record whose block never
slides on a grid has no μ_max there (an empty cell), as in the collection study.

:func:`write_mu_max_comparisons` sets them beside the paper's printed values
(``table6_comparison.csv``, ``table7_comparison.csv``) and writes, per record,
the interval of q that would reproduce the paper's Table 7 range
(``table7_q_intervals.csv``).  A record that could not be swept keeps its rows,
with its status ``missing: …``.
"""

from __future__ import annotations

from pathlib import Path

import xarray as xr

from stickslip.analysis import consistent_q_interval
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.errors import StickslipError
from stickslip.optimum import DEFAULT_Q, RESULTS, curves_of, grid_results
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, write_comparison
from stickslip.studies.errata import confirmed_errata
from stickslip.sweeps import read_cube


def _per_record(cube: xr.Dataset, q: float = DEFAULT_Q) -> dict[str, dict[str, float]]:
    """Record id -> the grid results of :func:`stickslip.optimum.grid_results` for the records of ``cube``."""
    results = grid_results(curves_of(cube), q)
    return {str(record_id): {name: float(values[index]) for name, values in results.items()}
            for index, record_id in enumerate(cube.record.values)}


def _stored(cube: xr.Dataset, q: float | None = None) -> dict[str, dict[str, float]]:
    """Record id -> the per-record results a refined sweep stored (:func:`stickslip.with_optimum`).

    StickslipError when ``q`` is given and they were found with another near-optimal fraction.
    """
    if q is not None and float(cube.attrs["near_optimal_fraction"]) != q:
        raise StickslipError(f"the fine grid's results are for q = {cube.attrs['near_optimal_fraction']}, not {q}: "
                             "rerun its sweep")
    return {str(record_id): {name: float(cube[name].values[index]) for name in RESULTS}
            for index, record_id in enumerate(cube.record.values)}


def _flag(value: float) -> bool | str:
    """A 1/0 flag as True/False, or "" where it is undefined (NaN)."""
    return "" if value != value else bool(value)


def results_rows(grid: xr.Dataset, fine: xr.Dataset) -> list[dict]:
    """One Table 6 row per record of the cubes (a missing record keeps a row with its status)."""
    on_grid, on_fine = _per_record(grid), _stored(fine)
    rows = []
    for record_id, status in zip(grid.record.values, grid.status.values):
        if status != "ok":
            rows.append({"record": record_id, "status": status})
            continue
        case = grid.sel(record=record_id)
        paper, dense = on_grid[str(record_id)], on_fine[str(record_id)]
        rows.append({
            "record": record_id,
            "event": str(case.event.values),
            "station": str(case.station.values),
            "component": str(case.component.values),
            "status": "ok",
            "pga": float(case.pga),
            "rms_acceleration": float(case.rms_acceleration),
            "significant_duration": float(case.significant_duration),
            "energy_dissipated_max": paper["energy_dissipated_max"],
            "mu_max": paper["mu_max"],
            "mu_max_fine": dense["mu_max"],
            "energy_dissipated_max_fine": dense["energy_dissipated_max"],
            "mu_max_continuous": dense["mu_max_continuous"],
            "energy_dissipated_max_continuous": dense["energy_dissipated_max_continuous"],
            "mu_max_on_grid_edge": _flag(paper["mu_max_at_grid_edge"]),
            "mu_max_fine_on_grid_edge": _flag(dense["mu_max_at_grid_edge"]),
        })
    return rows


def ranges_rows(grid: xr.Dataset, fine: xr.Dataset, q: float) -> list[dict]:
    """One Table 7 row per record: the near-optimal ranges on the paper's grid and on the fine grid."""
    on_grid, on_fine = _per_record(grid, q), _stored(fine, q)
    rows = []
    for record_id, status in zip(grid.record.values, grid.status.values):
        if status != "ok":
            rows.append({"record": record_id, "status": status})
            continue
        paper, dense = on_grid[str(record_id)], on_fine[str(record_id)]
        rows.append({"record": record_id, "status": "ok", "q": q, "mu_low": paper["mu_low"],
                     "mu_high": paper["mu_high"], "contiguous": _flag(paper["contiguous"]),
                     "mu_low_fine": dense["mu_low"], "mu_high_fine": dense["mu_high"],
                     "contiguous_fine": _flag(dense["contiguous"])})
    return rows


def q_interval_rows(grid: xr.Dataset) -> list[dict]:
    """Per record of the paper's Table 7: the interval (above, at_most] of q that reproduces its printed range."""
    paper = paper_tables()["table7_ranges"]["rows"]
    rows = []
    for record_id, status in zip(grid.record.values, grid.status.values):
        if record_id not in paper:
            continue
        if status != "ok":
            rows.append({"record": record_id, "status": status})
            continue
        energy = grid.energy_dissipated.sel(record=record_id)
        above, at_most = consistent_q_interval(energy.values, energy.mu.values,
                                               paper[record_id]["mu_low"], paper[record_id]["mu_high"])
        rows.append({"record": record_id, "status": "ok", "paper_mu_low": paper[record_id]["mu_low"],
                     "paper_mu_high": paper[record_id]["mu_high"], "q_above": above, "q_at_most": at_most})
    ok = [row for row in rows if row["status"] == "ok"]
    if ok:
        above, at_most = max(row["q_above"] for row in ok), min(row["q_at_most"] for row in ok)
        rows.append({"record": "all records", "status": "one q fits all" if above < at_most else "no single q fits all",
                     "q_above": above, "q_at_most": at_most})
    return rows


def comparisons(rows: list[dict], q_rows: list[dict], tolerances: dict,
                errata: dict[str, str] | None = None) -> tuple[list, list]:
    """Cell-by-cell comparison of Tables 6 and 7 with the paper's printed values.

    ``errata`` marks the cells that confirmed errata explain
    (:func:`stickslip.studies.errata.confirmed_errata`).
    """
    reference = paper_tables()
    missing = {row["record"]: row["status"] for row in rows if row["status"] != "ok"}
    ours6 = {row["record"]: _numbers(row) for row in rows if row["status"] == "ok"}
    table6 = compare_cells(
        "table6", ours6, reference["table6_results"]["rows"],
        ["pga", "rms_acceleration", "energy_dissipated_max", "mu_max"], tolerances, missing=missing, errata=errata,
        notes={"rms_acceleration": "printed column repeats Table 4's model E_df column (typesetting error); "
                                   "see the table6_text row for the value the text gives",
               "energy_dissipated_max": "ours lower for every record; likely NGA-West1 vs the paper's NGA-West2 "
                                        "processing and the paper's ANSYS model (docs/studies.md)"},
    )
    text_values = reference["table6_results"]["text_values"]
    table6 += compare_cells(
        "table6_text", {key: ours6[key] for key in text_values if key in ours6}, text_values, ["rms_acceleration"],
        tolerances, notes={"rms_acceleration": "RMS acceleration quoted in the paper's text (section 5.3.1)"},
    )
    ours7 = {row["record"]: _numbers(row) for row in q_rows if row["status"] == "ok"}
    table7 = compare_cells("table7", ours7, reference["table7_ranges"]["rows"], ["mu_low", "mu_high"], tolerances,
                           missing=missing)
    return table6, table7


def write_mu_max_tables(grid_path, fine_path, results_path, ranges_path, q: float) -> list[Path]:
    """Tables 6 and 7 (ours) from the gathered paper-grid and fine-grid cubes."""
    grid, fine = read_cube(grid_path), read_cube(fine_path)
    return [write_csv_atomic(results_path, results_rows(grid, fine)),
            write_csv_atomic(ranges_path, ranges_rows(grid, fine, q))]


def write_mu_max_comparisons(results_path, ranges_path, grid_path, errata_path, table6_path, table7_path, q_path,
                             tolerances: dict) -> list[Path]:
    """Our Tables 6 and 7 beside the paper's, and the q intervals that reproduce the paper's ranges.

    ``errata_path`` is ``errata.csv`` (:mod:`stickslip.studies.errata`): the
    cells its confirmed errata explain get the status ``paper erratum: …``.
    """
    errata = confirmed_errata(read_csv_rows(errata_path))
    table6, table7 = comparisons(read_csv_rows(results_path), read_csv_rows(ranges_path), tolerances, errata)
    return [write_comparison(table6_path, table6), write_comparison(table7_path, table7),
            write_csv_atomic(q_path, q_interval_rows(read_cube(grid_path)))]


def _numbers(row: dict) -> dict:
    """The numeric cells of a CSV row as floats (the text cells left out)."""
    numbers = {}
    for key, value in row.items():
        try:
            numbers[key] = float(value)
        except (TypeError, ValueError):
            continue
    return numbers
