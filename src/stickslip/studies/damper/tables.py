"""The damper study's tables: every case, the statistics over records, and the study's JSON.

From the gathered cube (:mod:`stickslip.studies.damper.sweep`):

- ``damper_cases.csv`` (:func:`case_rows`): one row per record, mass ratio and period T [s]: the bare drift [m],
  μ_Edf and μ_drift [1], their ratio, the drift reductions at each and the reduction given up [1], the grid-edge
  flags;
- ``damper_summary.csv`` (:func:`summary_rows`): per library (``paper``, the collection's, ``all``), mass ratio,
  T and quantity, the number of records, the median and the 84th percentile over the records;
- ``damper_curves.csv`` (:func:`curve_rows`): per library, mass ratio, T and friction level η = μg/PFA_bare, the
  drift reduction's median and 16th and 84th percentiles (the band of the drift-reduction figure);
- ``damper_study.json`` (:func:`study_document`): settings, counts, what was left out, and the pooled medians
  and 84th percentiles per mass ratio and T.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from stickslip.plumbing.files import provenance, write_csv_atomic, write_text_atomic
from stickslip.studies.damper.sweep import OPTIMA

CASE_FIELDS = ["library", "record", "pga", "mass_ratio", "period", "bare_peak_drift", "bare_peak_floor_acceleration",
               *OPTIMA]

#: The quantities summarised over records: column -> units.
SUMMARISED = {"mu_ratio": "1", "mu_energy": "1", "mu_drift": "1", "drift_reduction_at_mu_energy": "1",
              "drift_reduction_at_mu_drift": "1", "reduction_given_up": "1"}
SUMMARY_FIELDS = ["library", "mass_ratio", "period", "quantity", "units", "records", "median", "p84"]
CURVE_FIELDS = ["library", "mass_ratio", "period", "level", "records", "median", "p16", "p84"]

#: The rows that pool the libraries.
ALL_LIBRARIES = "all"


def case_rows(cube) -> list[dict]:
    """One row per record, mass ratio and T of the study's cube (:data:`CASE_FIELDS`)."""
    rows = []
    values = {name: cube[name].values for name in OPTIMA}
    for i, record in enumerate(cube.record.values):
        for k, ratio in enumerate(cube.mass_ratio.values):
            for p, period in enumerate(cube.period.values):
                rows.append({"library": str(cube.library.values[i]), "record": str(record),
                             "pga": float(cube.pga.values[i]), "mass_ratio": float(ratio), "period": float(period),
                             "bare_peak_drift": float(cube.bare_peak_drift.values[i, p]),
                             "bare_peak_floor_acceleration": float(cube.bare_peak_floor_acceleration.values[i, p]),
                             **{name: float(values[name][i, k, p]) for name in OPTIMA}})
    return rows


def _groups(rows: Sequence[Mapping], keys: Sequence[str]) -> dict[tuple, list[Mapping]]:
    """``rows`` by library (and :data:`ALL_LIBRARIES` when there are several) and ``keys``, in library order."""
    libraries = list(dict.fromkeys(row["library"] for row in rows))
    groups: dict[tuple, list[Mapping]] = {}
    for row in rows:
        cell = tuple(float(row[key]) for key in keys)
        groups.setdefault((row["library"], *cell), []).append(row)
        if len(libraries) > 1:
            groups.setdefault((ALL_LIBRARIES, *cell), []).append(row)
    order = [*libraries, ALL_LIBRARIES]
    return dict(sorted(groups.items(), key=lambda item: (order.index(item[0][0]), *item[0][1:])))


def _finite(values) -> np.ndarray:
    values = np.asarray(values, dtype=float)
    return values[np.isfinite(values)]


