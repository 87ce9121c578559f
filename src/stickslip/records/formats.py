"""Record file formats, one registry entry each: how to recognise a file, how to read it, what it implies.

xarray's backends are the model: :data:`FORMATS` maps a format's name to its
:class:`RecordFormat`, which holds its detection (``detects``, tried in the
registry's order on the first lines of a file), its reader (``read``: the
values in the file's units, the time step [s] and units it states, and the
event, station and component of a header), how many values a data line holds
and the units the format implies.  :func:`stickslip.records.readers.read_record`
asks the registry for a file's format and reader, the record manifest and the
command line (``--format``) take the list of names from it.  A new format is
one reader function and one entry.

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
    (``stickslip/data/records.yaml``, then the SLAMMER library's own manifest,
    :mod:`stickslip.records.library`), else from the ``dt`` argument.
``time_acc_csv``
    pySLAMMER sample motion: ``#`` comment lines (or one ``time,acc`` header
    row), then ``time,acc`` rows in g.  Time step from the time column; units
    from a column title such as ``Acceleration (g's)``, ``a [m/s2]`` or
    ``acc_cm_s2``; a title naming units in brackets that stickslip does not
    know is an error.
``two_column``
    Generic text with time [s] and acceleration per line, separated by blanks
    or commas, optionally below one header row; the units must be given.
``netcdf``
    A stored record: the NetCDF file that ``stickslip records fetch`` and the
    workflow write (``results/records/{id}.nc``, :mod:`stickslip.records.netcdf`),
    acceleration in m/s² with its time step and the provenance of its source
    file (record id, event, station, component, the source's units and
    SHA-256, processing).  A binary format: recognised by the first bytes of
    the file (:attr:`RecordFormat.magic`), read from its bytes.
"""

from __future__ import annotations

import functools
import math
import re
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from stickslip.errors import RecordError, StickslipWarning
from stickslip.records.numbers import NUMBER, parse_numbers
from stickslip.records.record import RecordMeta
from stickslip.units import normalise_units

#: Canonical units of record values.
RECORD_UNITS = ("g", "m/s2", "cm/s2")

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
    # as column titles write them (``acc_ms2``, ``a [m s-2]``): nobody writes an acceleration in ms²
    "ms2": "m/s2",
    "ms-2": "m/s2",
    "ms^-2": "m/s2",
    "m.s-2": "m/s2",
    "cms2": "cm/s2",
    "cms-2": "cm/s2",
    "cms^-2": "cm/s2",
    "cm.s-2": "cm/s2",
}

#: Relative tolerance on the spacing of a time column written in double precision.
TIME_STEP_RTOL = 1e-6

#: How far [fraction of dt] a time of a time column may lie from the uniform grid through its first and last
#: times: printing jitter (steps of 0.004996 s in a 0.005 s record) is accepted, a skipped or repeated sample
#: (a whole step off) is refused.
TIME_JITTER = 0.01

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

#: Units in a column title, as in pySLAMMER's ``# Time (s),Acceleration (g's)`` or a ``time,acc [m/s2]`` row.
_ACCELERATION_TITLE_UNITS = re.compile(r"acc\w*\s*[(\[]([^)\]]+)[)\]]", re.IGNORECASE)
#: Units in brackets or parentheses: ``a (m/s^2)``, ``ag [g]``.
_BRACKETED_UNITS = re.compile(r"[(\[]([^)\]]+)[)\]]")
#: Seconds per unit of a time column, by the units its title names (``time [ms]``).
TIME_UNITS = {"s": 1.0, "sec": 1.0, "seconds": 1.0, "ms": 1e-3, "msec": 1e-3, "milliseconds": 1e-3}
#: The title of a time column: ``t``, ``time``, ``Time (s)``, ``time_s``, ``t[s]``.
_TIME_TITLE = re.compile(r"t(?:ime)?(?:$|[^a-z])", re.IGNORECASE)

_WORD = re.compile(r"[A-Za-z]")

#: Headers, comments and column titles are among this many first lines.
_HEAD_LINES = 64


@dataclass(frozen=True)
class Parsed:
    """What a format reader found: values in the file's units and the time step [s].

    ``meta`` is the provenance a stored record carries (that of its source
    file: :class:`~stickslip.records.record.RecordMeta`), None for a source file.
    """

    values: np.ndarray
    dt: float | None
    units: str | None
    event: str = ""
    station: str = ""
    component: str = ""
    meta: RecordMeta | None = None


class DecodedText:
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


def unit_factor(units: str, g: float) -> float:
    """m/s² per unit of the canonical ``units`` (:data:`RECORD_UNITS`): ``g`` [m/s²] for ``"g"``, 1 for ``"m/s2"``,
    0.01 for ``"cm/s2"``."""
    return g if units == "g" else {"m/s2": 1.0, "cm/s2": 0.01}[units]


