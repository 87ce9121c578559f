"""The records the damper study runs on, read where the workflow stored them (no record file is opened here).

- the paper's records: ``results/records/{id}.nc`` as the paper's sweeps read them; one that is missing is
  named with its reason, and left out;
- the collection study's records (``{STUDY_DIR}/records/{chunk}.nc``: the SLAMMER library's 521 near-fault
  records, or pyslammer's samples offline): those stored ``ok``.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from stickslip.collections.store import read_record_store
from stickslip.errors import RecordNotFoundError
from stickslip.records.netcdf import read_record_netcdf
from stickslip.records.record import Record

#: The library of the paper's records, as the study's tables name it.
PAPER = "paper"


def paper_records(record_paths: Sequence[str | Path]) -> tuple[list[tuple[str, Record]], dict[str, str]]:
    """The stored paper records, (id, record) with the manifest's id (the file's stem), and the missing ones: id -> why."""
    found, missing = [], {}
    for path in record_paths:
        try:
            found.append((Path(path).stem, read_record_netcdf(path)))
        except RecordNotFoundError as error:
            missing[Path(path).stem] = str(error)
    return found, missing


def collection_records(store_path: str | Path) -> tuple[list[tuple[str, Record]], dict[str, str]]:
    """The records of one chunk's store read ``ok``, (id, record), and the others: id -> status and reason."""
    found, missing = [], {}
    for row in read_record_store(store_path):
        if row.record is None:
            missing[row.record_id] = f"{row.status}: {row.reason}"
        else:
            found.append((row.record_id, row.record))
    return found, missing
