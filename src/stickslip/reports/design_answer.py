"""One record's design answer as ``stickslip optimum`` prints it: its numbers, and the report's table of them.

The numbers are the per-record results of :mod:`stickslip.optimum` (a row of
``stickslip optimum --json``, or a record of a cube with them);
:func:`format_number` writes each with the digits :func:`digits` gives it, in
the terminal table of ``stickslip optimum`` and on the record report's page
alike, so that the two show the same figures.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from stickslip.grids import COEFFICIENTS
from stickslip.optimum import range_bounds
from stickslip.units import readable_units

#: Significant digits of the results printed with other than four: name template -> digits ({c}: mu or ky).
_DIGITS = {"{c}_max_continuous": 5, "efficiency": 3}


def format_number(value: float | int, digits: int = 4) -> str:
    """``value`` with ``digits`` significant digits, ``-`` for NaN (no value), never ``-0``; an integer (a count) whole."""
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if math.isnan(value):
        return "-"
    return f"{value + 0.0:.{digits}g}"  # + 0.0 turns -0.0 into 0.0


def digits(name: str, coefficient: str = "mu") -> int:
    """The significant digits ``stickslip optimum`` prints the result ``name`` with (of a grid of ``coefficient``)."""
    return next((count for template, count in _DIGITS.items() if template.format(c=coefficient) == name), 4)


def shown(row: Mapping, name: str, coefficient: str = "mu", bounds: Mapping[str, str] | None = None) -> str:
    """The result ``name`` of ``row`` as ``stickslip optimum`` prints it; a bound (``bounds``, of
    :func:`stickslip.optimum.range_bounds`) with its ``≤`` or ``≥`` before it."""
    return (bounds or {}).get(name, "") + format_number(float(row[name]), digits(name, coefficient))


def answer_rows(row: Mapping, coefficient: str, q: float, reference: float,
                demands: Mapping | None = None) -> list[tuple[str, str, str, str]]:
    """The report's table of one record's results: (quantity, variable, value, units), the value as printed.

    ``row`` maps each result of a grid of ``coefficient`` (``"mu"`` or
    ``"ky"``) to its value (NaN where there is none); ``q`` and the
    ``reference`` value [1] say how the range and the efficiency were defined;
    ``demands`` are the model's further demands (a design's ``demands``: the
    pendulum's V/W), each at the optimum, the range's ends and its largest.
    Where the range reaches the grid's edge, its end there and its largest
    values are bounds, written with ``≤`` or ``≥`` before them
    (:func:`stickslip.optimum.range_bounds`).
    """
    c, symbol, slope = coefficient, COEFFICIENTS[coefficient].symbol, COEFFICIENTS[coefficient].slope
    edge = " (on the grid's edge: the maximum may lie beyond it)" if row[f"{c}_max_at_grid_edge"] == 1.0 else ""
    gap = "" if row["contiguous"] != 0.0 else " (not contiguous: some values inside fall below)"
    bounds = range_bounds(row, c, list(demands or {}))
    rows = [
        (f"{symbol}_max on the grid{edge}", f"{c}_max", "1"),
        (f"{symbol}_max, continuous", f"{c}_max_continuous", "1"),
        ("E_df,max on the grid", "energy_dissipated_max", "J"),
        (f"E_df,max at the continuous {symbol}_max", "energy_dissipated_max_continuous", "J"),
        (f"near-optimal range, E_df ≥ {q:g}·E_df,max: lowest{gap}", f"{c}_low", "1"),
        (f"near-optimal range, E_df ≥ {q:g}·E_df,max: highest", f"{c}_high", "1"),
    ]
    ends = (("max", f"the grid's {symbol}_max"), ("low", f"the range's lowest {symbol}"),
            ("high", f"the range's highest {symbol}"))
    rows += [(f"stroke (peak |x|) at {where}", f"peak_relative_displacement_at_{c}_{at}", "m") for at, where in ends]
    rows += [(f"residual displacement x at the end, at {where}", f"residual_displacement_at_{c}_{at}", "m")
             for at, where in ends]
    if slope:
        rows += [(f"downslope displacement at {where}", f"downslope_displacement_at_{c}_{at}", "m")
                 for at, where in ends]
    rows += [("largest stroke over the near-optimal range", "largest_stroke", "m"),
             (f"{symbol} where the stroke is largest", f"{c}_at_largest_stroke", "1"),
             ("largest residual displacement over the near-optimal range", "largest_residual_displacement", "m"),
             (f"{symbol} where the residual displacement is largest", f"{c}_at_largest_residual_displacement", "1")]
    if slope:
        rows.append(("largest downslope displacement over the near-optimal range", "largest_downslope_displacement",
                     "m"))
    for demand, (units, _, label) in (demands or {}).items():
        rows += [(f"{label} at {where}", f"{demand}_at_{c}_{at}", units) for at, where in ends]
        rows += [(f"largest {label} over the near-optimal range", f"largest_{demand}", units),
                 (f"{symbol} where {label} is largest", f"{c}_at_largest_{demand}", "1")]
    rows += [(f"E_df at the reference {symbol} = {reference:g}", "energy_dissipated_reference", "J"),
             (f"efficiency of {symbol} = {reference:g}, E_df / E_df,max (continuous)", "efficiency", "1")]
    return [(quantity, name, shown(row, name, c, bounds), readable_units(units)) for quantity, name, units in rows]
