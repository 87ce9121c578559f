"""The simplified estimates measured against the rigorous answers on every record of a collection.

Two stages, as the workflow runs them (``workflow/rules/estimates.smk``):

* per chunk of the collection study's record store,
  :func:`write_chunk_flexible`: for each sliding-mass period T_s of the study,
  the record's 5 %-damped Sa(1.5 T_s) [g] and the coupled displacement D [cm]
  of a linear soil layer of that period (height V_s·T_s/4 over the study's
  V_s and V_s,base, :func:`stickslip.solve` of the coupled model, exact scheme) at every
  yield coefficient k_y, in both polarities;
* over the collection, :func:`write_estimates`: every method of
  :data:`stickslip.estimates.registry.METHODS` (but those that came after
  SLAMMER, :data:`~stickslip.estimates.registry.AFTER_SLAMMER`) evaluated on each record's
  measures (PGA, I_a and the rigid D_n of both polarities from the Jibson
  (2007) table, :mod:`stickslip.studies.jibson2007.displacements`, which the collection
  study has already solved; PGV and T_m from its measures chunks; the
  magnitude from the collection's table).  Rigid methods, and Bray and
  Travasarou's rigid branch (T_s = 0, Sa = PGA), are set against the rigid
  D_n; the flexible methods against the coupled D at each T_s.

Per method, k_y and T_s (:data:`SUMMARY_COLUMNS`): the rows (record ×
polarity), the share of zero displacements observed (D = 0 exactly) and
predicted (the mean of P(D = 0), a certain zero where k_y ≥ PGA counting 1),
the shares below the displacement floor (D < floor [cm], Bray and
Travasarou's "zero"), and the log residual ln(D_observed / D̂) over the rows
with D_observed ≥ floor: its mean (the bias; > 0 where the method
underestimates), its standard deviation and its RMS [ln units], beside the
method's own σ converted to ln units.  Per threshold d of the study
(:data:`EXCEEDANCE_COLUMNS`): the share of rows with D_observed > d beside the
mean predicted P(D > d).  Displacements in cm, SLAMMER's and the papers' unit.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from stickslip.collections.collection import study_collection
from stickslip.collections.store import read_record_store
from stickslip.estimates.bray_travasarou import RIGID_PERIOD
from stickslip.estimates.estimate import LOG_BASES
from stickslip.estimates.measures import spectral_acceleration_g
from stickslip.estimates.ranking import ranking_rows  # noqa: F401 (the study's notebook reads it here)
from stickslip.estimates.registry import AFTER_SLAMMER, METHODS
from stickslip.models.parameters import POLARITIES
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic, write_text_atomic

#: Centimetres per metre.
CM_PER_M = 100.0

#: The chunk table's columns (one row per record, T_s, k_y and polarity; units: stickslip.units.UNITS).
FLEXIBLE_COLUMNS = ("record", "status", "site_period", "spectral_acceleration", "ky", "polarity",
                    "coupled_displacement")

#: The per-row table's columns.
ROW_COLUMNS = ("method", "record", "event", "ky", "site_period", "polarity", "observed_displacement",
               "estimated_displacement", "estimated_sigma_ln", "estimated_p_zero")

#: The summary's columns.
SUMMARY_COLUMNS = ("method", "compared_with", "ky", "site_period", "rows", "records", "observed_zero_share",
                   "estimated_zero_share", "observed_below_floor_share", "estimated_below_floor_share",
                   "residual_rows", "bias_ln", "sigma_ln", "rms_ln", "method_sigma_ln")

#: The exceedance table's columns.
EXCEEDANCE_COLUMNS = ("method", "ky", "site_period", "displacement", "observed_share", "estimated_probability")


def chunk_flexible(store_path: str | Path, critical_accelerations_g: Sequence[float], site_periods: Sequence[float],
                   vs: float, vs_base: float, damping: float, g: float) -> list[dict]:
    """The chunk table's rows (see the module's docstring); a record not stored keeps one row with its status."""
    import stickslip

    rows = []
    for stored in read_record_store(store_path):
        if stored.record is None:
            rows.append({"record": stored.record_id, "status": f"not solved: {stored.status}: {stored.reason}"})
            continue
        for period in site_periods:
            layer = stickslip.Layer(vs * period / 4.0, vs, vs_base, damping)
            sa = spectral_acceleration_g(stored.record, period, g)
            for ky in critical_accelerations_g:
                for polarity in POLARITIES:
                    result = stickslip.solve(stored.record, model="coupled", ky=float(ky), g=g,
                                             inverse=polarity == "inverse", ledger=False, **layer.parameters())
                    rows.append({"record": stored.record_id, "status": "ok", "site_period": float(period),
                                 "spectral_acceleration": sa, "ky": float(ky), "polarity": polarity,
                                 "coupled_displacement": CM_PER_M * result.displacement})
    return rows


def write_chunk_flexible(store_path: str | Path, table_path: str | Path, critical_accelerations_g: Sequence[float],
                         site_periods: Sequence[float], vs: float, vs_base: float, damping: float, g: float) -> Path:
    """:func:`chunk_flexible` written as CSV to ``table_path``, atomically."""
    rows = chunk_flexible(store_path, critical_accelerations_g, site_periods, vs, vs_base, damping, g)
    return write_csv_atomic(table_path, rows, list(FLEXIBLE_COLUMNS))


def _number(text) -> float | None:
    """A table cell as a number; None for an empty cell or NaN."""
    if text in (None, ""):
        return None
    value = float(text)
    return value if math.isfinite(value) else None


def _estimate_rows(method: str, inputs: dict, observed: Mapping[str, float], base: dict) -> list[dict]:
    """One row per polarity of ``method``'s estimate from ``inputs`` against ``observed`` D [cm] per polarity."""
    entry = METHODS[method]
    if entry.missing(inputs):
        return []
    estimate = entry.estimate(inputs)
    sigma_ln = None if estimate.sigma is None else estimate.sigma * LOG_BASES[estimate.log_base]
    p_zero = estimate.p_zero if estimate.p_zero is not None else 0.0
    return [{**base, "method": method, "polarity": polarity, "observed_displacement": value,
             "estimated_displacement": CM_PER_M * estimate.median_displacement, "estimated_sigma_ln": sigma_ln,
             "estimated_p_zero": p_zero} for polarity, value in observed.items()]