def normalize_units(units: str, source: str | Path) -> str:
    """The canonical name (``g``, ``m/s2`` or ``cm/s2``) of ``units``; RecordError if unknown."""
    key = re.sub(r"\s+", "", str(units)).lower()
    if key not in UNIT_ALIASES:
        raise RecordError(source, f"unknown units {units!r}; known units: g, m/s2, cm/s2 (aliases: gal, m/s^2, cm/s^2)")
    return UNIT_ALIASES[key]


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


def _data_start(decoded: DecodedText, format: str, source: str) -> int:
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


def _read_at2(decoded: DecodedText, source: str) -> Parsed:
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
    return Parsed(values, header_dt, header_units, event, station, component)


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
    """The units of an AT2 file's values, from its ``... IN UNITS OF G`` line; a PEER velocity or displacement
    record (``.VT2``, ``.DT2``) is refused naming what it is (:func:`_other_series`)."""
    for line in header:
        match = _AT2_UNITS.search(line)
        if match:
            other = _other_series(line, match.group(1))
            if other is not None:
                what, short, units = other
                raise RecordError(source, f"the file is a PEER {what} record ({short}, {units}); stickslip reads "
                                          "accelerations (.AT2)")
            return normalize_units(match.group(1), source)
    return None


#: PEER's time series other than accelerations: the word of their units line -> (what, its short name).
PEER_OTHER_SERIES = {"VELOCITY": ("velocity", "VEL"), "DISPLACEMENT": ("displacement", "DISP")}


def _other_series(line: str, units: str) -> tuple[str, str, str] | None:
    """(what, short name, units) when the AT2 units line ``line`` (units ``units``) is a velocity's
    (``VELOCITY TIME SERIES IN UNITS OF CM/S``, the ``.VT2`` files) or a displacement's (``.DT2``), else None."""
    shown = units.lower().replace("sec", "s")
    for word, (what, short) in PEER_OTHER_SERIES.items():
        if word in line.upper():
            return what, short, shown
    spelled = normalise_units(units)
    if spelled in ("m s-1", "cm s-1"):
        return "velocity", "VEL", shown
    if shown in ("cm", "m", "mm", "in"):
        return "displacement", "DISP", shown
    return None


def _at2_description(line: str) -> tuple[str, str, str]:
    """(event, station, component) from an AT2 header's description line."""
    parts = [part.strip() for part in line.split(",") if part.strip()]
    if len(parts) < 3:
        return (parts[0] if parts else "", "", "")
    event = _TRAILING_DATE.sub("", parts[0])
    component = _TRAILING_NETWORK.sub("", parts[-1])
    return event, parts[-2], component


def _read_one_column(decoded: DecodedText, source: str) -> Parsed:
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
    return Parsed(parse_numbers(body, start + 1, source, columns=1)[:, 0], None, None)


def _read_time_column(decoded: DecodedText, source: str, format: str = "two_column") -> Parsed:
    """Time [s, or ms where its title says: ``time [ms]``] and acceleration columns; dt from the time column,
    which must be uniform.

    The steps are judged against the precision of the written times: the
    last decimal written, and float32 rounding for a column written in
    single precision.  Units from a column title (``Acceleration (g)``).
    """
    start = _data_start(decoded, format, source)
    body = decoded.body(start)
    table = parse_numbers(body, start + 1, source, columns=2, commas=True)
    time = table[:, 0]
    dt = _uniform_step(time, start, source, _written_resolution(body)) if time.size >= 2 else None
    seconds = _time_title_seconds(decoded.head[:start], source)
    return Parsed(table[:, 1], None if dt is None else dt * seconds, _title_units(decoded.head[:start], source))


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
    """The acceleration units a comment or header row names, or None.

    An acceleration's title with its units in brackets (``Acceleration (g's)``,
    ``acc [m/s2]``), or the second title of a row of two whose first names
    time (:func:`_second_title_units`: ``t, a (m/s^2)``, ``time,acc_cm_s2``).
    Bracketed units stickslip does not know are an error, not a guess.
    """
    for line in header:
        match = _ACCELERATION_TITLE_UNITS.search(line)
        title, named = (match.group(0), match.group(1)) if match else _second_title_units(line.lstrip("#").strip())
        if named is None:
            continue
        key = re.sub(r"\s+", "", named).lower()
        if key not in UNIT_ALIASES:
            raise RecordError(
                source,
                f"the column title {title!r} names units {named!r} that stickslip does not know; "
                "known units: g, m/s2, cm/s2 (convert the file, or pass units= and remove the title's units)",
            )
        return UNIT_ALIASES[key]
    return None


