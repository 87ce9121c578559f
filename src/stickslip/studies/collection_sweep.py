"""The sweep stage of a collection study, per chunk of records, and the study's gathered results.

For every record of a chunk (:mod:`stickslip.studies.collection_records`,
measures from :mod:`stickslip.studies.collection_measures`) the exact solver
sweeps the study's friction grid (:func:`stickslip.sweeps.sweep`), and adds
per record:

- ``mu_max`` [1] and ``energy_dissipated_max`` [J] on the grid, and
  ``mu_max_at_grid_edge`` when the grid's maximum is its first or last point
  (the true maximum may then lie outside the grid);
- ``mu_max_continuous`` [1] and ``energy_dissipated_max_continuous`` [J],
  maximised continuously (:func:`stickslip.analysis.refine_mu_max`);
- the near-optimal range ``mu_low``, ``mu_high`` [1] where E_df ≥ q·E_df,max on
  the grid, and whether it is ``contiguous``;
- ``energy_dissipated_reference`` [J] at the reference friction ratio (the
  paper's recommended μ = 0.1) and the ``efficiency`` E_df(μ_ref)/E_df,max [1].

:func:`gather_study` joins the chunks into one cube (``study.nc``) and one
table with a row per record (``records.csv``): the collection's metadata,
our measures, the ratio μ_max·g/PGA and the results above.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.analysis import near_optimal_range, refine_mu_max
from stickslip.collections import load_collection
from stickslip.collections.store import read_record_store
from stickslip.io import read_csv_rows, write_csv_atomic
from stickslip.solvers.exact import SCALAR_NAMES, record_scalars
from stickslip.studies.collection_measures import MEASURES, SLAMMER_COLUMNS
from stickslip.studies.record_sweep import friction_grid
from stickslip.sweeps import gather, missing_cube, read_cube, sweep, write_cube

#: Per-record results of the sweep stage: name -> (units, long_name).
RESULTS = {
    "mu_max": ("1", "friction ratio of maximum energy dissipated, on the grid"),
    "energy_dissipated_max": ("J", "maximum energy dissipated by friction on the grid"),
    "mu_max_at_grid_edge": ("1", "1 where mu_max is the grid's first or last point, else 0"),
    "mu_max_continuous": ("1", "friction ratio of maximum energy dissipated, maximised continuously"),
    "energy_dissipated_max_continuous": ("J", "maximum energy dissipated by friction, continuous in mu"),
    "mu_low": ("1", "smallest grid mu with energy dissipated >= q times the maximum"),
    "mu_high": ("1", "largest grid mu with energy dissipated >= q times the maximum"),
    "contiguous": ("1", "1 where every grid mu between mu_low and mu_high qualifies, else 0"),
    "energy_dissipated_reference": ("J", "energy dissipated by friction at the reference friction ratio"),
    "efficiency": ("1", "energy dissipated at the reference friction ratio over the continuous maximum"),
}


def sweep_chunk(store_path: str | Path, measures_path: str | Path, mu, mass: float, g: float,
                near_optimal_fraction: float, reference_mu: float) -> xr.Dataset:
    """The cube of one chunk: (record, mu) scalars and the per-record :data:`RESULTS`, in the store's order.

    Friction grid ``mu`` (list or ``{start, stop, step}``) [1], block mass
    ``mass`` [kg], gravity ``g`` [m s-2], near-optimal fraction q, reference
    friction ratio [1].  A record that is missing or rejected gets a cube of
    NaN with its status (:func:`stickslip.sweeps.missing_cube`).
    """
    grid = friction_grid(mu)
    measures = {row["record"]: row for row in read_csv_rows(measures_path)}
    settings = {"grid": "collection", "mu": mu, "near_optimal_fraction": near_optimal_fraction,
                "reference_mu": reference_mu}
    stored = read_record_store(store_path)
    present = [row.record for row in stored if row.record is not None]
    cubes = []
    if present:
        cube = sweep(present, grid, mass=mass, g=g, config=settings,
                     measures=[{name: float(measures[record.meta.record_id][name]) for name in MEASURES}
                               for record in present])
        cubes.append(cube.assign(_results(present, cube.energy_dissipated.values, grid, mass, g,
                                          near_optimal_fraction, reference_mu)))
    for row in stored:
        if row.record is None:
            cube = missing_cube(row.record_id, f"{row.status}: {row.reason}", grid, mass=mass, g=g, config=settings)
            cubes.append(cube.assign({name: ("record", [np.nan], {"units": units, "long_name": long_name})
                                      for name, (units, long_name) in RESULTS.items()}))
    cube = gather(cubes)
    return cube.sel(record=[row.record_id for row in stored])


def _results(records, energy: np.ndarray, grid: np.ndarray, mass: float, g: float, q: float,
             reference_mu: float) -> dict[str, tuple]:
    """The :data:`RESULTS` of ``records`` from their energies ``energy`` [J] (record, mu) on ``grid``."""
    best = np.argmax(energy, axis=1)
    mu_low, mu_high, contiguous = near_optimal_range(energy, grid, q=q)
    column = SCALAR_NAMES.index("energy_dissipated")
    maxima = [refine_mu_max(record, grid, mass=mass, g=g, energy_on_grid=curve)
              for record, curve in zip(records, energy)]
    reference = np.array([record_scalars(record.acceleration, record.dt, reference_mu, g)[column] * mass
                          for record in records])
    maximum = np.array([found.value for found in maxima])
    values = {
        "mu_max": grid[best],
        "energy_dissipated_max": energy[np.arange(len(records)), best],
        "mu_max_at_grid_edge": ((best == 0) | (best == grid.size - 1)).astype(float),
        "mu_max_continuous": np.array([found.argument for found in maxima]),
        "energy_dissipated_max_continuous": maximum,
        "mu_low": np.asarray(mu_low, dtype=float),
        "mu_high": np.asarray(mu_high, dtype=float),
        "contiguous": np.asarray(contiguous, dtype=float),
        "energy_dissipated_reference": reference,
        "efficiency": np.divide(reference, maximum, out=np.full(len(records), np.nan), where=maximum > 0),
    }
    return {name: ("record", value, {"units": RESULTS[name][0], "long_name": RESULTS[name][1]})
            for name, value in values.items()}


def write_chunk_sweep(store_path: str | Path, measures_path: str | Path, cube_path: str | Path, mu, mass: float,
                      g: float, near_optimal_fraction: float, reference_mu: float) -> Path:
    """:func:`sweep_chunk` written to ``cube_path``, atomically."""
    return write_cube(sweep_chunk(store_path, measures_path, mu, mass, g, near_optimal_fraction, reference_mu),
                      cube_path)


def gather_study(cube_paths: Sequence[str | Path], measures_paths: Sequence[str | Path], study_path: str | Path,
                 table_path: str | Path, collection: Mapping, g: float) -> list[Path]:
    """Join the chunks' cubes into ``study_path`` and write the per-record table ``table_path``.

    The table has, for every record of the chunks, the collection's metadata
    (:data:`stickslip.collections.collection.COLUMNS`), the status, our
    measures and those in SLAMMER's definitions, the ratio ``mu_max_g_over_pga`` = μ_max,continuous·g/PGA [1],
    ``pgv_over_pga`` [s] and the per-record :data:`RESULTS`.
    """
    cube = gather([read_cube(path) for path in cube_paths])
    write_cube(cube, study_path)
    source = load_collection(collection["kind"], collection.get("folder"), collection.get("metadata"))
    measures = {row["record"]: row for path in measures_paths for row in read_csv_rows(path)}
    rows = []
    for index, record_id in enumerate(cube.record.values.astype(str)):
        row = {name: _plain(value) for name, value in source.table.loc[record_id].items()}
        measured = measures[record_id]
        row.update(status=measured["status"], reason=measured["reason"])
        row.update({name: measured[name] for name in (*MEASURES, *SLAMMER_COLUMNS)})
        row.update({name: _plain(cube[name].values[index]) for name in RESULTS})
        pga, pgv = (float(measured[name]) if measured[name] else np.nan for name in ("pga", "pgv"))
        row["mu_max_g_over_pga"] = _plain(float(cube["mu_max_continuous"].values[index]) * g / pga)
        row["pgv_over_pga"] = _plain(pgv / pga)
        rows.append(row)
    write_csv_atomic(table_path, rows)
    return [Path(study_path), Path(table_path)]


def _plain(value):
    """A table cell: "" for a missing value, a float or int as such, text as text."""
    if value is None:
        return ""
    if isinstance(value, (float, np.floating)):
        return "" if np.isnan(value) else float(value)
    if isinstance(value, np.integer):
        return int(value)
    return value
