"""Record collections: a set of record files with a metadata table, and how to find and check each file.

Three kinds (``docs/collections.md``):

``slammer``
    The USGS SLAMMER library (2,133 records; :mod:`stickslip.collections.slammer`).
    Its manifest ships with the package.  Files come from a local copy of the
    library (``folder``), else, when asked, from a checked download.
``pyslammer``
    The 18 sample motions of the ``pyslammer`` package, read as data: the
    collection that is always available offline.  They are SLAMMER records,
    and take their metadata from the SLAMMER manifest.
``folder``
    Any folder of record files, in every format :func:`~stickslip.records.readers.read_record`
    reads: metadata from the files' headers, the manifests we ship and,
    optionally, a CSV table of more columns (``metadata``); a record file
    that cannot be read keeps a row with the reason, and a file that is no
    record file (a README, notes, an image, a table of metadata) is listed
    as skipped (:func:`not_a_record`).

Every collection has the same table (:data:`COLUMNS`), indexed by record id
(:mod:`stickslip.collections.ids`); columns a collection does not know are
empty.  ``listed_pga`` [g, UDUNITS ``standard_free_fall``] is the collection's
published PGA where it has one (SLAMMER), else the largest value of the file (in
g): it is what a PGA floor filters on.
"""

from __future__ import annotations

import functools
import importlib.resources
import math
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from stickslip.collections.ids import duplicated_ids, record_id
from stickslip.collections.slammer import MANIFEST_COLUMNS, download_url
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, RecordNotFoundError, StickslipError
from stickslip.plumbing.files import read_csv_rows
from stickslip.records.formats import FORMATS
from stickslip.records.numbers import NUMBER
from stickslip.records.readers import (ARGUMENT_IN_MESSAGE, normalize_units, read_file_bytes, read_record_bytes,
                                      sha256_hex)
from stickslip.records.record import Record, RecordMeta

#: Kinds of collection.
KINDS = ("slammer", "pyslammer", "folder")

#: Columns of every collection's table: the SLAMMER manifest's, then the file's format and units and the
#: listed PGA [standard_free_fall]; units of each in :data:`stickslip.units.UNITS`.
COLUMNS = (*MANIFEST_COLUMNS, "format", "units", "listed_pga")

#: Environment variable naming a local copy of the SLAMMER library.
SLAMMER_DIR_ENV = "STICKSLIP_SLAMMER_DIR"

#: Environment variable that overrides the download mirror (as for the record manifest).
MIRROR_ENV = "STICKSLIP_MIRROR_URL"

#: Default mirror of the SLAMMER source repository.
DEFAULT_MIRROR = "https://raw.githubusercontent.com"


@dataclass(frozen=True)
class SkippedFile:
    """A file of a folder collection that is no record file: its path relative to the folder, and why."""

    file: str
    reason: str


