"""The damper study's cubes: every record at every mass ratio, structure period T and friction level, with the two
optima.

Each record's friction grid is μ = η·PFA_bare/g, the levels η [1] times its bare floor's peak absolute acceleration
in g (:mod:`stickslip.studies.damper.response`).  Per record, mass ratio m_d/m_s and period T [s] (:func:`optima`):

- μ_Edf, the grid's μ of the most energy dissipated by the damper (the paper's μ_max; NaN where the damper never
  slides on the grid);
- μ_drift, the grid's μ of the smallest peak story drift;
- their ratio μ_Edf/μ_drift [1];
- the drift reduction 1 − drift/drift_bare [1] at each, and what the paper's μ gives up against the drift's optimum,
  the reduction at μ_drift less that at μ_Edf (≥ 0);
- whether either optimum lies at an end of the grid (then it is a bound).

Two kinds of job write a cube of the same variables (:func:`damper_cube`, dimensions record × mass_ratio ×
period × level; one period a job): :func:`write_paper_cube` on the paper's stored records,
:func:`write_collection_chunk_cube` on one chunk of the collection study's.  :func:`gather_damper_study` joins
them along ``period`` and ``record`` into ``damper.nc``.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.grids import positive_increasing
from stickslip.plumbing.files import provenance
from stickslip.records.record import Record
from stickslip.studies.damper.motions import PAPER, collection_records, paper_records
from stickslip.studies.damper.response import bare_peaks, damper_curves
from stickslip.sweeps import read_cube, write_cube

#: The cube's variables over record × mass_ratio × period × level: (units, long name).
CURVES = {
    "energy_dissipated": ("J", "energy dissipated by the damper's friction E_df (structure of 1 kg)"),
    "peak_drift": ("m", "peak story drift of the structure with the damper"),
    "drift_reduction": ("1", "drift reduction 1 - drift/drift_bare"),
}
#: The cube's variables over record × mass_ratio × period: (units, long name).
OPTIMA = {
    "mu_energy": ("1", "grid mu of the most energy dissipated by the damper (the paper's mu_max)"),
    "mu_drift": ("1", "grid mu of the smallest peak story drift"),
    "mu_ratio": ("1", "mu_energy over mu_drift"),
    "drift_reduction_at_mu_energy": ("1", "drift reduction at mu_energy"),
    "drift_reduction_at_mu_drift": ("1", "drift reduction at mu_drift"),
    "reduction_given_up": ("1", "drift reduction at mu_drift less that at mu_energy"),
    "mu_energy_at_grid_edge": ("1", "1 where mu_energy is the grid's first or last value (a bound), else 0"),
    "mu_drift_at_grid_edge": ("1", "1 where mu_drift is the grid's first or last value (a bound), else 0"),
}


def study_settings(settings: Mapping) -> dict:
    """The configured grids checked, as arrays: mass ratios m_d/m_s [1], periods T [s], friction levels η [1];
    damping as given."""
    return {"mass_ratios": positive_increasing(settings["mass_ratios"], "damper_study.mass_ratios"),
            "periods": positive_increasing(settings["periods"], "damper_study.periods"),
            "levels": positive_increasing(settings["levels"], "damper_study.levels"),
            "damping_ratio": float(settings["damping_ratio"])}


def optima(energy, drift, bare_drift, mu) -> dict[str, np.ndarray]:
    """The two optima of curves over the last axis of ``energy`` [J] and ``drift`` [m], whose friction ratios are
    ``mu`` [1] (broadcast to them), against the bare drift ``bare_drift`` [m] (the other axes): :data:`OPTIMA`,
    each over the other axes."""
    energy, drift = np.asarray(energy, float), np.asarray(drift, float)
    mu = np.broadcast_to(np.asarray(mu, float), energy.shape)
    reduction = 1.0 - drift / np.asarray(bare_drift, float)[..., None]
    at_energy, at_drift = np.argmax(energy, axis=-1), np.argmin(drift, axis=-1)
    slides = np.max(energy, axis=-1) > 0.0
    take = lambda values, index: np.take_along_axis(values, index[..., None], axis=-1)[..., 0]  # noqa: E731
    mu_energy = np.where(slides, take(mu, at_energy), np.nan)
    mu_drift = take(mu, at_drift)
    reduction_energy = np.where(slides, take(reduction, at_energy), np.nan)
    reduction_drift = take(reduction, at_drift)
    edge = lambda index: ((index == 0) | (index == energy.shape[-1] - 1)).astype(float)  # noqa: E731
    return {"mu_energy": mu_energy, "mu_drift": mu_drift, "mu_ratio": mu_energy / mu_drift,
            "drift_reduction_at_mu_energy": reduction_energy, "drift_reduction_at_mu_drift": reduction_drift,
            "reduction_given_up": reduction_drift - reduction_energy,
            "mu_energy_at_grid_edge": np.where(slides, edge(at_energy), np.nan),
            "mu_drift_at_grid_edge": edge(at_drift)}


def damper_cube(records: Sequence[tuple[str, Record]], library: str, settings: Mapping, period: float,
                g: float) -> xr.Dataset:
    """Every (id, record) of ``records`` at the period ``period`` [s] and every mass ratio and friction level of
    ``settings`` (:func:`study_settings`), with the bare building's peaks and the optima; gravity ``g`` [m/s²]."""
    grid = study_settings(settings)
    ratios, levels = grid["mass_ratios"], grid["levels"]
    shape = (len(records), ratios.size, 1, levels.size)
    energy, drift = np.full(shape, np.nan), np.full(shape, np.nan)
    bare = {"drift": np.full((len(records), 1), np.nan), "floor_acceleration": np.full((len(records), 1), np.nan)}
    motions = [record for _, record in records]
    if motions:
        peaks = bare_peaks(motions, period, grid["damping_ratio"], g)
        bare["drift"][:, 0], bare["floor_acceleration"][:, 0] = peaks.drift, peaks.floor_acceleration
        for k, ratio in enumerate(ratios):
            started = time.perf_counter()
            curves = damper_curves(motions, period, ratio, grid["damping_ratio"], levels, peaks.floor_acceleration, g)
            energy[:, k, 0], drift[:, k, 0] = curves.energy_dissipated, curves.peak_drift
            print(f"m_d/m_s = {ratio:g}, T = {period:g} s: {len(motions)} records x {levels.size} levels, "
                  f"{sum(record.npts for record in motions)} samples, in {time.perf_counter() - started:.2f} s",
                  flush=True)
    mu = levels * bare["floor_acceleration"][..., None] / g  # (record, period, level)
    found = optima(energy, drift, bare["drift"][:, None, :], mu[:, None, :, :])
    curves = {"energy_dissipated": energy, "peak_drift": drift,
              "drift_reduction": 1.0 - drift / bare["drift"][:, None, :, None]}
    dims = ("record", "mass_ratio", "period", "level")
    return xr.Dataset(
        {**{name: (dims, curves[name], {"units": units, "long_name": text}) for name, (units, text) in CURVES.items()},
         **{name: (dims[:3], found[name], {"units": units, "long_name": text}) for name, (units, text) in OPTIMA.items()},
         "mu": (("record", "period", "level"), mu, {"units": "1", "long_name": "friction coefficient of the damper, "
                                                   "level x bare peak floor acceleration / g"}),
         "bare_peak_drift": (("record", "period"), bare["drift"], {"units": "m", "long_name": "peak story drift of "
                                                                   "the bare structure (no damper)"}),
         "bare_peak_floor_acceleration": (("record", "period"), bare["floor_acceleration"],
                                          {"units": "m s-2", "long_name": "peak absolute floor acceleration of the "
                                                                          "bare structure"})},
        coords={"record": ("record", np.asarray([record_id for record_id, _ in records], dtype=object)),
                "library": ("record", np.asarray([library] * len(records), dtype=object)),
                "pga": ("record", np.asarray([float(np.abs(record.acceleration).max()) for record in motions]),
                        {"units": "m s-2", "long_name": "peak ground acceleration"}),
                "mass_ratio": ("mass_ratio", ratios, {"units": "1", "long_name": "damper mass over structure mass"}),
                "period": ("period", [float(period)], {"units": "s", "long_name": "period T of the structure"}),
                "level": ("level", levels, {"units": "1", "long_name": "friction level: mu g over the bare structure's "
                                                                       "peak floor acceleration"})},
        attrs={"title": "a flat friction damper on a one-story building: the mu of most E_df against the mu of least "
                        "drift",
               "damping_ratio": grid["damping_ratio"], "damping_ratio_long_name": "damping ratio of the structure",
               "gravity": g, "gravity_units": "m s-2", "Conventions": "CF-1.8", **provenance()})


