"""The measures stage of a collection study: intensity measures of a chunk of stored records.

For every record of a record store (:mod:`stickslip.studies.collections.records`)
one row: our intensity measures (SI, :func:`stickslip.measures.intensity_measures`:
PGA, PGV, PGD [m s-2, m s-1, m], Arias intensity [m s-1], t5, t95, t_e [s],
RMS acceleration over t_e [m s-2], mean period T_m [s], npts, duration [s]; the
time step is the collection's) and the same record's
measures in SLAMMER's definitions (``slammer_convention_*``, unrounded;
:mod:`stickslip.collections.slammer_measures`), for the check against the
library's database.  Records that are missing or rejected keep their row,
with their status and no values.
"""

from __future__ import annotations

from pathlib import Path

from stickslip.collections.slammer_measures import slammer_convention
from stickslip.collections.store import read_record_store
from stickslip.plumbing.files import write_csv_atomic
from stickslip.measures import intensity_measures

#: Our measures in the table, in order (units: stickslip.measures.MEASURE_UNITS).
MEASURES = ("pga", "pgv", "pgd", "arias_intensity", "t5", "t95", "significant_duration", "rms_acceleration",
            "mean_period", "npts", "duration")

#: The SLAMMER-convention columns.
SLAMMER_COLUMNS = tuple(f"slammer_convention_{name}" for name in ("pga", "arias_intensity", "dobry_duration",
                                                                     "mean_period"))


def chunk_measures(store_path: str | Path, g: float) -> list[dict]:
    """One row per record of the store: id, status, reason and measures (our measures with gravity ``g`` [m s-2])."""
    rows = []
    for stored in read_record_store(store_path):
        row = {"record": stored.record_id, "status": stored.status, "reason": stored.reason}
        if stored.record is not None:
            measures = intensity_measures(stored.record, g=g).as_dict()
            row.update({name: measures[name] for name in MEASURES})
            convention = slammer_convention(stored.record.acceleration, stored.record.dt)
            row.update({f"slammer_convention_{name}": value for name, value in convention.items()})
        rows.append(row)
    return rows


def write_chunk_measures(store_path: str | Path, measures_path: str | Path, g: float) -> Path:
    """:func:`chunk_measures` written as CSV to ``measures_path``, atomically."""
    columns = ["record", "status", "reason", *MEASURES, *SLAMMER_COLUMNS]
    return write_csv_atomic(measures_path, chunk_measures(store_path, g), columns)
