"""Readers for ground-motion record files.

The formats, how each is recognised and read, are the entries of
:mod:`stickslip.records.formats` (``docs/records.md``).

Every file may be UTF-8 (with or without a byte-order mark) or Latin-1, with
LF, CRLF or CR line ends and a DOS end-of-file byte (Ctrl-Z).  Only regular
files are read, up to :func:`stickslip.limits.max_file_size` bytes.

Every reader returns a :class:`~stickslip.records.record.Record` with the
acceleration in m/s² (values in g are multiplied by the caller's ``g``, by
default :data:`~stickslip.constants.STANDARD_GRAVITY` = 9.81 m/s²: one g per
call converts the records and the friction or yield levels) and the time step
in s, all finite.  Every problem with a file raises one
:class:`~stickslip.errors.RecordError` that names the file, the line where
there is one, and what is wrong.  A time step outside
:data:`USUAL_TIME_STEPS` gives a :class:`~stickslip.errors.StickslipWarning`,
one outside :data:`POSSIBLE_TIME_STEPS` is an error; so is a PGA outside
:data:`POSSIBLE_PGA` (no ground motion, or none on Earth), and one outside
:data:`~stickslip.records.plausibility.PLAUSIBLE_PGA` in the units assumed
(above 2 g already where neither the file, the user nor a manifest states them)
gives a warning that names the units that would make it plausible.
"""

from __future__ import annotations

import hashlib
import os
import re
import stat
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, StickslipError, StickslipWarning
from stickslip.limits import check_memory, format_size, max_file_size
from stickslip.records.formats import (
    FORMATS,
    TIME_STEP_RTOL,
    DecodedText,
    binary_format,
    detect_format,
    normalize_units,
    record_format,
    unit_factor,
)
from stickslip.records.library import LIBRARY_MANIFEST, library_file
from stickslip.records.manifest import (
    find_version,
    load_manifest,
    may_know,
)
from stickslip.records.numbers import compiled_conversion, line_of_value
from stickslip.records.plausibility import PLAUSIBLE_PGA, PLAUSIBLE_PGA_UNSTATED, other_readings, pga_doubt
from stickslip.records.record import Record, RecordMeta

#: The reader's arguments as its messages name them (``pass dt= in seconds``), for a caller
#: that takes them under other names to rename them (``--dt`` on the command line).
ARGUMENT_IN_MESSAGE = re.compile(r"\b(dt|units|format)=(?=[\s),]|$)")


#: Time steps [s] of real strong-motion records; one outside gives a warning (units of ms?).
USUAL_TIME_STEPS = (1e-4, 1.0)

#: Time steps [s] that any digitised ground motion can have; one outside is an error.  No accelerograph
#: samples at a megahertz, and samples ten seconds apart cannot describe shaking: either is a unit mistake.
POSSIBLE_TIME_STEPS = (1e-6, 10.0)

#: PGA [g] a record can have: below, the file holds no ground motion (every value is zero, subnormal or
#: under a micro-g, finer than any accelerograph resolves); above, none recorded on Earth comes near
#: (the largest are about 4 g): the values are in other units than read.  Either is an error.
POSSIBLE_PGA = (1e-6, 100.0)

#: Bytes of memory that parsing takes per byte of file (its text, an ASCII copy, the values).
READ_BYTES_PER_BYTE = 16

#: Bytes asked for by each read after the first (which asks for the file's size) [bytes].
READ_CHUNK = 1 << 20


_CONTROL_BYTES = re.compile(rb"[\x00-\x08\x0e-\x19\x1b-\x1f]")
_NOT_CONTROL_BYTES = bytes(range(0x20, 0x100)) + b"\t\n\r\x0b\x0c\x1a"


def sha256_hex(data: bytes) -> str:
    """SHA-256 of ``data``, lower-case hex."""
    return hashlib.sha256(data).hexdigest()


def read_record(
    path: str | Path,
    format: str | None = None,
    dt: float | None = None,
    units: str | None = None,
    manifest: dict | None = None,
    *,
    g: float = STANDARD_GRAVITY,
    accept_zero: bool = False,
) -> Record:
    """Read a ground-motion record file into a :class:`Record` (acceleration in m/s², dt in s).

    Parameters
    ----------
    path:
        The file to read: a regular file of at most
        :func:`stickslip.limits.max_file_size` bytes (not a pipe, a device
        or the ``.part`` file of an interrupted write).
    format:
        A key of :data:`stickslip.records.formats.FORMATS`; detected from the content when ``None``
        (or taken from the manifest when the file's SHA-256 is known).
    dt:
        Time step [s] for a file without one (``slammer_1col``) that no
        manifest knows.  The time step is the file's own (AT2 header, time
        column), else the one a manifest we ship gives for the file's SHA-256
        (``stickslip/data/records.yaml``, then the SLAMMER library's), else ``dt``;
        a ``dt`` that differs from the file's or the manifest's is an error.
    units:
        Units of the values in the file (``g``, ``m/s2``, ``cm/s2`` or an
        alias); required for ``two_column``.  Units that differ from the
        ones the file's header (``peer_at2``, a ``time_acc_csv`` column title)
        or, for a known version, the manifest states are an error.
    manifest:
        Record manifest (see :func:`stickslip.records.manifest.load_manifest`);
        the default ``stickslip/data/records.yaml`` when ``None``.  Gives the record
        id, and dt for a one-column file, when the file's SHA-256 is known.
        A file it does not know is looked up in the SLAMMER library's
        manifest (:func:`stickslip.records.library.library_file`), which
        gives the record id, event, station, component, dt and units.
    g:
        Gravity [m/s²] that converts values in g into m/s² (the command's
        ``--g``, the workflow's ``gravity``).  A stored record (``netcdf``)
        whose source was in g and was converted with another g is converted
        again with this one, and says so in its ``processing``.
    accept_zero:
        Accept a record whose values are all zero (the ground at rest: one
        component of a uniaxial test in a pair); refused otherwise, as a file
        that holds no ground motion.
    """
    path = Path(path)
    return read_record_bytes(read_file_bytes(path), str(path), format=format, dt=dt, units=units, manifest=manifest,
                             g=g, accept_zero=accept_zero)


