"""Readers for ground-motion record files.

Formats (see ``docs/records.md``):

``peer_at2``
    PEER AT2: four header lines (NGA-West1 "PEER STRONG MOTION DATABASE
    RECORD. PROCESSING BY PACIFIC ENGINEERING." or NGA-West2 "PEER NGA STRONG
    MOTION DATABASE RECORD"); line 2 names event, station and component, line
    3 the units ("UNITS OF G"), line 4 holds ``NPTS=…, DT=… SEC`` (or the older
    ``7818 0.0050 NPTS, DT``).  The values follow, several per line, possibly
    in Fortran E format.  Time step from the header.
``slammer_1col``
    USGS SLAMMER library file: one value per line, in g, no header.  The time
    step is an argument or comes from the manifest (``config/records.yaml``)
    when the file's SHA-256 is a known version.
``time_acc_csv``
    pySLAMMER sample motion: ``#`` comment lines, then ``time,acc`` rows in g
    (a UTF-8 byte-order mark and CRLF line ends are accepted).  Time step from
    the time column; units from a comment's column title such as
    ``Acceleration (g's)``.
``two_column``
    Generic text with time [s] and acceleration per line, separated by blanks
    or commas; the units must be given.

Every reader returns a :class:`~stickslip.records.record.Record` with the
acceleration in m/s² (values in g are multiplied by
:data:`~stickslip.constants.STANDARD_GRAVITY` = 9.81 m/s²) and the time step
in s.  Every problem with a file raises one :class:`~stickslip.errors.RecordError`
that names the file and says what is wrong.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError
from stickslip.records.manifest import find_version
from stickslip.records.record import Record, RecordMeta

#: The formats :func:`read_record` understands.
KNOWN_FORMATS = ("peer_at2", "slammer_1col", "time_acc_csv", "two_column")

#: Canonical units -> factor to m/s², with g = 9.81 m/s².
UNIT_FACTORS = {"g": STANDARD_GRAVITY, "m/s2": 1.0, "cm/s2": 0.01}

#: Accepted spellings (lower case, blanks removed) -> canonical units.
UNIT_ALIASES = {
    "g": "g",
    "g's": "g",
    "gs": "g",
    "m/s2": "m/s2",
    "m/s^2": "m/s2",
    "m/s**2": "m/s2",
    "m/s²": "m/s2",
    "m/sec2": "m/s2",
    "m/sec^2": "m/s2",
    "mps2": "m/s2",
    "cm/s2": "cm/s2",
    "cm/s^2": "cm/s2",
    "cm/s**2": "cm/s2",
    "cm/s²": "cm/s2",
    "cm/sec2": "cm/s2",
    "cm/sec^2": "cm/s2",
    "gal": "cm/s2",
}

#: Units a format implies when neither the file, the caller nor the manifest says.
FORMAT_UNITS = {"slammer_1col": "g", "time_acc_csv": "g"}

#: Relative tolerance on the spacing of a time column.
TIME_STEP_RTOL = 1e-6

_AT2_NPTS_DT = re.compile(r"NPTS\s*=\s*(\d+)\s*,?\s*DT\s*=\s*([-+0-9.EeDd]+)", re.IGNORECASE)
_AT2_OLD_NPTS_DT = re.compile(r"^\s*(\d+)\s+([-+0-9.EeDd]+)\s+NPTS\s*,\s*DT", re.IGNORECASE)
_AT2_UNITS = re.compile(r"UNITS\s+OF\s+([^\s,.]+(?:\.[^\s,.]+)?)", re.IGNORECASE)
_TRAILING_DATE = re.compile(r"\s+\d{1,2}/\d{1,2}/\d{2,4}(\s+\d{3,4})?\s*$")
_TRAILING_NETWORK = re.compile(r"\s*\([^)]*\)\s*$")
_AT2_HEADER_LINES = 4
#: Units in a column title of a comment line, as in pySLAMMER's ``# Time (s),Acceleration (g's)``.
_CSV_ACCELERATION_UNITS = re.compile(r"acc\w*\s*\(([^)]+)\)", re.IGNORECASE)


@dataclass(frozen=True)
class _Parsed:
    """What a format reader found: values in the file's units and the time step [s]."""

    values: np.ndarray
    dt: float | None
    units: str | None
    event: str = ""
    station: str = ""
    component: str = ""


