"""Quantities on the command line: a number with its unit, or a bare number in the option's own unit.

``--arias 97cm/s`` is 0.97 m/s, ``--tm 0.4s`` is 0.4 s, ``--damping 5%`` is
0.05; a bare number is in the option's unit (``--arias 0.97`` in m/s), where
the option allows one.  A bare number outside the usual range of its quantity
is a guess at its unit: it gets a warning naming the reading taken and the
readings in the option's other units that lie inside the range, the same line
as a bare acceleration gets (:func:`stickslip.cli.accelerations.in_units_of_g`)::

    --arias 97: 97 m/s if the number is in m/s, more than 30 m/s; 0.97 m/s if it is in cm/s (write the unit: 97cm/s)
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import dataclass

from stickslip.errors import StickslipError, StickslipWarning
from stickslip.units import normalise_units


def doubt(shown: str, value: float, unit: str, problem: str, readings: list[tuple[str, float]]) -> str:
    """The warning (or error) line of a bare number: ``shown`` (``--arias 97``) is ``value`` [``unit``] if the number
    is in ``unit``, ``problem`` (``more than 30 m/s``); then each reading (units it may be in, value [``unit``]),
    the likeliest first, and how to write the first."""
    others = "".join(f"; {reading:.3g} {unit} if it is in {units}" for units, reading in readings)
    number = shown.split()[-1]
    hint = f" (write the unit: {number}{readings[0][0]})" if readings else ""
    return f"{shown}: {value:g} {unit} if the number is in {unit}, {problem}{others}{hint}"


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
    """

    unit: str
    factors: Mapping[str | None, float]
    example: str
    usual: tuple[float, float] | None = None

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


def read_quantity(text: str, option: str, quantity: Quantity) -> float:
    """The value [``quantity.unit``] of an option's ``text``: a number and one of its units, or a bare number.

    One :class:`StickslipError` naming ``option`` and the forms it takes for
    anything else; a bare number outside ``quantity.usual`` gets a warning
    (:func:`doubt`).
    """
    from stickslip.cli.accelerations import number_and_unit

    parsed = number_and_unit(text)
    if parsed is not None:
        value, spelling = parsed
        units = quantity.units_of(spelling)
        if units != "":
            if units is None and quantity.usual is not None:
                warn_if_unusual(f"{option} {text.strip()}", value, quantity)
            return value * quantity.factors[units]
    raise StickslipError(f"{option} {text!r}: expected a number with its unit, such as {quantity.example}")


def warn_if_unusual(shown: str, value: float, quantity: Quantity) -> None:
    """A warning when the bare number ``value`` (``shown`` as given) lies outside ``quantity.usual``.

    Zero, negative and non-finite numbers get none: the option's check refuses them in one line.
    """
    low, high = quantity.usual
    if not (value > 0.0 and value != float("inf")) or low <= value <= high:
        return
    readings = [(units, value * factor) for units, factor in quantity.factors.items()
                if units is not None and low <= value * factor <= high]
    problem = f"more than {high:g} {quantity.unit}" if value > high else f"less than {low:g} {quantity.unit}"
    warnings.warn(doubt(shown, value, quantity.unit, problem, readings), StickslipWarning, stacklevel=3)


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
