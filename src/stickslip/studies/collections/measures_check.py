"""An external check of our intensity measures against a collection's published values (SLAMMER's database).

For every record with published values, each of PGA [g], Arias intensity
[m s-1], 5–95 % duration [s] and mean period [s] is recomputed from our
reading of the file in SLAMMER's definitions
(:mod:`stickslip.collections.slammer_measures`: its 0.1603 constant and
rectangle-rule sum, its whole-sample duration, our mean period) and compared
with the database.  The tolerance of each value is the database's rounding,
half a unit in its last decimal, plus 1e-9 for the binary round-off of a
value that lies on a rounding boundary; a value beyond it is explained in
the table when a known cause applies.

The table also gives, for the same records, the relative difference between
our own definitions (g = 9.81 m s-2, trapezoid rule, interpolated Husid
times) and the database, so that the size of the conventions is visible.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from stickslip.collections.slammer_measures import DATABASE_DECIMALS, UNITS, database_tolerance
from stickslip.constants import STANDARD_GRAVITY
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic, write_text_atomic

#: Checked measures: name -> (published column, our own measure in SI, factor from ours to the published units).
CHECKED = {
    "pga": ("slammer_pga", "pga", 1.0 / STANDARD_GRAVITY),
    "arias_intensity": ("slammer_arias_intensity", "arias_intensity", 1.0),
    "dobry_duration": ("slammer_dobry_duration", "significant_duration", 1.0),
    "mean_period": ("slammer_mean_period", "mean_period", 1.0),
}

#: Slack [in the measure's units] for values on a rounding boundary.
ROUND_OFF = 1e-9


def check_rows(rows: list[dict]) -> list[dict]:
    """One row per (record, measure) with a published value: ours, theirs, the difference and the verdict."""
    table = []
    for row in rows:
        if row["status"] != "ok":
            continue
        for name, (published, own, factor) in CHECKED.items():
            if row.get(published) in ("", None):
                continue
            theirs = float(row[published])
            converted = float(row[f"slammer_convention_{name}"])
            rounded = round(converted, DATABASE_DECIMALS[name])
            difference = converted - theirs
            tolerance = database_tolerance(name) + ROUND_OFF
            within = abs(difference) <= tolerance
            table.append({
                "record": row["id"], "event": row["event"], "measure": name, "units": UNITS[name],
                "published": theirs, "ours_slammer_convention": converted, "ours_rounded": rounded,
                "difference": difference, "tolerance": tolerance,
                "ours_own_definition": float(row[own]) * factor,
                "own_definition_relative_difference": float(row[own]) * factor / theirs - 1 if theirs else np.nan,
                "status": "within tolerance" if within else "beyond tolerance",
                "explanation": "" if within else _explanation(name, difference),
            })
    return table


def _explanation(name: str, difference: float) -> str:
    """A known cause of a difference beyond the rounding, or a plain statement that none is known."""
    step = 10.0 ** -DATABASE_DECIMALS[name]
    if abs(abs(difference) - step) <= 0.5 * step:
        return "one unit in the database's last decimal: a value rounded from a slightly different file or sum"
    return "not explained: the published value differs by more than the database's rounding"


def summary(table: list[dict], pass_rate_threshold: float) -> dict:
    """Pass rates per measure and overall, the threshold and whether it is met, and the records beyond tolerance."""
    result = {"threshold": pass_rate_threshold, "measures": {}}
    for name in CHECKED:
        rows = [row for row in table if row["measure"] == name]
        passed = sum(row["status"] == "within tolerance" for row in rows)
        result["measures"][name] = {"checked": len(rows), "within": passed,
                                    "pass_rate": passed / len(rows) if rows else None,
                                    "tolerance": database_tolerance(name), "units": UNITS[name]}
    checked = len(table)
    within = sum(row["status"] == "within tolerance" for row in table)
    result.update(checked=checked, within=within, records=len({row["record"] for row in table}),
                  pass_rate=within / checked if checked else None,
                  passes=bool(checked) and within / checked >= pass_rate_threshold,
                  beyond=[{key: row[key] for key in ("record", "measure", "published", "ours_slammer_convention",
                                                      "explanation")}
                          for row in table if row["status"] != "within tolerance"])
    return result


def write_measures_check(table_path: str | Path, check_path: str | Path, summary_path: str | Path,
                         pass_rate: float) -> list[Path]:
    """Write the check's table (CSV) and summary (JSON) from the study's per-record table."""
    table = check_rows(read_csv_rows(table_path))
    write_csv_atomic(check_path, table, ["record", "event", "measure", "units", "published",
                                         "ours_slammer_convention", "ours_rounded", "difference", "tolerance",
                                         "ours_own_definition", "own_definition_relative_difference", "status",
                                         "explanation"])
    write_text_atomic(summary_path, json.dumps(summary(table, pass_rate), indent=1) + "\n")
    return [Path(check_path), Path(summary_path)]
