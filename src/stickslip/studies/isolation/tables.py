"""The isolation study's tables: every case, the statistics over records, and the study's JSON.

From the gathered cube (:mod:`stickslip.studies.isolation.sweep`):

- ``isolation_cases.csv`` (:func:`case_rows`): one row per component, fixed-base period T [s], radius R [m] and
  μ [1]: the isolated building's peak drift [m], floor acceleration [m/s²] and isolator displacement [m], the
  fixed-base building's peak drift and floor acceleration, and the two ratios isolated / fixed base [1];
- ``isolation_summary.csv`` (:func:`summary_rows`): per library (``slammer``, ``three_component`` and ``all``),
  T, R, μ and quantity (the two ratios and the isolator displacement), the number of records, the median and
  the 16th and 84th percentiles over the records;
- ``isolation_near_far.csv`` (:func:`stickslip.studies.isolation.near_far.near_far_rows`): per T, R, μ and
  quantity, near-fault against far-field components (empty where a group is too small);
- ``isolation_study.json`` (:func:`study_document`): the settings, what was available (else how to get it),
  the counts, the best (R, μ) per T by the median drift ratio, and the near-fault against far-field comparison
  (or what it lacks).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from stickslip.plumbing.files import provenance, write_csv_atomic, write_text_atomic
from stickslip.studies.isolation.motions import LIBRARIES
from stickslip.studies.isolation.near_far import (NEAR_FAR_FIELDS, distance_groups, far_field_status,
                                                  near_far_rows, near_far_summary)
from stickslip.studies.isolation.sweep import CASE_VARIABLES, FIXED_BASE_VARIABLES

CASE_FIELDS = ["library", "station", "component", "record", "rupture_distance", "period", "radius", "mu",
               *CASE_VARIABLES, *FIXED_BASE_VARIABLES]

#: The quantities summarised over records: column -> units.
SUMMARISED = {"drift_ratio": "1", "floor_acceleration_ratio": "1", "peak_isolator_displacement": "m"}
#: The percentiles of the summary, beside the median: the 16-84 % band (one standard deviation of a lognormal).
PERCENTILES = (16, 84)
SUMMARY_FIELDS = ["library", "period", "radius", "mu", "quantity", "units", "records", "median", "p16", "p84"]

#: The summary's rows that pool the libraries.
ALL_LIBRARIES = "all"


def case_rows(cube) -> list[dict]:
    """One row per component, T, R and μ of the study's cube (:data:`CASE_FIELDS`)."""
    rows = []
    values = {name: cube[name].values for name in (*CASE_VARIABLES, *FIXED_BASE_VARIABLES)}
    for i, record in enumerate(cube.record.values):
        described = {"library": str(cube.library.values[i]), "station": str(cube.station.values[i]),
                     "component": str(cube.component.values[i]), "record": str(record),
                     "rupture_distance": float(cube.rupture_distance.values[i])}
        for p, period in enumerate(cube.period.values):
            for r, radius in enumerate(cube.radius.values):
                for m, mu in enumerate(cube.mu.values):
                    rows.append({**described, "period": float(period), "radius": float(radius), "mu": float(mu),
                                 **{name: float(values[name][i, p, r, m]) for name in CASE_VARIABLES},
                                 **{name: float(values[name][i, p]) for name in FIXED_BASE_VARIABLES}})
    return rows


def statistics(values) -> dict:
    """The number of finite ``values``, their median and 16th and 84th percentiles (NaN when there is none)."""
    values = np.asarray(values, dtype=float)
    values = values[np.isfinite(values)]
    if not values.size:
        return {"records": 0, "median": math.nan, "p16": math.nan, "p84": math.nan}
    low, high = np.percentile(values, PERCENTILES)
    return {"records": int(values.size), "median": float(np.median(values)), "p16": float(low), "p84": float(high)}


def summary_rows(cases: Sequence[Mapping]) -> list[dict]:
    """Per library (and :data:`ALL_LIBRARIES`, when there are two), T, R, μ and quantity: the statistics over the
    records (:func:`statistics`)."""
    groups: dict[tuple, list[Mapping]] = {}
    libraries = {row["library"] for row in cases}
    for row in cases:
        cell = (float(row["period"]), float(row["radius"]), float(row["mu"]))
        groups.setdefault((row["library"], *cell), []).append(row)
        if len(libraries) > 1:
            groups.setdefault((ALL_LIBRARIES, *cell), []).append(row)
    order = [*LIBRARIES, ALL_LIBRARIES]
    rows = []
    for (library, period, radius, mu), members in sorted(groups.items(),
                                                          key=lambda item: (order.index(item[0][0]), *item[0][1:])):
        for quantity, units in SUMMARISED.items():
            rows.append({"library": library, "period": period, "radius": radius, "mu": mu, "quantity": quantity,
                         "units": units, **statistics([float(row[quantity]) for row in members])})
    return rows


