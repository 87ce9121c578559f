"""The sweep stage: one record's friction-ratio sweep on one grid, and the grid's gathered cube.

A *grid* is what a sweep computes over, as the workflow's configuration
defines it (``workflow/rules/common.smk``)::

    {"mu": [...] or {"start": ..., "stop": ..., "step": ...},   # friction ratios [1]
     "target_pga": [...] or None,   # target PGAs [m/s²]: adds a ``scale`` dimension
     "masses": [...] or None,       # block masses [kg]: adds a ``mass`` dimension
     "refine": bool}                # also find the continuous μ_max (fine grids)

:func:`sweep_record` reads a stored record (``results/records/{id}.nc``) and its
measures (``results/measures/{id}.json``) and returns its cube; a missing
record gives a cube of NaN with its status (:func:`stickslip.sweeps.missing_cube`).
:func:`gather_grid` joins the per-record cubes of a grid in the study's order.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.analysis import refine_mu_max
from stickslip.grids import grid_values
from stickslip.errors import RecordNotFoundError
from stickslip.records.netcdf import read_record_netcdf
from stickslip.studies.record_measures import read_record_measures
from stickslip.sweeps import gather, missing_cube, read_cube, sweep, write_cube
from stickslip.units import UNITS


def sweep_record(record_path: str | Path, measures_path: str | Path, grid: Mapping, mass: float, g: float,
                 name: str = "") -> xr.Dataset:
    """The cube of one stored record on ``grid`` (block mass ``mass`` [kg], gravity ``g`` [m/s²])."""
    mu = grid_values(grid["mu"])
    target_pga = grid.get("target_pga")
    masses = grid.get("masses") or [mass]
    settings = {"grid": name, **grid}
    try:
        record = read_record_netcdf(record_path)
    except RecordNotFoundError as error:
        record_id = Path(record_path).stem
        cubes = [missing_cube(record_id, f"missing: {error}", mu, target_pga=target_pga, mass=m, g=g, config=settings)
                 for m in masses]
        return _with_masses(cubes, grid, mu, refine_missing=True)
    measures = read_record_measures(measures_path)["measures"]
    cubes = [sweep([record], mu, target_pga=target_pga, mass=m, g=g, config=settings, measures=[measures])
             for m in masses]
    cube = _with_masses(cubes, grid, mu, refine_missing=False)
    if grid.get("refine"):
        maximum = refine_mu_max(record, mu, mass=mass, g=g, energy_on_grid=cube.energy_dissipated.values[0])
        cube = _with_continuous(cube, maximum.argument, maximum.value)
    return cube


def _with_masses(cubes: list[xr.Dataset], grid: Mapping, mu, refine_missing: bool) -> xr.Dataset:
    """One cube, or the cubes of several masses stacked along ``mass`` [kg]."""
    if grid.get("masses"):
        cube = xr.concat(cubes, dim=xr.Variable("mass", np.asarray(grid["masses"], dtype=float),
                                               attrs={"units": UNITS["block_mass"], "long_name": "block mass"}),
                         combine_attrs="drop_conflicts")
        cube["energy_dissipated_per_mass"] = (cube.energy_dissipated / cube.mass).assign_attrs(
            units=UNITS["energy_dissipated_per_mass"], long_name="energy dissipated by friction per unit block mass")
    else:
        cube = cubes[0]
    if grid.get("refine") and refine_missing:
        cube = _with_continuous(cube, np.nan, np.nan)
    return cube


def _with_continuous(cube: xr.Dataset, mu_max: float, energy_max: float) -> xr.Dataset:
    """``cube`` with the continuous μ_max [1] and E_df,max [J] of its one record."""
    return cube.assign(
        mu_max_continuous=("record", [mu_max], {"units": UNITS["mu_max_continuous"], "long_name": "friction ratio of maximum energy "
                                                "dissipated, maximised continuously"}),
        energy_dissipated_max_continuous=("record", [energy_max], {"units": UNITS["energy_dissipated_max_continuous"], "long_name": "maximum energy "
                                                                   "dissipated by friction, continuous in mu"}),
    )


def write_record_sweep(record_path, measures_path, cube_path, grid: Mapping, mass: float, g: float,
                       name: str = "") -> Path:
    """:func:`sweep_record`, written to ``cube_path`` atomically."""
    return write_cube(sweep_record(record_path, measures_path, grid, mass, g, name), cube_path)


def gather_grid(cube_paths: Sequence[str | Path], gathered_path: str | Path) -> Path:
    """Join the per-record cubes of one grid, in the given order, into ``gathered_path``."""
    return write_cube(gather([read_cube(path) for path in cube_paths]), gathered_path)