def estimate_rows(rigid_rows: Sequence[Mapping], measures: Mapping[str, Mapping], flexible_rows: Sequence[Mapping],
                  magnitudes: Mapping[str, float | None], critical_accelerations_g: Sequence[float],
                  g: float) -> list[dict]:
    """Every method's estimate beside the rigorous displacement, one row per method, record, k_y, T_s and polarity.

    ``rigid_rows``: the Jibson (2007) table's rows (``pga`` [m s-2], ``arias_intensity`` [m s-1],
    ``newmark_displacement`` [cm]); ``measures``: record -> its measures row (``pgv`` [m s-1],
    ``mean_period`` [s]); ``flexible_rows``: the chunk tables' rows; ``magnitudes``: record -> M.
    """
    wanted = {round(float(ky), 12) for ky in critical_accelerations_g}
    rigid: dict[tuple[str, float], dict] = {}
    for row in rigid_rows:
        if row["status"] != "ok" or round(float(row["ky"]), 12) not in wanted:
            continue
        case = rigid.setdefault((row["record"], float(row["ky"])), {"row": row, "observed": {}})
        case["observed"][row["polarity"]] = float(row["newmark_displacement"])
    flexible: dict[tuple[str, float], dict] = {}
    for row in flexible_rows:
        if row["status"] != "ok":
            continue
        case = flexible.setdefault((row["record"], float(row["ky"])), {})
        period = case.setdefault(float(row["site_period"]), {"sa": float(row["spectral_acceleration"]), "observed": {}})
        period["observed"][row["polarity"]] = float(row["coupled_displacement"])
    rigid_methods = [name for name, entry in METHODS.items() if entry.kind == "rigid"]
    flexible_methods = [name for name, entry in METHODS.items()
                        if entry.kind == "flexible" and name not in AFTER_SLAMMER]
    rows = []
    for (record, ky), case in rigid.items():
        row, measured = case["row"], measures.get(record, {})
        pgv = _number(measured.get("pgv"))
        inputs = {"ky": ky, "pga": float(row["pga"]) / g, "arias_intensity": float(row["arias_intensity"]),
                  "pgv": None if pgv is None else CM_PER_M * pgv, "mean_period": _number(measured.get("mean_period")),
                  "magnitude": magnitudes.get(record)}
        base = {"record": record, "event": row.get("event", ""), "ky": ky}
        for method in rigid_methods:
            rows += _estimate_rows(method, inputs, case["observed"], {**base, "site_period": 0.0})
        # Bray and Travasarou's rigid branch: T_s = 0, Sa = PGA, against the rigid D_n
        rows += _estimate_rows("bray_travasarou_2007", {**inputs, "site_period": 0.0}, case["observed"],
                               {**base, "site_period": 0.0})
        for period, values in sorted(flexible.get((record, ky), {}).items()):
            if period < RIGID_PERIOD:
                continue
            for method in flexible_methods:
                rows += _estimate_rows(method, {**inputs, "site_period": period, "spectral_acceleration": values["sa"]},
                                       values["observed"], {**base, "site_period": period})
    return rows


