"""Which records of a collection study enter its fits and statistics, and why the others are left out.

A record of the study's table (``records.csv``) enters when it was read
(``status`` ``"ok"``), is a horizontal component (``vertical`` empty) and has
a maximum of the energy dissipated on the study's friction grid
(``optimum_status`` ``"ok"``).  The others are left out of the relations,
fits, coverage, claims and design chart, each with its reason, and the report
and the index count and name them:

- not read: the file is not here, or was refused (``status`` and ``reason``);
- vertical: a vertical component (``vertical`` says what says so:
  :func:`stickslip.records.components.vertical_component`); its sweep is in
  the study's cube, but the relations are those of horizontal shaking;
- never slides: E_df = 0 at every μ of the grid, because the record's PGA is
  below μ·g at the grid's smallest μ; it has no μ_max, no near-optimal range
  and no efficiency (``optimum_status`` says so).
"""

from __future__ import annotations

#: How a record left out is counted: its group -> what the report calls the group.
GROUPS = {"not read": "could not be read",
          "vertical": "were vertical components, apart from the horizontal shaking the study relates",
          "never slides": "never slid at any μ of the grid"}


def studied(rows: list[dict]) -> list[dict]:
    """The rows of the records that enter the study's fits and statistics."""
    return [row for row in rows if row["status"] == "ok" and not row.get("vertical") and row["optimum_status"] == "ok"]


def left_out(rows: list[dict]) -> list[dict]:
    """One row per record left out: ``id``, ``event``, ``group`` (a key of :data:`GROUPS`) and ``reason``."""
    out = []
    for row in rows:
        if row["status"] != "ok":
            out.append({"id": row["id"], "event": row["event"], "group": "not read",
                        "reason": f"{row['status']}: {row['reason']}" if row["reason"] else row["status"]})
        elif row.get("vertical"):
            out.append({"id": row["id"], "event": row["event"], "group": "vertical", "reason": row["vertical"]})
        elif row["optimum_status"] != "ok":
            out.append({"id": row["id"], "event": row["event"], "group": "never slides",
                        "reason": row["optimum_status"]})
    return out


def too_few(n: int, min_records: int, what: str = "a fit") -> str | None:
    """The reason a statistic of ``n`` records is not given (``None`` when ``n`` ≥ ``min_records``)."""
    if n >= min_records:
        return None
    return f"too few records: {n}, {what} needs at least {min_records} (collection_study.min_records)"