def write_paper_cube(record_paths: Sequence[str | Path], cube_path: str | Path, settings: Mapping, period: float,
                     g: float) -> Path:
    """The cube of the paper's stored records at ``period`` [s]; the missing ones, with why, in ``left_out``."""
    records, missing = paper_records(record_paths)
    cube = damper_cube(records, PAPER, settings, float(period), g)
    cube.attrs["left_out"] = "; ".join(f"{name}: {why}" for name, why in missing.items())
    return write_cube(cube, cube_path)


def write_collection_chunk_cube(store_path: str | Path, cube_path: str | Path, collection: str, settings: Mapping,
                                period: float, g: float) -> Path:
    """The cube of one chunk of the collection study's records at ``period`` [s] (``collection``: its kind, the
    records' library)."""
    records, missing = collection_records(store_path)
    cube = damper_cube(records, collection, settings, float(period), g)
    cube.attrs["left_out"] = "; ".join(f"{name}: {why}" for name, why in missing.items())
    return write_cube(cube, cube_path)


def gather_damper_study(cube_paths: Sequence[str | Path], study_path: str | Path, periods: int) -> Path:
    """The jobs' cubes, each group of ``periods`` consecutive ones the periods of one set of records, joined along
    ``period`` and then ``record``; the left-out records kept once."""
    cubes = [read_cube(path) for path in cube_paths]
    groups = [cubes[start:start + periods] for start in range(0, len(cubes), periods)]
    left_out = "; ".join(dict.fromkeys(cube.attrs["left_out"] for cube in cubes if cube.attrs.get("left_out")))
    joined = [xr.concat(group, dim="period", data_vars="all", coords="different", compat="equals",
                        combine_attrs="override") for group in groups]
    study = xr.concat(joined, dim="record", data_vars="all", coords="different", compat="equals",
                      combine_attrs="override")
    study.attrs.update(left_out=left_out, **provenance())
    return write_cube(study, study_path)
