"""Study ``table6``: μ_max of the paper's records (its Tables 6 and 7, Figs. 21 to 23).

Sweeps every available paper record with the paper's block mass on the
paper's friction grid (``mu_grid``) and on a fine grid (``table6.fine_mu``),
then writes, under ``out_dir`` (the results folder):

- ``sweeps/paper_grid.nc`` and ``sweeps/paper_fine.nc``: the cubes;
- ``tables/table6_results.csv``: PGA [m/s²], RMS acceleration over the
  significant duration [m/s²], E_df,max [J] and μ_max on the paper's grid,
  on the fine grid and continuous (:func:`stickslip.analysis.refine_mu_max`);
- ``tables/table7_ranges.csv``: the near-optimal range {μ : E_df ≥ q·E_df,max}
  on both grids, and the interval of q that would reproduce the paper's range;
- ``tables/table6_comparison.csv``, ``tables/table7_comparison.csv``: ours
  against the paper cell by cell;
- ``fits.json``: μ_max against PGA (line, r, bootstrap band; Fig. 22) and
  against RMS acceleration (Fig. 23), with the raw points.

A record that cannot be acquired keeps its rows, with status ``missing: …``.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.analysis import consistent_q_interval, mu_max_on_grid, near_optimal_range, refine_mu_max, relation_summary
from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.io import write_csv_atomic, write_text_atomic
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, write_comparison
from stickslip.studies.records import load_study_records
from stickslip.sweeps import sweep, write_cube


def fine_grid(settings: dict) -> np.ndarray:
    """The fine friction grid [1] from ``{start, stop, step}`` (stop included)."""
    count = int(round((settings["stop"] - settings["start"]) / settings["step"])) + 1
    return np.round(settings["start"] + settings["step"] * np.arange(count), 9)


def study_sweeps(config: dict, records: dict, mu_grid, settings: dict) -> tuple[xr.Dataset, xr.Dataset]:
    """The paper-grid and fine-grid cubes of ``records`` (block mass from the config)."""
    common = {
        "mass": config.get("block_mass", PAPER_BLOCK_MASS),
        "g": config.get("gravity", STANDARD_GRAVITY),
        "config": {"study": "table6", "mu_grid": list(mu_grid), "table6": settings},
    }
    records = list(records.values())
    return sweep(records, mu_grid, **common), sweep(records, fine_grid(settings["fine_mu"]), **common)


def results_rows(records: dict, record_ids, missing, grid: xr.Dataset, fine: xr.Dataset) -> list[dict]:
    """One Table 6 row per record id (missing records keep a row with their status)."""
    energy, fine_energy = grid.energy_dissipated, fine.energy_dissipated
    rows = []
    for record_id in record_ids:
        if record_id in missing:
            rows.append({"record": record_id, "status": missing[record_id]})
            continue
        case = grid.sel(record=record_id)
        continuous = refine_mu_max(records[record_id], fine.mu.values, mass=grid.attrs["block_mass"], g=grid.attrs["gravity"],
                                   energy_on_grid=fine_energy.sel(record=record_id).values)
        rows.append({
            "record": record_id,
            "event": str(case.event.values),
            "station": str(case.station.values),
            "component": str(case.component.values),
            "status": "ok",
            "pga": float(case.pga),
            "rms_acceleration": float(case.rms_acceleration),
            "significant_duration": float(case.significant_duration),
            "energy_dissipated_max": float(energy.sel(record=record_id).max("mu")),
            "mu_max": float(mu_max_on_grid(energy.sel(record=record_id))),
            "mu_max_fine": continuous.grid_argument,
            "energy_dissipated_max_fine": continuous.grid_value,
            "mu_max_continuous": continuous.argument,
            "energy_dissipated_max_continuous": continuous.value,
        })
    return rows


def ranges_rows(record_ids, missing, grid: xr.Dataset, fine: xr.Dataset, q: float) -> list[dict]:
    """One Table 7 row per record id: near-optimal ranges and the q interval matching the paper's."""
    paper = paper_tables()["table7_ranges"]["rows"]
    rows = []
    for record_id in record_ids:
        if record_id in missing:
            rows.append({"record": record_id, "status": missing[record_id]})
            continue
        energy = grid.energy_dissipated.sel(record=record_id)
        low, high, contiguous = near_optimal_range(energy.values, energy.mu.values, q=q)
        fine_low, fine_high, fine_contiguous = near_optimal_range(
            fine.energy_dissipated.sel(record=record_id).values, fine.mu.values, q=q
        )
        row = {"record": record_id, "status": "ok", "q": q, "mu_low": low, "mu_high": high,
               "contiguous": bool(contiguous), "mu_low_fine": fine_low, "mu_high_fine": fine_high,
               "contiguous_fine": bool(fine_contiguous)}
        if record_id in paper:
            q_above, q_at_most = consistent_q_interval(energy.values, energy.mu.values,
                                                       paper[record_id]["mu_low"], paper[record_id]["mu_high"])
            row.update(q_reproducing_paper_above=q_above, q_reproducing_paper_at_most=q_at_most)
        rows.append(row)
    return rows


