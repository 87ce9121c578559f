"""Quantities on the command line: a number with its unit, or a bare number in the option's own unit.

``--arias 97cm/s`` is 0.97 m/s, ``--radius 200cm`` 2 m, ``--mu 6%`` a
friction ratio of 0.06, ``--mass 5100g`` 5.1 kg, ``--g 981cm/s2`` 9.81 m/s²,
``--tm 0.4s`` 0.4 s; a bare number is in the option's unit (``--arias 0.97``
in m/s), where the option allows one.  Each model parameter's option reads so
from its declared unit (:func:`of_unit`, the units of
:data:`stickslip.units.QUANTITY_UNITS`), and so do the options of a time, a
ratio or an angle (``--dt 5ms``, ``--q 95%``, ``--angles 5deg``:
:func:`quantity_type`).  A bare number outside the usual range of its
quantity is a guess at its unit: it gets a warning naming the reading taken
and the readings in the option's other units that lie inside the range, the
same line as a bare acceleration gets
(:func:`stickslip.cli.accelerations.in_units_of_g`), one for each value of a
list or grid::

    --arias 97: 97 m/s if the number is in m/s, more than 30 m/s; 0.97 m/s if it is in cm/s (write the unit: 97cm/s)
"""

from __future__ import annotations

import argparse
import math
import re
import warnings
from collections.abc import Mapping
from dataclasses import dataclass

from stickslip.errors import StickslipError, StickslipWarning
from stickslip.units import QUANTITY_UNITS, normalise_units, readable_units


def doubt(shown: str, value: float, unit: str, problem: str, readings: list[tuple[str, float]],
          number: str | None = None) -> str:
    """The warning (or error) line of a bare number: ``shown`` (``--arias 97``) is ``value`` [``unit``] if the number
    is in ``unit``, ``problem`` (``more than 30 m/s``); then each reading (units it may be in, value [``unit``]),
    the likeliest first, and how to write the first: ``number`` with it (default the last word of ``shown``)."""
    spaced = f" {unit}" if unit else ""
    others = "".join(f"; {reading:.3g}{spaced} if it is in {units}" for units, reading in readings)
    number = number or shown.split()[-1]
    hint = f" (write the unit: {number}{readings[0][0]})" if readings else ""
    reading = f"{value:g} {unit} if the number is in {unit}" if unit else f"{value:g} as a plain number"
    return f"{shown}: {reading}, {problem}{others}{hint}"


@dataclass(frozen=True)
class Quantity:
    """How an option reads one quantity.

    Attributes
    ----------
    unit:
        The unit the value is returned in, as the option's help writes it (``m/s``).
    factors:
        Each unit the option takes, as written (``cm/s``; any spelling of the same
        units is taken: :func:`stickslip.units.normalise_units`), -> the factor to
        ``unit``; the key None for a bare number (absent: a bare number is refused).
    example:
        The forms shown in the error line (``1.2 or 1.2m/s``).
    usual:
        ``(low, high)`` [``unit``]: a bare number outside gets a warning naming its
        readings in the other units that lie inside; None: no such range.
    usual_for:
        What the range is usual for (``the surfaces of friction pendulums``): the
        warning then names the range, ``outside the 0.2 to 20 m usual for ...``.
    """

    unit: str
    factors: Mapping[str | None, float]
    example: str
    usual: tuple[float, float] | None = None
    usual_for: str = ""

    def units_of(self, spelling: str) -> str | None:
        """The key of :attr:`factors` that ``spelling`` writes (None for a bare number), or ``""`` if none."""
        if not spelling:
            return None if None in self.factors else ""
        canonical = _canonical(spelling)
        for units in self.factors:
            if units is not None and (spelling == units or canonical is not None and canonical == _canonical(units)):
                return units
        return ""


def _canonical(spelling: str) -> str | None:
    """One spelling of the units ``spelling`` writes (``m/s²`` and ``m s-2`` alike, ``gal`` and ``cm/s2`` alike), or
    None for units neither :func:`stickslip.units.normalise_units` nor the record formats know."""
    from stickslip.errors import RecordError
    from stickslip.records.formats import normalize_units

    units = normalise_units(spelling)
    if units not in (None, "1"):
        return units
    try:
        return "record " + normalize_units(spelling, "")
    except RecordError:
        return None


def of_unit(unit: str, usual: tuple[float, float, str] | None = None) -> Quantity:
    """The quantity of a value in ``unit`` (UDUNITS spelling, as a model's parameter declares it): a bare number in
    ``unit``, or one with a unit of :data:`~stickslip.units.QUANTITY_UNITS` (``200cm``, ``6%``); ``usual`` is
    ``(low, high, what it is usual for)`` [``unit``] (:attr:`~stickslip.models.entry.Parameter.usual`)."""
    written = [spelling for spelling in QUANTITY_UNITS.get(unit, {}) if spelling]
    factors = {None: 1.0, **{spelling: QUANTITY_UNITS[unit][spelling] for spelling in written}}
    shown = readable_units(unit)
    example = ("0.06 or 6%" if unit == "1" else
               f"{', '.join(f'1{spelling}' for spelling in written)} or a bare number in {shown}" if written else
               f"a number in {shown}")
    low_high, usual_for = (usual[:2], usual[2]) if usual is not None else (None, "")
    return Quantity(shown if unit != "1" else "", factors, example, low_high, usual_for)


