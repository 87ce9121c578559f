"""The isolation study's cubes: every component at every fixed-base period T, radius R and friction μ.

Two kinds of job write a cube of the same variables (:func:`isolation_cube`, dimensions record × period ×
radius × mu, one period a job; units in the variables' attributes, CF):

- :func:`write_pair_chunk_cube`, one per chunk of the planar study's station pairs (both components of each);
- :func:`write_three_component_cube`, the three-component stations' ``H1`` and ``H2`` (an empty cube without
  their store).

:func:`gather_isolation_study` joins them along ``period`` and ``record`` into ``isolation.nc``.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.grids import grid_values, positive_increasing
from stickslip.plumbing.files import provenance
from stickslip.studies.isolation.motions import Component, described, pair_components, three_component_components
from stickslip.studies.isolation.response import fixed_base_peaks, isolated_peaks
from stickslip.sweeps import read_cube, write_cube

#: The cube's variables over record × period × radius × mu: (units, long name).
CASE_VARIABLES = {
    "peak_drift": ("m", "peak story drift |u_1 - u_b| of the isolated building"),
    "peak_floor_acceleration": ("m s-2", "peak absolute floor acceleration of the isolated building"),
    "peak_isolator_displacement": ("m", "peak isolator displacement |u_b| relative to the ground"),
    "drift_ratio": ("1", "peak story drift isolated over on a fixed base"),
    "floor_acceleration_ratio": ("1", "peak absolute floor acceleration isolated over on a fixed base"),
}
#: The cube's variables over record × period: (units, long name).
FIXED_BASE_VARIABLES = {
    "fixed_base_peak_drift": ("m", "peak story drift of the building on a fixed base"),
    "fixed_base_peak_floor_acceleration": ("m s-2", "peak absolute floor acceleration of the building on a fixed base"),
}


def study_settings(settings: Mapping) -> dict:
    """The configured grids checked, as arrays: periods T [s], radii R [m], mu [1]; mass ratio and damping as given."""
    return {"periods": positive_increasing(settings["periods"], "isolation_study.periods"),
            "radii": positive_increasing(settings["radii"], "isolation_study.radii"),
            "mu": grid_values(settings["mu"], "isolation_study.mu"),
            "mass_ratio": float(settings["mass_ratio"]), "damping_ratio": float(settings["damping_ratio"])}


def isolation_cube(components: Sequence[Component], settings: Mapping, period: float, g: float) -> xr.Dataset:
    """Every component of ``components`` at the fixed-base period ``period`` [s] and every R × μ of ``settings``
    (:func:`study_settings`), isolated and on a fixed base, with the ratios; gravity ``g`` [m/s²]."""
    grid = study_settings(settings)
    period, radii, mu = float(period), grid["radii"], grid["mu"]
    shape = (len(components), 1, radii.size, mu.size)
    case = {name: np.full(shape, np.nan) for name in ("peak_drift", "peak_floor_acceleration",
                                                       "peak_isolator_displacement")}
    fixed = {name: np.full(shape[:2], np.nan) for name in FIXED_BASE_VARIABLES}
    records = [item.record for item in components]
    if records:
        base = fixed_base_peaks(records, period, grid["mass_ratio"], grid["damping_ratio"], g)
        fixed["fixed_base_peak_drift"][:, 0] = base.drift
        fixed["fixed_base_peak_floor_acceleration"][:, 0] = base.floor_acceleration
    for r, radius in enumerate(radii if records else []):
        started = time.perf_counter()
        peaks = isolated_peaks(records, period, grid["mass_ratio"], grid["damping_ratio"], radius, mu, g)
        case["peak_drift"][:, 0, r] = peaks.drift
        case["peak_floor_acceleration"][:, 0, r] = peaks.floor_acceleration
        case["peak_isolator_displacement"][:, 0, r] = peaks.isolator_displacement
        print(f"T = {period:g} s, R = {radius:g} m: {len(records)} components x {mu.size} mu, "
              f"{sum(record.npts for record in records)} samples, in {time.perf_counter() - started:.2f} s",
              flush=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        case["drift_ratio"] = case["peak_drift"] / fixed["fixed_base_peak_drift"][:, :, None, None]
        case["floor_acceleration_ratio"] = (case["peak_floor_acceleration"]
                                            / fixed["fixed_base_peak_floor_acceleration"][:, :, None, None])
    dims = ("record", "period", "radius", "mu")
    columns = described(components)
    cube = xr.Dataset(
        {**{name: (dims, case[name], {"units": units, "long_name": text})
            for name, (units, text) in CASE_VARIABLES.items()},
         **{name: (dims[:2], fixed[name], {"units": units, "long_name": text})
            for name, (units, text) in FIXED_BASE_VARIABLES.items()}},
        coords={"record": ("record", np.asarray(columns["record"], dtype=object)),
                "library": ("record", np.asarray(columns["library"], dtype=object)),
                "station": ("record", np.asarray(columns["station"], dtype=object),
                            {"long_name": "event/station of a pair, or the three-component set"}),
                "component": ("record", np.asarray(columns["component"], dtype=object)),
                "rupture_distance": ("record", np.asarray(columns["rupture_distance"], dtype=float),
                                     {"units": "km", "long_name": "closest distance to the rupture (NaN: not known)"}),
                **grid_coordinates(period, radii, mu)},
        attrs={"title": "a one-story building on friction pendulums against the same building on a fixed base",
               **building_attrs(grid, g)})
    return cube


def grid_coordinates(period: float, radii, mu) -> dict:
    """A cube's coordinates of one fixed-base period ``period`` [s], the radii ``radii`` [m] and ``mu`` [1]."""
    return {"period": ("period", [float(period)], {"units": "s", "long_name": "fixed-base period T of the building"}),
            "radius": ("radius", radii, {"units": "m", "long_name": "radius R of the pendulum's surface"}),
            "mu": ("mu", mu, {"units": "1", "long_name": "friction coefficient of the pendulum"})}


