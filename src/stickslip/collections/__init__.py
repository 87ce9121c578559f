"""Record collections (the SLAMMER library, pyslammer's samples, a folder of PEER files) and their studies.

See ``docs/collections.md``: :func:`load_collection` gives a
:class:`Collection` (a metadata table indexed by record id, and how to read
and check each file); :class:`RecordFilter` selects records by distance,
magnitude, PGA, event and site class.
"""

from stickslip.collections.collection import KINDS, Collection, RecordFilter, load_collection
from stickslip.collections.ids import record_id

__all__ = ["KINDS", "Collection", "RecordFilter", "load_collection", "record_id"]
