"""The findings of a collection study: relations, coverage of μ, the paper's claims, near against far, design chart.

One workflow step reads the study's per-record table (``records.csv``) and
cube (``study.nc``, :mod:`stickslip.studies.collections.sweep`) and writes:

- ``relations.csv``: μ_max against each predictor (:mod:`stickslip.studies.collections.relations`);
- ``coverage.csv``: the reference μ and the design μ by PGA band (:mod:`stickslip.studies.collections.friction_design`);
- ``claims.csv``: the paper's claims, tested;
- ``near_far.csv``: near-fault against far-field records (empty without both);
- ``design.json``: the design chart: μ_max against its best predictor with a
  95 % prediction band, the ratio μ_max·g/PGA's quantiles (a band
  proportional to PGA, as the scaling law suggests), the records' points
  and the paper's eight points from its Table 6.

Only the records studied enter them
(:func:`stickslip.collections.members.studied`: read, and sliding at
some μ of the grid); a statistic of fewer than ``min_records`` records is not
given, and the outputs say why.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from stickslip.plumbing.files import read_csv_rows, write_csv_atomic, write_text_atomic
from stickslip.collections.members import studied, too_few
from stickslip.studies.collections.relations import (PREDICTORS, RESPONSE, best_predictor, prediction_band,
                                                    relations_rows)
from stickslip.studies.collections.friction_design import claims_rows, coverage_rows, near_far_rows, paper_line, paper_points
from stickslip.sweeps import read_cube

#: Quantiles of μ_max·g/PGA drawn on the design chart.
RATIO_QUANTILES = (0.1, 0.5, 0.9)


def design_chart(rows: list[dict], relations: list[dict], g: float, min_records: int) -> dict:
    """The design chart's data (see the module's docstring); ``g`` [m s-2]."""
    ok = studied(rows)
    best = best_predictor(relations, len(ok))
    chart = {"records": len(ok), "g": g, "units": {"mu_max": "1", "pga": "m s-2", "g": "m s-2"},
             "paper_points": paper_points(), "paper_points_source": "the paper's Table 6, as printed",
             "paper_fit": paper_line(),
             "pga_points": [{"record": row["id"], "event": row["event"], "x": float(row["pga"]),
                             "y": float(row[RESPONSE])} for row in ok]}
    ratio = np.array([float(row["mu_max_g_over_pga"]) for row in ok])
    reason = too_few(ratio.size, min_records, "a quantile band")
    if reason:
        chart["ratio_status"] = reason
    else:
        chart["ratio_status"] = "ok"
        chart["ratio_quantiles"] = {f"{q:g}": float(np.quantile(ratio, q)) for q in RATIO_QUANTILES}
    if best is None:
        pga = next(row for row in relations if row["predictor"] == "pga")
        return {**chart, "status": "no fit: " + (pga["status"] if pga["status"] != "ok" else
                                                 "no predictor is known for 90 % of the records studied")}
    name = best["predictor"]
    pairs = [(float(row[name]), float(row[RESPONSE]), row["id"], row["event"]) for row in ok if row[name] != ""]
    x = np.array([p[0] for p in pairs])
    y = np.array([p[1] for p in pairs])
    band = prediction_band(x, y, np.linspace(x.min(), x.max(), 60))
    return {**chart, "status": "ok", "predictor": name, "predictor_label": PREDICTORS[name][1],
            "predictor_units": PREDICTORS[name][0], "loeo_rmse": best["loeo_rmse"], "band": band,
            "points": [{"record": p[2], "event": p[3], "x": p[0], "y": p[1]} for p in pairs]}


def write_collection_analysis(table_path: str | Path, study_path: str | Path, relations_path: str | Path,
                              coverage_path: str | Path, claims_path: str | Path, near_far_path: str | Path,
                              design_path: str | Path, n_boot: int, seed: int, min_records: int,
                              reference_mu: float, near_optimal_fraction: float, efficiency_target: float,
                              coverage_target: float, pga_bands_g: list[float], near_fault_km: float,
                              g: float) -> list[Path]:
    """Write the five outputs of the module's docstring from the study's table and cube."""
    rows = read_csv_rows(table_path)
    relations = relations_rows(rows, n_boot, seed, min_records)
    ok_rows = studied(rows)
    cube = read_cube(study_path).sel(record=[row["id"] for row in ok_rows])
    coverage = coverage_rows(cube, np.array([float(row["pga"]) / g for row in ok_rows]), pga_bands_g, reference_mu,
                             near_optimal_fraction, efficiency_target, coverage_target,
                             np.array([float(row["efficiency"]) for row in ok_rows]), min_records)
    write_csv_atomic(relations_path, relations)
    write_csv_atomic(coverage_path, coverage)
    write_csv_atomic(claims_path, claims_rows(relations, coverage, len(ok_rows), reference_mu),
                     ["claim", "paper", "ours", "verdict", "rule"])
    write_csv_atomic(near_far_path, near_far_rows(rows, near_fault_km, min_records),
                     ["quantity", "units", "n_near", "n_far", "median_near", "median_far", "mann_whitney_p_value"])
    write_text_atomic(design_path, json.dumps(design_chart(rows, relations, g, min_records), indent=1) + "\n")
    return [Path(p) for p in (relations_path, coverage_path, claims_path, near_far_path, design_path)]
