"""Records as NetCDF files (``results/records/{id}.nc``) and back.

The file holds one variable, ``acceleration`` [m/s²], on the dimension
``time`` [s], with the record's provenance as global attributes: record id,
event, station, component, source file, its SHA-256, its format and units,
the processing steps, the time step dt [s], the g [m/s²] that converted a
source in g (``gravity``), and the code that wrote it
(:func:`stickslip.plumbing.files.provenance`).  Every command reads such a
file as a record (the ``netcdf`` format of :mod:`stickslip.records.formats`).

A record that no source could provide is stored too, as a file with no
variable and the attributes ``status = "missing"`` and ``reason`` (what was
tried and how to obtain the record): the workflow's later stages read it and
name the record as missing instead of failing (:func:`write_missing_record`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, RecordNotFoundError
from stickslip.plumbing.files import atomic_path, provenance
from stickslip.records.record import Record, RecordMeta
from stickslip.units import CF_CONVENTIONS, UNITS, normalise_units

#: Separator of the processing steps in the ``processing`` attribute.
_STEP_SEPARATOR = "; "


def record_to_dataset(record: Record) -> xr.Dataset:
    """An xarray Dataset of ``record``: ``acceleration`` [m/s²] over ``time`` [s], provenance in attributes."""
    meta = record.meta
    # No standard_name "time": CF keeps it for times since a reference date, and this is time since the record began.
    time = xr.Variable("time", record.time,
                       attrs={"units": UNITS["time"], "long_name": "time since the start of the record"})
    acceleration = xr.Variable(
        "time", record.acceleration, attrs={"units": UNITS["acceleration"], "long_name": "ground acceleration"}
    )
    attrs = {
        "title": f"ground-motion record {meta.record_id}",
        "Conventions": CF_CONVENTIONS,
        "record_id": meta.record_id,
        "event": meta.event,
        "station": meta.station,
        "component": meta.component,
        "source": meta.source,
        "sha256": meta.sha256,
        "source_units": meta.units,
        "format": meta.format,
        "processing": _STEP_SEPARATOR.join(meta.processing),
        "dt": record.dt,
        "dt_units": UNITS["dt"],
        "dt_source": meta.dt_source,
        **({"gravity": meta.gravity, "gravity_units": UNITS["gravity"]} if meta.gravity is not None else {}),
        **provenance(),
    }
    return xr.Dataset({"acceleration": acceleration}, coords={"time": time}, attrs=attrs)


def write_record(record: Record, path: str | Path, description: dict | None = None) -> Path:
    """Write ``record`` as NetCDF-4 to ``path`` atomically; return the path.

    ``description`` adds attributes the record itself does not carry (the
    manifest's ``year`` and moment magnitude ``mw``, for example).
    """
    path = Path(path)
    dataset = record_to_dataset(record)
    dataset.attrs.update(_attributes(description))
    with atomic_path(path) as tmp:
        dataset.to_netcdf(tmp, engine="netcdf4")
    return path


def write_missing_record(record_id: str, reason: str, path: str | Path, description: dict | None = None) -> Path:
    """Store at ``path`` that ``record_id`` is missing, and why (atomically); return the path.

    ``description`` (event, station, component, year, mw …) is kept as attributes,
    so that tables can describe the record they could not include.
    """
    path = Path(path)
    attrs = {"title": f"ground-motion record {record_id} (missing)", "Conventions": CF_CONVENTIONS,
             "record_id": record_id, **_attributes(description), "status": "missing", "reason": reason, **provenance()}
    with atomic_path(path) as tmp:
        xr.Dataset(attrs=attrs).to_netcdf(tmp, engine="netcdf4")
    return path


def record_description(path: str | Path) -> dict:
    """The global attributes of a stored record (available or missing), without reading its samples."""
    with xr.open_dataset(path, engine="netcdf4") as dataset:
        return dict(dataset.attrs)


def _attributes(description: dict | None) -> dict:
    """``description`` without empty values (NetCDF attributes cannot be None)."""
    return {key: value for key, value in (description or {}).items() if value is not None and value != ""}


def record_status(path: str | Path) -> str:
    """``"ok"`` for a stored record, ``"missing: <reason>"`` for a missing one (see :func:`write_missing_record`)."""
    try:
        read_record_netcdf(path)
    except RecordNotFoundError as error:
        return f"missing: {error}"
    return "ok"


def read_record_netcdf(path: str | Path) -> Record:
    """Read a record written by :func:`write_record` (acceleration in m/s², dt in s).

    The ``units`` of ``acceleration`` may be any spelling of m s-2
    (:func:`stickslip.units.normalise_units`): ``m/s2``, ``m/s²``, ``m s^-2`` ….

    A file written by :func:`write_missing_record` raises
    :class:`~stickslip.errors.RecordNotFoundError` with the stored reason.
    """
    path = Path(path)
    if path.name.endswith(".part"):
        raise RecordError(path, "is the temporary .part file of an unfinished write, not a record")
    if not path.is_file():
        raise RecordError(path, "file not found" if not path.exists() else "is not a regular file")
    try:
        with xr.open_dataset(path, engine="netcdf4") as dataset:
            return record_from_dataset(dataset, path)
    except (OSError, ValueError) as error:
        raise RecordError(path, f"not a readable NetCDF file ({error})") from None


def record_from_bytes(data: bytes, source: str | Path) -> Record:
    """The record stored in ``data``, the bytes of a file written by :func:`write_record`; see :func:`read_record_netcdf`."""
    import netCDF4

    try:
        with xr.open_dataset(xr.backends.NetCDF4DataStore(netCDF4.Dataset(str(source), memory=data))) as dataset:
            return record_from_dataset(dataset, source)
    except (OSError, ValueError) as error:
        raise RecordError(source, f"not a readable NetCDF file ({error})") from None


def record_from_dataset(dataset: xr.Dataset, source: str | Path) -> Record:
    """The record an open stored-record dataset holds (acceleration in m/s², dt in s, its source's provenance).

    ``source`` names the file in messages.  A missing record raises
    :class:`~stickslip.errors.RecordNotFoundError` with the stored reason.  A
    record whose source was in g has ``meta.gravity``, the g [m/s²] that
    converted it: the stored ``gravity``, or 9.81 m/s² for a file written
    before that attribute was stored (every conversion then used it).
    """
    attrs = dict(dataset.attrs)
    if attrs.get("status") == "missing":
        raise RecordNotFoundError(str(attrs.get("reason", f"record {Path(source).stem} is missing")))
    if "acceleration" not in dataset:
        raise RecordError(source, "NetCDF file has no 'acceleration' variable")
    acceleration = np.asarray(dataset["acceleration"].values, dtype=np.float64)
    units = dataset["acceleration"].attrs.get("units")
    if units is None or normalise_units(units) != UNITS["acceleration"]:
        raise RecordError(source, f"acceleration units are {units!r}; expected m s-2 (or a spelling of it: m/s2, m/s², "
                                  "m s^-2)")
    if "dt" not in attrs:
        raise RecordError(source, "NetCDF file has no 'dt' attribute")
    processing = attrs.get("processing", "")
    source_units = str(attrs.get("source_units", "m/s2"))
    meta = RecordMeta(
        record_id=str(attrs.get("record_id", Path(source).stem)),
        event=str(attrs.get("event", "")),
        station=str(attrs.get("station", "")),
        component=str(attrs.get("component", "")),
        source=str(attrs.get("source", "")),
        sha256=str(attrs.get("sha256", "")),
        units=source_units,
        format=str(attrs.get("format", "")),
        processing=tuple(processing.split(_STEP_SEPARATOR)) if processing else (),
        dt_source=str(attrs.get("dt_source", "")),
        gravity=float(attrs.get("gravity", STANDARD_GRAVITY)) if source_units == "g" else None,
    )
    return Record(acceleration=acceleration, dt=float(attrs["dt"]), meta=meta)
