"""Readers for ground-motion record files.

Formats (see ``docs/records.md``):

``peer_at2``
    PEER AT2: four header lines (NGA-West1 "PEER STRONG MOTION DATABASE
    RECORD. PROCESSING BY PACIFIC ENGINEERING." or NGA-West2 "PEER NGA STRONG
    MOTION DATABASE RECORD"); line 2 names event, station and component, line
    3 the units ("UNITS OF G"), line 4 holds ``NPTS=…, DT=… SEC`` (or the older
    ``7818 0.0050 NPTS, DT``).  The values follow, several per line, possibly
    in Fortran E or D format, possibly glued by fixed-width output, possibly
    separated by commas.  Time step from the header.
``slammer_1col``
    USGS SLAMMER library file: one value per line, in g, no header.  The time
    step comes from a manifest we ship when the file's SHA-256 is known there
    (``config/records.yaml``, then the SLAMMER library's own manifest,
    :mod:`stickslip.records.library`), else from the ``dt`` argument.
``time_acc_csv``
    pySLAMMER sample motion: ``#`` comment lines (or one ``time,acc`` header
    row), then ``time,acc`` rows in g.  Time step from the time column; units
    from a column title such as ``Acceleration (g's)``; a title naming units
    stickslip does not know is an error.
``two_column``
    Generic text with time [s] and acceleration per line, separated by blanks
    or commas, optionally below one header row; the units must be given.

Every file may be UTF-8 (with or without a byte-order mark) or Latin-1, with
LF, CRLF or CR line ends and a DOS end-of-file byte (Ctrl-Z).  Only regular
files are read, up to :func:`stickslip.limits.max_file_size` bytes.

Every reader returns a :class:`~stickslip.records.record.Record` with the
acceleration in m/s² (values in g are multiplied by
:data:`~stickslip.constants.STANDARD_GRAVITY` = 9.81 m/s²) and the time step
in s, all finite.  Every problem with a file raises one
:class:`~stickslip.errors.RecordError` that names the file, the line where
there is one, and what is wrong.  A time step outside
:data:`USUAL_TIME_STEPS` gives a :class:`~stickslip.errors.StickslipWarning`,
one outside :data:`POSSIBLE_TIME_STEPS` is an error; so is a PGA outside
:data:`POSSIBLE_PGA` (no ground motion, or none on Earth), and one above
:data:`UNUSUAL_PGA` gives a warning.
"""

from __future__ import annotations

import functools
import hashlib
import math
import os
import re
import stat
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, StickslipError, StickslipWarning
from stickslip.limits import check_memory, format_size, max_file_size
from stickslip.records.library import LIBRARY_MANIFEST, library_file
from stickslip.records.manifest import DEFAULT_MANIFEST, find_version, load_manifest, may_know
from stickslip.records.numbers import NUMBER, compiled_conversion, line_of_value, parse_numbers
from stickslip.records.record import Record, RecordMeta

#: The reader's arguments as its messages name them (``pass dt= in seconds``), for a caller
#: that takes them under other names to rename them (``--dt`` on the command line).
ARGUMENT_IN_MESSAGE = re.compile(r"\b(dt|units|format)=(?=[\s),]|$)")

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
    "m/s/s": "m/s2",
    "m/sec2": "m/s2",
    "m/sec^2": "m/s2",
    "m/sec/sec": "m/s2",
    "mps2": "m/s2",
    "cm/s2": "cm/s2",
    "cm/s^2": "cm/s2",
    "cm/s**2": "cm/s2",
    "cm/s²": "cm/s2",
    "cm/s/s": "cm/s2",
    "cm/sec2": "cm/s2",
    "cm/sec^2": "cm/s2",
    "cm/sec/sec": "cm/s2",
    "gal": "cm/s2",
}

#: Units a format implies when neither the file, the caller nor the manifest says.
FORMAT_UNITS = {"slammer_1col": "g", "time_acc_csv": "g"}

#: Relative tolerance on the spacing of a time column written in double precision.
TIME_STEP_RTOL = 1e-6

#: How far [fraction of dt] a time of a time column may lie from the uniform grid through its first and last
#: times: printing jitter (steps of 0.004996 s in a 0.005 s record) is accepted, a skipped or repeated sample
#: (a whole step off) is refused.
TIME_JITTER = 0.01

#: Time steps [s] of real strong-motion records; one outside gives a warning (units of ms?).
USUAL_TIME_STEPS = (1e-4, 1.0)

#: Time steps [s] that any digitised ground motion can have; one outside is an error.  No accelerograph
#: samples at a megahertz, and samples ten seconds apart cannot describe shaking: either is a unit mistake.
POSSIBLE_TIME_STEPS = (1e-6, 10.0)