def normalize_units(units: str, source: str | Path) -> str:
    """The canonical name (``g``, ``m/s2`` or ``cm/s2``) of ``units``; RecordError if unknown."""
    key = re.sub(r"\s+", "", str(units)).lower()
    if key not in UNIT_ALIASES:
        raise RecordError(source, f"unknown units {units!r}; known units: g, m/s2, cm/s2 (aliases: gal, m/s^2, cm/s^2)")
    return UNIT_ALIASES[key]


def sha256_hex(data: bytes) -> str:
    """SHA-256 of ``data``, lower-case hex."""
    return hashlib.sha256(data).hexdigest()


def read_record(
    path: str | Path,
    format: str | None = None,
    dt: float | None = None,
    units: str | None = None,
    manifest: dict | None = None,
) -> Record:
    """Read a ground-motion record file into a :class:`Record` (acceleration in m/s², dt in s).

    Parameters
    ----------
    path:
        The file to read.
    format:
        One of :data:`KNOWN_FORMATS`; detected from the content when ``None``
        (or taken from the manifest when the file's SHA-256 is known).
    dt:
        Time step [s] for a file without one (``slammer_1col``).  A ``dt``
        that differs from the one the file (or, for a known version, the
        manifest) states is an error.
    units:
        Units of the values in the file (``g``, ``m/s2``, ``cm/s2`` or an
        alias); required for ``two_column``.  Units that differ from the
        ones the file's header (``peer_at2``, a ``time_acc_csv`` column title)
        or, for a known version, the manifest states are an error.
    manifest:
        Record manifest (see :func:`stickslip.records.manifest.load_manifest`);
        the default ``config/records.yaml`` when ``None``.  Gives the record
        id, and dt for a one-column file, when the file's SHA-256 is known.
    """
    path = Path(path)
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise RecordError(path, "file not found") from None
    except IsADirectoryError:
        raise RecordError(path, "is a directory, not a record file") from None
    except OSError as error:
        raise RecordError(path, f"cannot read the file ({error.strerror})") from None
    return read_record_bytes(data, str(path), format=format, dt=dt, units=units, manifest=manifest)


def read_record_bytes(
    data: bytes,
    source: str,
    format: str | None = None,
    dt: float | None = None,
    units: str | None = None,
    manifest: dict | None = None,
) -> Record:
    """Parse the bytes ``data`` of a record file named ``source``; see :func:`read_record`."""
    text = _decode(data, source)
    sha256 = sha256_hex(data)
    known = find_version(sha256, manifest)
    entry, version = known if known else (None, None)
    if format is None:
        format = version.format if version else detect_format(text, source)
    if format not in KNOWN_FORMATS:
        raise RecordError(source, f"unknown format {format!r}; known formats: {', '.join(KNOWN_FORMATS)}")
    lines = text.splitlines()
    parsed = _READERS[format](lines, source)
    if parsed.values.size < 2:
        raise RecordError(source, f"only {parsed.values.size} value(s) read; a record needs at least 2 samples")
    _check_finite(parsed.values, lines, source)
    step = _time_step(parsed.dt, dt, version.dt if version else None, format, source, entry.id if entry else None)
    units = _units(parsed.units, units, version.units if version else None, format, source, entry.id if entry else None)
    meta = RecordMeta(
        record_id=entry.id if entry else Path(source).stem,
        event=parsed.event or (entry.event if entry else ""),
        station=parsed.station or (entry.station if entry else ""),
        component=parsed.component or (entry.component if entry else ""),
        source=source,
        sha256=sha256,
        units=units,
        format=format,
    )
    return Record(acceleration=parsed.values * UNIT_FACTORS[units], dt=step, meta=meta)


def _units(
    file_units: str | None,
    given_units: str | None,
    manifest_units: str | None,
    format: str,
    source: str,
    record_id: str | None = None,
) -> str:
    """The canonical units of the values: the file's own, else the given ones, else the manifest's or the format's.

    Given units that contradict the file's or the manifest's are an error
    (the same units under another spelling are fine).
    """
    if given_units is not None:
        given = normalize_units(given_units, source)
        if file_units is not None and given != file_units:
            raise RecordError(source, f"the file says units {file_units} but units {given_units!r} were given")
        if file_units is None and manifest_units is not None and given != normalize_units(manifest_units, source):
            raise RecordError(
                source,
                f"the manifest says units {normalize_units(manifest_units, source)} for this version of record "
                f"{record_id} but units {given_units!r} were given",
            )
    units = next((value for value in (file_units, given_units, manifest_units, FORMAT_UNITS.get(format)) if value), None)
    if units is None:
        raise RecordError(source, f"units unknown for a {format} file; pass units (--units g, m/s2 or cm/s2)")
    return normalize_units(units, source)


