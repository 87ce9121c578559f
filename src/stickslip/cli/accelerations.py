"""Accelerations on the command line: a bare number is in units of g, a number with a unit is in that unit.

``--ky 0.15`` is k_y = 0.15 (a yield acceleration of 0.15 g, as SLAMMER,
pySLAMMER and Jibson's tables write it), and so is ``--ky 0.15g``;
``--ky 1.47m/s2`` is a yield acceleration of 1.47 m/s², k_y = 1.47 / g.
``--target-pga`` reads the same way (``0.4``, ``0.4g``, ``3.92m/s2`` or
``392cm/s2``).  Where a percentage of g is usual (a yield coefficient:
``--ky 15%`` is 0.15), ``percent=True`` also takes one.  Every unit
``--units`` takes is accepted, in every spelling
:func:`stickslip.records.formats.normalize_units` knows (``m/s^2``, ``m/s²``,
``gal``, ``cm/s/s`` ...), and every spelling of m s-2 that
:func:`stickslip.units.normalise_units` knows (``m s-2`` ...).

A bare number is a guess at its unit: one beyond what it can plausibly be
(a PGA above 4 g, a yield coefficient above 1) gives a warning that names the
reading taken and the ones that would be plausible (:func:`in_units_of_g`'s
``largest``); a PGA beyond any ground motion (above 100 g, as for a record)
is an error that names them (``impossible``).  The line is the one every bare
number outside its usual range gets (:func:`stickslip.cli.quantities.doubt`).
"""

from __future__ import annotations

import re
import warnings

from stickslip.checks import checked_positive
from stickslip.cli.quantities import doubt
from stickslip.errors import RecordError, StickslipError, StickslipWarning
from stickslip.records.formats import normalize_units, unit_factor
from stickslip.records.plausibility import other_readings
from stickslip.units import normalise_units

#: A number, then whatever follows it (the unit), spaces allowed between.
_NUMBER_AND_UNIT = re.compile(r"([-+]?(?:(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?|inf|nan))\s*(.*)", re.IGNORECASE)


def number_and_unit(text: str) -> tuple[float, str] | None:
    """``"40cm/s"`` -> (40.0, ``"cm/s"``), ``"0.3"`` -> (0.3, ``""``): a number and what follows it; None if no number leads."""
    match = _NUMBER_AND_UNIT.fullmatch(text.strip())
    return None if match is None else (float(match.group(1)), match.group(2).strip())


def _record_units(unit: str) -> str | None:
    """The canonical record units (``g``, ``m/s2``, ``cm/s2``) of ``unit``, or None when it is none of them."""
    if normalise_units(unit) == "m s-2":
        return "m/s2"
    try:
        return normalize_units(unit, "")
    except RecordError:
        return None


def in_units_of_g(text: str, g: float, option: str, example: str, largest: float | None = None,
                  impossible: float | None = None, percent: bool = False) -> float:
    """The acceleration ``text`` in units of g [1], any sign: ``"0.15"`` and ``"0.15g"`` -> 0.15, ``"1.47m/s2"`` -> 1.47/g.

    ``g`` [m/s²] converts a value in other units; ``option`` and ``example``
    (``"0.15"``) name the option and show its forms in the one-line error
    for anything else.  A bare number above ``largest`` [g] gives a warning,
    any value above ``impossible`` [g] is an error; both name the readings of
    the number in the other units that lie below ``largest``.  With
    ``percent``, ``"15%"`` is 0.15, and a bare number's readings name it first.
    """
    g = checked_positive(g, "gravity g [m/s2]")
    parsed = number_and_unit(text)
    if parsed is not None:
        value, unit = parsed
        units = "g" if unit == "" else "%" if (percent and unit == "%") else _record_units(unit)
        if units is not None:
            in_g = (value if units == "g" else value / 100.0 if units == "%"
                    else value * unit_factor(units, g) / g)  # a number in g stays exact
            if impossible is not None and abs(in_g) > impossible:
                raise StickslipError(_readings(text, in_g, g, option, f"more than {impossible:g} g, which no ground "
                                                                      "motion comes near", largest, percent))
            if unit == "" and largest is not None and abs(value) > largest:
                warnings.warn(_readings(text, value, g, option, f"more than {largest:g} g", largest, percent),
                              StickslipWarning, stacklevel=2)
            return in_g
    in_percent = f", {float(example) * 100:g}%" if percent else ""
    raise StickslipError(f"{option} {text!r}: expected a number in units of g ({example}, or {example}g) or an "
                         f"acceleration with its unit ({float(example) * g:.3g}m/s2, "
                         f"{float(example) * g * 100:.3g}cm/s2{in_percent})")


def _readings(text: str, value: float, g: float, option: str, problem: str, largest: float | None,
              percent: bool = False) -> str:
    """``--target-pga 400: 400 g if the number is in g, <problem>; 0.408 g if it is in cm/s2 (write the unit: ...)``:
    the number ``value`` [g] of ``text``, and its readings in other units at most ``largest`` [g] (a percentage of g
    first, with ``percent``)."""
    readings = other_readings(value, "g", g, 0.0, largest) if largest is not None else []
    if percent and largest is not None and abs(value) / 100.0 <= largest:
        readings.insert(0, ("%", abs(value) / 100.0))
    return doubt(f"{option} {text.strip()}", abs(value), "g", problem, readings)


def acceleration(text: str, g: float, option: str, example: str, largest: float | None = None,
                 impossible: float | None = None) -> float:
    """The acceleration ``text`` [m/s²]: :func:`in_units_of_g` times ``g`` [m/s²]."""
    return in_units_of_g(text, g, option, example, largest, impossible) * g
