"""Jibson's (2007) two regression forms refitted on our displacements, with bootstrap intervals over records.

The rows are those of :mod:`stickslip.studies.jibson2007.displacements` (one per record,
polarity and critical acceleration a_c).  The two forms of :data:`FORMS`, in
Jibson's units (D_n [cm], a_c and a_max [g], I_a [m s-1], logarithms base 10),
with r = a_c/a_max:

* ``critical_acceleration_ratio``:
  log10 D_n = c0 + c1·log10(1 − r) + c2·log10 r  (Jibson: 0.215, 2.341, −1.438);
* ``arias_intensity_and_ratio``:
  log10 D_n = c0 + c1·log10 I_a + c2·log10 r  (Jibson: −1.474, 0.561, −3.833).

His equations (:func:`~stickslip.estimates.jibson.predict`, the regressors of
:func:`~stickslip.estimates.jibson.design_matrix`) are those of
:mod:`stickslip.estimates.jibson`.  Each is fitted by ordinary least squares on log10 D_n (:func:`numpy.linalg.lstsq`);
σ is the residual standard deviation, √(Σ residual² / (n − p)) [log10 units].
The coefficients' and σ's intervals are percentile intervals of a bootstrap
that resamples *records* with replacement (all rows of a drawn record enter
together: the rows of one record, its a_c values and polarities, are not
independent), ``n_boot`` resamples from ``seed``.

Which rows enter (:func:`select`), each exclusion counted by its reason
(:data:`EXCLUSIONS`): rows of records that could not be solved; rows with
a_c ≥ a_max (the issue's grid is a_c < PGA; there D_n = 0 anyway); rows where
the block never slides, D_n = 0, which have no logarithm and cannot enter a
log fit; and, for the selection with a floor, rows with 0 < D_n < floor.
Every fit is made twice: with the configured displacement floor and without
any (all D_n > 0).  Jibson's printed values are read from the package's
reference file (``stickslip/reference/jibson2007.yaml``) and set beside ours,
never computed with.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from stickslip.estimates.jibson import FORM_TERMS, design_matrix, jibson_reference, predict  # noqa: F401 (this module's API)
from stickslip.plumbing.files import read_csv_rows, write_text_atomic

#: The forms refitted: name -> their terms, in coefficient order (c0, c1, c2 of the module's docstring).
FORMS = {form: FORM_TERMS[form] for form in ("critical_acceleration_ratio", "arias_intensity_and_ratio")}

#: Why a row does not enter a fit, in the order the reasons are applied.
EXCLUSIONS = ("not solved", "a_c >= PGA", "does not slide (D_n = 0)", "below the displacement floor")

#: Confidence level of the bootstrap intervals.
CONFIDENCE = 0.95


def select(rows: Sequence[Mapping], floor_cm: float | None) -> tuple[list[Mapping], dict[str, int]]:
    """The rows that enter a fit, and how many rows each reason of :data:`EXCLUSIONS` kept out.

    ``rows``: the displacement table's rows (strings or numbers); ``floor_cm``:
    the displacement floor [cm], or None for none (then every D_n > 0 enters).
    """
    kept, excluded = [], dict.fromkeys(EXCLUSIONS, 0)
    for row in rows:
        if row["status"] != "ok":
            reason = "not solved"
        elif float(row["critical_acceleration_ratio"]) >= 1.0:
            reason = "a_c >= PGA"
        elif float(row["newmark_displacement"]) <= 0.0:
            reason = "does not slide (D_n = 0)"
        elif floor_cm is not None and float(row["newmark_displacement"]) < floor_cm:
            reason = "below the displacement floor"
        else:
            kept.append(row)
            continue
        excluded[reason] += 1
    return kept, excluded


def least_squares(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, float, float]:
    """Coefficients, σ = √(SSE/(n − p)) and R² of the least-squares fit of ``y`` on the columns of ``x``."""
    coefficients, *_ = np.linalg.lstsq(x, y, rcond=None)
    residuals = y - x @ coefficients
    sse = float(residuals @ residuals)
    sst = float(((y - y.mean()) ** 2).sum())
    return coefficients, float(np.sqrt(sse / (y.size - x.shape[1]))), 1.0 - sse / sst if sst > 0 else float("nan")


def record_bootstrap(x: np.ndarray, y: np.ndarray, groups: Sequence[str], n_boot: int,
                     seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Coefficients (n_used, p) and σ (n_used,) of ``n_boot`` fits on resamples of whole groups (records).

    Each resample draws as many groups as there are, with replacement, and
    takes all their rows; a resample whose regressors are rank-deficient (too
    few distinct rows) is skipped, so n_used ≤ ``n_boot``.
    """
    _, codes = np.unique(np.asarray(groups, dtype=str), return_inverse=True)
    order = np.argsort(codes, kind="stable")
    members = np.split(order, np.cumsum(np.bincount(codes))[:-1])
    rng = np.random.default_rng(seed)
    coefficients, sigmas = [], []
    for _ in range(n_boot):
        rows = np.concatenate([members[k] for k in rng.integers(0, len(members), len(members))])
        if rows.size <= x.shape[1] or np.linalg.matrix_rank(x[rows]) < x.shape[1]:
            continue
        values, sigma, _ = least_squares(x[rows], y[rows])
        coefficients.append(values)
        sigmas.append(sigma)
    return np.array(coefficients).reshape(-1, x.shape[1]), np.array(sigmas)


