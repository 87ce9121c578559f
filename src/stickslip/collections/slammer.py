"""The USGS SLAMMER record library as a collection: its manifest, generated from the library's own database.

SLAMMER (Jibson, Rathje, Jibson and Lee; public domain) ships 2,133
processed strong-motion records from 28 earthquakes, one file per record
(``records/<event>/<record>``: one acceleration per line, in g, no header),
and a database ``eq.sql`` of their metadata and intensity measures.
:func:`slammer_manifest` turns ``eq.sql`` and a list of the files' SHA-256
(``sha256.csv``: ``path,sha256,bytes[,...]``) into our manifest, a table with
one row per record (columns: :data:`MANIFEST_COLUMNS`; units: :data:`stickslip.units.UNITS`), which the
package ships as ``stickslip/data/slammer_library.csv``
(``scripts/make-slammer-manifest.py`` regenerates it).

The files are looked up in a local copy of the library (a folder holding
``records/<event>/<record>``, or ``<event>/<record>``), then downloaded from
the source repository at :data:`SLAMMER_COMMIT`, each checked against its
SHA-256.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path
from urllib.parse import quote

import pandas as pd

from stickslip.collections.ids import duplicated_ids, record_id
from stickslip.errors import StickslipError

#: Repository and commit of the SLAMMER source whose ``records/`` folder the manifest describes.
SLAMMER_REPOSITORY = "maddyblue/slammer"
SLAMMER_COMMIT = "4b98d112a165defbe6c837bec37a68e5b56dd464"

#: Columns of ``eq.sql`` (tab-separated, no header), in order.
EQ_SQL_FIELDS = (
    "earthquake", "record", "dt", "mw", "arias_intensity", "dobry_duration", "pga", "pgv", "mean_period",
    "epicentral_distance", "hypocentral_distance", "rupture_distance", "vs30", "site_class", "mechanism",
    "location", "owner", "latitude", "longitude",
)

#: Geomatrix C3 site classes of ``eq.sql``'s codes 1 to 5.
SITE_CLASSES = {"1": "A", "2": "B", "3": "C", "4": "D", "5": "E"}

#: Focal mechanisms of ``eq.sql``'s codes 1 to 5.
MECHANISMS = {"1": "strike-slip", "2": "normal", "3": "reverse", "4": "oblique normal", "5": "oblique reverse"}

#: The manifest's columns, in order; their units are in :data:`stickslip.units.UNITS` (text columns have
#: none).  ``slammer_*`` are the database's published intensity measures, as SLAMMER computed and
#: rounded them (see ``docs/collections.md``).
MANIFEST_COLUMNS = (
    "id", "event", "year", "record", "file", "sha256", "bytes", "dt", "mw", "epicentral_distance",
    "hypocentral_distance", "rupture_distance", "vs30", "site_class", "mechanism", "station", "owner",
    "latitude", "longitude", "slammer_pga", "slammer_pgv", "slammer_arias_intensity", "slammer_dobry_duration",
    "slammer_mean_period",
)

#: The published measures: manifest column -> eq.sql field.
PUBLISHED = {
    "slammer_pga": "pga", "slammer_pgv": "pgv", "slammer_arias_intensity": "arias_intensity",
    "slammer_dobry_duration": "dobry_duration", "slammer_mean_period": "mean_period",
}


def slammer_manifest(eq_sql: str | Path, sha256_csv: str | Path) -> pd.DataFrame:
    """The manifest of the SLAMMER library from its database ``eq_sql`` and the files' ``sha256_csv``.

    One row per record of ``eq.sql``, in its order, with the columns of
    :data:`MANIFEST_COLUMNS`.  A record without a SHA-256, a row with the wrong
    number of fields, or two records with the same id raise
    :class:`StickslipError` naming the file and line.
    """
    eq_sql, sha256_csv = Path(eq_sql), Path(sha256_csv)
    hashes = _hashes(sha256_csv)
    rows = []
    with eq_sql.open(encoding="utf-8", newline="") as handle:
        for number, line in enumerate(handle, start=1):
            if not line.strip():
                continue
            fields = line.rstrip("\r\n").split("\t")
            if len(fields) != len(EQ_SQL_FIELDS):
                raise StickslipError(f"{eq_sql}, line {number}: {len(fields)} tab-separated fields, "
                                     f"expected {len(EQ_SQL_FIELDS)}")
            rows.append(_manifest_row(dict(zip(EQ_SQL_FIELDS, fields)), hashes, eq_sql, number))
    table = pd.DataFrame(rows, columns=list(MANIFEST_COLUMNS))
    twice = duplicated_ids(table["id"])
    if twice:
        raise StickslipError(f"{eq_sql}: records with the same id: {', '.join(twice)}")
    return table


def _hashes(sha256_csv: Path) -> dict[str, tuple[str, int]]:
    """``<event>/<record>`` -> (SHA-256, size in bytes) from ``sha256.csv``."""
    with sha256_csv.open(encoding="utf-8", newline="") as handle:
        reader = csv.DictReader(handle)
        missing = {"path", "sha256", "bytes"} - set(reader.fieldnames or ())
        if missing:
            raise StickslipError(f"{sha256_csv}: no column {', '.join(sorted(missing))}")
        hashes = {}
        for row in reader:
            if not re.fullmatch(r"[0-9a-f]{64}", row["sha256"] or "") or not (row["bytes"] or "").isdigit():
                raise StickslipError(f"{sha256_csv}, line {reader.line_num}: expected path, a 64-digit hex "
                                     f"SHA-256 and a size in bytes, got {row['path']!r}, {row['sha256']!r}, "
                                     f"{row['bytes']!r} (a path with a comma must be quoted)")
            hashes[row["path"]] = (row["sha256"], int(row["bytes"]))
        return hashes


def _manifest_row(fields: dict[str, str], hashes: dict, source: Path, number: int) -> dict:
    file = f"{fields['earthquake']}/{fields['record']}"
    if file not in hashes:
        raise StickslipError(f"{source}, line {number}: no SHA-256 for the file {file!r}")
    year = re.search(r"(\d{4})\s*$", fields["earthquake"])
    sha256, size = hashes[file]
    row = {
        "id": record_id(fields["earthquake"], fields["record"]),
        "event": fields["earthquake"],
        "year": int(year.group(1)) if year else None,
        "record": fields["record"],
        "file": file,
        "sha256": sha256,
        "bytes": size,
        "site_class": SITE_CLASSES.get(fields["site_class"], ""),
        "mechanism": MECHANISMS.get(fields["mechanism"], ""),
        "station": fields["location"],
        "owner": fields["owner"],
    }
    for name in ("dt", "mw", "epicentral_distance", "hypocentral_distance", "rupture_distance", "vs30",
                 "latitude", "longitude"):
        row[name] = float(fields[name]) if fields[name].strip() else None
    for column, field in PUBLISHED.items():
        row[column] = float(fields[field]) if fields[field].strip() else None
    return row


def download_url(file: str, mirror_url: str = "https://raw.githubusercontent.com") -> str:
    """The URL of the library file ``file`` (``<event>/<record>``) at :data:`SLAMMER_COMMIT`."""
    return f"{mirror_url.rstrip('/')}/{SLAMMER_REPOSITORY}/{SLAMMER_COMMIT}/{quote('records/' + file)}"