def best_cells(summary: Sequence[Mapping], library: str) -> list[dict]:
    """Per T, the (R, μ) of ``library``'s smallest median drift ratio, with the floor acceleration ratio and the
    isolator displacement there (median and 84th percentile)."""
    cells: dict[tuple, dict] = {}
    for row in summary:
        if row["library"] == library:
            cells.setdefault((row["period"], row["radius"], row["mu"]), {})[row["quantity"]] = row
    best = {}
    for (period, radius, mu), found in cells.items():
        drift = found["drift_ratio"]["median"]
        if math.isfinite(drift) and (period not in best or drift < best[period]["drift_ratio_median"]):
            best[period] = {"period": period, "radius": radius, "mu": mu, "drift_ratio_median": drift,
                            "drift_ratio_p84": found["drift_ratio"]["p84"],
                            "floor_acceleration_ratio_median": found["floor_acceleration_ratio"]["median"],
                            "floor_acceleration_ratio_p84": found["floor_acceleration_ratio"]["p84"],
                            "isolator_displacement_median": found["peak_isolator_displacement"]["median"],
                            "isolator_displacement_p84": found["peak_isolator_displacement"]["p84"]}
    return [best[period] for period in sorted(best)]


def pairs_status(collection: str, components: int) -> str:
    """``ok``, or one sentence on why the SLAMMER library's pairs are not in the study and how to add them."""
    if components:
        return "ok"
    return (f"The SLAMMER library's station pairs were not available (the collection study ran on the {collection} "
            "collection, which has none): set STICKSLIP_SLAMMER_DIR or collection_study.folder to a copy of the "
            "library (docs/collections.md).")


#: What the study's JSON says of the case of the largest isolator displacement.
LARGEST_FIELDS = ("library", "station", "component", "period", "radius", "mu", "peak_isolator_displacement",
                  "drift_ratio", "peak_floor_acceleration", "fixed_base_peak_floor_acceleration")


def largest_isolator_displacement(cases: Sequence[Mapping]) -> dict | None:
    """The case of the largest isolator displacement [m] (:data:`LARGEST_FIELDS`), None without a case."""
    found = max((row for row in cases if math.isfinite(row["peak_isolator_displacement"])),
                key=lambda row: row["peak_isolator_displacement"], default=None)
    return None if found is None else {key: found[key] for key in LARGEST_FIELDS}


def study_document(cube, cases: Sequence[Mapping], summary: Sequence[Mapping], near_far: Sequence[Mapping],
                   settings: Mapping, collection: str, near_fault_km: float, min_records: int,
                   three_component_message: str) -> dict:
    """``isolation_study.json``: settings, availability, counts, the best cells per T, the far-field sentence and,
    per quantity, what the near-fault against far-field rows (``near_far``) show."""
    counts = {library: sorted({row["record"] for row in cases if row["library"] == library}) for library in LIBRARIES}
    stations = {library: sorted({row["station"] for row in cases if row["library"] == library})
                for library in LIBRARIES}
    pooled = ALL_LIBRARIES if all(counts.values()) else next((name for name in LIBRARIES if counts[name]), None)
    return {
        "settings": dict(settings),
        "available": bool(cases),
        "components": {library: len(names) for library, names in counts.items()},
        "stations": {library: len(names) for library, names in stations.items()},
        "pairs_status": pairs_status(collection, len(counts["slammer"])),
        "three_component_status": three_component_message or "ok",
        "left_out": cube.attrs.get("left_out", "") if cube is not None else "",
        "far_field_status": far_field_status(cases, near_fault_km, min_records),
        "near_far": {"near_fault_km": near_fault_km, "min_records": min_records,
                     "components": {group: len(records) for group, records in distance_groups(cases,
                                                                                              near_fault_km).items()},
                     "compared": bool(near_far), "quantities": near_far_summary(near_far)},
        "pooled": pooled,
        "best": best_cells(summary, pooled) if pooled else [],
        "largest_isolator_displacement": largest_isolator_displacement(cases),
        **provenance(),
    }


def write_isolation_tables(cases_path, summary_path, near_far_path, study_path, study_cube_path, settings: Mapping,
                           collection: str, near_fault_km: float, min_records: int,
                           three_component_message: str = "") -> list[str]:
    """The study's tables (CSV) and JSON from the gathered cube (:mod:`stickslip.studies.isolation.sweep`):
    near-fault within ``near_fault_km`` [km], a comparison with at least ``min_records`` components a side."""
    from stickslip.sweeps import read_cube

    cube = read_cube(study_cube_path)
    cases = case_rows(cube)
    summary = summary_rows(cases)
    near_far = near_far_rows(cases, SUMMARISED, near_fault_km, min_records)
    write_csv_atomic(cases_path, cases, CASE_FIELDS)
    write_csv_atomic(summary_path, summary, SUMMARY_FIELDS)
    write_csv_atomic(near_far_path, near_far, NEAR_FAR_FIELDS)
    document = study_document(cube, cases, summary, near_far, settings, collection, near_fault_km, min_records,
                              three_component_message)
    write_text_atomic(study_path, json.dumps(document, indent=2, default=_plain) + "\n")
    return [str(Path(path)) for path in (cases_path, summary_path, near_far_path, study_path)]


def _plain(value):
    return value.item() if hasattr(value, "item") else str(value)