#: PGA [g] a record can have: below, the file holds no ground motion (every value is zero, subnormal or
#: under a micro-g, finer than any accelerograph resolves); above, none recorded on Earth comes near
#: (the largest are about 4 g): the values are in other units than read.  Either is an error.
POSSIBLE_PGA = (1e-6, 100.0)

#: PGA [g] above every ground motion recorded so far; a larger one gives a warning (units?).
UNUSUAL_PGA = 5.0

#: Bytes of memory that parsing takes per byte of file (its text, an ASCII copy, the values).
READ_BYTES_PER_BYTE = 16

#: Bytes asked for by each read after the first (which asks for the file's size) [bytes].
READ_CHUNK = 1 << 20

#: Most samples an AT2 header may announce (a record of 100 million samples is not a record).
MAX_NPTS = 100_000_000

_AT2_NPTS_DT_LINE = re.compile(r"NPTS.*DT|DT.*NPTS", re.IGNORECASE)
_AT2_NPTS = re.compile(r"NPTS\s*=\s*([^\s,]*)", re.IGNORECASE)
#: A whole number of samples, possibly written as a decimal with a zero fraction (``18000.0``).
_WHOLE_NUMBER = re.compile(r"([0-9]+)(?:\.0*)?")
#: A comma between two values written with a decimal point (``-.1831E-02, .1827E-02``), or after one at a
#: line end: the only commas an AT2 data block may hold (``0,0123`` would be a decimal comma).
_SEPARATING_COMMA = re.compile(r"\.[0-9]*(?:[EeDd][+-]?[0-9]+)?[ \t]*(,)(?=[ \t]*(?:[+-]?[0-9]*\.[0-9]|\n|$))")
_AT2_DT = re.compile(r"DT\s*=\s*([^\s,]*)", re.IGNORECASE)
_AT2_OLD_NPTS_DT = re.compile(r"^\s*(\S+)\s+(\S+)\s+NPTS\s*,\s*DT", re.IGNORECASE)
_AT2_UNITS = re.compile(r"UNITS\s+OF\s+([^\s,.]+(?:\.[^\s,.]+)?)", re.IGNORECASE)
_AT2_TITLE = re.compile(r"PEER.*(DATABASE|RECORD)", re.IGNORECASE)
_TRAILING_DATE = re.compile(r"\s+\d{1,2}/\d{1,2}/\d{2,4}(\s+\d{3,4})?\s*$")
_TRAILING_NETWORK = re.compile(r"\s*\([^)]*\)\s*$")
#: The NPTS/DT line is among this many first lines.
_AT2_HEADER_SEARCH = 6
#: Units in a column title, as in pySLAMMER's ``# Time (s),Acceleration (g's)`` or a ``time,acc (g)`` row.
_ACCELERATION_TITLE_UNITS = re.compile(r"acc\w*\s*\(([^)]+)\)", re.IGNORECASE)
_WORD = re.compile(r"[A-Za-z]")
_CONTROL_BYTES = re.compile(rb"[\x00-\x08\x0e-\x19\x1b-\x1f]")
_NOT_CONTROL_BYTES = bytes(range(0x20, 0x100)) + b"\t\n\r\x0b\x0c\x1a"
#: Headers, comments and column titles are among this many first lines.
_HEAD_LINES = 64


@dataclass(frozen=True)
class _Parsed:
    """What a format reader found: values in the file's units and the time step [s]."""

    values: np.ndarray
    dt: float | None
    units: str | None
    event: str = ""
    station: str = ""
    component: str = ""


