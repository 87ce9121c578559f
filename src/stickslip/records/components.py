"""What a record's names say of it: the direction of its component, whether it is vertical, its station and event.

Record files name their component in a header (the PEER AT2 description
line: ``Kocaeli Turkey, 8/17/1999, Duzce, UP``), in a manifest (the SLAMMER
library's ``TAK-090``) or in the file name (``RSN1158_KOCAELI_DZC-UP.AT2``,
``CHY080-N.AT2``).  This module reads those names:

- :func:`component_direction` and :func:`component_azimuth`: the horizontal
  direction a name ends with (``TAK-090`` → 90 degrees clockwise from north,
  ``CHY080-N`` → 0, ``PAR-L`` → longitudinal);
- :func:`vertical_component`: whether a record is a vertical component, and
  what says so (``UP``, ``DN``, ``DWN``, ``V``, ``VER``, ``Z`` and the
  seismometer channels ``HNZ``, ``HLZ`` ...: in the component the header or a
  manifest gives, else at the end of the file name, as PEER writes
  ``C05DWN`` and ``TAB-V1``);
- :func:`recording_mismatch`: what says that two records are not one
  station's recording of one event (their events, their stations, or the
  PEER record sequence numbers of their file names differ).

Names are compared as sources spell them: an event's name without its year
(``Chi-Chi, Taiwan 1999`` and ``CHI-CHI``), word by word, a word of letters
possibly abbreviated (``SUPERST HILLS`` and ``Superstition Hills-02``), words
with digits equal (``Imperial Valley-02`` is not ``Imperial Valley-06``, nor
``El Centro Array #5`` ``El Centro Array #6``).  A station is compared by its
code where both records give one (``CHY080`` from the header of
``CHY080-N.AT2`` and from the SLAMMER library's ``CHY080-090``, whose
station name is the region, ``Chiayi``), else by its name.
"""

from __future__ import annotations

import re
from pathlib import PurePath

from stickslip.records.record import RecordMeta

_COMPASS = {"N": 0.0, "E": 90.0, "S": 180.0, "W": 270.0}
_DIRECTION = r"(?P<direction>\d{3}|[NESW]|L[N1-9]?|T[R1-9]?)"
_SUFFIX = re.compile(rf"^(?:(?P<station>.+?)[-_ ])?{_DIRECTION}$", re.IGNORECASE)

#: A vertical component's name, or the last part of one: up, down, vertical, Z, a seismometer's Z channel.
_VERTICAL_WORD = r"(?:UP|DN|DWN|DOWN|V[1-9]?|VER|VERT|VERTICAL|VRT|Z|[BEHLMS][HLNG]Z)"
_VERTICAL_NAME = re.compile(rf"(?:^|.*[-_ .]){_VERTICAL_WORD}$", re.IGNORECASE)
#: A vertical's name after a station code and a separator: ``TAK-UP``, ``RSN143_TABAS_TAB-V1``.
_SEPARATED_VERTICAL = re.compile(rf"[-_ .]{_VERTICAL_WORD}$", re.IGNORECASE)
#: PEER's file names glue a vertical's direction to the station code: ``RSN30_PARKF_C05DWN``, ``G03UP``.
_GLUED_VERTICAL = re.compile(r"(?:[A-Z0-9]DWN|[0-9]UP)$", re.IGNORECASE)

#: A station code as headers give it (``CHY080``, ``TCU068``): letters, then digits.
_STATION_CODE = re.compile(r"[A-Z]{2,5}[0-9]{2,4}", re.IGNORECASE)
#: The PEER NGA record sequence number at the start of a file name (``RSN180_IMPVALL.H_H-E05140.AT2``).
_RECORD_SEQUENCE = re.compile(r"^RSN(\d+)_", re.IGNORECASE)
_YEAR = re.compile(r"\b(1[89]\d\d|20\d\d)\b")


def component_direction(name: str) -> tuple[str, str, float | None] | None:
    """(station prefix, kind, azimuth) of a component's name, or None when it names no horizontal direction.

    ``kind`` is ``"azimuth"`` (``TAK-090`` → (``TAK``, ``azimuth``, 90);
    ``ARL-360`` → 0; ``CHY080-N`` → 0, ``-E`` → 90), ``"longitudinal"``
    (``PAR-L``, ``CLW-LN``, ``BAJ-L1``) or ``"transverse"`` (``PAR-T``,
    ``CLW-TR``, ``BAJ-T1``), the last two without an azimuth.  A name that is
    a direction only (``090``, ``N``, as some manifests give the component)
    has the station prefix ``""``; ``UP``, ``HNZ`` or a name without a
    direction give None.
    """
    name = name.strip()
    match = _SUFFIX.match(name)
    if match is None or _VERTICAL_NAME.match(name):
        return None
    station, direction = (match["station"] or "").strip("-_ ").upper(), match["direction"].upper()
    if direction.isdigit():
        value = float(direction)
        return (station, "azimuth", value % 360.0) if value <= 360.0 else None
    if direction in _COMPASS:
        return station, "azimuth", _COMPASS[direction]
    return station, "longitudinal" if direction[0] == "L" else "transverse", None


def component_azimuth(name: str) -> float | None:
    """The azimuth [degrees clockwise from north] that a component's name ends with, or None.

    ``TAK-090`` → 90, ``LCN-345`` → 345, ``CHY080-N`` → 0, ``CHY080-E`` → 90;
    ``PAR-L``, ``UP``, ``HNZ`` or a name without one → None.
    """
    found = component_direction(name)
    return found[2] if found is not None else None