def _title_fields(line: str) -> list[str] | None:
    """The two column titles of a row whose first names time (``time [s],acc [g]``, ``t a(m/s2)``), else None."""
    if re.search(r"[,;\t]", line):
        fields = [field.strip() for field in re.split(r"[,;\t]", line)]
    else:
        fields = re.findall(r"(?:[^\s(\[]|[(\[][^)\]]*[)\]])+", re.sub(r"\s+(?=[(\[])", "", line))
    return fields if len(fields) == 2 and _TIME_TITLE.match(fields[0]) and fields[1] else None


def _named_units(title: str) -> str:
    """The units a column title names: in brackets (``a (m/s^2)``), else after its name's first ``_``, ``-`` or
    blank (``acc_cm_s2``: ``cm/s2``); "" for none."""
    bracketed = _BRACKETED_UNITS.search(title)
    if bracketed is not None:
        return bracketed.group(1)
    parts = re.split(r"[_\s-]", title, maxsplit=1)
    return parts[1].replace("_", "/") if len(parts) == 2 else ""


def _second_title_units(line: str) -> tuple[str, str | None]:
    """The second title of a row of two column titles whose first names time (:func:`_title_fields`), and the
    acceleration units it names (:func:`_named_units`): in brackets any (``(in/s^2)`` too, for an error, but not
    ``(DAY)``, no acceleration's unit), else those stickslip knows but g (``acc_cm_s2``; ``acc_g``, which may name
    the ground's acceleration, and ``acc_x``: none).  ``(line, None)`` for any other line."""
    fields = _title_fields(line)
    if fields is None:
        return line, None
    title = fields[1]
    named = _named_units(title)
    key = re.sub(r"\s+", "", named).lower()
    bracketed = _BRACKETED_UNITS.search(title) is not None
    if bracketed and (key in UNIT_ALIASES or re.search(r"/s|s\^?-?2", key)):
        return title, named
    if not bracketed and key in UNIT_ALIASES and UNIT_ALIASES[key] != "g":  # acc_g may be the ground's acceleration
        return title, named
    return title, None


def _time_title_seconds(header: list[str], source: str) -> float:
    """Seconds per unit of the time column, as its title names them (``time [ms]``, ``t_ms``: 0.001; ``Time (s)``:
    1), else 1; time units stickslip does not know in brackets (``time [min]``) are an error."""
    for line in header:
        fields = _title_fields(line.lstrip("#").strip())
        if fields is None:
            continue
        named = _named_units(fields[0]).strip().lower()
        if named in TIME_UNITS:
            return TIME_UNITS[named]
        if _BRACKETED_UNITS.search(fields[0]):
            raise RecordError(source, f"the column title {fields[0]!r} names time units {named!r} that stickslip "
                                      f"does not know; known: {', '.join(TIME_UNITS)}")
        return 1.0
    return 1.0


def _read_time_acc_csv(decoded: DecodedText, source: str) -> Parsed:
    """pySLAMMER's time/acceleration CSV: as :func:`_read_time_column`."""
    return _read_time_column(decoded, source, "time_acc_csv")


@dataclass(frozen=True)
class FileHead:
    """What detection looks at: the first lines of a file and its first line of values.

    ``fields`` are the blank- or comma-separated fields of that line (empty
    when there is none); ``titled`` says whether ``#`` comments or a row of
    column titles come before it.
    """

    lines: list[str]
    data_line: str
    fields: list[str]
    titled: bool

    @property
    def numeric_columns(self) -> int:
        """How many numbers the first line of values holds (0 when it holds anything else)."""
        return len(self.fields) if self.fields and all(NUMBER.fullmatch(field) for field in self.fields) else 0

    @classmethod
    def of(cls, text: str) -> FileHead:
        """The head of the decoded ``text`` of a file."""
        lines = [line.rstrip("\r") for line in text.lstrip("\ufeff").split("\n", _HEAD_LINES)[:_HEAD_LINES]]
        start = _first_data_line(lines)
        if start is None:
            lines = text.lstrip("\ufeff").splitlines()
            start = _first_data_line(lines)
        if start is None:
            return cls(lines, "", [], False)
        titled = any(line.lstrip().startswith("#") for line in lines[:start]) or _header_row(lines, start)
        return cls(lines, lines[start], _fields(lines[start]), titled)


