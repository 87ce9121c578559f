"""Ground-motion records: the Record type, file readers, manifest, acquisition and processing."""

from stickslip.records.record import Record, RecordMeta

__all__ = ["Record", "RecordMeta"]