def _time_step(
    file_dt: float | None,
    given_dt: float | None,
    manifest_dt: float | None,
    format: str,
    source: str,
    record_id: str | None = None,
) -> float:
    """The time step [s]: the file's own, else the given one, else the manifest's.

    A given dt that contradicts the file's or the manifest's is an error.
    """
    if file_dt is not None and given_dt is not None and not np.isclose(file_dt, given_dt, rtol=TIME_STEP_RTOL):
        raise RecordError(source, f"the file says dt = {file_dt:g} s but dt = {given_dt:g} s was given")
    if (
        file_dt is None
        and manifest_dt is not None
        and given_dt is not None
        and not np.isclose(manifest_dt, given_dt, rtol=TIME_STEP_RTOL)
    ):
        raise RecordError(
            source,
            f"the manifest says dt = {manifest_dt:g} s for this version of record {record_id} "
            f"but dt = {given_dt:g} s was given",
        )
    step = next((value for value in (file_dt, given_dt, manifest_dt) if value is not None), None)
    if step is None:
        raise RecordError(source, f"no time step: a {format} file has none; pass dt (--dt) in seconds")
    if not np.isfinite(step) or step <= 0.0:
        raise RecordError(source, f"time step must be positive, got dt = {step:g} s")
    return float(step)


