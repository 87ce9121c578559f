"""Study ``table8``: μ_max of records scaled to PGA 0.60 g, 0.80 g and 1.00 g (the paper's Table 8, Figs. 24-25).

The paper scaled the Mendoza 1985 record, which no reachable source holds.
This study scales each record of ``table8.records`` (default: every
available paper record) instead, and says so: every row names its record,
and the comparison with the paper's Table 8 keeps the paper's Mendoza rows
with status ``missing: …``.  Writes under ``out_dir``:

- ``sweeps/table8_scaling.nc``: the cube over (record, target PGA [m/s²], μ);
- ``tables/table8_results.csv``: for each record, the unscaled record and
  each target: scale factor [1], PGA and RMS acceleration [m/s²], E_df,max [J], μ_max [1];
- ``tables/table8_comparison.csv``: the paper's Mendoza rows against ours (missing).
"""

from __future__ import annotations

from pathlib import Path

import xarray as xr

from stickslip.analysis import mu_max_on_grid
from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.io import write_csv_atomic
from stickslip.reference import paper_tables
from stickslip.studies.compare import compare_cells, write_comparison
from stickslip.studies.records import load_study_records
from stickslip.sweeps import sweep, write_cube


def scaling_rows(unscaled: xr.Dataset, scaled: xr.Dataset, missing: dict) -> list[dict]:
    """One row per (record, scaling): the unscaled record first, then each target PGA."""
    rows = []
    for record_id in unscaled.record.values:
        base = unscaled.sel(record=record_id)
        rows.append({"record": record_id, "scaling": "unscaled", "target_pga": "", "scale_factor": 1.0,
                     "pga": float(base.pga), "rms_acceleration": float(base.rms_acceleration),
                     "energy_dissipated_max": float(base.energy_dissipated.max("mu")),
                     "mu_max": float(mu_max_on_grid(base.energy_dissipated)), "status": "ok"})
        for target in scaled.scale.values:
            case = scaled.sel(record=record_id, scale=target)
            rows.append({"record": record_id, "scaling": f"PGA {target / scaled.attrs['gravity']:.2f} g",
                         "target_pga": float(target), "scale_factor": float(case.scale_factor),
                         "pga": float(case.pga), "rms_acceleration": float(case.rms_acceleration),
                         "energy_dissipated_max": float(case.energy_dissipated.max("mu")),
                         "mu_max": float(mu_max_on_grid(case.energy_dissipated)), "status": "ok"})
    rows += [{"record": record_id, "status": status} for record_id, status in missing.items()]
    return rows


def comparison(missing: dict, ours_by_scale: dict, tolerances: dict) -> list[dict]:
    """The paper's Table 8 (Mendoza) rows, keyed ``record x scale``, against ours when we have the record."""
    reference = paper_tables()["table8_scaling_mendoza"]
    record_id = reference["record"]
    paper = {f"{record_id} x{row['scale']:.2f}": row for row in reference["rows"]}
    missing_rows = {key: missing[record_id] for key in paper if record_id in missing}
    return compare_cells("table8", ours_by_scale, paper, ["pga", "rms_acceleration", "energy_dissipated_max", "mu_max"],
                         tolerances, missing=missing_rows)


def run(config: dict, out_dir: Path) -> list[Path]:
    """Run the scaling study; write the cube and tables under ``out_dir``; return their paths."""
    out_dir = Path(out_dir)
    settings = config["table8"]
    g = config.get("gravity", STANDARD_GRAVITY)
    record_ids = list(settings.get("records") or config["paper_records"])
    paper_record = paper_tables()["table8_scaling_mendoza"]["record"]
    records, missing = load_study_records(config, record_ids + [paper_record] * (paper_record not in record_ids))
    studied = [records[record_id] for record_id in record_ids if record_id in records]
    common = {"mass": config.get("block_mass", PAPER_BLOCK_MASS), "g": g,
              "config": {"study": "table8", "mu_grid": list(config["mu_grid"]), "table8": settings}}
    unscaled = sweep(studied, config["mu_grid"], **common)
    scaled = sweep(studied, config["mu_grid"], target_pga=[value * g for value in settings["target_pga_g"]], **common)
    rows = scaling_rows(unscaled, scaled, {key: value for key, value in missing.items() if key in record_ids})
    ours_paper_record = {}
    if paper_record in records:
        reference_rows = paper_tables()["table8_scaling_mendoza"]["rows"]
        ours = [row for row in rows if row["record"] == paper_record and row["status"] == "ok"]
        ours_paper_record = {f"{paper_record} x{paper['scale']:.2f}": row for paper, row in zip(reference_rows, ours)}
    tables = out_dir / "tables"
    return [
        write_cube(scaled, out_dir / "sweeps" / "table8_scaling.nc"),
        write_csv_atomic(tables / "table8_results.csv", rows),
        write_comparison(tables / "table8_comparison.csv", comparison(missing, ours_paper_record, config["comparison_tolerance"])),
    ]