def read_records(
    paths: Sequence[str | Path],
    dts: Sequence[float | None] | None = None,
    format: str | None = None,
    units: str | None = None,
    manifest: dict | None = None,
    *,
    g: float = STANDARD_GRAVITY,
) -> list[Record]:
    """:func:`read_record` of each of many files, with their numbers converted by a compiled kernel.

    The records, checks and errors are those of :func:`read_record`, file by
    file; ``dts`` gives each file's time step [s] (or ``None``), ``format``,
    ``units``, ``manifest`` and ``g`` [m/s²] are shared.  The conversion is about three
    times as fast as ``np.loadtxt``, after loading the kernel once per process
    (about a second): worth it for a few hundred files and more.
    """
    paths = list(paths)
    dts = [None] * len(paths) if dts is None else list(dts)
    if len(dts) != len(paths):
        raise StickslipError(f"read_records: {len(paths)} files but {len(dts)} time steps")
    if manifest is None:
        manifest = load_manifest()
    with compiled_conversion():
        return [read_record(path, format=format, dt=dt, units=units, manifest=manifest, g=g)
                for path, dt in zip(paths, dts)]


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
    g: float = STANDARD_GRAVITY,
    accept_zero: bool = False,
) -> Record:
    """Parse the bytes ``data`` of a record file named ``source``; see :func:`read_record`.

    ``default_dt`` [s] and ``default_units`` serve only a file that states
    neither and that no manifest knows (a folder of headerless files): unlike
    ``dt`` and ``units``, they never contradict a file or a manifest.
    """
    check_memory(len(data) * READ_BYTES_PER_BYTE, f"reading {source} ({format_size(len(data))})")
    sha256 = sha256_hex(data)
    binary = binary_format(data)
    if format is None and binary is not None:
        format = binary
    decoded = None if format is not None and record_format(format, source).binary else _decode(data, source)
    if manifest is None:  # parsed only when its text mentions the file
        manifest = load_manifest() if may_know(sha256, os.path.basename(source)) else {}
    known = _known_file(sha256, manifest)
    if format is None:
        format = known.format if known else detect_format(decoded.text, source)
    entry = record_format(format, source)
    parsed = entry.read(data if entry.binary else decoded, source)
    if parsed.values.size < 2:
        raise RecordError(source, f"only {parsed.values.size} value(s) read; a record needs at least 2 samples")
    if known is None:
        _check_known_length(source, parsed.values.size, manifest)
    step, dt_source = _time_step(parsed.dt, dt, known, format, source, default_dt)
    units, assumed = _units(parsed.units, units, known.units if known else None, format, source, known, default_units)
    with np.errstate(over="ignore"):  # an overflow is reported below, naming its line
        acceleration = parsed.values * unit_factor(units, g)
    where = _value_locator(decoded, entry, source)
    _check_finite(acceleration, parsed.values, where, source)
    if parsed.meta is not None:  # a stored record: the provenance of its source, in the call's g
        meta = _stored_meta(parsed.meta, source, g)
        if meta.gravity is not None and meta.gravity != parsed.meta.gravity:
            acceleration = acceleration * (meta.gravity / parsed.meta.gravity)
        _check_pga(acceleration, parsed.values, units, g, where, source, accept_zero, None)
        return Record(acceleration=acceleration, dt=step, meta=meta)
    _check_pga(acceleration, parsed.values, units, g, where, source, accept_zero, assumed)
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
        gravity=g if units == "g" else None,
    )
    return Record(acceleration=acceleration, dt=step, meta=meta)


def _stored_meta(stored: RecordMeta, path: str, g: float) -> RecordMeta:
    """The metadata of a stored record read from ``path``: its source's, the file read named, values in g in ``g``.

    A record whose source was in g and was stored converted with another g
    is converted again with ``g`` [m/s²]: one g per call.
    """
    processing = stored.processing
    if stored.gravity is not None and stored.gravity != g:
        processing += (f"converted from g with g = {g:g} m/s2 (stored converted with {stored.gravity:g} m/s2)",)
    return replace(stored, stored_in=path, processing=processing,
                   gravity=g if stored.gravity is not None else None)


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
                          "stickslip's record manifest (stickslip/data/records.yaml)")
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