@dataclass(frozen=True)
class Collection:
    """A collection: its kind, its table (one row per record, indexed by id) and its folder.

    ``folder`` is the local copy of a ``slammer`` library or the folder of a
    ``folder`` collection; ``None`` for ``pyslammer``, and for a ``slammer``
    collection with no local copy (its records can then only be downloaded).
    ``skipped``: the files of a ``folder`` collection that are no record files
    (:func:`not_a_record`), in the folder's order.
    """

    kind: str
    table: pd.DataFrame
    folder: Path | None = None
    skipped: tuple[SkippedFile, ...] = ()

    @property
    def ids(self) -> list[str]:
        """Every record id, in the table's order."""
        return list(self.table.index)

    def local_file(self, record_id: str):
        """The file of ``record_id`` here on this machine (a path or a package resource), or ``None``."""
        file = self.table.at[record_id, "file"]
        if self.kind == "pyslammer":
            return _pyslammer_samples().get(file)
        if self.folder is None:
            return None
        for root in (self.folder / "records", self.folder):
            if (root / file).is_file():
                return root / file
        return None

    def has_local_files(self) -> bool:
        """Whether any record's file is here (stops at the first one found)."""
        return any(self.local_file(record_id) is not None for record_id in self.ids)

    def local_ids(self) -> list[str]:
        """The ids whose file is here on this machine (present, not yet checked)."""
        return [record_id for record_id in self.ids if self.local_file(record_id) is not None]

    def select(self, record_filter: "RecordFilter | None") -> "Collection":
        """The collection restricted to the records ``record_filter`` keeps."""
        if record_filter is None:
            return self
        return Collection(self.kind, self.table[record_filter.keeps(self.table)], self.folder, self.skipped)

    def file_bytes(self, record_id: str, download: bool = False,
                   cache_dir: str | Path | None = None) -> tuple[bytes, str]:
        """The bytes of the file of ``record_id`` and where they came from (not yet checked).

        The local file first; else, for ``slammer`` with ``download``, the
        file from the source repository (kept in ``cache_dir``, default the
        user cache).  :class:`RecordNotFoundError` says what was tried.
        """
        if record_id not in self.table.index:
            raise StickslipError(f"unknown record id {record_id!r} in the {self.kind} collection; "
                                 f"`stickslip records list --collection {self.kind}` shows its ids")
        found = self.local_file(record_id)
        if found is not None:
            data = found.read_bytes() if not isinstance(found, Path) else read_file_bytes(found)
            return data, f"pyslammer:{self.table.at[record_id, 'file']}" if self.kind == "pyslammer" else str(found)
        if self.kind == "slammer" and download:
            return _download(self.table.loc[record_id], cache_dir)
        raise RecordNotFoundError(self.missing_reason(record_id, download))

    def read(self, record_id: str, download: bool = False, cache_dir: str | Path | None = None,
             g: float = STANDARD_GRAVITY) -> Record:
        """The record ``record_id`` (acceleration in m/s², values in g converted with ``g`` [m/s²]; dt in s), its
        file's SHA-256 checked where known.

        See :meth:`file_bytes` for where the file comes from; :class:`RecordError`
        names a file whose checksum or content is wrong.
        """
        data, location = self.file_bytes(record_id, download, cache_dir)
        return _record(data, location, record_id, self.table.loc[record_id], g)

    def missing_reason(self, record_id: str, download: bool) -> str:
        """Why ``record_id`` cannot be read here, and how to obtain it."""
        file = self.table.at[record_id, "file"]
        if self.kind == "slammer":
            where = f"not in {self.folder}" if self.folder is not None else "no SLAMMER folder set"
            return (f"{record_id} ({file}): {where}; download {'failed' if download else 'not asked for'}. "
                    f"Obtain it with `stickslip records fetch --collection slammer {record_id} --out-dir FOLDER` "
                    f"(checked download from {download_url(file)})")
        return f"{record_id} ({file}): file not found"


@dataclass(frozen=True)
class RecordFilter:
    """Which records of a collection to keep; ``None`` keeps everything on that count.

    Distances in km, magnitude Mw, PGA [g] (the ``listed_pga`` column);
    ``events`` are case-insensitive parts of the event name; ``site_classes``
    Geomatrix letters A to E.  A record with no value for a filtered column
    (an empty rupture distance, say) is left out.
    """

    min_rupture_distance: float | None = None
    max_rupture_distance: float | None = None
    min_magnitude: float | None = None
    max_magnitude: float | None = None
    min_pga: float | None = None
    events: tuple[str, ...] = ()
    site_classes: tuple[str, ...] = ()

    @classmethod
    def from_mapping(cls, values: dict | None) -> "RecordFilter":
        """A filter from the configuration's ``filters`` (missing keys keep everything)."""
        values = dict(values or {})
        unknown = sorted(set(values) - set(cls.__dataclass_fields__))
        if unknown:
            raise StickslipError(f"unknown record filter(s): {', '.join(unknown)}; known: "
                                 f"{', '.join(cls.__dataclass_fields__)}")
        for name in ("events", "site_classes"):
            values[name] = tuple(values.get(name) or ())
        return cls(**values)

    def keeps(self, table: pd.DataFrame) -> pd.Series:
        """A boolean mask of the rows of ``table`` that pass."""
        keep = pd.Series(True, index=table.index)
        bounds = [("rupture_distance", self.min_rupture_distance, self.max_rupture_distance),
                  ("mw", self.min_magnitude, self.max_magnitude), ("listed_pga", self.min_pga, None)]
        for column, low, high in bounds:
            values = pd.to_numeric(table[column], errors="coerce")
            if low is not None:
                keep &= values >= low
            if high is not None:
                keep &= values <= high
        if self.events:
            names = table["event"].astype(str).str.lower()
            keep &= np.logical_or.reduce([names.str.contains(event.lower(), regex=False) for event in self.events])
        if self.site_classes:
            keep &= table["site_class"].isin([letter.upper() for letter in self.site_classes])
        return keep

    def describe(self) -> str:
        """The filter in words, or ``"all records"``."""
        parts = []
        for name, value in self.__dict__.items():
            if value not in (None, ()):
                parts.append(f"{name.replace('_', ' ')} {', '.join(value) if isinstance(value, tuple) else value}")
        return "; ".join(parts) or "all records"