def _mean(values) -> float | None:
    return float(np.mean(values)) if len(values) else None


def summary_rows(rows: Sequence[Mapping], floor_cm: float, min_rows: int) -> list[dict]:
    """One row per method, k_y and T_s (:data:`SUMMARY_COLUMNS`); bias and σ need ``min_rows`` residuals."""
    groups: dict[tuple, list[Mapping]] = {}
    for row in rows:
        groups.setdefault((row["method"], float(row["ky"]), float(row["site_period"])), []).append(row)
    summary = []
    order = list(METHODS)
    for (method, ky, period), members in sorted(groups.items(), key=lambda item: (order.index(item[0][0]),
                                                                                  item[0][2], item[0][1])):
        observed = np.array([float(row["observed_displacement"]) for row in members])
        estimated = np.array([float(row["estimated_displacement"]) for row in members])
        p_zero = np.array([float(row["estimated_p_zero"]) for row in members])
        sigma = np.array([np.nan if row["estimated_sigma_ln"] in (None, "") else float(row["estimated_sigma_ln"])
                          for row in members])
        below = [_probability_below(floor_cm, median, s, p) for median, s, p in zip(estimated, sigma, p_zero)]
        kept = (observed >= floor_cm) & (estimated > 0.0)
        residuals = np.log(observed[kept] / estimated[kept])
        enough = residuals.size >= max(min_rows, 2)
        summary.append({
            "method": method, "compared_with": "rigid" if period == 0.0 else "coupled", "ky": ky,
            "site_period": period, "rows": len(members),
            "records": len({row["record"] for row in members}),
            "observed_zero_share": float(np.mean(observed <= 0.0)), "estimated_zero_share": float(np.mean(p_zero)),
            "observed_below_floor_share": float(np.mean(observed < floor_cm)),
            "estimated_below_floor_share": float(np.mean(below)), "residual_rows": int(residuals.size),
            "bias_ln": float(residuals.mean()) if enough else None,
            "sigma_ln": float(residuals.std(ddof=1)) if enough else None,
            "rms_ln": float(np.sqrt(np.mean(residuals**2))) if enough else None,
            "method_sigma_ln": _mean(sigma[np.isfinite(sigma)]),
        })
    return summary


def _probability_below(displacement_cm: float, median_cm: float, sigma_ln: float, p_zero: float) -> float:
    """P(D < d) of a lognormal estimate with P(D = 0) (D̂ = 0: certainly below)."""
    if median_cm <= 0.0 or not math.isfinite(sigma_ln):
        return 1.0
    z = math.log(displacement_cm / median_cm) / sigma_ln
    return p_zero + (1.0 - p_zero) * 0.5 * math.erfc(-z / math.sqrt(2.0))