def _value_locator(decoded: DecodedText | None, entry, source: str):
    """``where(index)``: ``"line 7"`` for the value number ``index`` of a text file, ``"sample 8"`` in a binary one."""
    if decoded is None:
        return lambda index: f"sample {index + 1}"

    def where(index: int) -> str:
        first, columns = entry.first_data_line(decoded, source), entry.columns
        return f"line {line_of_value(decoded.body(first), first + 1, index * columns + columns - 1)}"

    return where


def _check_finite(acceleration: np.ndarray, values: np.ndarray, where, source: str) -> None:
    """Every acceleration must be finite in m/s² (a value like 1e400, or 1e308 g, is not); ``where`` names a value."""
    finite = np.isfinite(acceleration)
    if finite.all():
        return
    index = int(np.argmin(finite))
    problem = "is not a finite number" if not np.isfinite(values.flat[index]) else "overflows to infinity in m/s2"
    raise RecordError(source, f"{where(index)}: value {values.flat[index]:g} {problem}")


#: What to do about a PGA in doubt, by where the units came from (:func:`_units`).
_UNITS_ADVICE = {"file": "the file says {units}: check its values",
                 "given": "check units=",
                 "manifest": "a manifest says {units} for this file: check its values",
                 "assumed": "give units="}


def _check_pga(acceleration: np.ndarray, values: np.ndarray, units: str, g: float, where, source: str,
               accept_zero: bool, assumed: str | None) -> None:
    """The PGA must lie within :data:`POSSIBLE_PGA`; outside :data:`~stickslip.records.plausibility.PLAUSIBLE_PGA`
    (:data:`~stickslip.records.plausibility.PLAUSIBLE_PGA_UNSTATED` where the units were assumed) it gives a
    warning naming the units that would make it plausible.

    ``g`` [m/s²] converts to g; ``where(index)`` names the value number
    ``index``; ``accept_zero`` lets every value be zero; ``assumed`` says where
    the units came from (a key of :data:`_UNITS_ADVICE`), None for a stored
    record, whose values are in m/s² (no warning).
    """
    index = int(np.argmax(np.abs(acceleration)))
    pga = float(abs(acceleration[index])) / g  # [g]
    low, high = POSSIBLE_PGA
    if pga == 0.0:
        if accept_zero:
            return
        raise RecordError(source, "every acceleration is zero: the file holds no ground motion")
    if pga < low:
        raise RecordError(
            source, f"the largest value is {values[index]:.3g} {units}, a PGA of {pga:.3g} g, below the {low:g} g "
            "that an accelerograph resolves: the file holds no ground motion (are its values in other units?)")
    if pga > high:
        readings = "".join(f"; {value:.3g} g if they are in {other}"
                           for other, value in other_readings(float(values[index]), units, g, *PLAUSIBLE_PGA))
        raise RecordError(source, f"{where(index)}: value {values[index]:.6g} {units} is a PGA of {pga:.3g} g, more "
                                  f"than {high:g} g, which no ground motion comes near (the largest recorded are about "
                                  f"4 g){readings}: are the values in other units (units=)?")
    plausible = PLAUSIBLE_PGA_UNSTATED if assumed == "assumed" else PLAUSIBLE_PGA
    doubt = pga_doubt(float(values[index]), units, g, plausible=plausible) if assumed is not None else None
    if doubt is not None:
        advice = _UNITS_ADVICE[assumed].format(units=units)
        warnings.warn(f"{source}: {where(index)}: {doubt}: {advice}", StickslipWarning, stacklevel=4)


def _units(
    file_units: str | None,
    given_units: str | None,
    manifest_units: str | None,
    format: str,
    source: str,
    known: _KnownFile | None = None,
    default_units: str | None = None,
) -> tuple[str, str]:
    """The canonical units of the values, and where they came from: the file's own (``"file"``), else the given
    ones (``"given"``), else the manifest's (``"manifest"``), the default ones or the format's (``"assumed"``).

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
    units, assumed = next(((value, where) for value, where in (
        (file_units, "file"), (given_units, "given"), (manifest_units, "manifest"), (default_units, "assumed"),
        (FORMATS[format].units, "assumed")) if value), (None, None))
    if units is None:
        raise RecordError(source, f"units unknown for a {format} file; pass units= (g, m/s2 or cm/s2)")
    return normalize_units(units, source), assumed


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


def _decode(data: bytes, source: str) -> DecodedText:
    """The text of a record file: UTF-8 (or Latin-1), a DOS end-of-file byte dropped, ``\\n`` line ends (for LF,
    CR LF, CR CR LF or CR)."""
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
    if "\r" in text:  # CR LF, CR CR LF (a CR LF file converted to CR LF once more) and CR each end one line
        text = re.sub(r"\r+\n", "\n", text).replace("\r", "\n")
    return DecodedText(text)


