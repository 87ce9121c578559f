"""The planar study's stages before the analysis: the station pairs listed, each chunk of pairs swept, the chunks gathered.

- :func:`write_pair_tables` (one job): the pairs of the collection study's
  members (:func:`stickslip.studies.planar.pairs.form_pairs`) with the chunk
  each is swept in, whether both components were read (the collection
  study's record stores, ``{STUDY_DIR}/records/{chunk}.nc``), their lengths
  and the zeros padded at the end of the shorter (``pairs.csv``); the members
  left unpaired, with the reason (``unpaired.csv``).
- :func:`write_pair_chunk_sweep` (one job per chunk): every pair of the chunk
  whose components were read, padded (:meth:`~stickslip.records.pair.RecordPair.padded`)
  and swept by :func:`stickslip.models.sweep` (the planar model) in the plane, on
  each component alone and on the axes turned by every azimuth of the grid;
  the pair's vector RMS acceleration (:func:`pair_measures`) added.
- :func:`gather_planar_study` joins the chunks into ``planar.nc``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.collections.collection import study_collection
from stickslip.collections.store import read_record_store
from stickslip.grids import grid_values
from stickslip.measures import cumulative_squared_acceleration, husid_time, window_rms
from stickslip.models import sweep
from stickslip.models.planar import azimuths
from stickslip.plumbing.files import provenance, read_csv_rows, write_csv_atomic
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record, RecordMeta
from stickslip.studies.planar.pairs import collection_members, form_pairs, pair_chunks
from stickslip.sweeps import read_cube, write_cube

#: Columns of pairs.csv.
PAIR_COLUMNS = ("pair", "chunk", "status", "reason", "event", "station_key", "station", "first", "second",
                "first_component", "second_component", "dt", "rupture_distance", "separation", "orthogonal",
                "directions", "npts_first", "npts_second", "padded_samples", "padded_component")


def study_pairs(collection: Mapping, ids: Sequence[str], chunk_size: int) -> tuple[list[dict], list[dict]]:
    """The pairs of the members ``ids`` of ``collection`` (each with its ``chunk``, ``"000"``…) and the unpaired members.

    Decided from the collection's metadata alone, so the workflow knows the
    chunks before any record is read.
    """
    table = study_collection(collection).table
    pairs, unpaired = form_pairs(collection_members(table, ids))
    for number, chunk in enumerate(pair_chunks(pairs, chunk_size)):
        for pair in chunk:
            pair["chunk"] = f"{number:03d}"
    return pairs, unpaired


def _stored(store_paths: Sequence[str | Path]) -> dict:
    """Every row of the record stores, by record id."""
    return {row.record_id: row for path in store_paths for row in read_record_store(path)}


def write_pair_tables(store_paths: Sequence[str | Path], pairs_path: str | Path, unpaired_path: str | Path,
                      collection: Mapping, ids: Sequence[str], chunk_size: int) -> list[Path]:
    """Write ``pairs.csv`` and ``unpaired.csv`` (see the module's docstring)."""
    pairs, unpaired = study_pairs(collection, ids, chunk_size)
    stored = _stored(store_paths)
    rows = []
    for pair in pairs:
        row = {**pair, "status": "ok", "reason": "", "npts_first": "", "npts_second": "", "padded_samples": 0,
               "padded_component": ""}
        unread = [stored[pair[side]] for side in ("first", "second") if stored[pair[side]].record is None]
        if unread:
            row.update(status="not read", reason="; ".join(f"{item.record_id}: {item.status}: {item.reason}"
                                                           for item in unread))
        else:
            lengths = [stored[pair[side]].record.npts for side in ("first", "second")]
            row.update(npts_first=lengths[0], npts_second=lengths[1], padded_samples=abs(lengths[0] - lengths[1]),
                       padded_component=("" if lengths[0] == lengths[1] else
                                         pair["first_component"] if lengths[0] < lengths[1] else
                                         pair["second_component"]))
        rows.append(row)
    write_csv_atomic(pairs_path, rows, list(PAIR_COLUMNS))
    write_csv_atomic(unpaired_path, unpaired, ["id", "event", "component", "group", "reason"])
    return [Path(pairs_path), Path(unpaired_path)]


def record_pair(row: Mapping, stored: Mapping) -> RecordPair:
    """The padded pair of a row of ``pairs.csv``, its components named as in the collection (``TAK-090``)."""
    records = []
    for side in ("first", "second"):
        record = stored[row[side]].record
        meta = RecordMeta(record_id=row[side], event=row["event"], station=row["station"],
                          component=row[f"{side}_component"], source=record.meta.source, sha256=record.meta.sha256)
        records.append(Record(record.acceleration, record.dt, meta))
    return RecordPair.padded(*records)


def pair_measures(pair: RecordPair) -> dict:
    """The pair's vector intensity measures: RMS of |a(t)| over its significant duration, and that duration.

    |a(t)| is the magnitude of the horizontal acceleration vector on the
    pair's orthogonal axes; the significant duration t5-t95 is that of the sum
    of the two axes' Husid integrands, ∫(a₁² + a₂²) dt (the vector's Arias
    intensity), and ``rms_plane`` = sqrt(∫_{t5}^{t95} |a|² dt / (t95 − t5)), the
    1-D study's RMS acceleration (:mod:`stickslip.measures`) with a² replaced by |a|².
    """
    first, second = pair.horizontal()
    cumulative = cumulative_squared_acceleration(first, pair.dt) + cumulative_squared_acceleration(second, pair.dt)
    husid = cumulative / cumulative[-1]
    t5, t95 = husid_time(husid, pair.dt, 0.05), husid_time(husid, pair.dt, 0.95)
    return {"rms_plane": window_rms(cumulative, pair.dt, t5, t95), "significant_duration_plane": t95 - t5}


def _component_rms(acceleration: np.ndarray, dt: float) -> float:
    """The 1-D study's RMS acceleration over the component's own significant duration [m/s²]."""
    cumulative = cumulative_squared_acceleration(acceleration, dt)
    husid = cumulative / cumulative[-1]
    return window_rms(cumulative, dt, husid_time(husid, dt, 0.05), husid_time(husid, dt, 0.95))


def sweep_pair_chunk(pairs_path: str | Path, store_paths: Sequence[str | Path], chunk: str, mu, angle_step: float,
                     mass: float, g: float) -> xr.Dataset:
    """The planar cube of the chunk's pairs that were read; an empty dataset (no ``pair``) when none was."""
    rows = [row for row in read_csv_rows(pairs_path) if row["chunk"] == chunk and row["status"] == "ok"]
    if not rows:
        return xr.Dataset(attrs={"status": f"no pair of chunk {chunk} could be read", **provenance()})
    stored = _stored(store_paths)
    pairs = [record_pair(row, stored) for row in rows]
    cube = sweep(pairs, mu=grid_values(mu), mass=mass, g=g, angles=azimuths(angle_step))
    measures = [pair_measures(pair) for pair in pairs]
    axes = [pair.horizontal() for pair in pairs]
    extra = {
        "pair_id": ("pair", [row["pair"] for row in rows], {"long_name": "event/station"}),
        "rupture_distance": ("pair", [float(row["rupture_distance"]) if row["rupture_distance"] else np.nan
                                      for row in rows], {"units": "km", "long_name": "rupture distance"}),
        "padded_samples": ("pair", [int(row["padded_samples"]) for row in rows],
                           {"long_name": "zeros added at the end of the shorter component"}),
        "rms_plane": ("pair", [m["rms_plane"] for m in measures],
                      {"units": "m s-2", "long_name": "RMS of the acceleration vector's magnitude over its t5-t95"}),
        "significant_duration_plane": ("pair", [m["significant_duration_plane"] for m in measures],
                                       {"units": "s", "long_name": "t95 - t5 of the vector's Arias intensity"}),
        "rms_first": ("pair", [_component_rms(a, p.dt) for (a, _), p in zip(axes, pairs)],
                      {"units": "m s-2", "long_name": "RMS acceleration of axis 1 over its own t5-t95"}),
        "rms_second": ("pair", [_component_rms(b, p.dt) for (_, b), p in zip(axes, pairs)],
                       {"units": "m s-2", "long_name": "RMS acceleration of axis 2 over its own t5-t95"}),
    }
    return cube.assign_coords(**extra)


def write_pair_chunk_sweep(pairs_path: str | Path, store_paths: Sequence[str | Path], cube_path: str | Path,
                           chunk: str, mu, angle_step: float, mass: float, g: float) -> Path:
    """:func:`sweep_pair_chunk` written to ``cube_path``, atomically."""
    return write_cube(sweep_pair_chunk(pairs_path, store_paths, chunk, mu, angle_step, mass, g), cube_path)


def gather_planar_study(cube_paths: Sequence[str | Path], study_path: str | Path) -> Path:
    """Join the chunks' cubes along ``pair`` into ``study_path``; a dataset without pairs when no chunk has one."""
    cubes = [cube for cube in (read_cube(path) for path in cube_paths) if "pair" in cube.dims]
    if cubes:
        study = xr.concat(cubes, dim="pair", data_vars="all", coords="different", compat="equals",
                          combine_attrs="override")
        study.attrs.update(provenance())
    else:
        study = xr.Dataset(attrs={"status": "no pair", **provenance()})
    return write_cube(study, study_path)
