"""Accelerations on the command line: a bare number is in units of g, a number with a unit is in that unit.

``--ky 0.15`` is k_y = 0.15 (a yield acceleration of 0.15 g, as SLAMMER,
pySLAMMER and Jibson's tables write it), and so is ``--ky 0.15g``;
``--ky 1.47m/s2`` is a yield acceleration of 1.47 m/s², k_y = 1.47 / g.
``--target-pga`` reads the same way (``0.4``, ``0.4g`` or ``3.92m/s2``).
Every spelling of m/s² that :func:`stickslip.units.normalise_units` knows is
accepted (``m/s2``, ``m/s^2``, ``m/s²`` ...).
"""

from __future__ import annotations

import re

from stickslip.checks import checked_positive
from stickslip.errors import StickslipError
from stickslip.units import normalise_units

#: A number, then whatever follows it (the unit), spaces allowed between.
_NUMBER_AND_UNIT = re.compile(r"([-+]?(?:(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?|inf|nan))\s*(.*)", re.IGNORECASE)


def number_and_unit(text: str) -> tuple[float, str] | None:
    """``"40cm/s"`` -> (40.0, ``"cm/s"``), ``"0.3"`` -> (0.3, ``""``): a number and what follows it; None if no number leads."""
    match = _NUMBER_AND_UNIT.fullmatch(text.strip())
    return None if match is None else (float(match.group(1)), match.group(2).strip())


def in_units_of_g(text: str, g: float, option: str, example: str) -> float:
    """The acceleration ``text`` in units of g [1], any sign: ``"0.15"`` and ``"0.15g"`` -> 0.15, ``"1.47m/s2"`` -> 1.47/g.

    ``g`` [m/s²] converts a value in m/s²; ``option`` and ``example`` (``"0.15"``)
    name the option and show its forms in the one-line error for anything else.
    """
    g = checked_positive(g, "gravity g [m/s2]")
    parsed = number_and_unit(text)
    if parsed is not None:
        value, unit = parsed
        if unit.lower() in ("", "g"):
            return value
        if normalise_units(unit) == "m s-2":
            return value / g
    raise StickslipError(f"{option} {text!r}: expected a number in units of g ({example}, or {example}g) or an "
                         f"acceleration with its unit ({float(example) * g:.3g}m/s2)")


def acceleration(text: str, g: float, option: str, example: str) -> float:
    """The acceleration ``text`` [m/s²]: :func:`in_units_of_g` times ``g`` [m/s²]."""
    return in_units_of_g(text, g, option, example) * g
