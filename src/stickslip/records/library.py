"""The SLAMMER library's files recognised by their SHA-256, for the readers (no pandas, read once, on demand).

The package ships the SLAMMER library's manifest (``stickslip/data/slammer_library.csv``,
2,133 rows; :mod:`stickslip.collections.slammer` describes it).  A file of
the library has no header: its time step [s], units (g) and description
(event, station, component) are known only from the manifest.
:func:`library_file` finds the row of a file by its SHA-256 with one search
of the manifest's text, so that a reader pays nothing for the 2,132 other
rows, and the command line does not import pandas to read one file.
"""

from __future__ import annotations

import csv
import functools
import importlib.resources
from dataclasses import dataclass

#: What the readers call the SLAMMER library's manifest in messages.
LIBRARY_MANIFEST = "the SLAMMER library manifest"


@dataclass(frozen=True)
class LibraryFile:
    """A file of the SLAMMER library, as its manifest describes it.

    Attributes
    ----------
    record_id:
        The library's record id (``kobe_japan_1995_kjm_090``).
    event, station, component:
        Earthquake (with its year), recording station, and the record's name in the library (``KJM-090``).
    dt:
        Time step [s].
    units:
        Units of the values in the file (``g``).
    format:
        Reader format (``slammer_1col``).
    """

    record_id: str
    event: str
    station: str
    component: str
    dt: float
    units: str = "g"
    format: str = "slammer_1col"


@functools.cache
def _manifest_text() -> str:
    """The text of the shipped manifest (about 0.6 MB), read once per process; empty when it is not installed."""
    resource = importlib.resources.files("stickslip").joinpath("data", "slammer_library.csv")
    try:
        return resource.read_text(encoding="utf-8")
    except OSError:
        return ""


def library_file(sha256: str) -> LibraryFile | None:
    """The SLAMMER library file whose bytes have this SHA-256 (lower-case hex), or ``None``."""
    text = _manifest_text()
    found = text.find(f",{sha256},") if len(sha256) == 64 else -1
    if found < 0:
        return None
    header = text[:text.index("\n")]
    start = text.rfind("\n", 0, found) + 1
    end = text.find("\n", found)
    line = text[start:end if end >= 0 else None].rstrip("\r")
    row = dict(zip(next(csv.reader([header.rstrip("\r")])), next(csv.reader([line]))))
    return LibraryFile(record_id=row["id"], event=row["event"], station=row["station"], component=row["record"],
                       dt=float(row["dt"]))
