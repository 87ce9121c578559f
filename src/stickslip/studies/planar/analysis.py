"""The planar study's findings, written in one workflow step from the gathered cube and the pair tables.

- ``pair_results.csv``: per pair, the optimum in the plane, on each component, on the worst azimuth and
  the azimuths' median, and the ratio R (:func:`stickslip.studies.planar.ratios.pair_rows`);
- ``ratio_by_mu.csv``: R against μ (:func:`stickslip.studies.planar.ratios.ratio_rows`);
- ``relations.csv``, ``design.json``, ``near_far.csv``: :mod:`stickslip.studies.planar.design`;
- ``summary.json``: the counts (pairs formed, swept, left out and why), the largest energy-balance
  residual over every pair and μ relative to the pair's largest E_I (in the plane and in 1-D), the headline
  numbers and the settings, which the page, the index and docs/planar.md quote.

Without any pair (pyslammer's sample motions are single components) every file is written and says so.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import numpy as np
from scipy import stats

from stickslip.plumbing.files import read_csv_rows, write_csv_atomic, write_text_atomic
from stickslip.collections.members import too_few
from stickslip.studies.planar.design import design_chart, near_far_reason, near_far_rows, relations_rows
from stickslip.studies.planar.pairs import REASONS
from stickslip.studies.planar.ratios import pair_rows, ratio_rows
from stickslip.sweeps import read_cube

#: Columns of pair_results.csv, in order.
RESULT_COLUMNS = (
    "pair", "status", "event", "station", "first_component", "second_component", "separation", "rupture_distance",
    "near_fault", "padded_samples", "pga_first", "pga_second", "pga_larger", "pga_plane", "rms_first", "rms_second",
    "rms_plane", "mu_max_plane", "mu_max_first", "mu_max_second", "mu_max_worst_azimuth", "worst_azimuth",
    "mu_max_rotd50", "energy_dissipated_max_plane", "energy_dissipated_max_first", "energy_dissipated_max_second",
    "energy_dissipated_max_worst_azimuth", "energy_dissipated_max_rotd50", "peak_displacement_plane",
    "peak_displacement_first", "peak_displacement_second", "peak_displacement_rotd100", "residual_displacement_plane",
    "ratio_components", "ratio_azimuths", "energy_ratio_plane_to_worst_azimuth", "mu_max_plane_over_larger_component",
    "mu_max_plane_over_worst_azimuth", "mu_max_plane_g_over_pga_plane",
)


def _quantiles(values, qs=(0.1, 0.5, 0.9)) -> dict:
    values = np.asarray(values, dtype=float)
    values = values[np.isfinite(values)]
    return {"n": int(values.size), **({f"q{round(q * 100):02d}": float(np.quantile(values, q)) for q in qs}
                                       if values.size else {})}


def _spearman(x, y) -> dict:
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    keep = np.isfinite(x) & np.isfinite(y)
    if keep.sum() < 3:
        return {"n": int(keep.sum())}
    result = stats.spearmanr(x[keep], y[keep])
    return {"n": int(keep.sum()), "rho": float(result.statistic), "p_value": float(result.pvalue)}


def summary(pairs: list[dict], unpaired: list[dict], rows: list[dict], ratios: list[dict], relations: list[dict],
            design: dict, cube_attrs: dict, settings: dict) -> dict:
    """The summary.json document (see the module's docstring)."""
    ok = [row for row in rows if row["status"] == "ok"]
    document = {
        "members": settings["members"], "pairs_formed": len(pairs),
        "pairs_swept": len(rows), "pairs_not_read": [{"pair": p["pair"], "reason": p["reason"]}
                                                     for p in pairs if p["status"] != "ok"],
        "pairs_never_sliding": [row["pair"] for row in rows if row["status"] != "ok"],
        "pairs_studied": len(ok), "events": len({row["event"] for row in ok}),
        "unpaired": dict(Counter(row["group"] for row in unpaired)),
        "unpaired_reasons": {group: REASONS[group] for group in {row["group"] for row in unpaired}},
        "not_orthogonal": [{"pair": p["pair"], "separation": float(p["separation"]), "directions": p["directions"]}
                           for p in pairs if p["orthogonal"] in (False, "False")],
        "taken_as_orthogonal": [p["pair"] for p in pairs if "taken as orthogonal" in p["directions"]],
        "padded": {"pairs": sum(int(p["padded_samples"] or 0) > 0 for p in pairs if p["status"] == "ok"),
                   "largest_samples": max([int(p["padded_samples"] or 0) for p in pairs if p["status"] == "ok"],
                                          default=0)},
        "largest_balance_residual": settings.get("largest_balance_residual"),
        "settings": {**{key: value for key, value in settings.items() if key not in ("members",
                                                                                   "largest_balance_residual")},
                     "rtol": cube_attrs.get("rtol"), "method": cube_attrs.get("method")},
    }
    if not pairs:
        groups = ", ".join(f"{n} {group}" for group, n in document["unpaired"].items())
        return {**document, "status": f"no pair: none of the {settings['members']} records of the collection study "
                                      f"has the other horizontal component of its station among them ({groups})"}
    if len(ok) < settings["min_records"]:
        return {**document, "status": too_few(len(ok), settings["min_records"], "the study's statistics")}
    largest = [max(row["mu_max_first"], row["mu_max_second"]) for row in ok]
    document.update({
        "status": "ok",
        "ratio_components_at_mu_max_plane": _quantiles([row["ratio_components"] for row in ok]),
        "ratio_azimuths_at_mu_max_plane": _quantiles([row["ratio_azimuths"] for row in ok]),
        "share_ratio_components_above_1": float(np.mean([row["ratio_components"] > 1 for row in ok])),
        "share_ratio_azimuths_above_1": float(np.mean([row["ratio_azimuths"] > 1 for row in ok])),
        "mu_max_plane": _quantiles([row["mu_max_plane"] for row in ok]),
        "mu_max_larger_component": _quantiles(largest),
        "mu_max_worst_azimuth": _quantiles([row["mu_max_worst_azimuth"] for row in ok]),
        "mu_max_plane_over_larger_component": _quantiles([row["mu_max_plane_over_larger_component"] for row in ok]),
        "mu_max_plane_over_worst_azimuth": _quantiles([row["mu_max_plane_over_worst_azimuth"] for row in ok]),
        "energy_ratio_plane_to_worst_azimuth": _quantiles([row["energy_ratio_plane_to_worst_azimuth"] for row in ok]),
        "mu_max_plane_g_over_pga_plane": _quantiles([row["mu_max_plane_g_over_pga_plane"] for row in ok]),
        "share_worst_azimuth_not_a_component": float(np.mean([row["worst_azimuth"] not in (0.0, 90.0) for row in ok])),
        "ratio_components_vs_pga_plane": _spearman([row["pga_plane"] for row in ok],
                                                   [row["ratio_components"] for row in ok]),
        "ratio_components_vs_rupture_distance": _spearman([row["rupture_distance"] for row in ok],
                                                          [row["ratio_components"] for row in ok]),
        "near_fault_pairs": sum(row["near_fault"] is True for row in ok),
        "far_pairs": sum(row["near_fault"] is False for row in ok),
        "near_far_status": near_far_reason(rows, settings["near_fault_km"], settings["min_records"]) or "ok",
        "relations": {f"{row['response']}_vs_{row['predictor']}": {
            key: row.get(key) for key in ("status", "n", "slope", "slope_low", "slope_high", "intercept", "pearson_r",
                                          "pearson_r_low", "pearson_r_high", "spearman_rho", "spearman_rho_low",
                                          "spearman_rho_high", "loeo_rmse", "loeo_skill")} for row in relations},
        "design": {side: {key: design[side].get(key) for key in ("n", "status", "ratio_quantiles")}
                   | ({"band": {k: design[side]["band"][k] for k in ("slope", "intercept", "residual_sd", "level")}}
                      if "band" in design[side] else {})
                   | ({"coverage": [{k: band.get(k) for k in ("pga_band", "n", "status", "design_mu",
                                                               "share_design_mu", "design_meets_target",
                                                               "share_reference_in_range")}
                                    for band in design[side].get("coverage", [])]})
                   for side in ("plane", "components") if side in design},
        "ratio_by_mu": {f"{row['mu']:g}": {key: row[key] for key in ("pairs_sliding_in_plane", "ratio_components_q50",
                                                                       "ratio_components_q90", "ratio_azimuths_q50",
                                                                       "ratio_azimuths_q90")}
                        for row in ratios if round(row["mu"], 6) in (0.025, 0.05, 0.1, 0.2, 0.3)},
    })
    return document


def largest_balance_residual(cube) -> dict:
    """The largest |E_k + E_df − E_I| at the end of the record over every pair and μ, in the plane and in 1-D.

    Relative to the pair's energy scale, the largest E_I over its μ grid in that direction: at a large μ
    the block barely slides and E_I at the end is the ground's own small kinetic energy left, beside which
    the round-off of sums that reached far larger energies during the record is not small.
    """
    scale = cube["energy_input"].max("mu")
    relative = np.abs(cube["balance_residual"]) / scale.where(scale > 0)
    return {direction: float(relative.sel(direction=direction).max()) for direction in ("plane", "first", "second")}


def write_planar_analysis(study_path: str | Path, pairs_path: str | Path, unpaired_path: str | Path,
                          results_path: str | Path, ratio_path: str | Path, relations_path: str | Path,
                          near_far_path: str | Path, design_path: str | Path, summary_path: str | Path, n_boot: int,
                          seed: int, min_records: int, reference_mu: float, near_optimal_fraction: float,
                          efficiency_target: float, coverage_target: float, pga_bands_g: list[float],
                          near_fault_km: float, g: float) -> list[Path]:
    """Write the files of the module's docstring."""
    pairs = read_csv_rows(pairs_path)
    unpaired = read_csv_rows(unpaired_path)
    cube = read_cube(study_path)
    swept = "pair" in cube.dims
    rows = pair_rows(cube, near_fault_km, g) if swept else []
    ratios = ratio_rows(cube, min_records) if swept else []
    relations = relations_rows(rows, n_boot, seed, min_records)
    design_settings = {"min_records": min_records, "pga_bands_g": pga_bands_g, "reference_mu": reference_mu,
                       "q": near_optimal_fraction, "efficiency_target": efficiency_target,
                       "coverage_target": coverage_target}
    design = design_chart(rows, cube, g, design_settings) if swept else {
        "status": "no pair", "g": g, "pairs": 0}
    settings = {"members": len(pairs) * 2 + len(unpaired), "min_records": min_records, "near_fault_km": near_fault_km,
                "reference_mu": reference_mu, "mu": [float(cube.mu.values[0]), float(cube.mu.values[-1]),
                                                     float(cube.mu.values[1] - cube.mu.values[0])] if swept else None,
                "mu_points": int(cube.sizes["mu"]) if swept else 0,
                "angles": [float(a) for a in cube.angle.values] if swept else [],
                "mass": cube.attrs.get("mass"), "g": g,
                "largest_balance_residual": largest_balance_residual(cube) if swept else None}
    write_csv_atomic(results_path, [{key: row.get(key, "") for key in RESULT_COLUMNS} for row in rows],
                     list(RESULT_COLUMNS))
    write_csv_atomic(ratio_path, ratios, ["mu", "pairs_sliding_in_plane"] if not ratios else None)
    write_csv_atomic(relations_path, relations)
    write_csv_atomic(near_far_path, near_far_rows(rows, near_fault_km, min_records),
                     ["quantity", "units", "n_near", "n_far", "median_near", "median_far", "mann_whitney_p_value"])
    write_text_atomic(design_path, json.dumps(design, indent=1, default=_plain) + "\n")
    document = summary(pairs, unpaired, rows, ratios, relations, design, dict(cube.attrs), settings)
    write_text_atomic(summary_path, json.dumps(document, indent=1, default=_plain) + "\n")
    return [Path(p) for p in (results_path, ratio_path, relations_path, near_far_path, design_path, summary_path)]


def _plain(value):
    if isinstance(value, (np.floating, np.integer)):
        return value.item()
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"not JSON: {type(value)}")
