"""Grids and accelerations written on the command line: ``START:STOP:STEP``, a comma list, one value; a PGA.

``START:STOP:STEP`` includes STOP when it lies on the grid
(:func:`stickslip.grids.range_values`), and every grid is checked as the
workflow's configuration is (:func:`stickslip.grids.checked_range`,
:func:`stickslip.grids.positive_increasing`); a mistake is one line naming
the option.
"""

from __future__ import annotations

import numpy as np

from stickslip.cli.accelerations import acceleration, in_units_of_g
from stickslip.errors import StickslipError
from stickslip.grids import checked_range, positive_increasing, range_values
from stickslip.records.plausibility import PLAUSIBLE_PGA
from stickslip.records.readers import POSSIBLE_PGA


def parse_mu_bounds(text: str, min_values: int = 1) -> tuple[float, float, float]:
    """(START, STOP, STEP) [1] of a ``--mu`` range of at least ``min_values``, checked: :func:`stickslip.grids.range_values` gives its grid."""
    return _parse_bounds(text, "--mu", "friction ratios mu", "numbers such as 0.05:0.2:0.025", float, min_values)


def parse_ky_range(text: str, g: float) -> np.ndarray:
    """Yield coefficients k_y [1] from ``START:STOP:STEP``, ``0.05,0.1`` or one value (each k_y, a percentage of g,
    or k_y·g with its unit; ``g`` [m/s²]); each bare number above 1 gets a warning naming its likely readings."""
    from stickslip.models.parameters import KY

    return parse_values(text, "--ky", "yield coefficients k_y", "0.02:0.4:0.02",
                        lambda part: in_units_of_g(part, g, "--ky", "0.15", largest=KY.plausible, percent=True))


def parse_values(text: str, option: str, quantity: str, example: str, number) -> np.ndarray:
    """Grid values from ``START:STOP:STEP``, a comma list ``A,B,C`` or one value ``A``, each converted by ``number``.

    ``quantity`` (``"friction ratios mu"``) names them in a message and ``example`` shows a grid of them.
    """
    if ":" in text or "," in text:
        return _parse_range(text, option, quantity, f"numbers such as {example}", number)
    try:
        value = number(text)
    except ValueError:
        raise StickslipError(f"{option} {text!r}: expected START:STOP:STEP, three numbers such as {example}, or a "
                             "comma list (0.05,0.1,0.15)") from None
    return positive_increasing([value], f"{option} {text!r}: {quantity}")


def _parse_range(text: str, option: str, quantity: str, example: str, number) -> np.ndarray:
    """Grid values from ``START:STOP:STEP`` (STOP included when it lies on the grid) or a comma list ``A,B,C``.

    Each number is converted by ``number``; ``quantity`` (``"friction ratios mu"``) names them in a message.
    """
    if "," in text:
        try:
            values = [number(part) for part in text.split(",")]
        except ValueError:
            raise StickslipError(f"{option} {text!r}: expected a comma list of {quantity} (0.05,0.1,0.15) or "
                                 f"START:STOP:STEP") from None
        return positive_increasing(values, f"{option} {text!r}: {quantity}")
    return range_values(*_parse_bounds(text, option, quantity, example, number))


def _parse_bounds(text: str, option: str, quantity: str, example: str, number,
                  min_values: int = 1) -> tuple[float, float, float]:
    """(START, STOP, STEP) of ``START:STOP:STEP`` (at least ``min_values`` values), checked by :func:`stickslip.grids.checked_range`."""
    parts = text.split(":")
    try:
        start, stop, step = (number(part) for part in parts)
    except ValueError:
        raise StickslipError(f"{option} {text!r}: expected START:STOP:STEP, three {example}, or a comma list "
                             "(0.05,0.1,0.15)") from None
    return checked_range(start, stop, step, f"{option} {text!r}", quantity, min_values)


def parse_pga(text: str, g: float, option: str = "--target-pga") -> float:
    """A PGA [m/s²] from ``"0.6"`` or ``"0.6g"`` (units of g, ``g`` [m/s²] each), ``"5.89m/s2"`` or ``"589cm/s2"``
    (any units ``--units`` takes); a bare number above 4 g gives a warning naming its plausible readings, a PGA above
    100 g (:data:`~stickslip.records.readers.POSSIBLE_PGA`, as for a record) is an error."""
    return acceleration(text, g, option, "0.4", largest=PLAUSIBLE_PGA[1], impossible=POSSIBLE_PGA[1])