def summary_rows(cases: Sequence[Mapping]) -> list[dict]:
    """Per library, mass ratio, T and quantity (:data:`SUMMARISED`): the number of records with a value, the median
    and the 84th percentile over them."""
    rows = []
    for (library, ratio, period), members in _groups(cases, ("mass_ratio", "period")).items():
        for quantity, units in SUMMARISED.items():
            values = _finite([row[quantity] for row in members])
            rows.append({"library": library, "mass_ratio": ratio, "period": period, "quantity": quantity,
                         "units": units, "records": int(values.size),
                         "median": float(np.median(values)) if values.size else math.nan,
                         "p84": float(np.percentile(values, 84)) if values.size else math.nan})
    return rows


def curve_rows(cube) -> list[dict]:
    """Per library, mass ratio, T and friction level: the drift reduction's median and 16th and 84th percentiles
    over the records."""
    reduction = cube["drift_reduction"].values
    rows = []
    libraries = list(dict.fromkeys(str(value) for value in cube.library.values))
    chosen = {library: cube.library.values == library for library in libraries}
    if len(libraries) > 1:
        chosen[ALL_LIBRARIES] = np.ones(cube.sizes["record"], dtype=bool)
    for library, members in chosen.items():
        for k, ratio in enumerate(cube.mass_ratio.values):
            for p, period in enumerate(cube.period.values):
                for m, level in enumerate(cube.level.values):
                    values = _finite(reduction[members, k, p, m])
                    low, middle, high = (np.percentile(values, (16, 50, 84)) if values.size
                                         else (math.nan, math.nan, math.nan))
                    rows.append({"library": library, "mass_ratio": float(ratio), "period": float(period),
                                 "level": float(level), "records": int(values.size), "median": float(middle),
                                 "p16": float(low), "p84": float(high)})
    return rows


def study_document(cube, cases: Sequence[Mapping], summary: Sequence[Mapping], settings: Mapping,
                   collection: str) -> dict:
    """``damper_study.json``: the settings, the counts, what was left out and the pooled statistics."""
    libraries = list(dict.fromkeys(row["library"] for row in cases))
    pooled = ALL_LIBRARIES if len(libraries) > 1 else (libraries[0] if libraries else None)
    cells = {}
    for row in summary:
        if row["library"] == pooled:
            cells.setdefault((row["mass_ratio"], row["period"]), {"mass_ratio": row["mass_ratio"],
                                                                  "period": row["period"]})[row["quantity"]] = {
                "median": row["median"], "p84": row["p84"], "records": row["records"]}
    edges = {name: int(sum(row[f"{name}_at_grid_edge"] == 1.0 for row in cases)) for name in ("mu_energy", "mu_drift")}
    return {
        "settings": dict(settings),
        "available": bool(cases),
        "collection": collection,
        "records": {library: len({row["record"] for row in cases if row["library"] == library})
                    for library in libraries},
        "left_out": cube.attrs.get("left_out", ""),
        "never_slides": int(sum(math.isnan(row["mu_energy"]) for row in cases)),
        "at_grid_edge": edges,
        "pooled": pooled,
        "cells": list(cells.values()),
        **provenance(),
    }


def write_damper_tables(cases_path, summary_path, curves_path, study_path, study_cube_path, settings: Mapping,
                        collection: str) -> list[str]:
    """The study's tables (CSV) and JSON from the gathered cube (:mod:`stickslip.studies.damper.sweep`)."""
    from stickslip.sweeps import read_cube

    cube = read_cube(study_cube_path)
    cases = case_rows(cube)
    summary = summary_rows(cases)
    write_csv_atomic(cases_path, cases, CASE_FIELDS)
    write_csv_atomic(summary_path, summary, SUMMARY_FIELDS)
    write_csv_atomic(curves_path, curve_rows(cube), CURVE_FIELDS)
    document = study_document(cube, cases, summary, settings, collection)
    write_text_atomic(study_path, json.dumps(document, indent=2, default=_plain) + "\n")
    return [str(Path(path)) for path in (cases_path, summary_path, curves_path, study_path)]


def _plain(value):
    return value.item() if hasattr(value, "item") else str(value)