def fits(rows: list[dict], q_rows: list[dict], settings: dict) -> dict:
    """μ_max against PGA and RMS (grid and continuous μ_max), and the q analysis of Table 7."""
    ok = [row for row in rows if row["status"] == "ok"]
    labels = [row["record"] for row in ok]
    boot = {"n_boot": settings.get("n_boot", 2000), "seed": settings.get("seed", 0)}
    summary = {"units": {"pga": "m/s2", "rms_acceleration": "m/s2", "mu_max": "1"}, "records": labels}
    for x_name in ("pga", "rms_acceleration"):
        for y_name in ("mu_max", "mu_max_continuous"):
            summary[f"{y_name}_vs_{x_name}"] = relation_summary(
                [row[x_name] for row in ok], [row[y_name] for row in ok], labels=labels, **boot
            )
    intervals = [(row["q_reproducing_paper_above"], row["q_reproducing_paper_at_most"])
                 for row in q_rows if "q_reproducing_paper_above" in row]
    if intervals:
        above, at_most = max(low for low, _ in intervals), min(high for _, high in intervals)
        summary["q_reproducing_paper_table7"] = {
            "above": above, "at_most": at_most, "exists": above < at_most,
            "per_record": {row["record"]: [row["q_reproducing_paper_above"], row["q_reproducing_paper_at_most"]]
                           for row in q_rows if "q_reproducing_paper_above" in row},
        }
    return summary


def comparisons(rows: list[dict], q_rows: list[dict], missing: dict, tolerances: dict) -> tuple[list, list]:
    """Cell-by-cell comparison of Tables 6 and 7 with the paper's printed values."""
    reference = paper_tables()
    ours6 = {row["record"]: row for row in rows if row["status"] == "ok"}
    table6 = compare_cells(
        "table6", ours6, reference["table6_results"]["rows"],
        ["pga", "rms_acceleration", "energy_dissipated_max", "mu_max"], tolerances, missing=missing,
        notes={"rms_acceleration": "printed column repeats Table 4's model E_df column (typesetting error); "
                                   "see the table6_text row for the value the text gives",
               "energy_dissipated_max": "ours lower for every record; likely NGA-West1 vs the paper's NGA-West2 "
                                        "processing and the paper's ANSYS model (docs/studies.md)"},
    )
    text_values = reference["table6_results"]["text_values"]
    table6 += compare_cells(
        "table6_text", {key: ours6[key] for key in text_values if key in ours6}, text_values, ["rms_acceleration"], tolerances,
        notes={"rms_acceleration": "RMS acceleration quoted in the paper's text (section 5.3.1)"},
    )
    ours7 = {row["record"]: row for row in q_rows if row["status"] == "ok"}
    table7 = compare_cells("table7", ours7, reference["table7_ranges"]["rows"], ["mu_low", "mu_high"], tolerances,
                           missing=missing)
    return table6, table7


def run(config: dict, out_dir: Path) -> list[Path]:
    """Run the study; write the cubes, tables and fits under ``out_dir``; return their paths."""
    out_dir = Path(out_dir)
    settings = config["table6"]
    record_ids = list(config["paper_records"])
    records, missing = load_study_records(config, record_ids)
    grid, fine = study_sweeps(config, records, config["mu_grid"], settings)
    rows = results_rows(records, record_ids, missing, grid, fine)
    q_rows = ranges_rows(record_ids, missing, grid, fine, float(settings["near_optimal_fraction"]))
    table6, table7 = comparisons(rows, q_rows, missing, config["comparison_tolerance"])
    tables = out_dir / "tables"
    return [
        write_cube(grid, out_dir / "sweeps" / "paper_grid.nc"),
        write_cube(fine, out_dir / "sweeps" / "paper_fine.nc"),
        write_csv_atomic(tables / "table6_results.csv", rows),
        write_csv_atomic(tables / "table7_ranges.csv", q_rows),
        write_comparison(tables / "table6_comparison.csv", table6),
        write_comparison(tables / "table7_comparison.csv", table7),
        _write_json(out_dir / "fits.json", fits(rows, q_rows, settings)),
    ]


def _write_json(path: Path, document: dict) -> Path:
    write_text_atomic(path, json.dumps(document, indent=2) + "\n")
    return path
