"""The planar study's relations of μ_max with PGA and RMS, the design chart in 2-D, and near-fault against farther pairs.

The 1-D collection study's own functions, applied to the plane:

- :func:`relations_rows`: μ_max against a predictor by
  :func:`stickslip.studies.collections.relations.relation_row` (Pearson r and
  Spearman ρ with 95 % bootstrap intervals, the least-squares line and its
  slope's interval, leave-one-event-out error), for the block in the plane
  against the pair's vector measures (PGA = the peak of |a(t)|, which is the
  maximum-direction PGA, RotD100; RMS of |a(t)| over the vector's t5-t95), and
  for the 1-D block on each component (both components of every pair, each
  against its own PGA and RMS: the 1-D study on the same records).  μ_max is
  on the planar study's grid (no continuous refinement in 2-D).
- :func:`design_chart`: μ_max against PGA with the 95 % prediction band
  (:func:`~stickslip.studies.collections.relations.prediction_band`), the
  quantiles of μ_max·g/PGA and, per PGA band, the design μ of
  :func:`stickslip.studies.collections.friction_design.coverage_rows`, for the plane
  (its E_df(μ) curves, bands of the vector PGA) beside the components.
- :func:`near_far_rows`: medians near the fault (rupture distance ≤
  ``near_fault_km``) and farther, with a Mann-Whitney test.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from scipy import stats

from stickslip.collections.members import too_few
from stickslip.studies.collections.relations import prediction_band, relation_row
from stickslip.studies.collections.friction_design import coverage_rows

#: The relations fitted: (response, predictor, label of the predictor, units).
RELATIONS = (
    ("plane", "pga_plane", "PGA of the vector, max |a(t)| (RotD100)", "m s-2"),
    ("plane", "rms_plane", "RMS of |a(t)| over the vector's t5-t95", "m s-2"),
    ("plane", "pga_larger", "PGA of the larger component", "m s-2"),
    ("worst_azimuth", "pga_plane", "PGA of the vector, max |a(t)| (RotD100)", "m s-2"),
    ("components", "pga", "PGA of the component", "m s-2"),
    ("components", "rms", "RMS acceleration of the component over its t5-t95", "m s-2"),
)

#: Quantiles of μ_max·g/PGA drawn on the design chart.
RATIO_QUANTILES = (0.1, 0.5, 0.9)

#: Quantities compared near the fault and farther: column of pair_results.csv -> units.
NEAR_FAR = {"ratio_components": "1", "ratio_azimuths": "1", "mu_max_plane": "1",
            "mu_max_plane_over_larger_component": "1", "mu_max_plane_g_over_pga_plane": "1",
            "energy_ratio_plane_to_worst_azimuth": "1", "pga_plane": "m s-2"}


def _ok(rows: list[dict]) -> list[dict]:
    return [row for row in rows if row["status"] == "ok"]


def relation_points(rows: list[dict], response: str, predictor: str) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """(x, y, events) of one relation: per pair, or per component (both components of each pair)."""
    points = []
    for row in _ok(rows):
        if response == "components":
            for side in ("first", "second"):
                points.append((row[f"{predictor}_{side}"], row[f"mu_max_{side}"], row["event"]))
        else:
            points.append((row[predictor], row[f"mu_max_{response}"], row["event"]))
    points = [point for point in points if np.isfinite(point[0]) and np.isfinite(point[1])]
    return (np.array([p[0] for p in points], dtype=float), np.array([p[1] for p in points], dtype=float),
            [p[2] for p in points])


def relations_rows(rows: list[dict], n_boot: int, seed: int, min_records: int) -> list[dict]:
    """One row per relation of :data:`RELATIONS` (columns of :func:`~stickslip.studies.collections.relations.relation_row`)."""
    table = []
    for response, predictor, label, units in RELATIONS:
        x, y, events = relation_points(rows, response, predictor)
        row = relation_row(predictor, x, y, events, n_boot, seed, min_records)
        table.append({"response": f"mu_max_{response}", **row, "label": label, "units": units})
    return table


def _efficiency(energy: np.ndarray, mu: np.ndarray, reference_mu: float) -> np.ndarray:
    reference = int(np.argmin(np.abs(mu - reference_mu)))
    peak = energy.max(axis=1)
    return np.where(peak > 0, energy[:, reference] / np.where(peak > 0, peak, 1.0), np.nan)


def _chart_side(x: np.ndarray, y: np.ndarray, energy: np.ndarray, mu: np.ndarray, g: float, settings: dict) -> dict:
    """One side of the design chart: points, band, ratio quantiles and coverage by PGA band."""
    side = {"n": int(x.size), "points": [{"x": float(a), "y": float(b)} for a, b in zip(x, y)]}
    reason = too_few(int(x.size), settings["min_records"], "a fit")
    if reason:
        return {**side, "status": reason}
    ratio = y * g / x
    cube = xr.Dataset({"energy_dissipated": (("record", "mu"), energy)}, coords={"mu": mu})
    coverage = coverage_rows(cube, x / g, settings["pga_bands_g"], settings["reference_mu"], settings["q"],
                             settings["efficiency_target"], settings["coverage_target"],
                             _efficiency(energy, mu, settings["reference_mu"]), settings["min_records"])
    return {**side, "status": "ok", "band": prediction_band(x, y, np.linspace(x.min(), x.max(), 60)),
            "ratio_quantiles": {f"{q:g}": float(np.quantile(ratio, q)) for q in RATIO_QUANTILES},
            "coverage": coverage}


def design_chart(rows: list[dict], cube: xr.Dataset, g: float, settings: dict) -> dict:
    """The design chart in 2-D: the plane against the vector PGA, beside the components against their own PGA.

    ``settings``: ``min_records``, ``pga_bands_g`` [g], ``reference_mu``, ``q`` (near-optimal fraction),
    ``efficiency_target``, ``coverage_target``.  Only pairs that slide in the plane enter.
    """
    ok = _ok(rows)
    chart = {"g": g, "units": {"mu_max": "1", "pga": "m s-2"}, "pairs": len(ok),
             "pga": "plane: the peak of the acceleration vector's magnitude (RotD100); components: each its own"}
    if not ok:
        return {**chart, "status": "no pair slides in the plane"}
    mu = cube.mu.values
    names = [str(name) for name in cube.pair_id.values] if "pair_id" in cube.coords else list(cube.pair.values)
    index = [names.index(row["pair"]) for row in ok]
    energy = cube.energy_dissipated.values[index]
    x = np.array([row["pga_plane"] for row in ok])
    y = np.array([row["mu_max_plane"] for row in ok])
    chart["plane"] = _chart_side(x, y, energy[:, 0, :], mu, g, settings)
    sliding = [(row[f"pga_{side}"], row[f"mu_max_{side}"], energy[k, d, :]) for k, row in enumerate(ok)
               for d, side in ((1, "first"), (2, "second")) if np.isfinite(row[f"mu_max_{side}"])]
    chart["components"] = _chart_side(np.array([s[0] for s in sliding]), np.array([s[1] for s in sliding]),
                                      np.array([s[2] for s in sliding]).reshape(len(sliding), mu.size), mu, g, settings)
    chart["status"] = chart["plane"]["status"]
    return chart


def near_far_reason(rows: list[dict], near_fault_km: float, min_records: int) -> str | None:
    """Why near-fault and farther pairs are not compared (``None`` when they are)."""
    ok = _ok(rows)
    near = [row for row in ok if str(row["near_fault"]) == "True"]
    far = [row for row in ok if str(row["near_fault"]) == "False"]
    if not near and not far:
        return "no pair studied has a rupture distance"
    if len(near) < min_records or len(far) < min_records:
        return (f"too few pairs: {len(near)} within {near_fault_km:g} km and {len(far)} farther, a comparison needs "
                f"at least {min_records} on each side (collection_study.min_records)")
    return None


def near_far_rows(rows: list[dict], near_fault_km: float, min_records: int) -> list[dict]:
    """Medians of :data:`NEAR_FAR` near the fault and farther, and the Mann-Whitney p-value; empty with a reason."""
    if near_far_reason(rows, near_fault_km, min_records):
        return []
    ok = _ok(rows)
    table = []
    for name, units in NEAR_FAR.items():
        near = np.array([row[name] for row in ok if str(row["near_fault"]) == "True"], dtype=float)
        far = np.array([row[name] for row in ok if str(row["near_fault"]) == "False"], dtype=float)
        near, far = near[np.isfinite(near)], far[np.isfinite(far)]
        table.append({"quantity": name, "units": units, "n_near": near.size, "n_far": far.size,
                      "median_near": float(np.median(near)), "median_far": float(np.median(far)),
                      "mann_whitney_p_value": float(stats.mannwhitneyu(near, far).pvalue)})
    return table