def fit_form(form: str, rows: Sequence[Mapping], n_boot: int, seed: int) -> dict:
    """``form`` fitted on ``rows`` (selected rows of the table): coefficients, σ, R², intervals, counts.

    Too few rows or records for a fit (fewer rows than 1 + the number of
    coefficients, fewer than two records, or regressors without spread) give
    a ``status`` that says so and no values.
    """
    terms = FORMS[form]
    records = [row["record"] for row in rows]
    result = {"status": "ok", "rows": len(rows), "records": len(set(records)),
              "events": len({row["event"] for row in rows})}
    if len(rows) <= len(terms) or result["records"] < 2:
        return {**result, "status": f"too few data: {len(rows)} rows of {result['records']} records; a fit of "
                                    f"{len(terms)} coefficients needs more than {len(terms)} rows of at least 2 records"}
    x = design_matrix(form, [float(row["critical_acceleration_ratio"]) for row in rows],
                      [float(row["arias_intensity"]) for row in rows])
    if np.linalg.matrix_rank(x) < len(terms):
        return {**result, "status": "the regressors have no spread: the coefficients are not determined"}
    y = np.log10([float(row["newmark_displacement"]) for row in rows])
    values, sigma, r_squared = least_squares(x, y)
    boot_values, boot_sigmas = record_bootstrap(x, y, records, n_boot, seed)
    tails = 100 * np.array([(1 - CONFIDENCE) / 2, (1 + CONFIDENCE) / 2])
    low, high = (np.percentile(boot_values, tails, axis=0) if len(boot_sigmas)
                 else np.full((2, len(terms)), np.nan))
    sigma_low, sigma_high = np.percentile(boot_sigmas, tails) if len(boot_sigmas) else (np.nan, np.nan)
    return {**result, "r_squared": r_squared, "bootstrap_resamples": int(len(boot_sigmas)),
            "coefficients": {term: {"value": float(values[k]), "low": _number(low[k]), "high": _number(high[k])}
                             for k, term in enumerate(terms)},
            "sigma": {"value": sigma, "low": _number(sigma_low), "high": _number(sigma_high)}}


def _number(value) -> float | None:
    """``value`` as a float, None when it is not a number (JSON has no NaN): an interval no resample could give."""
    return float(value) if np.isfinite(value) else None


def fit_selection(rows: Sequence[Mapping], floor_cm: float | None, n_boot: int, seed: int) -> dict:
    """Both forms fitted on the rows :func:`select` keeps with ``floor_cm``, and the selection's counts."""
    kept, excluded = select(rows, floor_cm)
    return {"displacement_floor_cm": floor_cm, "rows": len(kept), "records": len({row["record"] for row in kept}),
            "excluded_rows": excluded, "forms": {form: fit_form(form, kept, n_boot, seed) for form in FORMS}}


def jibson_fit(rows: Sequence[Mapping], critical_accelerations_g: Sequence[float], displacement_floor_cm: float,
               n_boot: int, seed: int, g: float) -> dict:
    """The fit document: settings, the collection's counts, both selections' fits, and Jibson's values beside them."""
    solved = [row for row in rows if row["status"] == "ok"]
    records = list(dict.fromkeys(row["record"] for row in rows))
    return {
        "reference": jibson_reference(),
        "settings": {"critical_accelerations_g": list(map(float, critical_accelerations_g)),
                     "displacement_floor_cm": displacement_floor_cm, "n_boot": n_boot, "seed": seed,
                     "confidence": CONFIDENCE, "gravity": g,
                     "sliding": "one-way (downslope only), rigid block, exact solver; polarities normal and inverse"},
        "collection": {"records": len(records), "records_solved": len({row["record"] for row in solved}),
                       "events": len({row["event"] for row in solved}), "rows": len(rows)},
        "selections": {"with_floor": fit_selection(rows, displacement_floor_cm, n_boot, seed),
                       "without_floor": fit_selection(rows, None, n_boot, seed)},
    }


def write_jibson_fit(table_path: str | Path, fit_path: str | Path, critical_accelerations_g: Sequence[float],
                     displacement_floor_cm: float, n_boot: int, seed: int, g: float) -> Path:
    """:func:`jibson_fit` of the displacement table ``table_path``, written as JSON to ``fit_path``, atomically."""
    document = jibson_fit(read_csv_rows(table_path), critical_accelerations_g, displacement_floor_cm, n_boot, seed, g)
    write_text_atomic(fit_path, json.dumps(document, indent=2, allow_nan=False) + "\n")
    return Path(fit_path)