def detect_format(text: str, source: str) -> str:
    """Guess the format of a record file from its decoded ``text``; RecordError if none fits."""
    head = text.lstrip("\ufeff").splitlines()[:6]
    if any("PEER" in line.upper() for line in head[:1]) or any(
        _AT2_NPTS_DT.search(line) or _AT2_OLD_NPTS_DT.search(line) for line in head
    ):
        return "peer_at2"
    data_lines = [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    has_comments = any(line.lstrip().startswith("#") for line in head)
    if data_lines:
        fields = _split_fields(data_lines[0])
        if _all_numbers(fields):
            if len(fields) == 2:
                return "time_acc_csv" if has_comments and "," in data_lines[0] else "two_column"
            if len(fields) == 1:
                return "slammer_1col"
    raise RecordError(
        source,
        "unknown format: not a PEER AT2 file, nor one or two numeric columns; "
        f"known formats: {', '.join(KNOWN_FORMATS)}",
    )


def _decode(data: bytes, source: str) -> str:
    if not data.strip():
        raise RecordError(source, "empty file")
    if b"\x00" in data:
        raise RecordError(source, "binary file (contains NUL bytes); expected a text record")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        raise RecordError(source, f"binary file (not UTF-8 text at byte {error.start}); expected a text record") from None
    return text.removeprefix("\ufeff")


def _split_fields(line: str) -> list[str]:
    return line.replace(",", " ").split()


def _all_numbers(fields: list[str]) -> bool:
    try:
        [_to_float(field) for field in fields]
    except ValueError:
        return False
    return bool(fields)


def _parse_block(lines: list[str], first: int, source: str, columns: int | None) -> np.ndarray:
    """Numbers in ``lines[first:]`` (blank and ``#`` lines skipped).

    With ``columns`` set, every data line must hold that many fields and the
    result has that many columns; otherwise lines may hold any number of values.
    """
    numbered = [(number, line) for number, line in enumerate(lines[first:], start=first + 1) if line.strip()]
    numbered = [(number, line) for number, line in numbered if not line.lstrip().startswith("#")]
    tokens = " ".join(line for _, line in numbered).replace(",", " ").split()
    if columns is not None and len(tokens) != columns * len(numbered):
        for number, line in numbered:
            count = len(_split_fields(line))
            if count != columns:
                raise RecordError(source, f"line {number}: expected {columns} value(s), found {count}")
    try:
        values = np.array(tokens, dtype=np.float64)
    except ValueError:
        values = _parse_slowly(numbered, source)
    return values.reshape(-1, columns) if columns else values


def _to_float(token: str) -> float:
    """A number, with a Fortran ``D`` exponent read as ``E``."""
    return float(token.replace("D", "E").replace("d", "e"))


def _parse_slowly(numbered: list[tuple[int, str]], source: str) -> np.ndarray:
    """Parse token by token (Fortran ``D`` exponents); name the line of the first bad token."""
    values = []
    for number, line in numbered:
        for field in _split_fields(line):
            try:
                values.append(_to_float(field))
            except ValueError:
                raise RecordError(source, f"line {number}: non-numeric value {field!r}") from None
    return np.array(values, dtype=np.float64)


def _check_finite(values: np.ndarray, lines: list[str], source: str) -> None:
    if np.all(np.isfinite(values)):
        return
    for number, line in enumerate(lines, start=1):
        for field in _split_fields(line):
            if field.lower().lstrip("+-") in {"nan", "inf", "infinity"}:
                raise RecordError(source, f"line {number}: value {field!r} is not a finite number")
    raise RecordError(source, "values are not all finite numbers (NaN or infinity)")


def _read_at2(lines: list[str], source: str) -> _Parsed:
    """PEER AT2 (NGA-West1 or NGA-West2 header): NPTS, DT, units and description from the header."""
    header_end = None
    for index, line in enumerate(lines[:_AT2_HEADER_LINES + 2]):
        match = _AT2_NPTS_DT.search(line) or _AT2_OLD_NPTS_DT.search(line)
        if match:
            header_end = index
            break
    if header_end is None:
        raise RecordError(source, "PEER AT2 header has no 'NPTS=…, DT=…' line among its first lines")
    npts = int(match.group(1))
    header_dt = _to_float(match.group(2))
    values = _parse_block(lines, header_end + 1, source, columns=None)
    if values.size != npts:
        raise RecordError(
            source,
            f"header says NPTS={npts} but {values.size} values were read "
            f"({'truncated file' if values.size < npts else 'extra values'})",
        )
    header_units = _at2_units(lines[:header_end], source)
    event, station, component = _at2_description(lines[1] if header_end > 1 else "")
    return _Parsed(values, header_dt, header_units, event, station, component)


def _at2_units(header: list[str], source: str) -> str | None:
    for line in header:
        match = _AT2_UNITS.search(line)
        if match:
            return normalize_units(match.group(1), source)
    return None


def _at2_description(line: str) -> tuple[str, str, str]:
    """(event, station, component) from an AT2 header's second line."""
    parts = [part.strip() for part in line.split(",") if part.strip()]
    if len(parts) < 3:
        return (parts[0] if parts else "", "", "")
    event = _TRAILING_DATE.sub("", parts[0])
    component = _TRAILING_NETWORK.sub("", parts[-1])
    return event, parts[-2], component


def _read_one_column(lines: list[str], source: str) -> _Parsed:
    """One value per line, no header: no time step or units in the file."""
    return _Parsed(_parse_block(lines, 0, source, columns=1)[:, 0], None, None)


def _read_time_column(lines: list[str], source: str) -> _Parsed:
    """Time [s] and acceleration columns; dt from the time column, which must be uniform."""
    table = _parse_block(lines, 0, source, columns=2)
    time = table[:, 0]
    if time.size < 2:
        return _Parsed(table[:, 1], None, None)
    steps = np.diff(time)
    dt = float(f"{(time[-1] - time[0]) / (time.size - 1):.10g}")  # 0.02, not 0.019999999999999997
    if dt <= 0.0 or np.any(steps <= 0.0):
        bad = int(np.argmax(steps <= 0.0))
        raise RecordError(
            source, f"time step must be positive: t={time[bad + 1]:g} s follows t={time[bad]:g} s (sample {bad + 2})"
        )
    uneven = np.flatnonzero(np.abs(steps - dt) > TIME_STEP_RTOL * dt)
    if uneven.size:
        first = int(uneven[0])
        raise RecordError(
            source,
            f"non-uniform time step: {steps[first]:g} s between t={time[first]:g} s and t={time[first + 1]:g} s, "
            f"mean step {dt:g} s",
        )
    return _Parsed(table[:, 1], dt, None)


def _read_time_acc_csv(lines: list[str], source: str) -> _Parsed:
    """pySLAMMER's time/acceleration CSV: as :func:`_read_time_column`, units from the column title."""
    parsed = _read_time_column(lines, source)
    return _Parsed(parsed.values, parsed.dt, _comment_units(lines, source))


def _comment_units(lines: list[str], source: str) -> str | None:
    """The acceleration units a ``#`` comment line names (``Acceleration (g's)``), or None."""
    for line in lines:
        stripped = line.lstrip()
        if stripped and not stripped.startswith("#"):
            break
        match = _CSV_ACCELERATION_UNITS.search(stripped)
        if match:
            key = re.sub(r"\s+", "", match.group(1)).lower()
            return UNIT_ALIASES.get(key)  # units it does not know stay unstated, as before
    return None


_READERS = {
    "peer_at2": _read_at2,
    "slammer_1col": _read_one_column,
    "time_acc_csv": _read_time_acc_csv,
    "two_column": _read_time_column,
}