def building_attrs(grid: Mapping, g: float) -> dict:
    """A cube's attributes of the building of ``grid`` (m_s/m_b and ζ [1]) and gravity ``g`` [m/s²], CF."""
    return {"mass_ratio": grid["mass_ratio"], "mass_ratio_long_name": "superstructure mass over base mass m_s/m_b",
            "damping_ratio": grid["damping_ratio"],
            "damping_ratio_long_name": "damping ratio of the superstructure's fixed-base mode",
            "gravity": g, "gravity_units": "m s-2", "Conventions": "CF-1.8", **provenance()}


def write_pair_chunk_cube(pairs_path: str | Path, store_paths: Sequence[str | Path], cube_path: str | Path,
                          chunk: str, settings: Mapping, period: float, g: float) -> Path:
    """The cube of both components of each pair of ``chunk`` whose records were read, at ``period`` [s]."""
    components = pair_components(pairs_path, store_paths, chunk)
    return write_cube(isolation_cube(components, settings, period, g), cube_path)


def write_three_component_cube(cube_path: str | Path, settings: Mapping, period: float, g: float,
                               store_path: str | Path | None = None) -> Path:
    """The cube of the three-component stations' ``H1`` and ``H2`` at ``period`` [s] (no record without
    ``store_path``); the stations left out, with why, in its ``left_out`` attribute."""
    components, left_out = three_component_components(store_path)
    cube = isolation_cube(components, settings, period, g)
    cube.attrs["left_out"] = "; ".join(f"{name}: {why}" for name, why in left_out.items())
    return write_cube(cube, cube_path)


def gather_isolation_study(cube_paths: Sequence[str | Path], study_path: str | Path, periods: int) -> Path:
    """The jobs' cubes, each group of ``periods`` consecutive ones the periods of one set of components, joined
    along ``period`` and then ``record``; the left-out stations kept once."""
    cubes = [read_cube(path) for path in cube_paths]
    left_out = "; ".join(dict.fromkeys(cube.attrs["left_out"] for cube in cubes if cube.attrs.get("left_out")))
    groups = [cubes[start:start + periods] for start in range(0, len(cubes), periods)]
    joined = [xr.concat(group, dim="period", data_vars="all", coords="different", compat="equals",
                        combine_attrs="override") for group in groups]
    study = xr.concat(joined, dim="record", data_vars="all", coords="different", compat="equals",
                      combine_attrs="override")
    study.attrs.update(left_out=left_out, **provenance())
    return write_cube(study, study_path)
