"""Quantities on the command line: a number with its unit, or a bare number in the option's own unit.

``--radius 200cm`` is R = 2 m, ``--mu 6%`` a friction ratio of 0.06,
``--g 981cm/s2`` (or ``981gal``) 9.81 m/s², ``--mass 5100g`` 5.1 kg,
``--period 500ms`` 0.5 s: a number (:func:`stickslip.cli.accelerations.number_and_unit`), then a unit of
the same quantity (:data:`stickslip.units.QUANTITY_UNITS`; an acceleration in
every spelling ``--units`` takes, except g where the quantity is g itself).  A
bare number is in the option's unit: m, kg, s, m/s, m/s², a ratio.

A bare number outside the quantity's usual range (a declaration's ``usual``,
:class:`~stickslip.models.entry.Parameter`) gets one warning per value, as a
bare ``--target-pga`` does, that names the reading taken and the readings in
the other units that fall inside the range: ``--radius 200: 200 m if the number
is in m, outside the 0.2 to 20 m usual for ...; 2 m if it is in cm (write the
unit: 200cm)``.
"""

from __future__ import annotations

import argparse
import math
import re
import warnings

from stickslip.cli.accelerations import _record_units, number_and_unit
from stickslip.errors import StickslipError, StickslipWarning
from stickslip.records.formats import unit_factor
from stickslip.units import QUANTITY_UNITS, quantity_factor, readable_units

#: The acceleration units a value of m/s² may be written in (g only where the quantity is not gravity itself).
ACCELERATION_UNITS = {"m/s2": 1.0, "cm/s2": 0.01, "gal": 0.01}


def units_of(unit: str) -> dict[str, float]:
    """The units a quantity in ``unit`` (UDUNITS spelling) may be written in, as a message shows them -> factor to
    ``unit``; the unit itself first."""
    if unit == "m s-2":
        return dict(ACCELERATION_UNITS)
    units = {spelling: scale for spelling, scale in QUANTITY_UNITS.get(unit, {}).items() if spelling}
    return units or {readable_units(unit): 1.0}


def factor(written: str, unit: str) -> float | None:
    """How many ``unit`` one ``written`` unit is (``"cm"`` in ``"m"``: 0.01), or None when it is not one of them."""
    if unit == "m s-2":
        units = _record_units(written)
        return None if units is None or units == "g" else unit_factor(units, 1.0)
    return quantity_factor(written, unit)


def read_quantity(text: str, unit: str, option: str) -> tuple[float, bool]:
    """The value of ``text`` in ``unit`` (UDUNITS spelling), and whether it was a bare number (in ``unit`` itself).

    ``"200cm"`` in ``"m"`` -> (2.0, False), ``"6%"`` in ``"1"`` -> (0.06, False),
    ``"0.3"`` -> (0.3, True); anything else is one line naming ``option`` and the units it takes.
    """
    parsed = number_and_unit(str(text))
    if parsed is not None:
        number, written = parsed
        if written == "":
            return number, True
        found = factor(written, unit)
        if found is not None:
            return _times(number, found), False
    raise StickslipError(f"{option} {str(text).strip()!r}: expected {_expected(unit)}")


def _times(number: float, scale: float) -> float:
    """``number * scale``, divided where ``scale`` is 1/n so that ``6%`` is 0.06 and ``5100g`` 5.1 kg exactly."""
    inverse = 1.0 / scale
    return number / round(inverse) if scale < 1.0 and abs(inverse - round(inverse)) < 1e-9 else number * scale


def _expected(unit: str) -> str:
    """What a value in ``unit`` is written as, in words, for a message."""
    units = [spelling for spelling in units_of(unit) if spelling != "-"]
    if unit == "1":
        return "a number (a ratio, 0.06) or a percentage (6%)"
    shown = readable_units(unit)
    more = "" if unit != "m s-2" else "; not in g, which this sets"
    return f"a number [{shown}] or a number with its unit ({', '.join(units)}{more})"


def warn_if_unusual(value: float, bare: bool, unit: str, usual: tuple[float, float, str] | None, shown: str,
                    number: str | None = None) -> None:
    """A warning when the positive finite ``value`` [``unit``] lies outside ``usual`` ``(low, high, of_what)``.

    For a ``bare`` number the warning names its readings in the other units that
    fall inside the range and how to write the likeliest (``number`` is the
    number as written, default ``value``); ``shown`` is the option as given
    (``--radius 200``).  Zero and negative values are left to the check.
    """
    if usual is None or not (math.isfinite(value) and value > 0.0):
        return
    low, high, of_what = usual
    if low <= value <= high:
        return
    readable = readable_units(unit)
    outside = f"outside the {low:g} to {high:g} {readable} usual for {of_what}"
    if not bare:
        warnings.warn(f"{shown}: {value:g} {readable} is {outside}", StickslipWarning, stacklevel=2)
        return
    by_scale = {}  # one reading per scale: cm/s2, not cm/s2 and gal
    for written, scale in units_of(unit).items():
        if scale != 1.0 and low <= value * scale <= high:
            by_scale.setdefault(scale, (written, value * scale))
    readings = sorted(by_scale.values(), key=lambda reading: abs(math.log(reading[1] / value)))
    number = number or f"{value:g}"
    others = "".join(f"; {reading:.3g} {readable} if it is in {written}" for written, reading in readings)
    advice = f" (write the unit: {number}{readings[0][0]})" if readings else f"; check that it is in {readable}"
    warnings.warn(f"{shown}: {value:g} {readable} if the number is in {readable}, {outside}{others}{advice}",
                  StickslipWarning, stacklevel=2)


def quantity_type(unit: str, option: str):
    """argparse's ``type`` for ``option``, a quantity in ``unit`` (UDUNITS spelling): its value in ``unit``, written
    bare or with its unit (:func:`read_quantity`); argparse names the option in its one line for anything else."""

    def read(text: str) -> float:
        try:
            return read_quantity(text, unit, option)[0]
        except StickslipError as error:
            raise argparse.ArgumentTypeError(str(error).removeprefix(f"{option} ")) from None

    return read


def grid_part(read):
    """``read`` for one value of a grid or list (``START:STOP:STEP``, ``A,B``): a part that is no number, or a
    number followed by another or by a separator (``0.05;0.1``), raises ValueError, for the grid's reader to say
    which forms it takes; a number with a unit is ``read`` (and a wrong unit named by it)."""

    def part(text: str):
        parsed = number_and_unit(text)
        if parsed is None or re.search(r"[;,:]|^[-+.]?\d", parsed[1]):
            raise ValueError(text)
        return read(text)

    return part