def exceedance_rows(rows: Sequence[Mapping], thresholds_cm: Sequence[float]) -> list[dict]:
    """Per method, k_y, T_s and threshold d [cm]: the observed share with D > d beside the mean predicted P(D > d)."""
    groups: dict[tuple, list[Mapping]] = {}
    for row in rows:
        groups.setdefault((row["method"], float(row["ky"]), float(row["site_period"])), []).append(row)
    order = list(METHODS)
    table = []
    for (method, ky, period), members in sorted(groups.items(), key=lambda item: (order.index(item[0][0]),
                                                                                  item[0][2], item[0][1])):
        for threshold in thresholds_cm:
            observed = [float(row["observed_displacement"]) > threshold for row in members]
            predicted = [1.0 - _probability_below(threshold, float(row["estimated_displacement"]),
                                                  np.nan if row["estimated_sigma_ln"] in (None, "")
                                                  else float(row["estimated_sigma_ln"]),
                                                  float(row["estimated_p_zero"])) for row in members]
            table.append({"method": method, "ky": ky, "site_period": period, "displacement": float(threshold),
                          "observed_share": float(np.mean(observed)),
                          "estimated_probability": float(np.mean(predicted))})
    return table


def write_estimates(displacements_path: str | Path, measures_paths: Sequence[str | Path],
                    flexible_paths: Sequence[str | Path], rows_path: str | Path, summary_path: str | Path,
                    exceedance_path: str | Path, study_path: str | Path, collection: Mapping,
                    critical_accelerations_g: Sequence[float], site_periods: Sequence[float], layer: Mapping,
                    displacement_floor_cm: float, exceedance_cm: Sequence[float], min_rows: int, g: float) -> Path:
    """The study's four files: the rows, the summary, the exceedance table (CSV) and the study's document (JSON).

    ``collection``: the study's resolved collection (its table gives each
    record's event and magnitude ``mw``); ``layer``: ``vs``, ``vs_base`` [m s-1]
    and ``damping`` [1] of the layers; the other arguments as the module's
    docstring says, in its units.
    """
    table = study_collection(collection).table
    magnitudes = {str(record): _number(value) for record, value in table["mw"].items()}
    measures = {row["record"]: row for path in measures_paths for row in read_csv_rows(path)}
    rigid_rows = read_csv_rows(displacements_path)
    flexible_rows = [row for path in flexible_paths for row in read_csv_rows(path)]
    rows = estimate_rows(rigid_rows, measures, flexible_rows, magnitudes, critical_accelerations_g, g)
    write_csv_atomic(rows_path, rows, list(ROW_COLUMNS))
    write_csv_atomic(summary_path, summary_rows(rows, displacement_floor_cm, min_rows), list(SUMMARY_COLUMNS))
    write_csv_atomic(exceedance_path, exceedance_rows(rows, exceedance_cm), list(EXCEEDANCE_COLUMNS))
    records = {row["record"] for row in rigid_rows}
    solved = {row["record"] for row in rigid_rows if row["status"] == "ok"}
    document = {
        "collection": {"kind": collection["kind"], "records": len(records), "records_solved": len(solved),
                       "events": len({row["event"] for row in rigid_rows if row["record"] in solved}),
                       "records_with_magnitude": sum(magnitudes.get(record) is not None for record in solved),
                       "not_solved": sorted(records - solved)},
        "settings": {"critical_accelerations_g": list(map(float, critical_accelerations_g)),
                     "site_periods": list(map(float, site_periods)), "layer": dict(layer),
                     "displacement_floor_cm": displacement_floor_cm, "exceedance_cm": list(map(float, exceedance_cm)),
                     "min_rows": min_rows, "gravity": g,
                     "rigid": "one-way rigid block, exact solver, both polarities (the Jibson (2007) table)",
                     "flexible": "coupled analysis of a linear layer of height V_s T_s / 4, exact scheme, both "
                                 "polarities"},
        "methods": {name: {"label": entry.label, "reference": entry.reference, "kind": entry.kind}
                    for name, entry in METHODS.items()},
        "rows": len(rows),
    }
    write_text_atomic(study_path, json.dumps(document, indent=2, allow_nan=False) + "\n")
    return Path(study_path)