def load_collection(kind: str, folder: str | Path | None = None, metadata: str | Path | None = None,
                    dt: float | None = None, units: str | None = None) -> Collection:
    """The collection of ``kind`` (one of :data:`KINDS`).

    ``folder``: for ``slammer`` a local copy of the library (default the
    environment variable ``STICKSLIP_SLAMMER_DIR``; none is fine, the files
    are then downloaded); for ``folder`` the folder of record files
    (required).  ``metadata``, ``dt`` [s] and ``units``: for ``folder``, a
    CSV table of more columns and the time step and units of the files that
    state none (see :func:`folder_table`).
    """
    if kind not in KINDS:
        raise StickslipError(f"unknown collection {kind!r}; known: {', '.join(KINDS)}")
    if kind == "slammer":
        folder = folder or os.environ.get(SLAMMER_DIR_ENV) or None
        if folder is not None and not Path(folder).is_dir():
            raise StickslipError(f"{folder}: the SLAMMER folder does not exist")
        return Collection("slammer", slammer_table(), Path(folder) if folder else None)
    if kind == "pyslammer":
        return Collection("pyslammer", pyslammer_table())
    if folder is None:
        raise StickslipError("a folder collection needs its folder (collection_study.folder or --folder)")
    table, skipped = folder_table(Path(folder), metadata, dt, units)
    return Collection("folder", table, Path(folder), skipped)


def study_collection(settings: Mapping) -> Collection:
    """The collection of a study's resolved settings: ``kind``, ``folder``, ``metadata``, ``dt`` and ``units``."""
    return load_collection(settings["kind"], settings.get("folder"), settings.get("metadata"), settings.get("dt"),
                           settings.get("units"))


@functools.cache
def slammer_table() -> pd.DataFrame:
    """The SLAMMER library's manifest (package data ``stickslip/data/slammer_library.csv``), indexed by id."""
    with importlib.resources.files("stickslip").joinpath("data", "slammer_library.csv").open("rb") as handle:
        table = pd.read_csv(handle, dtype={"sha256": str, "record": str, "file": str, "site_class": str})
    table = table.assign(format="slammer_1col", units="g", listed_pga=table["slammer_pga"])
    return table.set_index("id", drop=False)[list(COLUMNS)]


@functools.cache
def _pyslammer_samples() -> dict:
    """pyslammer's sample motions, file name -> package resource (empty when pyslammer is not installed)."""
    from stickslip.records.acquire import pyslammer_samples_folder

    folder = pyslammer_samples_folder()
    if folder is None:
        return {}
    return {item.name: item for item in folder.iterdir() if item.name.endswith(".csv")}


#: A pyslammer sample's file name: ``<Event>_<year>_<record>.csv``.
_SAMPLE_NAME = re.compile(r"^(?P<event>.+)_(?P<year>\d{4})_(?P<record>[^_]+)\.csv$")


def pyslammer_table() -> pd.DataFrame:
    """The table of pyslammer's sample motions, with the SLAMMER metadata of the same record.

    A sample is matched to the SLAMMER record of the same year, record name
    and event name start (``Kobe_1995_TAK-090.csv`` to ``Kobe, Japan 1995/TAK-090``); the
    file itself (a time column added) is the pyslammer one, and its SHA-256
    is the installed file's, pinned by the environment's lock.
    """
    library = slammer_table()
    rows = []
    for name, resource in sorted(_pyslammer_samples().items()):
        match = _SAMPLE_NAME.match(name)
        if match is None:
            continue
        same = library[(library["year"] == int(match["year"])) & (library["record"] == match["record"])
                       & library["event"].map(record_id).str.startswith(record_id(match["event"]))]
        row = same.iloc[0].to_dict() if len(same) == 1 else {"event": match["event"].replace("_", " "),
                                                              "year": int(match["year"]), "record": match["record"]}
        data = resource.read_bytes()
        row.update(id=record_id("pyslammer", name.removesuffix(".csv")), file=name, sha256=sha256_hex(data),
                   bytes=len(data), format="time_acc_csv", units="g")
        rows.append(row)
    return _indexed(pd.DataFrame(rows, columns=list(COLUMNS)), "pyslammer")


