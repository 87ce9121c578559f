"""Records for the studies, acquired as the configuration says.

The configuration keys used are ``records_dir`` (local records folder),
``records_manifest`` (the record manifest, default ``config/records.yaml``)
and ``accept_unknown_versions`` (accept files whose SHA-256 is not a known
version of the record).
"""

from __future__ import annotations

from stickslip.errors import RecordNotFoundError
from stickslip.records.acquire import acquire
from stickslip.records.manifest import RecordEntry, load_manifest
from stickslip.records.record import Record


def study_manifest(config: dict) -> dict[str, RecordEntry]:
    """The record manifest named by the configuration's ``records_manifest``."""
    return load_manifest(config.get("records_manifest"))


def load_study_record(config: dict, record_id: str, manifest: dict[str, RecordEntry] | None = None) -> Record:
    """The record ``record_id`` (acceleration in m/s², dt in s), acquired as the configuration says.

    ``manifest`` defaults to :func:`study_manifest`.  Raises
    :class:`~stickslip.errors.RecordNotFoundError` when no source has the record.
    """
    return acquire(
        record_id,
        records_dir=config.get("records_dir"),
        manifest=study_manifest(config) if manifest is None else manifest,
        accept_unknown=bool(config.get("accept_unknown_versions", False)),
    )


def load_study_records(config: dict, record_ids: list[str]) -> tuple[dict[str, Record], dict[str, str]]:
    """``id -> Record`` for the records that can be acquired, and ``id -> "missing: why"`` for the rest."""
    manifest = study_manifest(config)
    records, missing = {}, {}
    for record_id in record_ids:
        try:
            records[record_id] = load_study_record(config, record_id, manifest)
        except RecordNotFoundError as error:
            missing[record_id] = f"missing: {error}"
    return records, missing
