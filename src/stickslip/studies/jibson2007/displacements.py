"""Jibson (2007), recomputed: one-way Newmark displacements of every record of a collection, per chunk.

For every record of a chunk of the collection study (its record store,
:mod:`stickslip.studies.collections.records`, and its measures,
:mod:`stickslip.studies.collections.measures`), the exact solver computes the
permanent downslope displacement D_n of a rigid block sliding one way
(downslope only) at each critical acceleration a_c of a grid, in both of
SLAMMER's polarities: ``normal`` (the record as given) and ``inverse`` (its
sign flipped).  The grid is given in g, as Jibson gives it: a_c = k_y·g, so
the yield coefficient k_y [1] is the value in g and the sweep is
:func:`stickslip.sweeps.sweep` over ``ky`` (one call per polarity).

One row per record, polarity and a_c, columns :data:`COLUMNS`:

* ``ky`` [1], the critical acceleration a_c in g;
* ``pga`` [m s-2] and ``arias_intensity`` [m s-1], the record's measures
  (those of the chunk's measures table, with the study's gravity);
* ``critical_acceleration_ratio`` a_c/a_max = k_y·g/PGA [1];
* ``newmark_displacement`` D_n [cm], Jibson's unit (≥ 0; 0 where the block
  never slides, which is certain when a_c ≥ PGA).

Every row of the grid is kept, also those with a_c ≥ PGA: which rows enter a
fit is decided, and counted, by :mod:`stickslip.studies.jibson2007.fit`.  A
record that is missing or rejected keeps one row with its ``status`` and no
values.  :func:`gather_displacements` joins the chunks' tables into one and
adds each record's ``event`` from the collection's table.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from stickslip.collections.collection import study_collection
from stickslip.collections.store import read_record_store
from stickslip.models.parameters import POLARITIES
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.studies.collections.measures import MEASURES
from stickslip.models import sweep

#: The table's columns, in order (units in :data:`stickslip.units.UNITS`); a chunk's table has all but ``event``.
COLUMNS = ("record", "event", "status", "polarity", "ky", "pga", "arias_intensity", "critical_acceleration_ratio",
           "newmark_displacement")

#: Centimetres per metre: D_n is in cm, Jibson's unit, the solver's lengths in m.
CM_PER_M = 100.0


def displacement_rows(records, measures: Sequence[dict], critical_accelerations_g: Sequence[float],
                      g: float) -> list[dict]:
    """The table's rows of ``records`` (:class:`~stickslip.records.record.Record`, acceleration in m s-2).

    ``measures``: each record's row of the chunk's measures table (PGA [m s-2], Arias intensity [m s-1], …);
    ``critical_accelerations_g``: a_c [g], positive and increasing; ``g`` [m s-2]
    the gravity of the measures and of a_c = k_y·g.  Rows are ordered by
    record, then polarity, then a_c.
    """
    records = list(records)
    if not records:
        return []
    measured = [{name: float(row[name]) for name in MEASURES} for row in measures]
    kys = np.asarray(critical_accelerations_g, dtype=float)
    displacements = {polarity: CM_PER_M * sweep(records, ky=kys, g=g, measures=measured,
                                                inverse=polarity == "inverse").downslope_displacement.values
                     for polarity in POLARITIES}
    rows = []
    for index, (record, measure) in enumerate(zip(records, measured)):
        for polarity in POLARITIES:
            for column, ky in enumerate(kys):
                rows.append({"record": str(record.meta.record_id), "status": "ok",
                             "polarity": polarity, "ky": float(ky), "pga": measure["pga"],
                             "arias_intensity": measure["arias_intensity"],
                             "critical_acceleration_ratio": float(ky) * g / measure["pga"],
                             "newmark_displacement": float(displacements[polarity][index, column])})
    return rows


def chunk_displacements(store_path: str | Path, measures_path: str | Path, critical_accelerations_g: Sequence[float],
                        g: float) -> list[dict]:
    """The rows of one chunk, in the store's order of records (see the module's docstring)."""
    measures = {row["record"]: row for row in read_csv_rows(measures_path)}
    stored = read_record_store(store_path)
    present = [row.record for row in stored if row.record is not None]
    solved = displacement_rows(present, [measures[record.meta.record_id] for record in present],
                               critical_accelerations_g, g)
    by_record = {}
    for row in solved:
        by_record.setdefault(row["record"], []).append(row)
    rows = []
    for row in stored:
        if row.record is None:
            rows.append({"record": row.record_id, "status": f"not solved: {row.status}: {row.reason}"})
        else:
            rows += by_record[row.record_id]
    return rows


def write_chunk_displacements(store_path: str | Path, measures_path: str | Path, table_path: str | Path,
                              critical_accelerations_g: Sequence[float], g: float) -> Path:
    """:func:`chunk_displacements` written as CSV to ``table_path``, atomically."""
    return write_csv_atomic(table_path, chunk_displacements(store_path, measures_path, critical_accelerations_g, g),
                            [name for name in COLUMNS if name != "event"])


def gather_displacements(chunk_paths: Sequence[str | Path], table_path: str | Path, collection: Mapping) -> Path:
    """The chunks' tables joined, in the given order, into ``table_path`` (CSV, atomically), with each record's event.

    ``collection``: the study's collection (``kind``, ``folder``, ``metadata``), whose table names the events.
    """
    events = study_collection(collection).table["event"]
    rows = [{**row, "event": events.get(row["record"], "")} for path in chunk_paths for row in read_csv_rows(path)]
    return write_csv_atomic(table_path, rows, list(COLUMNS))
