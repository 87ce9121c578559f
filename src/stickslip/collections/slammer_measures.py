"""Intensity measures as SLAMMER computes and rounds them, from our records: the conversions of the check.

SLAMMER's database (``eq.sql``) publishes, for each library record, values
computed by SLAMMER's ``ImportRecords`` on the file's samples a_i in g:

- PGA [g]: max |a_i|, rounded to 3 decimals;
- Arias intensity [m/s]: 0.1603 · dt · Σ (a_i · 9.80665)², a rectangle-rule sum
  with the constant 0.1603 (π/(2·9.80665) = 0.16017, rounded up), rounded to 3
  decimals;
- Dobry duration [s]: dt times the number of samples whose cumulative sum
  Σ a_i² lies between 5 % and 95 % of the total (whole samples), rounded to
  1 decimal;
- mean period [s]: Rathje's T_m after SLAMMER's processing (our
  :func:`stickslip.measures.mean_period` is the same), rounded to 2 decimals.

Our own measures use g = 9.81 m/s² to convert g to m/s², the trapezoid rule
and a Husid curve interpolated between samples (``docs/definitions.md``).
:func:`slammer_convention` recomputes SLAMMER's definitions on a record that
we read (acceleration in m/s², converted back to g with our 9.81): the
differences with the database are then its rounding only.
"""

from __future__ import annotations

import numpy as np

from stickslip.constants import STANDARD_GRAVITY
from stickslip.measures import mean_period
from stickslip.units import UNITS as ALL_UNITS

#: SLAMMER's gravity [cm/s²] (``Analysis.Gcmss``).
SLAMMER_GRAVITY_CM = 980.665

#: SLAMMER's Arias constant [s/m] (π/(2·9.80665) = 0.16017, as the program writes it).
SLAMMER_ARIAS_CONSTANT = 0.1603

#: Decimals to which the database rounds each measure (half up).
DATABASE_DECIMALS = {"pga": 3, "arias_intensity": 3, "dobry_duration": 1, "mean_period": 2}

#: Units of the measures in SLAMMER's convention (UDUNITS; ``standard_free_fall`` is g = 9.80665 m s-2).
UNITS = {name: ALL_UNITS[f"slammer_{name}"] for name in DATABASE_DECIMALS}


def slammer_convention(acceleration: np.ndarray, dt: float, g: float = STANDARD_GRAVITY) -> dict[str, float]:
    """PGA [g], Arias intensity [m/s], Dobry duration [s] and mean period [s] as SLAMMER defines them, unrounded.

    ``acceleration`` [m/s²] was converted from g with ``g`` [m/s²] (our reader's
    9.81); ``dt`` [s].
    """
    in_g = np.asarray(acceleration, dtype=np.float64) / g
    squared = np.square(in_g * SLAMMER_GRAVITY_CM / 100.0)
    cumulative = np.cumsum(squared)
    total = cumulative[-1]
    within = (cumulative >= 0.05 * total) & (cumulative <= 0.95 * total)
    return {
        "pga": float(np.max(np.abs(in_g))),
        "arias_intensity": float(SLAMMER_ARIAS_CONSTANT * dt * total),
        "dobry_duration": float(np.count_nonzero(within) * dt),
        "mean_period": mean_period(acceleration, dt),
    }


def database_tolerance(name: str) -> float:
    """Half a unit in the last decimal the database keeps for ``name``: the largest rounding difference."""
    return 0.5 * 10.0 ** -DATABASE_DECIMALS[name]