#: Columns of a folder collection's metadata table that say how to read a file (beside ``file``).
READ_COLUMNS = ("format", "dt", "units")


def folder_table(folder: Path, metadata: str | Path | None = None, dt: float | None = None,
                 units: str | None = None) -> tuple[pd.DataFrame, tuple[SkippedFile, ...]]:
    """The table of every record file under ``folder``, from the files, the manifests and ``metadata``; and the others.

    Every file (any depth, hidden ones and the ``metadata`` table left out)
    is read as ``stickslip`` reads any file: its format detected, its time
    step and units from the file, else from a manifest we ship that knows its
    SHA-256 (a SLAMMER library file then also takes the library's metadata),
    else from the file's row of ``metadata`` (columns ``format``, ``dt`` [s],
    ``units``), else from ``dt`` [s] and ``units``, the folder's defaults.
    A record file that cannot be read keeps a row, with the reader's reason
    in the column ``unreadable`` (empty for the others): the study reports it
    and goes on.  A file that is no record file (:func:`not_a_record`: a
    README, notes, an image, a table of metadata) gets no row: it is among
    the skipped files returned beside the table, with the reason.
    ``metadata`` is a CSV table with a column ``file`` (the path relative to
    ``folder``) and any of the columns of :data:`COLUMNS` (``mw``,
    ``rupture_distance`` [km], ``vs30`` [m/s], ``site_class``, …) or others,
    which are kept.
    """
    if not folder.is_dir():
        raise StickslipError(f"{folder}: the collection folder does not exist")
    if dt is not None and not (math.isfinite(dt) and dt > 0):
        raise StickslipError(f"{folder}: the folder's time step must be a positive number of seconds, got {dt!r}")
    if units is not None:
        normalize_units(units, f"{folder}: the folder's units")
    table_path = Path(metadata).resolve() if metadata is not None else None
    files = sorted(path for path in folder.rglob("*") if path.is_file() and path.resolve() != table_path
                   and not any(part.startswith(".") for part in path.relative_to(folder).parts))
    if not files:
        raise StickslipError(f"{folder}: no file in the collection folder")
    relative = {path: path.relative_to(folder).as_posix() for path in files}
    extra = _metadata_rows(table_path, set(relative.values())) if table_path is not None else {}
    library = slammer_table().drop_duplicates("sha256").set_index("sha256", drop=False)
    found = [_folder_row(path, name, extra.get(name, {}), dt, units, library) for path, name in relative.items()]
    skipped = tuple(item for item in found if isinstance(item, SkippedFile))
    rows = [item for item in found if not isinstance(item, SkippedFile)]
    if not rows:
        raise StickslipError(f"{folder}: no record file in the collection folder; skipped "
                             + "; ".join(f"{item.file} ({item.reason})" for item in skipped[:5])
                             + (f" and {len(skipped) - 5} more" if len(skipped) > 5 else ""))
    table = pd.DataFrame(rows, columns=[*COLUMNS, "unreadable"])
    if extra:
        table = _with_metadata(table, extra)
    return _indexed(table, str(folder)), skipped


def _folder_row(path: Path, relative: str, given: dict, dt: float | None, units: str | None,
                library: pd.DataFrame) -> dict | SkippedFile:
    """The row of the file ``path`` (``relative`` to its folder) in a folder collection's table (see :func:`folder_table`).

    A file that cannot be read and is no record file (:func:`not_a_record`) is a :class:`SkippedFile` instead.
    """
    row = {"id": record_id(Path(relative).with_suffix("").as_posix()), "record": path.stem, "file": relative,
           "event": "", "station": "", "format": given.get("format") or "", "units": "", "unreadable": ""}
    data = None
    try:
        data = read_file_bytes(path)
        row.update(sha256=sha256_hex(data), bytes=len(data))
        record = read_record_bytes(data, str(path), format=given.get("format") or None, dt=_number(given.get("dt")),
                                   units=given.get("units") or None, default_dt=dt, default_units=units)
    except RecordError as error:
        reason = None if given else not_a_record(path.name, data)  # a file the metadata table lists is a record
        if reason is not None:
            return SkippedFile(relative, reason)
        how = r"the folder's \1 (collection_study.\1, or --\1 of records list) or a \1 column of the metadata table"
        return {**row, "unreadable": ARGUMENT_IN_MESSAGE.sub(how, error.problem)}
    if row["sha256"] in library.index:  # a SLAMMER library file: the library's metadata, our own id and file
        row.update({name: value for name, value in library.loc[row["sha256"]].items()
                    if name in MANIFEST_COLUMNS and name not in ("id", "file", "record")})
    year = re.search(r"(1[89]\d\d|20\d\d)", record.meta.event)
    row.update(event=record.meta.event or row["event"], station=record.meta.station or row["station"],
               record=record.meta.component or path.stem, dt=record.dt, format=record.meta.format,
               units=record.meta.units, listed_pga=float(np.max(np.abs(record.acceleration))) / STANDARD_GRAVITY)
    if not pd.notna(row.get("year")) and year:
        row["year"] = int(year.group(1))
    return row


