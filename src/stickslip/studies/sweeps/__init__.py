"""The sweep stage: one record's friction-ratio sweep on one grid, and the grid's gathered cube.

A *grid* is what a sweep computes over, as the workflow's configuration
defines it (``workflow/rules/common.smk``)::

    {"mu": [...] or {"start": ..., "stop": ..., "step": ...},   # friction ratios [1]
     "target_pga": [...] or None,   # target PGAs [m/s²]: adds a ``scale`` dimension
     "masses": [...] or None,       # block masses [kg]: adds a ``mass`` dimension
     "refine": bool,                # also the per-record results (fine grids)
     "near_optimal_fraction": q,    # their near-optimal range's q [1]
     "model": name or None,         # the sliding-block model (stickslip.MODELS); None: the rigid block's mu
     "parameters": {...} or None}   # the model's further parameters, by name, in its units

The workflow's configuration sets a grid's ``model`` and ``parameters``
(``sweep_grids``, config/config.yaml); :func:`grid_model` checks them before
any job runs, as :func:`sweep_record` reads them.

The per-record results of a refined grid answer the model's own objective
(its first, :attr:`~stickslip.models.entry.Model.objectives`: the most
energy dissipated unless the model says otherwise).

A refined grid's cube carries the per-record results of
:func:`stickslip.with_optimum`, the one route to μ_max (on the grid
and continuous), the near-optimal range and the design quantities that
``stickslip optimum``, the record report and the collection study also take.

:func:`sweep_record` reads a stored record (``results/records/{id}.nc``) and its
measures (``results/measures/{id}.json``) and returns its cube; a missing
record gives a cube of NaN with its status (the model's ``missing_cube``).
:func:`gather_grid` joins the per-record cubes of a grid in the study's order.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.errors import RecordNotFoundError, StickslipError
from stickslip.grids import grid_values
from stickslip.optimum import DEFAULT_Q
from stickslip.records.netcdf import read_record_netcdf
from stickslip.studies.measures.record_measures import read_record_measures
from stickslip.models import chosen_model, with_optimum
from stickslip.sweeps import gather, read_cube, write_cube
from stickslip.units import UNITS


def sweep_record(record_path: str | Path, measures_path: str | Path, grid: Mapping, mass: float, g: float,
                 name: str = "") -> xr.Dataset:
    """The cube of one stored record on ``grid`` (block mass ``mass`` [kg], gravity ``g`` [m/s²])."""
    mu = grid_values(grid["mu"])
    target_pga = grid.get("target_pga")
    masses = grid.get("masses") or [mass]
    parameters = dict(grid.get("parameters") or {})
    entry = grid_model(grid, name or "grid")
    settings = {"grid": name, **grid}
    try:
        record = read_record_netcdf(record_path)
    except RecordNotFoundError as error:
        record_id = Path(record_path).stem
        cubes = [entry.missing_cube(record_id, f"missing: {error}", mu=mu, target_pga=target_pga, mass=m, g=g,
                                    config=settings, **parameters)
                 for m in masses]
        records = []
    else:
        measures = read_record_measures(measures_path)["measures"]
        cubes = [entry.sweep([record], mu=mu, target_pga=target_pga, mass=m, g=g, config=settings,
                             measures=[measures], **parameters)
                 for m in masses]
        records = [record]
    cube = _with_masses(cubes, grid)
    if grid.get("refine"):
        cube = with_optimum(cube, records, q=grid.get("near_optimal_fraction", DEFAULT_Q))
    return cube


#: What a grid sets itself, which its ``parameters`` may not: its friction ratios, the block mass and gravity.
GRID_OWN = ("mu", "mass", "g")


def grid_model(grid: Mapping, where: str):
    """The model that sweeps ``grid``: its ``model`` with its ``parameters`` (a name of
    :data:`~stickslip.models.MODELS`; None: the one the parameters choose, as the command line chooses it, the
    paper's rigid block without any), checked as a sweep checks them: a model that sweeps one component of a record
    over μ with a block mass, parameters it declares besides :data:`GRID_OWN`, each valid, and their combination
    at the grid's first μ; else one :class:`~stickslip.errors.StickslipError` naming ``where`` (the grid's key)."""
    from stickslip.models import MODELS

    parameters = dict(grid.get("parameters") or {})
    own = [name for name in GRID_OWN if name in parameters]
    if own:
        raise StickslipError(f"{where}.parameters: {', '.join(own)} is the grid's own (its mu, block_mass and "
                             "gravity), not a parameter of the model")
    sweeping = ", ".join(name for name, entry in MODELS.items() if entry.takes("component", ["mu", "mass"]))
    try:
        entry = chosen_model("component", ["mu", *parameters], grid.get("model"))
        if not entry.takes("component", ["mu", "mass"]):
            raise StickslipError(f"the {entry.name} model sweeps no friction ratio mu of a block of a given mass; "
                                 f"a grid's model is one of {sweeping}")
        taken = sorted(set(entry.declared) - set(GRID_OWN))
        unknown = sorted(set(parameters) - set(taken))
        if unknown:
            raise StickslipError(f"the {entry.name} model does not take {', '.join(unknown)}; its parameters: "
                                 f"{', '.join(taken) or 'none'}")
        entry.case(entry.checked({**parameters, "mu": float(grid_values(grid["mu"])[0])}))
    except StickslipError as error:
        raise StickslipError(f"{where}: {error}") from None
    return entry


def _with_masses(cubes: list[xr.Dataset], grid: Mapping) -> xr.Dataset:
    """One cube, or the cubes of several masses stacked along ``mass`` [kg]."""
    if grid.get("masses"):
        cube = xr.concat(cubes, dim=xr.Variable("mass", np.asarray(grid["masses"], dtype=float),
                                               attrs={"units": UNITS["block_mass"], "long_name": "block mass"}),
                         combine_attrs="drop_conflicts")
        cube["energy_dissipated_per_mass"] = (cube.energy_dissipated / cube.mass).assign_attrs(
            units=UNITS["energy_dissipated_per_mass"], long_name="energy dissipated by friction per unit block mass")
        return cube
    return cubes[0]


def write_record_sweep(record_path, measures_path, cube_path, grid: Mapping, mass: float, g: float,
                       name: str = "") -> Path:
    """:func:`sweep_record`, written to ``cube_path`` atomically."""
    return write_cube(sweep_record(record_path, measures_path, grid, mass, g, name), cube_path)


def gather_grid(cube_paths: Sequence[str | Path], gathered_path: str | Path) -> Path:
    """Join the per-record cubes of one grid, in the given order, into ``gathered_path``."""
    return write_cube(gather([read_cube(path) for path in cube_paths]), gathered_path)