@dataclass(frozen=True)
class RecordFormat:
    """One record format: its name, how to recognise and read a file of it, and what it implies.

    Attributes
    ----------
    name:
        What users write (``format="peer_at2"``, ``--format peer_at2``).
    summary:
        What a file of it looks like, in one line.
    detects:
        ``detects(head)``: whether a file whose :class:`FileHead` is ``head``
        is of this format; formats are tried in :data:`FORMATS`' order.
    read:
        ``read(decoded, source)``: the :class:`Parsed` content of the
        :class:`DecodedText` of the file ``source`` (for messages);
        :class:`~stickslip.errors.RecordError` naming the line of a problem.
        A binary format's reader takes the file's bytes instead of its text.
    columns:
        Values per data line (the acceleration is the last).
    units:
        Units it implies when neither the file, the caller nor a manifest says.
    states_dt:
        Whether a file of it states its time step (a header, a time column);
        one that does not takes dt [s] from its caller or a manifest.
    data_start:
        ``data_start(decoded, source)``: index of the first line of values;
        default: after ``#`` comments and at most one row of column titles.
    magic:
        The first bytes of a binary format's files, one of which a file of it
        starts with; empty for a text format.
    """

    name: str
    summary: str
    detects: Callable[[FileHead], bool]
    read: Callable[[DecodedText | bytes, str], Parsed]
    columns: int = 1
    units: str | None = None
    states_dt: bool = True
    data_start: Callable[[DecodedText, str], int] | None = None
    magic: tuple[bytes, ...] = ()

    @property
    def binary(self) -> bool:
        """Whether files of this format are binary (read from their bytes, not their text)."""
        return bool(self.magic)

    def first_data_line(self, decoded: DecodedText, source: str) -> int:
        """Index (0-based) of the first line of values of ``decoded``."""
        if self.data_start is not None:
            return self.data_start(decoded, source)
        return _data_start(decoded, self.name, source)


def _read_netcdf(data: bytes, source: str) -> Parsed:
    """A stored record (:func:`stickslip.records.netcdf.record_from_bytes`): m/s², its dt and its source's provenance."""
    from stickslip.records.netcdf import record_from_bytes

    record = record_from_bytes(data, source)
    meta = record.meta
    return Parsed(record.acceleration, record.dt, "m/s2", meta.event, meta.station, meta.component, meta=meta)


def _looks_like_at2(head: FileHead) -> bool:
    first = head.lines[:_AT2_HEADER_SEARCH]
    return bool(first and "PEER" in first[0].upper()) or any(_AT2_NPTS_DT_LINE.search(line) for line in first)


#: The formats, in the order detection tries them: name -> entry.
FORMATS: dict[str, RecordFormat] = {entry.name: entry for entry in (
    RecordFormat("peer_at2", "PEER AT2: a header with NPTS and DT, then the values in rows", _looks_like_at2,
                 _read_at2, data_start=lambda decoded, source: _at2_header_end(decoded.head, source) + 1),
    RecordFormat("time_acc_csv", "pySLAMMER's CSV: # comments or column titles, then time,acceleration rows",
                 lambda head: head.numeric_columns == 2 and head.titled and "," in head.data_line,
                 _read_time_acc_csv, columns=2, units="g"),
    RecordFormat("two_column", "time [s] and acceleration per line, separated by blanks or commas",
                 lambda head: head.numeric_columns == 2, _read_time_column, columns=2),
    RecordFormat("slammer_1col", "one value per line, no header (the SLAMMER library's files)",
                 lambda head: head.numeric_columns == 1 and not head.titled, _read_one_column, units="g",
                 states_dt=False),
    RecordFormat("netcdf", "a stored record: the NetCDF file of stickslip records fetch and the workflow "
                 "(acceleration in m/s2, dt and provenance)", lambda head: False, _read_netcdf, units="m/s2",
                 magic=(b"\x89HDF\r\n\x1a\n", b"CDF\x01", b"CDF\x02", b"CDF\x05")),
)}


def known_formats() -> str:
    """The names of the registered formats, as messages list them (alphabetical)."""
    return ", ".join(sorted(FORMATS))


def record_format(name: str, source: str | Path) -> RecordFormat:
    """The entry of the format ``name``; an unknown name is a :class:`RecordError` about ``source``."""
    if name not in FORMATS:
        raise RecordError(source, f"unknown format {name!r}; known formats: {known_formats()}")
    return FORMATS[name]


def binary_format(data: bytes) -> str | None:
    """The binary format whose files start as ``data`` does (:attr:`RecordFormat.magic`), or None."""
    return next((entry.name for entry in FORMATS.values() if entry.magic and data.startswith(entry.magic)), None)


def detect_format(text: str, source: str) -> str:
    """The format of a record file from its decoded ``text``: the first entry whose detection fits; else RecordError."""
    head = FileHead.of(text)
    for entry in FORMATS.values():
        if entry.detects(head):
            return entry.name
    semicolons = any(";" in line for line in head.lines if not line.lstrip().startswith("#"))
    raise RecordError(
        source,
        "unknown format: not a PEER AT2 file, nor one or two numeric columns, nor a stored record (NetCDF)"
        + ("; its columns are separated by semicolons, as a spreadsheet writes them where the decimal mark is a "
           "comma: save it with commas or blanks between the columns and points in the numbers" if semicolons else "")
        + f"; known formats: {known_formats()}",
    )
