"""The acquisition stage of a collection study: a chunk of a collection's records, read, checked and stored.

One job per chunk (``workflow/rules/collections.smk``) reads the chunk's
records from the collection (:mod:`stickslip.collections`), checks each
file's SHA-256 where the collection knows it, and writes them all to one
record store (:mod:`stickslip.collections.store`).  A record that is not
here is stored as ``missing``, one whose file is wrong (checksum, content) as
``rejected``, each with the reason; nothing later opens a source file again.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

from stickslip.collections.collection import study_collection
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, RecordNotFoundError


def store_chunk(ids: Sequence[str], store_path: str | Path, collection: Mapping,
                g: float = STANDARD_GRAVITY) -> Path:
    """Read the records ``ids`` of ``collection`` (values in g converted with ``g`` [m/s²], the workflow's
    ``gravity``) and write them to ``store_path``.

    ``collection`` is the configuration's ``collection_study.source``
    resolved by the workflow: ``kind``, ``folder``, ``metadata`` (CSV of a
    folder collection), ``download`` (fetch SLAMMER records not in the
    folder, checked) and ``cache_dir``.
    """
    source = study_collection(collection)
    rows = []
    for record_id in ids:
        try:
            record = source.read(record_id, download=bool(collection.get("download")),
                                 cache_dir=collection.get("cache_dir"), g=g)
            rows.append(StoredRecord(record_id, record, "ok"))
        except RecordNotFoundError as error:
            rows.append(StoredRecord(record_id, None, "missing", str(error)))
        except RecordError as error:
            rows.append(StoredRecord(record_id, None, "rejected", str(error)))
    return write_record_store(rows, store_path, attrs={"collection": collection["kind"]})

