"""Acquisition of a manifest record: local folder, pySLAMMER package data, then download.

The sources are tried in this order (see ``docs/records.md``):

1. the local records folder (argument, else ``STICKSLIP_RECORDS_DIR``; the
   workflow passes its configuration's ``records_dir``): each of the record's
   known file names;
2. the sample motions shipped as package data by ``pyslammer``, located
   with :mod:`importlib.util` / :mod:`importlib.resources` machinery and read
   as data only (the package's code is never imported or run);
3. a download with SHA-256 check (:func:`pooch.retrieve`) from
   ``{mirror}/{repo}/{commit}/{path}``, where the mirror is the manifest's
   ``mirror_url`` or the environment variable ``STICKSLIP_MIRROR_URL``.

A file whose SHA-256 is not a known version of the record is an error unless
``accept_unknown`` is true.  Values in g are converted with the caller's ``g``
[m/s²] (the workflow's ``gravity``), which the stored record keeps.  A record that no source provides raises
:class:`~stickslip.errors.RecordNotFoundError`, saying how to obtain it.
"""

from __future__ import annotations

import contextlib
import importlib.util
import logging
import os
import re
from collections.abc import Iterator
from dataclasses import dataclass, replace
from importlib.resources.abc import Traversable
from pathlib import Path

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, RecordNotFoundError, StickslipError
from stickslip.records.manifest import RecordEntry, load_manifest
from stickslip.records.readers import read_file_bytes, read_record_bytes, sha256_hex
from stickslip.records.record import Record

#: Environment variable that overrides the manifest's download mirror.
MIRROR_ENV = "STICKSLIP_MIRROR_URL"

#: Seconds to wait for the download mirror to answer.
DOWNLOAD_TIMEOUT = 30.0

#: Environment variable naming the local records folder.
RECORDS_DIR_ENV = "STICKSLIP_RECORDS_DIR"


@dataclass(frozen=True)
class AcquiredRecord:
    """A record and where it came from.

    ``source_kind`` is ``"local"``, ``"pyslammer"`` or ``"download"``;
    ``location`` the file path, package resource or URL read.
    """

    record: Record
    source_kind: str
    location: str


def acquire(
    record_id: str,
    records_dir: str | Path | None = None,
    manifest: dict[str, RecordEntry] | None = None,
    accept_unknown: bool = False,
    cache_dir: str | Path | None = None,
    download: bool = True,
    g: float = STANDARD_GRAVITY,
) -> Record:
    """The record ``record_id`` of the manifest (acceleration in m/s², dt in s); see :func:`acquire_with_source`."""
    return acquire_with_source(record_id, records_dir, manifest, accept_unknown, cache_dir, download, g).record


def acquire_with_source(
    record_id: str,
    records_dir: str | Path | None = None,
    manifest: dict[str, RecordEntry] | None = None,
    accept_unknown: bool = False,
    cache_dir: str | Path | None = None,
    download: bool = True,
    g: float = STANDARD_GRAVITY,
) -> AcquiredRecord:
    """Find, check and read the record ``record_id``; say which source served it.

    Parameters
    ----------
    record_id:
        A manifest id (``stickslip/data/records.yaml``).
    records_dir:
        Local folder to search first; default ``STICKSLIP_RECORDS_DIR``
        (:func:`resolve_records_dir`).
    manifest:
        Loaded manifest; default ``stickslip/data/records.yaml``.
    accept_unknown:
        Accept a file whose SHA-256 is not a known version of the record.
    cache_dir:
        Download cache; default the user cache (``pooch.os_cache("stickslip")/records``).
    download:
        Try the download mirror when no local source has the record.
    g:
        Gravity [m/s²] that converts values in g into m/s².
    """
    manifest = load_manifest() if manifest is None else manifest
    if record_id not in manifest:
        raise StickslipError(f"unknown record id {record_id!r}; `stickslip records list` shows the known ids")
    entry = manifest[record_id]
    folder = resolve_records_dir(records_dir)
    tried: list[str] = []
    if folder is not None:
        for name in entry.local_files:
            path = folder / name
            if path.is_file():
                return _accept(entry, read_file_bytes(path), str(path), "local", manifest, accept_unknown, g)
        tried.append(f"no file {', '.join(entry.local_files)} in {folder}")
    else:
        tried.append(f"no records folder set (--records-dir or {RECORDS_DIR_ENV})")
    sample = pyslammer_sample(entry.pyslammer_sample) if entry.pyslammer_sample else None
    if sample is not None:
        return _accept(entry, sample.read_bytes(), f"pyslammer:{entry.pyslammer_sample}", "pyslammer", manifest,
                       accept_unknown, g)
    if entry.pyslammer_sample:
        tried.append(f"pyslammer sample {entry.pyslammer_sample} not installed")
    if entry.downloads and not download:
        tried.append("download not tried")
    if download:
        for source in entry.downloads:
            url = source.url(os.environ.get(MIRROR_ENV))
            data = _download(url, source.file, entry, cache_dir, accept_unknown, tried)
            if data is not None:
                return _accept(entry, data, url, "download", manifest, accept_unknown, g)
    raise RecordNotFoundError(_not_found_message(entry, tried))


