"""The vertical-motion study's sweeps: every station, radius and vertical variant over μ, with its design answer.

One workflow job per direction (``H1``, ``H2``, or ``plane`` once the
pendulum takes a pair) sweeps the friction pendulum
(:func:`stickslip.sweep`, ``model="pendulum"``) on every station of
:func:`~stickslip.studies.vertical.records.stations` at every surface
radius R [m] (``inf``: the flat slider) and vertical variant (``none``,
``recorded``, ``reversed``), and adds each case's design answer
(:func:`stickslip.optimum.cube_with_optimum`: μ_max maximised continuously,
E_df,max, the displacement demand, the residual displacement and the base
shear V/W there and at the reference μ).  :func:`gather_vertical_study` puts
the directions together: one cube of dimensions (direction, radius,
vertical, record[, mu]).
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping

import numpy as np
import xarray as xr

from stickslip.errors import StickslipError
from stickslip.grids import grid_values
from stickslip.plumbing.files import atomic_path
from stickslip.studies.vertical.records import station_motion, stations

#: Variables of the sweeps' cubes kept in the study's, beside the design answer: over μ, by record.
SWEPT = ("energy_dissipated", "peak_relative_displacement", "residual_displacement", "peak_base_shear",
         "liftoff_time")


def case_cube(motions, radius: float, mu, q: float, reference_mu: float, xatol: float, mass: float, g: float):
    """The pendulum of radius ``radius`` [m] on ``motions`` over ``mu`` [1], with each record's design answer."""
    from stickslip.models import design_of, sweep
    from stickslip.optimum import cube_with_optimum

    cube = sweep(motions, model="pendulum", mu=mu, radius=radius, mass=mass, g=g)
    return cube_with_optimum(cube, motions, design_of(cube), q, reference_mu, xatol=xatol)


def vertical_peaks(motion, g: float) -> tuple[float, float]:
    """The vertical's largest downward acceleration −min a_v and its peak max |a_v|, both in g (NaN without one)."""
    vertical = getattr(motion, "vertical", None)
    if vertical is None:
        return math.nan, math.nan
    return float(-vertical.acceleration.min() / g), float(np.abs(vertical.acceleration).max() / g)


def direction_cube(stations_found, direction: str, radii, mu, variants, untold_positive, q: float,
                   reference_mu: float, xatol: float, mass: float, g: float) -> xr.Dataset:
    """Every station of ``stations_found`` in ``direction`` at every radius [m] and vertical variant, over ``mu`` [1].

    Dimensions (radius, vertical, record[, mu]); each case's progress is printed (the job's log).
    """
    by_radius = []
    for radius in radii:
        by_variant = []
        for variant in variants:
            started = time.perf_counter()
            motions = [station_motion(station, direction, variant, untold_positive)
                       for station in stations_found.values()]
            cube = case_cube(motions, radius, mu, q, reference_mu, xatol, mass, g)
            peaks = np.array([vertical_peaks(motion, g) for motion in motions])
            senses = np.array([getattr(motion, "sense", "") for motion in motions], dtype=object)
            keep = [*SWEPT, *(name for name in cube.data_vars if cube[name].dims == ("record",))]  # per station
            cube = cube[keep].assign(
                vertical_down_peak=("record", peaks[:, 0], {"units": "1", "long_name": "largest downward vertical "
                                                            "ground acceleration -min a_v, in g (g + a_v <= 0 lifts "
                                                            "the slider off where it exceeds 1)"}),
                vertical_pga=("record", peaks[:, 1], {"units": "1", "long_name": "peak vertical ground acceleration "
                                                      "max |a_v|, in g"}),
                vertical_sense=("record", senses, {"long_name": "how the vertical was read: its sense and how it "
                                                   "was told"}),
            )
            by_variant.append(cube.expand_dims(vertical=[variant]))
            print(f"{direction}, R = {radius:g} m, vertical {variant}: {len(motions)} stations x {len(mu)} mu in "
                  f"{time.perf_counter() - started:.1f} s", flush=True)
        by_radius.append(xr.concat(by_variant, dim="vertical", combine_attrs="drop_conflicts"))
    cube = xr.concat(by_radius, dim=xr.DataArray(np.asarray(radii, dtype=float), dims="radius",
                                                 attrs={"units": "m", "long_name": "radius R of the sliding "
                                                        "surface (inf: flat)"}),
                     combine_attrs="drop_conflicts")
    return cube.expand_dims(direction=[direction])


def study_grid(ranges) -> np.ndarray:
    """The study's friction grid [1]: the values of one or more ranges ``{start, stop, step}`` (or lists), joined."""
    parts = ranges if isinstance(ranges, (list, tuple)) and ranges and isinstance(ranges[0], Mapping) else [ranges]
    return np.unique(np.concatenate([grid_values(part, "vertical_study.mu") for part in parts]))


def write_direction_sweep(store_path, cube_path, direction: str, radii, mu, variants, untold_positive, q: float,
                          reference_mu: float, xatol: float, mass: float, g: float) -> str:
    """The workflow's sweep of one direction: :func:`direction_cube` of the stored stations, as NetCDF."""
    found, left_out = stations(store_path)
    if not found:
        raise StickslipError(f"{store_path}: no station has its three components checked ok ("
                             + "; ".join(f"{name}: {why}" for name, why in left_out.items()) + ")")
    radii = [float(radius) for radius in radii]
    values = study_grid(mu)
    cube = direction_cube(found, direction, radii, values, list(variants), untold_positive, q, reference_mu, xatol,
                          mass, g)
    cube = cube.assign_attrs(left_out="; ".join(f"{name}: {why}" for name, why in left_out.items()),
                             mu_max_tolerance=xatol, mu_max_tolerance_units="1")
    with atomic_path(cube_path) as tmp:
        cube.to_netcdf(tmp, engine="netcdf4")
    return str(cube_path)


def gather_vertical_study(cube_paths, study_path) -> str:
    """The directions' cubes in one, along ``direction``."""
    cubes = [xr.load_dataset(path, engine="netcdf4") for path in cube_paths]
    # the names as Python strings: concatenated as fixed-width ones, "plane" beside "H1" would be cut to "pl"
    cubes = [cube.assign_coords(direction=cube.direction.astype(object)) for cube in cubes]
    study = xr.concat(cubes, dim="direction", combine_attrs="drop_conflicts")
    with atomic_path(study_path) as tmp:
        study.to_netcdf(tmp, engine="netcdf4")
    return str(study_path)