class _Text:
    """A decoded record file with ``\\n`` line ends: its text and its lines."""

    def __init__(self, text: str):
        self.text = text

    @functools.cached_property
    def lines(self) -> list[str]:
        """Every line, without line ends."""
        return self.text.split("\n")[:-1] if self.text.endswith("\n") else self.text.split("\n")

    @functools.cached_property
    def head(self) -> list[str]:
        """The first lines, where headers and comments are (all lines for a short file)."""
        end = -1
        for _ in range(_HEAD_LINES):
            end = self.text.find("\n", end + 1)
            if end < 0:
                return self.text.split("\n")
        return self.text[:end].split("\n")  # not split(…, _HEAD_LINES), which copies the rest of the text

    def body(self, first: int) -> str:
        """The text from line index ``first`` (0-based) on."""
        offset = 0
        for _ in range(first):
            offset = self.text.find("\n", offset) + 1
            if offset == 0:
                return ""
        return self.text[offset:]


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
        The file to read: a regular file of at most
        :func:`stickslip.limits.max_file_size` bytes (not a pipe, a device
        or the ``.part`` file of an interrupted write).
    format:
        One of :data:`KNOWN_FORMATS`; detected from the content when ``None``
        (or taken from the manifest when the file's SHA-256 is known).
    dt:
        Time step [s] for a file without one (``slammer_1col``) that no
        manifest knows.  The time step is the file's own (AT2 header, time
        column), else the one a manifest we ship gives for the file's SHA-256
        (``config/records.yaml``, then the SLAMMER library's), else ``dt``;
        a ``dt`` that differs from the file's or the manifest's is an error.
    units:
        Units of the values in the file (``g``, ``m/s2``, ``cm/s2`` or an
        alias); required for ``two_column``.  Units that differ from the
        ones the file's header (``peer_at2``, a ``time_acc_csv`` column title)
        or, for a known version, the manifest states are an error.
    manifest:
        Record manifest (see :func:`stickslip.records.manifest.load_manifest`);
        the default ``config/records.yaml`` when ``None``.  Gives the record
        id, and dt for a one-column file, when the file's SHA-256 is known.
        A file it does not know is looked up in the SLAMMER library's
        manifest (:func:`stickslip.records.library.library_file`), which
        gives the record id, event, station, component, dt and units.
    """
    path = Path(path)
    return read_record_bytes(read_file_bytes(path), str(path), format=format, dt=dt, units=units, manifest=manifest)


def read_records(
    paths: Sequence[str | Path],
    dts: Sequence[float | None] | None = None,
    format: str | None = None,
    units: str | None = None,
    manifest: dict | None = None,
) -> list[Record]:
    """:func:`read_record` of each of many files, with their numbers converted by a compiled kernel.

    The records, checks and errors are those of :func:`read_record`, file by
    file; ``dts`` gives each file's time step [s] (or ``None``), ``format``,
    ``units`` and ``manifest`` are shared.  The conversion is about three
    times as fast as ``np.loadtxt``, after loading the kernel once per process
    (about a second): worth it for a few hundred files and more.
    """
    paths = list(paths)
    dts = [None] * len(paths) if dts is None else list(dts)
    if len(dts) != len(paths):
        raise StickslipError(f"read_records: {len(paths)} files but {len(dts)} time steps")
    if manifest is None:
        manifest = load_manifest() if DEFAULT_MANIFEST.is_file() else {}
    with compiled_conversion():
        return [read_record(path, format=format, dt=dt, units=units, manifest=manifest) for path, dt in zip(paths, dts)]


def read_file_bytes(path: str | Path) -> bytes:
    """The bytes of the regular file ``path``; RecordError for anything else or a file over the size limit.

    A named pipe or a device is refused without reading from it (no hang,
    no endless ``/dev/zero``), and so is a ``.part`` file, which an
    interrupted write leaves behind.
    """
    path = Path(path)
    if path.name.endswith(".part"):
        raise RecordError(path, "is the temporary .part file of an unfinished write, not a record")
    limit = max_file_size()
    try:
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        raise RecordError(path, "file not found") from None
    except IsADirectoryError:
        raise RecordError(path, "is a directory, not a record file") from None
    except OSError as error:
        raise RecordError(path, f"cannot read the file ({error.strerror})") from None
    try:
        status = os.fstat(descriptor)
        mode = status.st_mode
        if stat.S_ISDIR(mode):
            raise RecordError(path, "is a directory, not a record file")
        if not stat.S_ISREG(mode):
            kind = (
                "a named pipe" if stat.S_ISFIFO(mode)
                else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
                else "a socket or other special file"
            )
            raise RecordError(path, f"is {kind}, not a regular file; stickslip reads record files only")
        with open(descriptor, "rb", buffering=0, closefd=False) as handle:
            # Each read gets a buffer of the size it asks for: the file's size first, not the limit's.
            data = handle.read(min(status.st_size, limit) + 1)
            while len(data) <= limit:  # up to the end, or one byte over the limit
                more = handle.read(min(limit + 1 - len(data), READ_CHUNK))
                if not more:
                    break
                data += more
    except OSError as error:
        raise RecordError(path, f"cannot read the file ({error.strerror})") from None
    finally:
        os.close(descriptor)
    if len(data) > limit:
        raise RecordError(
            path, f"file is larger than the limit of {format_size(limit)} for a record; raise it with --max-file-size"
        )
    return data


def read_record_bytes(
    data: bytes,
    source: str,
    format: str | None = None,
    dt: float | None = None,
    units: str | None = None,
    manifest: dict | None = None,
    *,
    default_dt: float | None = None,
    default_units: str | None = None,
) -> Record:
    """Parse the bytes ``data`` of a record file named ``source``; see :func:`read_record`.

    ``default_dt`` [s] and ``default_units`` serve only a file that states
    neither and that no manifest knows (a folder of headerless files): unlike
    ``dt`` and ``units``, they never contradict a file or a manifest.
    """
    check_memory(len(data) * READ_BYTES_PER_BYTE, f"reading {source} ({format_size(len(data))})")
    decoded = _decode(data, source)
    sha256 = sha256_hex(data)
    if manifest is None:  # parsed only when its text mentions the file
        manifest = load_manifest() if may_know(sha256, os.path.basename(source)) else {}
    known = _known_file(sha256, manifest)
    if format is None:
        format = known.format if known else detect_format(decoded.text, source)
    if format not in KNOWN_FORMATS:
        raise RecordError(source, f"unknown format {format!r}; known formats: {', '.join(KNOWN_FORMATS)}")
    parsed = _READERS[format](decoded, source)
    if parsed.values.size < 2:
        raise RecordError(source, f"only {parsed.values.size} value(s) read; a record needs at least 2 samples")
    if known is None:
        _check_known_length(source, parsed.values.size, manifest)
    step, dt_source = _time_step(parsed.dt, dt, known, format, source, default_dt)
    units = _units(parsed.units, units, known.units if known else None, format, source, known, default_units)
    with np.errstate(over="ignore"):  # an overflow is reported below, naming its line
        acceleration = parsed.values * UNIT_FACTORS[units]
    _check_finite(acceleration, parsed.values, decoded, format, source)
    _check_pga(acceleration, parsed.values, units, decoded, format, source)
    meta = RecordMeta(
        record_id=known.record_id if known else Path(source).stem,
        event=parsed.event or (known.event if known else ""),
        station=parsed.station or (known.station if known else ""),
        component=parsed.component or (known.component if known else ""),
        source=source,
        sha256=sha256,
        units=units,
        format=format,
        dt_source=dt_source,
    )
    return Record(acceleration=acceleration, dt=step, meta=meta)


@dataclass(frozen=True)
class _KnownFile:
    """A file that a manifest we ship knows by its SHA-256: what it says of the file, and which manifest it is
    (``manifest`` and ``which`` for messages, ``name`` for :attr:`RecordMeta.dt_source`)."""

    record_id: str
    event: str
    station: str
    component: str
    format: str
    dt: float | None
    units: str
    manifest: str
    which: str
    name: str

    def says(self, what: str) -> str:
        """``"<manifest> says <what> for <this file>"``, for messages."""
        return f"{self.manifest} says {what} for {self.which}"


def _known_file(sha256: str, manifest: dict) -> _KnownFile | None:
    """The file of this SHA-256 in the record manifest ``manifest``, else in the SLAMMER library's, or None."""
    known = find_version(sha256, manifest)
    if known is not None:
        entry, version = known
        return _KnownFile(entry.id, entry.event, entry.station, entry.component, version.format, version.dt,
                          version.units, "the manifest", f"this version of record {entry.id}",
                          "the record manifest config/records.yaml")
    found = library_file(sha256)
    if found is not None:
        return _KnownFile(found.record_id, found.event, found.station, found.component, found.format, found.dt,
                          found.units, LIBRARY_MANIFEST, f"this file (record {found.record_id})",
                          f"{LIBRARY_MANIFEST} (stickslip/data/slammer_library.csv)")
    return None


def _check_known_length(source: str, npts: int, manifest: dict) -> None:
    """A file named like a known version but with fewer samples is cut short."""
    name = os.path.basename(source)
    for entry in manifest.values():
        for version in entry.versions:
            if version.file == name and npts < version.npts:
                raise RecordError(
                    source,
                    f"{npts} samples read, but the known file {name} (record {entry.id}) has {version.npts}: "
                    "the file looks cut short (its SHA-256 is not a known version)",
                )


def _check_finite(acceleration: np.ndarray, values: np.ndarray, decoded: _Text, format: str, source: str) -> None:
    """Every acceleration must be finite in m/s² (a value like 1e400, or 1e308 g, is not)."""
    finite = np.isfinite(acceleration)
    if finite.all():
        return
    index = int(np.argmin(finite))
    first = _data_start(decoded, format, source) if format != "peer_at2" else _at2_header_end(decoded.head, source) + 1
    columns = 2 if format in ("time_acc_csv", "two_column") else 1
    line = line_of_value(decoded.body(first), first + 1, index * columns + columns - 1)
    problem = "is not a finite number" if not np.isfinite(values.flat[index]) else "overflows to infinity in m/s2"
    raise RecordError(source, f"line {line}: value {values.flat[index]:g} {problem}")


def _check_pga(acceleration: np.ndarray, values: np.ndarray, units: str, decoded: _Text, format: str,
               source: str) -> None:
    """The PGA must lie within :data:`POSSIBLE_PGA`; above :data:`UNUSUAL_PGA` it gives a warning."""
    index = int(np.argmax(np.abs(acceleration)))
    pga = float(abs(acceleration[index])) / STANDARD_GRAVITY  # [g]
    low, high = POSSIBLE_PGA
    if pga == 0.0:
        raise RecordError(source, "every acceleration is zero: the file holds no ground motion")
    if pga < low:
        raise RecordError(
            source, f"the largest value is {values[index]:.3g} {units}, a PGA of {pga:.3g} g, below the {low:g} g "
            "that an accelerograph resolves: the file holds no ground motion (are its values in other units?)")
    if pga <= UNUSUAL_PGA:
        return
    first = _data_start(decoded, format, source) if format != "peer_at2" else _at2_header_end(decoded.head, source) + 1
    columns = 2 if format in ("time_acc_csv", "two_column") else 1
    line = line_of_value(decoded.body(first), first + 1, index * columns + columns - 1)
    where = f"line {line}: value {values[index]:.6g} {units} is a PGA of {pga:.3g} g"
    if pga > high:
        raise RecordError(source, f"{where}, more than {high:g} g, which no ground motion comes near (the largest "
                                  "recorded are about 4 g): are the values in other units (units=)?")
    warnings.warn(f"{source}: {where}, more than any ground motion recorded (about 4 g); check the units",
                  StickslipWarning, stacklevel=4)


def _units(
    file_units: str | None,
    given_units: str | None,
    manifest_units: str | None,
    format: str,
    source: str,
    known: _KnownFile | None = None,
    default_units: str | None = None,
) -> str:
    """The canonical units of the values: the file's own, else the given ones, else the manifest's, the default
    ones or the format's.

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
                f"{known.says(f'units {normalize_units(manifest_units, source)}')} but units {given_units!r} were given",
            )
    units = next((value for value in (file_units, given_units, manifest_units, default_units, FORMAT_UNITS.get(format))
                  if value), None)
    if units is None:
        raise RecordError(source, f"units unknown for a {format} file; pass units= (g, m/s2 or cm/s2)")
    return normalize_units(units, source)


def _time_step(
    file_dt: float | None,
    given_dt: float | None,
    known: _KnownFile | None,
    format: str,
    source: str,
    default_dt: float | None = None,
) -> tuple[float, str]:
    """The time step [s] and where it came from: the file's own, else the manifest's, the given one or the default.

    A given dt that contradicts the file's or the manifest's is an error (it
    would change every energy and displacement); a time step outside
    :data:`POSSIBLE_TIME_STEPS` is an error, one outside :data:`USUAL_TIME_STEPS`
    gives a warning.
    """
    manifest_dt = known.dt if known is not None else None
    if file_dt is not None and given_dt is not None and not np.isclose(file_dt, given_dt, rtol=TIME_STEP_RTOL):
        raise RecordError(source, f"the file says dt = {file_dt:g} s but dt = {given_dt:g} s was given "
                                  "(leave dt= out for a file that states its own time step)")
    if (
        file_dt is None
        and manifest_dt is not None
        and given_dt is not None
        and not np.isclose(manifest_dt, given_dt, rtol=TIME_STEP_RTOL)
    ):
        raise RecordError(source, f"{known.says(f'dt = {manifest_dt:g} s')} but dt = {given_dt:g} s was given "
                                  "(leave dt= out for a file that a manifest knows)")
    if file_dt is not None:
        step, where = file_dt, "the file"
    elif manifest_dt is not None:
        step, where = manifest_dt, known.name
    elif given_dt is not None:
        step, where = given_dt, "given"
    elif default_dt is not None:
        step, where = default_dt, "the default for files without one"
    else:
        raise RecordError(source, f"no time step: a {format} file has none and no manifest knows this file; "
                                  "pass dt= in seconds")
    if not np.isfinite(step) or step <= 0.0:
        raise RecordError(source, f"time step must be positive, got dt = {step:g} s")
    low, high = POSSIBLE_TIME_STEPS
    if not low <= step <= high:
        raise RecordError(source, f"time step dt = {step:g} s ({where}) is outside the {low:g} to {high:g} s that "
                                  "any digitised ground motion has: is it in seconds?")
    low, high = USUAL_TIME_STEPS
    if not low <= step <= high:
        warnings.warn(
            f"{source}: time step dt = {step:g} s is outside the usual {low:g} to {high:g} s of strong-motion records; "
            "check that it is in seconds",
            StickslipWarning,
            stacklevel=3,
        )
    return float(step), where


def detect_format(text: str, source: str) -> str:
    """Guess the format of a record file from its decoded ``text``; RecordError if none fits."""
    lines = [line.rstrip("\r") for line in text.lstrip("\ufeff").split("\n", _HEAD_LINES)[:_HEAD_LINES]]
    head = lines[:_AT2_HEADER_SEARCH]
    if (head and "PEER" in head[0].upper()) or any(_AT2_NPTS_DT_LINE.search(line) for line in head):
        return "peer_at2"
    start = _first_data_line(lines)
    if start is None:
        lines = text.lstrip("\ufeff").splitlines()
        start = _first_data_line(lines)
    if start is not None:
        fields = _fields(lines[start])
        if all(NUMBER.fullmatch(field) for field in fields):
            has_titles = any(line.lstrip().startswith("#") for line in lines[:start]) or _header_row(lines, start)
            if len(fields) == 2:
                return "time_acc_csv" if has_titles and "," in lines[start] else "two_column"
            if len(fields) == 1 and not has_titles:
                return "slammer_1col"
    raise RecordError(
        source,
        "unknown format: not a PEER AT2 file, nor one or two numeric columns; "
        f"known formats: {', '.join(KNOWN_FORMATS)}",
    )


def _decode(data: bytes, source: str) -> _Text:
    """The text of a record file: UTF-8 (or Latin-1), a DOS end-of-file byte dropped, ``\\n`` line ends."""
    data = data.rstrip(b"\x1a")
    if not data.strip():
        raise RecordError(source, "empty file")
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise RecordError(source, "UTF-16 text; save the record as UTF-8 or ASCII text")
    control = _CONTROL_BYTES.search(data) if data.translate(None, _NOT_CONTROL_BYTES) else None
    if control:
        kind = "contains NUL bytes" if b"\x00" in data else f"control byte 0x{control.group()[0]:02x} at byte {control.start()}"
        raise RecordError(source, f"binary file ({kind}); expected a text record")
    try:
        text = data.decode("ascii" if data.isascii() else "utf-8")
    except UnicodeDecodeError:
        text = data.decode("latin-1")  # header text from older Windows tools; numbers are ASCII either way
    text = text.removeprefix("\ufeff")
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    return _Text(text)


def _fields(line: str) -> list[str]:
    return line.replace(",", " ").split()


def _first_data_line(lines: list[str]) -> int | None:
    """Index of the first line that is neither blank nor a ``#`` comment nor a header row."""
    for index, line in enumerate(lines):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if _is_title_row(stripped) and index + 1 < len(lines):
            continue
        return index
    return None


def _is_title_row(line: str) -> bool:
    """A row of column titles such as ``time,acc`` or ``Time (s)  Acceleration (g)``: words, no numbers."""
    fields = _fields(line)
    return len(fields) >= 2 and all(_WORD.search(field) for field in fields) and not any(NUMBER.fullmatch(f) for f in fields)


def _header_row(lines: list[str], start: int) -> bool:
    return any(_is_title_row(line.strip()) for line in lines[:start] if not line.lstrip().startswith("#"))


def _data_start(decoded: _Text, format: str, source: str) -> int:
    """Index of the first data line of a column format (after comments and at most one header row)."""
    lines = decoded.head
    start = _first_data_line(lines)
    if start is None:
        lines = decoded.lines
        start = _first_data_line(lines)
    if start is None:
        raise RecordError(source, "no values in the file")
    rows = [index for index in range(start) if lines[index].strip() and not lines[index].lstrip().startswith("#")]
    if len(rows) > 1 or (rows and format == "slammer_1col"):
        raise RecordError(source, f"line {rows[-1] + 1}: non-numeric line {lines[rows[-1]].strip()[:40]!r}")
    return start


def _at2_header_end(lines: list[str], source: str) -> int:
    """Index of the NPTS/DT line of an AT2 header."""
    for index, line in enumerate(lines[:_AT2_HEADER_SEARCH]):
        if _AT2_NPTS_DT_LINE.search(line):
            return index
    raise RecordError(source, "PEER AT2 header has no 'NPTS=…, DT=…' line among its first lines")


def _at2_npts_dt(line: str, number: int, source: str) -> tuple[int, float]:
    """NPTS and DT [s] from the header line ``line`` (line ``number``), each checked."""
    old = _AT2_OLD_NPTS_DT.match(line)
    npts_match, dt_match = _AT2_NPTS.search(line), _AT2_DT.search(line)
    npts_text = old.group(1) if old else npts_match.group(1) if npts_match else None
    dt_text = old.group(2) if old else dt_match.group(1) if dt_match else None
    if npts_text is None or dt_text is None:
        raise RecordError(source, f"line {number}: AT2 header line has no {'NPTS=' if npts_text is None else 'DT='} value")
    whole = _WHOLE_NUMBER.fullmatch(npts_text)
    if not whole or not 2 <= int(whole.group(1)) <= MAX_NPTS:
        raise RecordError(
            source, f"line {number}: NPTS={npts_text!r} is not a whole number of samples between 2 and {MAX_NPTS:,}"
        )
    dt = float(dt_text.translate(str.maketrans("Dd", "Ee"))) if NUMBER.fullmatch(dt_text) else None
    if dt is None or not (np.isfinite(dt) and dt > 0.0):
        raise RecordError(source, f"line {number}: DT={dt_text!r} is not a positive number of seconds")
    return int(whole.group(1)), dt


def _read_at2(decoded: _Text, source: str) -> _Parsed:
    """PEER AT2 (NGA-West1 or NGA-West2 header): NPTS, DT, units and description from the header."""
    lines = decoded.head
    header_end = _at2_header_end(lines, source)
    npts, header_dt = _at2_npts_dt(lines[header_end], header_end + 1, source)
    body = decoded.body(header_end + 1)
    _check_separating_commas(body, header_end + 2, source)
    values = parse_numbers(body, header_end + 2, source, commas=True)
    if values.size != npts:
        raise RecordError(
            source,
            f"header says NPTS={npts} but {values.size} values were read "
            f"({'truncated file' if values.size < npts else 'extra values'})",
        )
    header = lines[:header_end]
    header_units = _at2_units(header, source)
    event, station, component = _at2_description(_at2_description_line(header))
    return _Parsed(values, header_dt, header_units, event, station, component)


def _check_separating_commas(body: str, first_line: int, source: str) -> None:
    """Commas in an AT2 data block may only separate values (``1.0E-02, 2.0E-02``), never be a decimal comma."""
    commas = body.count(",")
    if not commas:
        return
    separating = {match.start(1) for match in _SEPARATING_COMMA.finditer(body)}
    if len(separating) == commas:
        return
    bad = next(index for index, char in enumerate(body) if char == "," and index not in separating)
    start, end = body.rfind("\n", 0, bad) + 1, body.find("\n", bad)
    line = body[start:end if end >= 0 else None].strip()
    raise RecordError(source, f"line {first_line + body.count(chr(10), 0, bad)}: a comma that does not separate two "
                              f"values written with a decimal point (a decimal comma?) in {line[:60]!r}")


def _at2_description_line(header: list[str]) -> str:
    """The event/station/component line: the one just before the units line (or the NPTS line), if not the title."""
    units_index = next((index for index, line in enumerate(header) if _AT2_UNITS.search(line)), len(header))
    if units_index == 0 or _AT2_TITLE.search(header[units_index - 1]):
        return ""
    return header[units_index - 1]


def _at2_units(header: list[str], source: str) -> str | None:
    for line in header:
        match = _AT2_UNITS.search(line)
        if match:
            return normalize_units(match.group(1), source)
    return None


def _at2_description(line: str) -> tuple[str, str, str]:
    """(event, station, component) from an AT2 header's description line."""
    parts = [part.strip() for part in line.split(",") if part.strip()]
    if len(parts) < 3:
        return (parts[0] if parts else "", "", "")
    event = _TRAILING_DATE.sub("", parts[0])
    component = _TRAILING_NETWORK.sub("", parts[-1])
    return event, parts[-2], component


def _read_one_column(decoded: _Text, source: str) -> _Parsed:
    """One value per line, no header: no time step or units in the file.

    A blank line among the values is skipped with a warning naming it: in a
    file whose only clock is the line count, a lost value would shift every
    later sample.
    """
    start = _data_start(decoded, "slammer_1col", source)
    body = decoded.body(start)
    blank = [index for index, line in enumerate(body.rstrip().split("\n")) if not line.strip()]
    if blank:
        more = f" ({len(blank)} blank lines in all)" if len(blank) > 1 else ""
        warnings.warn(f"{source}: line {start + 1 + blank[0]}: blank line among the values skipped{more}; "
                      "a one-column file has no time column, so a missing value would shift every later sample",
                      StickslipWarning, stacklevel=4)
    return _Parsed(parse_numbers(body, start + 1, source, columns=1)[:, 0], None, None)


def _read_time_column(decoded: _Text, source: str, format: str = "two_column") -> _Parsed:
    """Time [s] and acceleration columns; dt from the time column, which must be uniform.

    The steps are judged against the precision of the written times: the
    last decimal written, and float32 rounding for a column written in
    single precision.  Units from a column title (``Acceleration (g)``).
    """
    start = _data_start(decoded, format, source)
    body = decoded.body(start)
    table = parse_numbers(body, start + 1, source, columns=2, commas=True)
    time = table[:, 0]
    dt = _uniform_step(time, start, source, _written_resolution(body)) if time.size >= 2 else None
    return _Parsed(table[:, 1], dt, _title_units(decoded.head[:start], source))


def _uniform_step(time: np.ndarray, start: int, source: str, rounding: float) -> float:
    """The step [s] of a uniform time column (first value on line index ``start``), as briefly as its precision allows.

    ``rounding`` [s] is half a unit of the last decimal the times are written with.

    Each time may differ from the uniform grid through its endpoints by
    :data:`TIME_JITTER` of a step, or by the precision the times are written
    with where that is more (a unit of their last decimal, float32 rounding
    and a unit of the seventh significant digit for a single-precision
    column), and each step from the median step by twice that.
    """
    steps = np.diff(time)
    if not np.all(steps > 0.0):
        bad = int(np.argmax(~(steps > 0.0)))
        raise RecordError(
            source,
            f"line {start + bad + 2}: time step must be positive: t={time[bad + 1]:g} s follows t={time[bad]:g} s "
            f"(sample {bad + 2})",
        )
    exact = (time[-1] - time[0]) / (time.size - 1)
    largest = float(np.max(np.abs(time)))
    if rounding and abs(exact / (2.0 * rounding) - round(exact / (2.0 * rounding))) < 1e-6:
        rounding = 0.0  # a step such as 0.02 written with 2 decimals is written exactly
    precision = max(  # how far a written time may lie from the grid through the first and last times when printed
        TIME_STEP_RTOL * exact,
        # single precision, printed with its 7 significant digits (%.7g, %.6E): float32 rounding and a unit
        # of the seventh digit, so that 6.072001 among 6.068 and 6.076 is read as 6.072
        2.0 * float(np.spacing(np.float32(largest))) + 10.0 ** (math.floor(math.log10(largest)) - 6),
        2.02 * rounding + 8.0 * float(np.spacing(largest)),
    )
    tolerance = max(precision, TIME_JITTER * exact)  # ... and when printed with jitter
    typical = float(np.median(steps))
    off = np.abs(steps - typical)
    drift = np.abs(time - (time[0] + exact * np.arange(time.size)))
    if not np.any(off > 2.0 * tolerance) and np.any(drift > tolerance):
        i = int(np.argmax(drift > tolerance))
        raise RecordError(
            source,
            f"line {start + i + 1}: t={time[i]:g} s lies {drift[i] / exact:.1%} of a step off the uniform grid of "
            f"step {exact:.6g} s through the first and last times (up to {TIME_JITTER:.0%} is taken as rounding)",
        )
    if np.any(off > 2.0 * tolerance):
        i = int(np.argmax(off > 2.0 * tolerance))
        step_text, typical_text = _distinct(steps[i], typical)
        before, after = _distinct(time[i], time[i + 1])
        raise RecordError(
            source,
            f"line {start + i + 2}: non-uniform time step: {step_text} s between t={before} s and t={after} s, "
            f"where the other steps are {typical_text} s (up to {TIME_JITTER:.0%} of a step off the grid is taken "
            "as rounding)",
        )
    for digits in range(1, 18):
        rounded = float(f"{exact:.{digits}g}")  # 0.02, not 0.019999999999999997
        if abs(rounded - exact) * (time.size - 1) <= precision:
            return rounded
    return float(exact)


def _written_resolution(body: str) -> float:
    """Half a unit of the last digit the last times are written with: 0.0005 s for ``12.345``, 0.005 s for ``1.2345E+02``.

    Of the last 20 times: without exponents, the one with the most decimals counts (``19.666666``,
    not ``20.0``, whose zeros were dropped); in E notation the coarsest, at the largest exponent
    (``1.00002E+02``, not ``9.99975E+01``).
    """
    times = [line.replace(",", " ").split()[0] for line in body.rstrip().rsplit("\n", 20)[-20:] if line.strip()]
    resolutions = [0.5 * 10.0 ** _last_digit_power(time) for time in times]
    exponents = any(marker in time.upper() for time in times for marker in "ED")
    return max(resolutions) if exponents else min(resolutions)


def _last_digit_power(number: str) -> int:
    """The power of ten of the last digit of the written ``number``: -3 for ``12.345``, -3 for ``1.2345E+02``."""
    mantissa, marker, exponent = number.upper().replace("D", "E").partition("E")
    power = int(exponent) if marker and NUMBER.fullmatch(number) else 0
    return min(max(power - len(mantissa.partition(".")[2]), -300), 300)  # an absurd exponent is refused later


def _distinct(first: float, second: float) -> tuple[str, str]:
    """Two numbers written with just enough digits to tell them apart."""
    for digits in range(4, 18):
        a, b = f"{first:.{digits}g}", f"{second:.{digits}g}"
        if a != b:
            return a, b
    return f"{first:g}", f"{second:g}"


def _title_units(header: list[str], source: str) -> str | None:
    """The acceleration units a comment or header row names (``Acceleration (g's)``), or None.

    Units stickslip does not know are an error, not a guess.
    """
    for line in header:
        match = _ACCELERATION_TITLE_UNITS.search(line)
        if match:
            key = re.sub(r"\s+", "", match.group(1)).lower()
            if key not in UNIT_ALIASES:
                raise RecordError(
                    source,
                    f"the column title {match.group(0)!r} names units {match.group(1)!r} that stickslip does not know; "
                    "known units: g, m/s2, cm/s2 (convert the file, or pass units= and remove the title's units)",
                )
            return UNIT_ALIASES[key]
    return None


def _read_time_acc_csv(decoded: _Text, source: str) -> _Parsed:
    """pySLAMMER's time/acceleration CSV: as :func:`_read_time_column`."""
    return _read_time_column(decoded, source, "time_acc_csv")


_READERS = {
    "peer_at2": _read_at2,
    "slammer_1col": _read_one_column,
    "time_acc_csv": _read_time_acc_csv,
    "two_column": _read_time_column,
}
