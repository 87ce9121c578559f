"""The units table ``results/tables/units.csv``: every table column and NetCDF variable with its units."""

from __future__ import annotations

from stickslip.plumbing.files import write_csv_atomic
from stickslip.units import UNITS


def write_units_table(units_path):
    """Write :data:`~stickslip.units.UNITS` as the CSV table ``units_path`` (columns ``column, units``), atomically;
    return its path."""
    return write_csv_atomic(units_path, [{"column": name, "units": units} for name, units in UNITS.items()],
                            ["column", "units"])