def parse_quantity(text: str, option: str, quantity: Quantity) -> tuple[float, bool]:
    """The value [``quantity.unit``] of an option's ``text`` and whether it was a bare number, without a doubt; one
    :class:`StickslipError` naming ``option`` and the forms it takes for anything else."""
    from stickslip.cli.accelerations import number_and_unit

    parsed = number_and_unit(str(text))
    if parsed is not None:
        value, spelling = parsed
        units = quantity.units_of(spelling)
        if units != "":
            return _times(value, quantity.factors[units]), units is None
    raise StickslipError(f"{option} {str(text).strip()!r}: expected a number with its unit, such as "
                         f"{quantity.example}")


def _times(number: float, factor: float) -> float:
    """``number * factor``, divided where ``factor`` is 1/n, so that ``6%`` is 0.06 and ``5100g`` 5.1 kg exactly."""
    inverse = 1.0 / factor
    return number / round(inverse) if factor < 1.0 and abs(inverse - round(inverse)) < 1e-9 else number * factor


def read_quantity(text: str, option: str, quantity: Quantity) -> float:
    """The value [``quantity.unit``] of an option's ``text``: a number and one of its units, or a bare number.

    One :class:`StickslipError` naming ``option`` and the forms it takes for
    anything else; a bare number outside ``quantity.usual`` gets a warning
    (:func:`doubt`).
    """
    value, bare = parse_quantity(text, option, quantity)
    if bare and quantity.usual is not None:
        warn_if_unusual(f"{option} {str(text).strip()}", value, quantity)
    return value


def warn_if_unusual(shown: str, value: float, quantity: Quantity, number: str | None = None) -> None:
    """A warning when the bare number ``value`` (``shown`` as given; ``number`` as written, for one value of a list)
    lies outside ``quantity.usual``.

    Zero, negative and non-finite numbers get none: the option's check refuses them in one line.
    """
    low, high = quantity.usual
    if not (value > 0.0 and value != float("inf")) or low <= value <= high:
        return
    by_factor = {}  # one reading per factor: cm/s2, not cm/s2 and gal
    for units, factor in quantity.factors.items():
        if units is not None and factor != 1.0 and low <= value * factor <= high:
            by_factor.setdefault(factor, (units, value * factor))
    readings = sorted(by_factor.values(), key=lambda reading: abs(math.log(reading[1] / value)))
    unit = f" {quantity.unit}" if quantity.unit else ""
    problem = (f"outside the {low:g} to {high:g}{unit} usual for {quantity.usual_for}" if quantity.usual_for else
               f"more than {high:g}{unit}" if value > high else f"less than {low:g}{unit}")
    warnings.warn(doubt(shown, value, quantity.unit, problem, readings, number), StickslipWarning, stacklevel=3)


def quantity_type(quantity: Quantity, option: str):
    """argparse's ``type`` for ``option``, a ``quantity``: its value, written bare or with its unit
    (:func:`read_quantity`); argparse names the option in its one line for anything else."""

    def read(text: str) -> float:
        try:
            return read_quantity(text, option, quantity)
        except StickslipError as error:
            raise argparse.ArgumentTypeError(str(error).removeprefix(f"{option} ")) from None

    return read


def grid_part(read):
    """``read`` for one value of a grid or list (``START:STOP:STEP``, ``A,B``): a part that is no number, or a
    number followed by another or by a separator (``0.05;0.1``), raises ValueError, for the grid's reader to say
    which forms it takes; a number with a unit is ``read`` (and a wrong unit named by it)."""
    from stickslip.cli.accelerations import number_and_unit

    def part(text: str):
        parsed = number_and_unit(text)
        if parsed is None or re.search(r"[;,:]|^[-+.]?\d", parsed[1]):
            raise ValueError(text)
        return read(text)

    return part


#: ``--damping``: a damping ratio [-], bare (0.05) or in per cent (5%).
DAMPING_RATIO = Quantity("-", {None: 1.0, "%": 0.01}, "0.05 or 5%")

#: ``--g``: gravity [m/s²], bare or with its unit; on Earth from 9.78 to 9.83 m/s² (9.81 the paper's, 9.80665
#: SLAMMER's standard gravity), so a bare number outside 9.7 to 9.9 is likely in cm/s² (981).
GRAVITY = Quantity("m/s2", {None: 1.0, "m/s2": 1.0, "cm/s2": 0.01}, "9.81 or 9.81m/s2", usual=(9.7, 9.9))


def read_gravity(text: str, option: str = "--g") -> float:
    """Gravity g [m/s²] from ``--g`` (``9.81``, ``9.81m/s2``, ``981cm/s2``); positive, or one error line."""
    value = read_quantity(str(text), option, GRAVITY)
    if not (value > 0.0 and value != float("inf")):
        raise StickslipError(f"{option} {text}: expected a positive gravity [m/s2]")
    return value