def store_record(
    record_id: str,
    path: str | Path,
    records_dir: str | Path | None = None,
    manifest: dict[str, RecordEntry] | str | Path | None = None,
    accept_unknown: bool = False,
    cache_dir: str | Path | None = None,
    download: bool = True,
    missing_ok: bool = True,
    g: float = STANDARD_GRAVITY,
) -> str:
    """Acquire ``record_id`` and store it as NetCDF at ``path``; a record no source has is stored as missing.

    The acquisition stage of the workflow (and ``stickslip records fetch``).
    Returns a line saying what was stored: ``"<path> (<source>: <location>)"``
    or ``"<id>: MISSING: <what was tried and how to obtain it>"``.  Any other
    problem (a checksum mismatch, an unreadable file) raises, as in :func:`acquire`, and so
    does a missing record when ``missing_ok`` is false.  ``manifest`` is a loaded
    manifest or the path of one (default ``stickslip/data/records.yaml``); ``g``
    [m/s²] converts values in g (the stored record keeps it).
    """
    from stickslip.records.netcdf import write_missing_record, write_record

    manifest = manifest if isinstance(manifest, dict) else load_manifest(manifest)
    try:
        acquired = acquire_with_source(record_id, records_dir, manifest, accept_unknown, cache_dir, download, g)
    except RecordNotFoundError as error:
        if not missing_ok:
            raise
        write_missing_record(record_id, str(error), path, _description(manifest[record_id]))
        return f"{record_id}: MISSING: {error}"
    write_record(acquired.record, path, _description(manifest[record_id]))
    return f"{path}  ({acquired.source_kind}: {acquired.location})"


def _description(entry: RecordEntry) -> dict:
    """What the manifest says of a record beyond its samples (stored with it)."""
    return {"event": entry.event, "year": entry.year, "mw": entry.mw, "station": entry.station,
            "component": entry.component}


def resolve_records_dir(records_dir: str | Path | None = None) -> Path | None:
    """The local records folder: ``records_dir``, else ``STICKSLIP_RECORDS_DIR``, else none.

    The workflow passes its configuration's ``records_dir`` (which the
    environment variable overrides there too); the library reads no
    configuration file of its own.
    """
    if records_dir is not None:
        return Path(records_dir)
    if os.environ.get(RECORDS_DIR_ENV):
        return Path(os.environ[RECORDS_DIR_ENV])
    return None


def pyslammer_sample(name: str) -> Traversable | None:
    """The pyslammer sample motion ``name`` as package data, or ``None`` if pyslammer or the file is absent."""
    folder = pyslammer_samples_folder()
    resource = folder / name if folder is not None else None
    return resource if resource is not None and resource.is_file() else None


