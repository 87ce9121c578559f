"""Per station pair: the optimum in the plane beside the 1-D optimum of each component and of every azimuth, and the ratio R.

From the planar study's cube (:func:`stickslip.models.sweep` of the planar model,
with azimuths, gathered by :mod:`stickslip.studies.planar.sweep`):

- :func:`pair_rows`: per pair, μ_max and E_df,max of the block in the plane,
  of each component alone (``first``, ``second``: the pair's orthogonal
  axes), of the worst azimuth (the turn of the axes whose 1-D block has the
  largest E_df,max; the RotD100 idea, so its E_df,max is the largest of all
  azimuths) and of the median over the azimuths (RotD50: μ_max of the curve
  that is, at each μ, the median E_df over the azimuths); and the ratio R of
  the peak displacement in the plane to the largest 1-D one at the same μ,
  the plane's μ_max: ``ratio_components`` over the two components,
  ``ratio_azimuths`` over every azimuth (which include the components).
- :func:`ratio_rows`: R against μ, its median and 10th and 90th percentiles across the pairs.

A pair that never slides in the plane on the grid has no μ_max and no R.
At a μ where the plane slides and no 1-D block does (the vector's magnitude
exceeds μg when no component does), R is infinite: counted, not in the quantiles.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from stickslip.analysis import grid_maximum_index

#: The directions of the per-pair table: the cube's three and the two over the azimuths.
DIRECTIONS = ("plane", "first", "second", "worst_azimuth", "rotd50")

#: Quantiles of R across the pairs, per μ.
RATIO_QUANTILES = (0.1, 0.5, 0.9)


def _near(distance: float, near_fault_km: float):
    return "" if not np.isfinite(distance) else bool(distance <= near_fault_km)


def _ratio(plane: np.ndarray, line: np.ndarray) -> np.ndarray:
    """plane/line where the plane slides; inf where only the plane slides, NaN where the plane does not."""
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(line > 0.0, plane / np.where(line > 0.0, line, 1.0), np.inf)
    return np.where(plane > 0.0, ratio, np.nan)


def pair_rows(cube: xr.Dataset, near_fault_km: float, g: float) -> list[dict]:
    """One row per pair of ``cube`` (see the module's docstring); ``g`` [m s-2] for μ_max·g/PGA."""
    mu = cube.mu.values
    peak = cube.peak_displacement.sel(direction=["plane", "first", "second"]).values
    worst = np.nanargmax(cube.energy_dissipated_max_azimuth.values, axis=1)
    rotd50_best = grid_maximum_index(np.where(cube.energy_dissipated_rotd50.values > 0,
                                              cube.energy_dissipated_rotd50.values, np.nan))
    rows = []
    for index, pair in enumerate(cube.pair.values.astype(str)):
        coords = {name: cube[name].values[index] for name in cube.coords if cube[name].dims == ("pair",)}
        pga_larger = max(float(coords["pga_first"]), float(coords["pga_second"]))
        row = {"pair": str(coords.get("pair_id", pair)), "event": str(coords["event"]),
               "station": str(coords["station"]), "first_component": str(coords["first_component"]),
               "second_component": str(coords["second_component"]), "separation": float(coords["separation"]),
               "rupture_distance": float(coords.get("rupture_distance", np.nan)),
               "near_fault": _near(float(coords.get("rupture_distance", np.nan)), near_fault_km),
               "padded_samples": int(coords.get("padded_samples", 0)),
               "pga_first": float(coords["pga_first"]), "pga_second": float(coords["pga_second"]),
               "pga_larger": pga_larger, "pga_plane": float(coords["pga_plane"]),
               "rms_first": float(coords.get("rms_first", np.nan)), "rms_second": float(coords.get("rms_second", np.nan)),
               "rms_plane": float(coords.get("rms_plane", np.nan))}
        mu_max = dict(zip(("plane", "first", "second"), cube.mu_max.values[index]))
        e_max = dict(zip(("plane", "first", "second"), cube.energy_dissipated_max.values[index]))
        angle = float(cube.angle.values[worst[index]])
        mu_max["worst_azimuth"] = float(cube.mu_max_azimuth.values[index, worst[index]])
        e_max["worst_azimuth"] = float(cube.energy_dissipated_max_azimuth.values[index, worst[index]])
        best = rotd50_best[index]
        mu_max["rotd50"] = float(mu[best]) if best >= 0 else np.nan
        e_max["rotd50"] = float(cube.energy_dissipated_rotd50.values[index, best]) if best >= 0 else 0.0
        row["worst_azimuth"] = angle
        for name in DIRECTIONS:
            row[f"mu_max_{name}"] = float(mu_max[name])
            row[f"energy_dissipated_max_{name}"] = float(e_max[name])
        if not np.isfinite(mu_max["plane"]):
            rows.append({**row, "status": "never slides in the plane on the grid"})
            continue
        at = int(np.flatnonzero(mu == mu_max["plane"])[0])
        plane, first, second = peak[index, :, at]
        azimuths = float(cube.peak_displacement_rotd100.values[index, at])
        larger_component = max(first, second)
        ratio_components = _ratio(np.array(plane), np.array(larger_component))
        ratio_azimuths = _ratio(np.array(plane), np.array(azimuths))
        larger_mu_max = np.nanmax([mu_max["first"], mu_max["second"]])
        rows.append({
            **row, "status": "ok",
            "peak_displacement_plane": float(plane), "peak_displacement_first": float(first),
            "peak_displacement_second": float(second), "peak_displacement_rotd100": azimuths,
            "residual_displacement_plane": float(cube.residual_displacement.values[index, 0, at]),
            "ratio_components": float(ratio_components), "ratio_azimuths": float(ratio_azimuths),
            "energy_ratio_plane_to_worst_azimuth": float(e_max["plane"] / e_max["worst_azimuth"])
            if e_max["worst_azimuth"] > 0 else np.nan,
            "mu_max_plane_over_larger_component": float(mu_max["plane"] / larger_mu_max)
            if np.isfinite(larger_mu_max) else np.nan,
            "mu_max_plane_over_worst_azimuth": float(mu_max["plane"] / mu_max["worst_azimuth"])
            if np.isfinite(mu_max["worst_azimuth"]) else np.nan,
            "mu_max_plane_g_over_pga_plane": float(mu_max["plane"] * g / row["pga_plane"]),
        })
    return rows


def ratio_rows(cube: xr.Dataset, min_records: int) -> list[dict]:
    """R against μ: per μ of the grid, the pairs that slide in the plane, those where only the plane slides, and
    R's quantiles (:data:`RATIO_QUANTILES`) over the two components and over every azimuth.

    A μ with fewer than ``min_records`` pairs of finite R has counts and no quantiles.
    """
    peak = cube.peak_displacement.values
    plane = peak[:, 0, :]
    components = _ratio(plane, np.maximum(peak[:, 1, :], peak[:, 2, :]))
    azimuths = _ratio(plane, cube.peak_displacement_rotd100.values)
    energy = cube.energy_dissipated.values
    with np.errstate(divide="ignore", invalid="ignore"):
        energy_ratio = np.where(cube.energy_dissipated_rotd100.values > 0,
                                energy[:, 0, :] / cube.energy_dissipated_rotd100.values, np.nan)
    rows = []
    for column, mu in enumerate(cube.mu.values):
        row = {"mu": float(mu), "pairs_sliding_in_plane": int(np.sum(plane[:, column] > 0)),
               "pairs_only_plane_slides": int(np.sum(np.isinf(azimuths[:, column])))}
        for name, values in (("ratio_components", components[:, column]), ("ratio_azimuths", azimuths[:, column]),
                             ("energy_ratio_plane_to_rotd100", energy_ratio[:, column])):
            finite = values[np.isfinite(values)]
            row[f"{name}_n"] = int(finite.size)
            for q in RATIO_QUANTILES:
                row[f"{name}_q{round(q * 100):02d}"] = float(np.quantile(finite, q)) if finite.size >= min_records \
                    else np.nan
        rows.append(row)
    return rows
