"""Many records in one NetCDF file: the acquisition stage of a collection study, one file per chunk of records.

The file is a CF *contiguous ragged array* of time series (CF Conventions
§9.3.3, ``featureType = "timeSeries"``): the samples of every record one
after the other in ``acceleration(sample)`` [m s-2], ``sample_count(record)``
(with ``sample_dimension = "sample"``) the number of samples of each, and
per record its id (``record``, ``cf_role = "timeseries_id"``), time step
``dt`` [s], SHA-256, source and status.  A record that could not be read
keeps its row with no samples, ``status`` ``"missing"`` or ``"rejected"``
and the reason: later stages name it instead of failing.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.errors import RecordError, StickslipError
from stickslip.plumbing.files import atomic_path, provenance
from stickslip.records.record import Record, RecordMeta
from stickslip.units import CF_CONVENTIONS


@dataclass(frozen=True)
class StoredRecord:
    """One row of a record store: the record when it could be read, else ``None``, its status and the reason."""

    record_id: str
    record: Record | None
    status: str
    reason: str = ""


def write_record_store(rows: Sequence[StoredRecord], path: str | Path, attrs: dict | None = None) -> Path:
    """Write ``rows`` as one CF ragged-array NetCDF file at ``path``, atomically."""
    counts = np.array([row.record.npts if row.record is not None else 0 for row in rows], dtype=np.int64)
    samples = [row.record.acceleration for row in rows if row.record is not None]

    def text(value_of) -> np.ndarray:
        return np.array([value_of(row) for row in rows], dtype=object)

    read = [row.record for row in rows]
    dataset = xr.Dataset(
        {
            "acceleration": ("sample", np.concatenate(samples) if samples else np.zeros(0),
                             {"units": "m s-2", "long_name": "ground acceleration"}),
            "sample_count": ("record", counts, {"sample_dimension": "sample",
                                                "long_name": "number of samples of each record"}),
            "dt": ("record", np.array([r.dt if r is not None else np.nan for r in read], dtype=float),
                   {"units": "s", "long_name": "time step"}),
            "status": ("record", text(lambda row: row.status), {"long_name": "ok, missing or rejected"}),
            "reason": ("record", text(lambda row: row.reason),
                       {"long_name": "why a record is missing or rejected"}),
            "sha256": ("record", text(lambda row: row.record.meta.sha256 if row.record else ""),
                       {"long_name": "SHA-256 of the record's source file"}),
            "source": ("record", text(lambda row: row.record.meta.source if row.record else ""),
                       {"long_name": "file, package resource or URL read"}),
        },
        coords={"record": ("record", text(lambda row: row.record_id),
                           {"cf_role": "timeseries_id", "long_name": "record id"})},
        attrs={"Conventions": CF_CONVENTIONS, "featureType": "timeSeries",
               "title": "ground-motion records of a collection (contiguous ragged array)",
               **(attrs or {}), **provenance()},
    )
    with atomic_path(path) as tmp:
        dataset.to_netcdf(tmp, engine="netcdf4", encoding={"acceleration": {"zlib": True, "complevel": 1}})
    return Path(path)


def read_record_store(path: str | Path) -> list[StoredRecord]:
    """The rows of a file written by :func:`write_record_store`, records in m/s² and s."""
    path = Path(path)
    try:
        with xr.open_dataset(path, engine="netcdf4") as dataset:
            dataset = dataset.load()
    except (OSError, ValueError) as error:
        raise RecordError(path, f"not a readable record store ({error})") from None
    missing = {"acceleration", "sample_count", "dt", "status", "reason"} - set(dataset.variables)
    if missing:
        raise RecordError(path, f"not a record store: no {', '.join(sorted(missing))}")
    counts = dataset["sample_count"].values.astype(np.int64)
    if counts.sum() != dataset.sizes["sample"]:
        raise StickslipError(f"{path}: sample counts add up to {counts.sum()}, "
                             f"the file holds {dataset.sizes['sample']} samples")
    ends = np.cumsum(counts)
    acceleration = dataset["acceleration"].values
    rows = []
    for index, record_id in enumerate(dataset["record"].values.astype(str)):
        status = str(dataset["status"].values[index])
        record = None
        if status == "ok":
            meta = RecordMeta(record_id=record_id, source=str(dataset["source"].values[index]),
                              sha256=str(dataset["sha256"].values[index]))
            record = Record(acceleration[ends[index] - counts[index]:ends[index]].copy(),
                            float(dataset["dt"].values[index]), meta)
        rows.append(StoredRecord(record_id, record, status, str(dataset["reason"].values[index])))
    return rows
