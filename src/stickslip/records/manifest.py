"""The record manifest ``stickslip/data/records.yaml``: known records, their file versions and sources.

Each record has an id, descriptive metadata, the known versions of its file
(name, SHA-256, format, dt [s], npts, units), expected intensity measures for
a sanity check (PGA [m/s²], Arias intensity [m/s], significant duration [s],
each with a relative tolerance) and where to get it (local file names, a
pySLAMMER sample name, download locations, or an ``obtain`` text).  The
structure is checked with a JSON schema when the file is loaded.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import quote

from stickslip.errors import StickslipError
from stickslip.records.formats import FORMATS

#: The manifest read when no path is given: the one shipped with stickslip (package data).
DEFAULT_MANIFEST = Path(__file__).resolve().parents[1] / "data" / "records.yaml"

#: Measures that ``expected`` may list, with their units.
EXPECTED_MEASURES = {"pga": "m/s2", "arias_intensity": "m/s", "significant_duration": "s"}

_FORMATS = sorted(FORMATS)
_SHA256 = {"type": "string", "pattern": "^[0-9a-f]{64}$"}
_POSITIVE = {"type": "number", "exclusiveMinimum": 0}

#: JSON schema of the manifest file.
MANIFEST_SCHEMA = {
    "type": "object",
    "required": ["mirror_url", "records"],
    "additionalProperties": False,
    "properties": {
        "mirror_url": {"type": "string", "pattern": "^https?://"},
        "records": {
            "type": "array",
            "minItems": 1,
            "items": {
                "type": "object",
                "required": ["id", "event", "year", "station", "component", "versions", "sources"],
                "additionalProperties": False,
                "properties": {
                    "id": {"type": "string", "pattern": "^[a-z0-9_]+$"},
                    "event": {"type": "string"},
                    "year": {"type": "integer"},
                    "mw": {"type": ["number", "null"]},
                    "station": {"type": "string"},
                    "component": {"type": "string"},
                    "format": {"enum": [*_FORMATS, None]},
                    "units": {"enum": ["g", "m/s2", "cm/s2", None]},
                    "dt": {"oneOf": [_POSITIVE, {"type": "null"}]},
                    "versions": {
                        "type": "array",
                        "items": {
                            "type": "object",
                            "required": ["file", "sha256", "format", "npts", "units", "description"],
                            "additionalProperties": False,
                            "properties": {
                                "file": {"type": "string", "minLength": 1},
                                "sha256": _SHA256,
                                "format": {"enum": _FORMATS},
                                "dt": _POSITIVE,
                                "npts": {"type": "integer", "minimum": 2},
                                "units": {"enum": ["g", "m/s2", "cm/s2"]},
                                "description": {"type": "string"},
                            },
                        },
                    },
                    "expected": {
                        "type": "object",
                        "additionalProperties": False,
                        "properties": {
                            name: {
                                "type": "object",
                                "required": ["value", "rtol"],
                                "additionalProperties": False,
                                "properties": {"value": _POSITIVE, "rtol": _POSITIVE},
                            }
                            for name in EXPECTED_MEASURES
                        },
                    },
                    "sources": {
                        "type": "object",
                        "required": ["local"],
                        "additionalProperties": False,
                        "properties": {
                            "local": {"type": "array", "items": {"type": "string", "minLength": 1}},
                            "pyslammer": {"type": "string"},
                            "download": {
                                "type": "array",
                                "items": {
                                    "type": "object",
                                    "required": ["repo", "commit", "path", "file"],
                                    "additionalProperties": False,
                                    "properties": {
                                        "repo": {"type": "string", "pattern": "^[^/]+/[^/]+$"},
                                        "commit": {"type": "string", "pattern": "^[0-9a-f]{40}$"},
                                        "path": {"type": "string"},
                                        "file": {"type": "string"},
                                    },
                                },
                            },
                        },
                    },
                    "obtain": {"type": "string"},
                },
            },
        },
    },
}


@dataclass(frozen=True)
class RecordVersion:
    """One known file of a record.

    Attributes
    ----------
    file:
        File name (what to look for in a local records folder).
    sha256:
        SHA-256 of the file's bytes, hex.
    format:
        Reader format (a key of :data:`stickslip.records.formats.FORMATS`).
    dt:
        Time step [s] for a format without one in the file, else ``None``.
    npts:
        Number of samples.
    units:
        Units of the values in the file.
    description:
        Which processing / window this file is.
    """

    file: str
    sha256: str
    format: str
    dt: float | None
    npts: int
    units: str
    description: str


@dataclass(frozen=True)
class DownloadSource:
    """A file in a public git repository, fetched as ``{mirror}/{repo}/{commit}/{path}``.

    ``file`` is the version (local file name) it serves; ``mirror_url`` the
    default base URL (``raw.githubusercontent.com``), which the environment
    variable ``STICKSLIP_MIRROR_URL`` overrides in :mod:`stickslip.records.acquire`.
    """

    repo: str
    commit: str
    path: str
    file: str
    mirror_url: str

    def url(self, mirror_url: str | None = None) -> str:
        """The download URL under ``mirror_url`` (default: the manifest's)."""
        base = (mirror_url or self.mirror_url).rstrip("/")
        return f"{base}/{self.repo}/{self.commit}/{quote(self.path)}"


@dataclass(frozen=True)
class ExpectedMeasure:
    """An expected intensity measure (SI units, see :data:`EXPECTED_MEASURES`) and its relative tolerance."""

    value: float
    rtol: float

    def accepts(self, measured: float) -> bool:
        """True if ``measured`` is within ``rtol`` of the expected value."""
        return abs(measured - self.value) <= self.rtol * abs(self.value)


@dataclass(frozen=True)
class RecordEntry:
    """One record of the manifest.

    ``format`` and ``units`` are those of the preferred version (``None`` for
    a record with no known file); ``mw`` is the moment magnitude where known; ``dt`` [s] the time step for
    a format without one; ``expected`` maps measure names of
    :data:`EXPECTED_MEASURES` to :class:`ExpectedMeasure`; ``local_files``
    are the file names to look for in a records folder, in order of
    preference; ``pyslammer_sample`` a file of pyslammer's
    ``sample_ground_motions`` package data; ``obtain`` says how to get a
    record that no source holds.
    """

    id: str
    event: str
    year: int
    mw: float | None
    station: str
    component: str
    format: str | None
    units: str | None
    dt: float | None
    versions: tuple[RecordVersion, ...]
    expected: dict[str, ExpectedMeasure] = field(default_factory=dict)
    local_files: tuple[str, ...] = ()
    pyslammer_sample: str | None = None
    downloads: tuple[DownloadSource, ...] = ()
    obtain: str = ""

    @property
    def known_sha256(self) -> tuple[str, ...]:
        """SHA-256 of every known version."""
        return tuple(version.sha256 for version in self.versions)

    def version_for(self, sha256: str) -> RecordVersion | None:
        """The known version with this SHA-256, or ``None``."""
        return next((version for version in self.versions if version.sha256 == sha256), None)


def load_manifest(path: str | Path | None = None) -> dict[str, RecordEntry]:
    """Read and validate a manifest (default ``stickslip/data/records.yaml``); record id -> entry."""
    path = Path(path) if path is not None else DEFAULT_MANIFEST
    try:
        stamp = path.stat().st_mtime_ns
    except OSError as error:
        raise StickslipError(f"{path}: cannot read the record manifest ({error.strerror})") from None
    return _load_manifest_cached(path.resolve(), stamp)


@functools.lru_cache(maxsize=8)
def _load_manifest_cached(path: Path, stamp: int) -> dict[str, RecordEntry]:
    import jsonschema
    import yaml

    try:
        document = yaml.load(path.read_text(encoding="utf-8"), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    except (OSError, UnicodeDecodeError) as error:
        raise StickslipError(f"{path}: cannot read the record manifest ({error})") from None
    except yaml.YAMLError as error:
        raise StickslipError(f"{path}: record manifest is not valid YAML ({error})".replace("\n", " ")) from None
    try:
        jsonschema.validate(document, MANIFEST_SCHEMA)
    except jsonschema.ValidationError as error:
        where = "/".join(str(part) for part in error.absolute_path) or "top level"
        raise StickslipError(f"{path}: record manifest is invalid at {where}: {error.message}") from None
    entries = [_entry(item, document["mirror_url"], path) for item in document["records"]]
    manifest = {entry.id: entry for entry in entries}
    if len(manifest) != len(entries):
        duplicates = sorted({entry.id for entry in entries if sum(e.id == entry.id for e in entries) > 1})
        raise StickslipError(f"{path}: record manifest has duplicate ids: {', '.join(duplicates)}")
    return manifest


def _entry(item: dict, mirror_url: str, path: Path) -> RecordEntry:
    versions = tuple(
        RecordVersion(
            file=v["file"],
            sha256=v["sha256"],
            format=v["format"],
            dt=v.get("dt"),
            npts=v["npts"],
            units=v["units"],
            description=v["description"],
        )
        for v in item["versions"]
    )
    sources = item["sources"]
    downloads = tuple(DownloadSource(mirror_url=mirror_url, **d) for d in sources.get("download", []))
    version_files = {version.file for version in versions}
    unknown = [d.file for d in downloads if d.file not in version_files]
    if unknown:
        raise StickslipError(
            f"{path}: record manifest is invalid at {item['id']}: download file {unknown[0]!r} is not one of its versions"
        )
    for version in versions:
        if not FORMATS[version.format].states_dt and version.dt is None:
            raise StickslipError(
                f"{path}: record manifest is invalid at {item['id']}: version {version.file} "
                f"({version.format}) needs dt"
            )
    return RecordEntry(
        id=item["id"],
        event=item["event"],
        year=item["year"],
        mw=item.get("mw"),
        station=item["station"],
        component=item["component"],
        format=item.get("format"),
        units=item.get("units"),
        dt=item.get("dt"),
        versions=versions,
        expected={name: ExpectedMeasure(**spec) for name, spec in item.get("expected", {}).items()},
        local_files=tuple(sources["local"]),
        pyslammer_sample=sources.get("pyslammer"),
        downloads=downloads,
        obtain=item.get("obtain", ""),
    )


def may_know(sha256: str, file_name: str, path: str | Path | None = None) -> bool:
    """Whether the manifest ``path`` (default ``stickslip/data/records.yaml``) may describe a file: its text names the
    file's SHA-256 or its name.

    A cheap test (one read of the text, no YAML parsing or schema check), so that reading a file
    no manifest entry mentions costs nothing more; False when there is no manifest.
    """
    path = Path(path) if path is not None else DEFAULT_MANIFEST
    try:
        text = _manifest_text(path.resolve(), path.stat().st_mtime_ns)
    except OSError:
        return False
    return sha256 in text or (bool(file_name) and file_name in text)


@functools.lru_cache(maxsize=8)
def _manifest_text(path: Path, stamp: int) -> str:
    return path.read_text(encoding="utf-8", errors="replace")


def find_version(
    sha256: str, manifest: dict[str, RecordEntry] | None = None
) -> tuple[RecordEntry, RecordVersion] | None:
    """The record and version whose file has this SHA-256, or ``None``.

    ``manifest`` defaults to the manifest shipped with stickslip (:data:`DEFAULT_MANIFEST`).
    """
    if manifest is None:
        manifest = load_manifest()
    for entry in manifest.values():
        for version in entry.versions:
            if version.sha256 == sha256:
                return entry, version
    return None
