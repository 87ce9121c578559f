"""Per-record intensity measures: ``results/records/{id}.nc`` -> ``results/measures/{id}.json``.

The measures stage of the workflow.  Each file holds the record's description
(event, station, component, source file, SHA-256), its status (``"ok"`` or
``"missing: <how to obtain it>"``) and, for an available record, the scalar
intensity measures of :func:`stickslip.measures.intensity_measures` in SI
units, with a ``units`` table.  Later stages (the records table, the sweeps)
read these files instead of computing the measures again.
"""

from __future__ import annotations

import json
from pathlib import Path

from stickslip.errors import RecordNotFoundError
from stickslip.plumbing.files import write_text_atomic
from stickslip.measures import MEASURE_UNITS, intensity_measures
from stickslip.records.netcdf import read_record_netcdf, record_description

#: Descriptive attributes of a stored record copied into its measures document.
DESCRIPTION_KEYS = ("event", "year", "mw", "station", "component")


def record_measures(record_path: str | Path, g: float) -> dict:
    """The measures document of the stored record at ``record_path`` (gravity ``g`` [m/s²])."""
    record_path = Path(record_path)
    attrs = record_description(record_path)
    document = {"record": str(attrs.get("record_id", record_path.stem))}
    document.update({key: _plain(attrs[key]) for key in DESCRIPTION_KEYS if key in attrs})
    try:
        record = read_record_netcdf(record_path)
    except RecordNotFoundError as error:
        return {**document, "status": f"missing: {error}"}
    meta = record.meta
    return {
        **document,
        "status": "ok",
        "source_file": Path(meta.source).name,
        "sha256": meta.sha256,
        "gravity": g,
        "measures": intensity_measures(record, g=g).as_dict(),
        "units": MEASURE_UNITS,
    }


def write_record_measures(record_path: str | Path, measures_path: str | Path, g: float) -> Path:
    """Compute the measures of the stored record and write them as JSON, atomically.

    :func:`stickslip.measures.intensity_measures` refuses a record whose measures are not finite.
    """
    document = record_measures(record_path, g)
    write_text_atomic(measures_path, json.dumps(document, indent=2) + "\n")
    return Path(measures_path)


def read_record_measures(path: str | Path) -> dict:
    """A measures document written by :func:`write_record_measures`."""
    return json.loads(Path(path).read_text(encoding="utf-8"))


def _plain(value):
    """A NetCDF attribute as a plain Python value (JSON-serialisable)."""
    return value.item() if hasattr(value, "item") else value
