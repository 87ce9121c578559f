"""The sweep stage of a collection study, per chunk of records, and the study's gathered results.

For every record of a chunk (:mod:`stickslip.studies.collections.records`,
measures from :mod:`stickslip.studies.collections.measures`) the exact solver
sweeps the study's friction grid (:func:`stickslip.models.sweep`, the rigid model), and adds
the per-record results of :mod:`stickslip.optimum` (:data:`~stickslip.optimum.RESULTS`):
μ_max on the grid and continuous, E_df,max, whether μ_max is on the grid's
edge, the near-optimal range, E_df and the efficiency at the reference
friction ratio, the stroke and residual displacement at μ_max and at the
range's ends, and ``optimum_status``: ``ok``, ``never slides: …`` (a record
too weak to slide at any μ of the grid, which then has no μ_max or
efficiency) or ``not solved`` (a missing or rejected record).

:func:`gather_study` joins the chunks into one cube (``study.nc``) and one
table with a row per record (``records.csv``): the collection's metadata,
our measures, the ratio μ_max·g/PGA, ``optimum_status`` and the results above;
and the files of a folder that are no record files (``skipped.csv``).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.collections.collection import study_collection
from stickslip.collections.store import read_record_store
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.optimum import RESULTS, STATUS
from stickslip.records.components import vertical_component
from stickslip.records.record import RecordMeta
from stickslip.studies.collections.measures import MEASURES, SLAMMER_COLUMNS
from stickslip.grids import grid_values
from stickslip.models import sweep, with_optimum
from stickslip.models.rigid import RIGID
from stickslip.sweeps import gather, read_cube, write_cube


def sweep_chunk(store_path: str | Path, measures_path: str | Path, mu, mass: float, g: float,
                near_optimal_fraction: float, reference_mu: float) -> xr.Dataset:
    """The cube of one chunk: (record, mu) scalars and the per-record :data:`~stickslip.optimum.RESULTS`, in the store's order.

    Friction grid ``mu`` (list or ``{start, stop, step}``) [1], block mass
    ``mass`` [kg], gravity ``g`` [m s-2], near-optimal fraction q, reference
    friction ratio [1].  A record that is missing or rejected gets a cube of
    NaN with its status (:meth:`~stickslip.models.rigid.RigidModel.missing_cube`) and the
    ``optimum_status`` ``not solved``.
    """
    grid = grid_values(mu)
    measures = {row["record"]: row for row in read_csv_rows(measures_path)}
    settings = {"grid": "collection", "mu": mu, "near_optimal_fraction": near_optimal_fraction,
                "reference_mu": reference_mu}
    stored = read_record_store(store_path)
    present = [row.record for row in stored if row.record is not None]
    cubes = []
    if present:
        cubes.append(sweep(present, mu=grid, mass=mass, g=g, config=settings,
                           measures=[{name: float(measures[record.meta.record_id][name]) for name in MEASURES}
                                     for record in present]))
    cubes += [RIGID.missing_cube(row.record_id, f"{row.status}: {row.reason}", mu=grid, mass=mass, g=g, config=settings)
              for row in stored if row.record is None]
    cube = gather(cubes).sel(record=[row.record_id for row in stored])
    return with_optimum(cube, present, near_optimal_fraction, reference_mu)


def write_chunk_sweep(store_path: str | Path, measures_path: str | Path, cube_path: str | Path, mu, mass: float,
                      g: float, near_optimal_fraction: float, reference_mu: float) -> Path:
    """:func:`sweep_chunk` written to ``cube_path``, atomically."""
    return write_cube(sweep_chunk(store_path, measures_path, mu, mass, g, near_optimal_fraction, reference_mu),
                      cube_path)


def gather_study(cube_paths: Sequence[str | Path], measures_paths: Sequence[str | Path], study_path: str | Path,
                 table_path: str | Path, skipped_path: str | Path, collection: Mapping, g: float) -> list[Path]:
    """Join the chunks' cubes into ``study_path``, write the per-record table ``table_path`` and the skipped files.

    The table has, for every record of the chunks, the collection's metadata
    (:data:`stickslip.collections.collection.COLUMNS`), the status, ``vertical``
    (why the record is a vertical component, :func:`~stickslip.records.components.vertical_component`
    of its component and file names; empty for the others), our measures and those in SLAMMER's definitions, the ratio ``mu_max_g_over_pga`` = μ_max,continuous·g/PGA [1],
    ``pgv_over_pga`` [s], ``optimum_status`` and the per-record :data:`~stickslip.optimum.RESULTS`
    (empty where a record has none: not solved, or never slides).  ``skipped_path`` lists the files of a
    folder collection that are no record files (a README, an image): columns ``file`` and ``reason``.
    """
    cube = gather([read_cube(path) for path in cube_paths])
    write_cube(cube, study_path)
    source = study_collection(collection)
    measures = {row["record"]: row for path in measures_paths for row in read_csv_rows(path)}
    rows = []
    for index, record_id in enumerate(cube.record.values.astype(str)):
        row = {name: _plain(value) for name, value in source.table.loc[record_id].items()}
        measured = measures[record_id]
        row.update(status=measured["status"], reason=measured["reason"],
                   vertical=vertical_component(RecordMeta(component=str(row["record"]), source=str(row["file"]))) or "")
        row.update({name: measured[name] for name in (*MEASURES, *SLAMMER_COLUMNS)})
        row[STATUS] = str(cube[STATUS].values[index])
        row.update({name: _plain(cube[name].values[index]) for name in RESULTS})
        pga, pgv = (float(measured[name]) if measured[name] else np.nan for name in ("pga", "pgv"))
        row["mu_max_g_over_pga"] = _plain(float(cube["mu_max_continuous"].values[index]) * g / pga)
        row["pgv_over_pga"] = _plain(pgv / pga)
        rows.append(row)
    write_csv_atomic(table_path, rows)
    write_csv_atomic(skipped_path, [{"file": item.file, "reason": item.reason} for item in source.skipped],
                     ["file", "reason"])
    return [Path(study_path), Path(table_path), Path(skipped_path)]


def _plain(value):
    """A table cell: "" for a missing value, a float or int as such, text as text."""
    if value is None:
        return ""
    if isinstance(value, (float, np.floating)):
        return "" if np.isnan(value) else float(value)
    if isinstance(value, np.integer):
        return int(value)
    return value