#: Name endings (lower case) of record files whatever their content: one that cannot be read is a record with a
#: problem, never skipped.  PEER's ``.AT2``, and the NetCDF records that ``stickslip records fetch`` writes.
RECORD_SUFFIXES = (".at2", ".nc")

#: The first bytes of files that are never records, and what each is.
_BINARY_KINDS = {b"\x89PNG": "a PNG image", b"\xff\xd8\xff": "a JPEG image", b"GIF8": "a GIF image",
                 b"%PDF": "a PDF document", b"PK\x03\x04": "a ZIP archive (or a spreadsheet, a document)",
                 b"II*\x00": "a TIFF image", b"MM\x00*": "a TIFF image"}

#: Lines of a text file looked at to decide whether it holds rows of values.
_LINES_LOOKED_AT = 2000


def not_a_record(name: str, data: bytes | None) -> str | None:
    """Why a file named ``name`` whose bytes are ``data`` is no record file; None when it is one (read or not).

    Called for a file the readers refused (``data`` None: its bytes could
    not be read, and only its name can tell).  By its name first: the
    ``.part`` file of an unfinished write is none; a ``.AT2`` or ``.nc`` file
    (:data:`RECORD_SUFFIXES`) is a record file that could not be read,
    whatever it holds (an AT2 with a broken header stays a rejected record
    with the reader's reason).  Then by its content: text whose
    lines are mostly rows of numbers (values, with a header above them or
    not: a headerless file without its time step, say) is a record file too.
    Anything else is not: binary content (an image, a PDF, a spreadsheet),
    an empty file, or text without rows of numbers (a README, notes, a table
    of metadata whose rows start with a file name).
    """
    if name.endswith(".part"):
        return "the temporary .part file of an unfinished write"
    if data is None or name.lower().endswith(RECORD_SUFFIXES):
        return None
    kind = next((kind for start, kind in _BINARY_KINDS.items() if data.startswith(start)), None)
    if kind is not None:
        return kind
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        text = data.decode("utf-16", errors="replace")
    elif b"\x00" in data:
        return "binary data, not text"
    else:
        text = data.decode("utf-8", errors="replace")
    lines = [line.strip() for line in text.splitlines()[:_LINES_LOOKED_AT] if line.strip()]
    if not lines:
        return "an empty file"
    uncommented = [line for line in lines if not line.startswith("#")]  # a CSV record's comments
    numeric = sum(all(NUMBER.fullmatch(field) for field in line.replace(",", " ").replace(";", " ").split())
                  for line in uncommented)
    if 2 * numeric > len(uncommented):
        return None
    titles = [title.strip().strip('"').lower() for title in re.split(r"[,;\t]", lines[0])]
    if "file" in titles and len(titles) > 1:
        return ("a table with a column 'file', as the folder's metadata table has, which collection_study.metadata "
                "or --metadata of records list names")
    return "text without rows of numbers"


def _number(value) -> float | None:
    """A table cell as a number, ``None`` when empty."""
    return None if value in (None, "") or value != value else float(value)


def _metadata_rows(path: Path, files: set[str]) -> dict[str, dict]:
    """The rows of a folder collection's metadata table ``path``, keyed by ``file``, one of ``files`` (relative paths)."""
    rows = read_csv_rows(path)
    if not rows or "file" not in rows[0]:
        raise StickslipError(f"{path}: the metadata table needs a column 'file' (path relative to the folder)")
    keyed = {row["file"]: row for row in rows}
    unknown = sorted(set(keyed) - files)
    if unknown:
        raise StickslipError(f"{path}: no such file in the collection folder: {', '.join(unknown[:5])}")
    for name, row in keyed.items():
        try:
            _number(row.get("dt"))
        except ValueError:
            raise StickslipError(f"{path}: file {name}: dt {row['dt']!r} is not a number of seconds") from None
    return keyed