def component_label(name: str) -> str:
    """How a component called ``name`` (its header's component, else its record id) is written on pages and axes.

    A bare azimuth in degrees (a PEER header's ``0`` or ``090``) gets its
    degree sign (``0°``, ``90°``): "displacement along 0" would read as a
    quantity, not a direction.  Other names stay as they are.
    """
    return f"{int(name) % 360}°" if name and name.isdigit() and int(name) <= 360 else name


def file_stem(meta: RecordMeta) -> str:
    """The name of the file a record was read from, without its folder and extension (``""`` for none)."""
    return PurePath(meta.source.replace("\\", "/")).stem if meta.source else ""


def vertical_component(meta: RecordMeta) -> str | None:
    """Why the record of ``meta`` is a vertical component, or None when nothing says it is.

    The component that the header or a manifest gives decides when it names
    a direction: ``its component is UP`` (``DWN``, ``V``, ``Z``, ``HNZ`` ...),
    and a horizontal one (``090``, ``TAK-090``, ``N``, ``L``; the SLAMMER
    library's stations ``DWN`` and ``VER`` are Downey and Vernon, whose
    components ``DWN-090`` and ``VER-180`` are horizontal) is not vertical.
    Otherwise the file name: ``its file name RSN30_PARKF_C05DWN ends in DWN``.
    """
    component = meta.component.strip()
    if component and _VERTICAL_NAME.match(component):
        return f"its component is {component}"
    if component_direction(component) is not None:
        return None
    stem = file_stem(meta)
    found = _VERTICAL_NAME.match(stem) or _GLUED_VERTICAL.search(stem)
    if found is None:
        return None
    ending = re.search(rf"{_VERTICAL_WORD}$", stem, re.IGNORECASE)
    return f"its file name {stem} ends in {ending.group().upper() if ending else stem}"


def station_codes(meta: RecordMeta) -> set[str]:
    """The station codes a record's names give, upper case: from its component and file names, and a station
    name that is a code.

    ``TAK-090`` and ``TAK-UP`` → ``TAK``; ``CHY080-N.AT2`` and the header's
    station ``CHY080`` → ``CHY080``; ``SLAMMER_Cape_Mendocino_1992_PET-090.txt``
    → ``PET`` (the last part of the name before its direction).
    """
    codes = set()
    for name in (meta.component, file_stem(meta)):
        found = component_direction(name)
        prefix = found[0] if found is not None else _SEPARATED_VERTICAL.sub("", name.strip()).upper()
        if prefix and prefix != name.strip().upper():
            codes.add(re.split(r"[-_ .]", prefix)[-1])
    if _STATION_CODE.fullmatch(meta.station.strip()):
        codes.add(meta.station.strip().upper())
    return codes - {""}


def _words(name: str) -> list[str]:
    return re.findall(r"[a-z0-9]+", name.casefold())


def same_words(one: str, other: str) -> bool:
    """Whether two names can name the same thing, as sources spell it: word by word, the shorter list
    beginning the longer; a word of letters may be abbreviated (``superst``, ``superstition``), a word with
    digits must be equal (``02`` is not ``06``, ``5`` not ``55``)."""
    shorter, longer = sorted((_words(one), _words(other)), key=len)
    return all(a == b or (a.isalpha() and b.isalpha() and (b.startswith(a) or a.startswith(b)))
               for a, b in zip(shorter, longer))


def same_event(one: str, other: str) -> bool:
    """Whether two event names can name the same earthquake: :func:`same_words` without the years, which must
    agree where both names give one (``Chi-Chi, Taiwan 1999`` and ``CHI-CHI``; not ``Imperial Valley-02`` and
    ``Imperial Valley-06``)."""
    years = [set(_YEAR.findall(name)) for name in (one, other)]
    if all(years) and not years[0] & years[1]:
        return False
    return same_words(_YEAR.sub(" ", one), _YEAR.sub(" ", other))


def record_sequence_number(meta: RecordMeta) -> str:
    """The PEER record sequence number that begins the record's file name (``RSN180_...`` → ``"180"``), or ``""``."""
    found = _RECORD_SEQUENCE.match(file_stem(meta))
    return found.group(1) if found else ""


def recording_mismatch(first: RecordMeta, second: RecordMeta) -> str | None:
    """What says that two records are not one station's recording of one event, or None.

    In order: their events (``different events ('Kobe 1995' and 'Landers 1992')``),
    their station codes where both give one, else their station names
    (``different stations (El Centro Array #5 and El Centro Array #6)``), and
    the PEER record sequence numbers their file names begin with
    (``different PEER records (RSN180 and RSN181)``).
    """
    events = first.event.strip(), second.event.strip()
    if all(events) and not same_event(*events):
        return f"different events ({events[0]!r} and {events[1]!r})"
    codes = station_codes(first), station_codes(second)
    if all(codes):
        if not codes[0] & codes[1]:
            return f"different stations ({' or '.join(sorted(codes[0]))} and {' or '.join(sorted(codes[1]))})"
    else:
        stations = first.station.strip(), second.station.strip()
        if all(stations) and not same_words(*stations):
            return f"different stations ({stations[0]} and {stations[1]})"
    numbers = record_sequence_number(first), record_sequence_number(second)
    if all(numbers) and numbers[0] != numbers[1]:
        return f"different PEER records (RSN{numbers[0]} and RSN{numbers[1]})"
    return None