def pyslammer_samples_folder() -> Traversable | None:
    """pyslammer's ``sample_ground_motions`` package data folder, or ``None`` if pyslammer is absent.

    The package is located without importing it (its ``__init__`` would run
    its code); the folder is then reached through the loader's resource
    reader, the machinery behind :func:`importlib.resources.files`.
    """
    spec = importlib.util.find_spec("pyslammer")
    if spec is None or spec.loader is None or not hasattr(spec.loader, "get_resource_reader"):
        return None
    reader = spec.loader.get_resource_reader(spec.name)
    if reader is None:
        return None
    folder = reader.files() / "sample_ground_motions"
    return folder if folder.is_dir() else None


def available_source(entry: RecordEntry, records_dir: Path | None) -> str:
    """Where :func:`acquire` would look first with success (by file presence only, no checksum, no network)."""
    if records_dir is not None:
        for name in entry.local_files:
            if (records_dir / name).is_file():
                return f"local {name}"
    if entry.pyslammer_sample and pyslammer_sample(entry.pyslammer_sample) is not None:
        return f"pyslammer {entry.pyslammer_sample}"
    if entry.downloads:
        return "download"
    return "missing"


def _accept(
    entry: RecordEntry, data: bytes, location: str, kind: str, manifest: dict, accept_unknown: bool, g: float
) -> AcquiredRecord:
    sha256 = sha256_hex(data)
    known = entry.version_for(sha256) is not None
    if not known and not accept_unknown:
        raise RecordError(location, _unknown_version_message(entry, sha256))
    record = read_record_bytes(data, location, dt=None if known else entry.dt, manifest=manifest, g=g)
    if record.meta.record_id != entry.id:  # an unknown version, or a version shared with another record
        record = Record(record.acceleration, record.dt, replace(record.meta, record_id=entry.id))
    return AcquiredRecord(record, kind, location)


def _unknown_version_message(entry: RecordEntry, sha256: str) -> str:
    expected = ", ".join(entry.known_sha256) or "none (no version is known)"
    return (
        f"SHA-256 {sha256} is not a known version of record {entry.id}; expected one of: {expected}. "
        "Pass --accept-unknown (accept_unknown=True) to use it anyway"
    )


@contextlib.contextmanager
def _quiet_pooch() -> Iterator[None]:
    """Keep pooch's "Downloading ..." log lines off stderr."""
    import pooch

    logger = pooch.get_logger()
    level = logger.level
    logger.setLevel(logging.WARNING)
    try:
        yield
    finally:
        logger.setLevel(level)


def _download(
    url: str, file_name: str, entry: RecordEntry, cache_dir: str | Path | None, accept_unknown: bool, tried: list[str]
) -> bytes | None:
    """The bytes at ``url`` (cached), or ``None`` after noting the failure in ``tried``.

    A file whose hash matches no known version raises :class:`RecordError`
    unless ``accept_unknown``.
    """
    import pooch
    import requests

    version = next(v for v in entry.versions if v.file == file_name)
    folder = Path(cache_dir) if cache_dir is not None else Path(pooch.os_cache("stickslip")) / "records"
    known_hash = None if accept_unknown else f"sha256:{version.sha256}"
    try:
        with _quiet_pooch():
            path = pooch.retrieve(
                url,
                known_hash=known_hash,
                fname=file_name,
                path=folder,
                downloader=pooch.HTTPDownloader(progressbar=False, timeout=DOWNLOAD_TIMEOUT),
            )
    except ValueError as error:  # pooch's hash mismatch; the bad file is not kept
        found = next((h for h in re.findall(r"[0-9a-f]{64}", str(error)) if h != version.sha256), "unknown")
        raise RecordError(url, _unknown_version_message(entry, found)) from None
    except (requests.RequestException, OSError) as error:
        tried.append(f"download {url} failed ({type(error).__name__})")
        return None
    return read_file_bytes(path)


def _not_found_message(entry: RecordEntry, tried: list[str]) -> str:
    how = entry.obtain or (
        f"put one of {', '.join(entry.local_files)} in the records folder "
        f"(--records-dir, {RECORDS_DIR_ENV}, or records_dir in the workflow's config/config.yaml)"
    )
    return f"record {entry.id} not found ({'; '.join(tried)}). How to obtain it: {how}"