def _with_metadata(table: pd.DataFrame, rows: dict[str, dict]) -> pd.DataFrame:
    """``table`` with the columns of the metadata ``rows`` (keyed by ``file``) filled in or added.

    The columns that said how to read a file (:data:`READ_COLUMNS`) were used
    by the reader; the table keeps what it read.
    """
    extra = pd.DataFrame(list(rows.values())).set_index("file").drop(columns=list(READ_COLUMNS), errors="ignore")
    table = table.set_index("file", drop=False)
    for column in extra.columns:
        values = extra[column].replace("", np.nan)
        numeric = pd.to_numeric(values, errors="coerce")
        values = numeric if numeric.notna().sum() == values.notna().sum() else values
        if column in table.columns:
            table[column] = values.reindex(table.index).combine_first(table[column])
        else:
            table[column] = values.reindex(table.index)
    return table.reset_index(drop=True)


def _indexed(table: pd.DataFrame, where: str) -> pd.DataFrame:
    twice = duplicated_ids(table["id"])
    if twice:
        files = table[table["id"].isin(twice)]["file"].tolist()
        raise StickslipError(f"{where}: files with the same record id {', '.join(twice)}: {', '.join(files)}")
    return table.set_index("id", drop=False)


def _record(data: bytes, location: str, record_id: str, row: pd.Series, g: float) -> Record:
    """Read ``data`` as the record ``record_id`` of ``row``, its SHA-256 checked, values in g converted with ``g`` [m/s²].

    A file that its collection found unreadable (a folder collection's column
    ``unreadable``) is refused with that reason.
    """
    if row.get("unreadable"):
        raise RecordError(location, row["unreadable"])
    sha256 = sha256_hex(data)
    if isinstance(row["sha256"], str) and sha256 != row["sha256"]:
        raise RecordError(location, f"SHA-256 {sha256} is not that of record {record_id} ({row['sha256']}): "
                                    "the file was changed or is another record")
    dt = None if FORMATS[row["format"]].states_dt else float(row["dt"])
    record = read_record_bytes(data, location, format=row["format"], dt=dt, units=row["units"], manifest={}, g=g)
    meta = RecordMeta(record_id=record_id, event=str(row["event"]), station=str(row["station"] or ""),
                      component=str(row["record"]), source=location, sha256=sha256, units=record.meta.units,
                      format=record.meta.format, gravity=record.meta.gravity)
    return Record(record.acceleration, record.dt, meta)


def _download(row: pd.Series, cache_dir: str | Path | None) -> tuple[bytes, str]:
    """The bytes of a SLAMMER library file from the source repository, checked by pooch, and their URL."""
    import pooch
    import requests

    from stickslip.records.acquire import DOWNLOAD_TIMEOUT

    url = download_url(row["file"], os.environ.get(MIRROR_ENV) or DEFAULT_MIRROR)
    folder = Path(cache_dir) if cache_dir is not None else Path(pooch.os_cache("stickslip")) / "slammer"
    try:
        event, name = row["file"].split("/")
        path = pooch.retrieve(url, known_hash=f"sha256:{row['sha256']}", fname=name, path=folder / event,
                              downloader=pooch.HTTPDownloader(progressbar=False, timeout=DOWNLOAD_TIMEOUT))
    except ValueError:
        raise RecordError(url, f"the downloaded file is not the SLAMMER library's {row['file']} "
                               f"(SHA-256 {row['sha256']} expected)") from None
    except (requests.RequestException, OSError) as error:
        raise RecordNotFoundError(f"{row['id']} ({row['file']}): download {url} failed "
                                  f"({type(error).__name__})") from None
    return read_file_bytes(path), url



def selected_ids(settings: dict, filters: dict | None) -> tuple[list[str], list[str]]:
    """The ids of a study's collection that ``filters`` keep: (those here or to download, those not here).

    ``settings`` has the collection's ``kind``, ``folder``, ``metadata`` and
    ``download`` (the workflow's resolved ``collection_study``).
    """
    source = study_collection(settings)
    chosen = source.select(RecordFilter.from_mapping(filters))
    if settings.get("download") and chosen.kind == "slammer":
        return chosen.ids, []
    here = set(chosen.local_ids())
    return [i for i in chosen.ids if i in here], [i for i in chosen.ids if i not in here]
