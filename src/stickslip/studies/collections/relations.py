"""How μ_max depends on the records' intensity measures and metadata, across a collection.

For each predictor of :data:`PREDICTORS`, over the records with a value for
it: Pearson r and Spearman ρ with 95 % bootstrap intervals
(:func:`scipy.stats.bootstrap`, pairs resampled, BCa), the least-squares line
μ_max = slope·x + intercept with a 95 % bootstrap interval of the slope, and
its prediction error under leave-one-event-out cross-validation: the records
of one earthquake are not independent (same source, often the same station's
two components), so each event in turn is left out, the line is fitted on the
others and the left-out records are predicted.  ``loeo_rmse`` is the root
mean square of those errors, ``loeo_rmse_mean_only`` that of predicting the
training mean, and ``loeo_skill`` = 1 − their ratio (0: no better than the
mean; 1: perfect).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from scipy import stats

from stickslip.collections.members import studied

#: Predictors of μ_max: table column -> (units, label).
PREDICTORS = {
    "pga": ("m s-2", "PGA"),
    "pgv": ("m s-1", "PGV"),
    "pgv_over_pga": ("s", "PGV/PGA"),
    "rms_acceleration": ("m s-2", "RMS acceleration over t_e"),
    "arias_intensity": ("m s-1", "Arias intensity"),
    "significant_duration": ("s", "significant duration t_e"),
    "mean_period": ("s", "mean period T_m"),
    "mw": ("1", "moment magnitude Mw"),
    "rupture_distance": ("km", "rupture distance"),
    "vs30": ("m s-1", "Vs30"),
}

#: The response related to the predictors.
RESPONSE = "mu_max_continuous"


def leave_one_event_out_splits(events: Sequence[str]) -> list[tuple[np.ndarray, np.ndarray]]:
    """(train, test) index arrays, one split per event: the test set is every record of that event."""
    events = np.asarray(events, dtype=object)
    return [(np.flatnonzero(events != event), np.flatnonzero(events == event))
            for event in dict.fromkeys(events.tolist())]


def loeo_errors(x: np.ndarray, y: np.ndarray, events: Sequence[str]) -> tuple[np.ndarray, np.ndarray]:
    """Prediction errors of the line and of the mean under leave-one-event-out cross-validation.

    A split whose training set has fewer than three records or a single x
    value predicts nothing (its errors are NaN).
    """
    line_errors = np.full(y.size, np.nan)
    mean_errors = np.full(y.size, np.nan)
    for train, test in leave_one_event_out_splits(events):
        if train.size < 3 or np.ptp(x[train]) == 0:
            continue
        slope, intercept = np.polyfit(x[train], y[train], 1)
        line_errors[test] = slope * x[test] + intercept - y[test]
        mean_errors[test] = y[train].mean() - y[test]
    return line_errors, mean_errors


def _pearson(x, y, axis=-1):
    x = x - x.mean(axis=axis, keepdims=True)
    y = y - y.mean(axis=axis, keepdims=True)
    return (x * y).sum(axis=axis) / np.sqrt((x * x).sum(axis=axis) * (y * y).sum(axis=axis))


def _spearman(x, y, axis=-1):
    return _pearson(stats.rankdata(x, axis=axis), stats.rankdata(y, axis=axis), axis=axis)


def _slope(x, y, axis=-1):
    x = x - x.mean(axis=axis, keepdims=True)
    return (x * (y - y.mean(axis=axis, keepdims=True))).sum(axis=axis) / (x * x).sum(axis=axis)


def _interval(statistic, x, y, n_boot: int, seed: int) -> tuple[float, float]:
    """95 % BCa bootstrap interval of ``statistic(x, y)``, pairs resampled; NaN when undefined."""
    with np.errstate(invalid="ignore", divide="ignore"):
        result = stats.bootstrap((x, y), statistic, paired=True, vectorized=True, n_resamples=n_boot,
                                 confidence_level=0.95, random_state=np.random.default_rng(seed))
    return float(result.confidence_interval.low), float(result.confidence_interval.high)


def relation_row(name: str, x: np.ndarray, y: np.ndarray, events: Sequence[str], n_boot: int, seed: int,
                 min_records: int) -> dict:
    """One row of the relations table for predictor ``name`` (see the module's docstring)."""
    units, label = PREDICTORS.get(name, ("", name))
    row = {"predictor": name, "label": label, "units": units, "n": int(x.size),
           "n_events": len(set(events))}
    if x.size == 0:
        return {**row, "status": f"no record has a value of {label}"}
    if x.size < max(min_records, 3):
        return {**row, "status": f"too few records: {x.size} with a value of {label}, a fit needs at least "
                                 f"{max(min_records, 3)}"}
    if np.ptp(x) == 0 or np.ptp(y) == 0:
        return {**row, "status": f"no spread: every record has the same {label if np.ptp(x) == 0 else 'mu_max'}"}
    slope, intercept = np.polyfit(x, y, 1)
    spearman = stats.spearmanr(x, y)
    line_errors, mean_errors = loeo_errors(x, y, events)
    predicted = np.isfinite(line_errors)
    rmse = float(np.sqrt(np.mean(line_errors[predicted] ** 2))) if predicted.any() else np.nan
    rmse_mean = float(np.sqrt(np.mean(mean_errors[predicted] ** 2))) if predicted.any() else np.nan
    r_low, r_high = _interval(_pearson, x, y, n_boot, seed)
    rho_low, rho_high = _interval(_spearman, x, y, n_boot, seed)
    slope_low, slope_high = _interval(_slope, x, y, n_boot, seed)
    return {
        **row, "status": "ok",
        "pearson_r": float(stats.pearsonr(x, y).statistic), "pearson_r_low": r_low, "pearson_r_high": r_high,
        "spearman_rho": float(spearman.statistic), "spearman_rho_low": rho_low, "spearman_rho_high": rho_high,
        "spearman_p_value": float(spearman.pvalue),
        "slope": float(slope), "slope_low": slope_low, "slope_high": slope_high, "intercept": float(intercept),
        "loeo_rmse": rmse, "loeo_rmse_mean_only": rmse_mean,
        "loeo_skill": 1.0 - rmse / rmse_mean if rmse_mean > 0 else np.nan,
        "loeo_records_predicted": int(predicted.sum()),
    }


def relations_rows(rows: list[dict], n_boot: int, seed: int, min_records: int) -> list[dict]:
    """The relations table: one row per predictor, from the records studied (:func:`~stickslip.collections.members.studied`)."""
    table = []
    for name in PREDICTORS:
        pairs = [(float(row[name]), float(row[RESPONSE]), row["event"]) for row in studied(rows)
                 if row.get(name) not in ("", None) and row[RESPONSE] not in ("", None)]
        x = np.array([p[0] for p in pairs])
        y = np.array([p[1] for p in pairs])
        table.append(relation_row(name, x, y, [p[2] for p in pairs], n_boot, seed, min_records))
    return table


def best_predictor(relations: list[dict], total: int, coverage: float = 0.9) -> dict | None:
    """The predictor with the smallest leave-one-event-out error among those known for ≥ ``coverage`` of records."""
    usable = [row for row in relations if row["status"] == "ok" and row["n"] >= coverage * total
              and np.isfinite(row["loeo_rmse"])]
    return min(usable, key=lambda row: row["loeo_rmse"]) if usable else None


def prediction_band(x: np.ndarray, y: np.ndarray, at: np.ndarray, level: float = 0.95) -> dict:
    """Least-squares line through (x, y) and its ``level`` prediction band at the abscissae ``at``.

    The band is ŷ ± t·s·√(1 + 1/n + (x − x̄)²/Sxx), with s the residual
    standard deviation and t the Student quantile with n − 2 degrees of
    freedom: where a new record's μ_max falls with probability ``level``, if
    the scatter about the line is normal and even.
    """
    n = x.size
    slope, intercept = np.polyfit(x, y, 1)
    residual = y - (slope * x + intercept)
    s = np.sqrt(np.sum(residual ** 2) / (n - 2))
    sxx = np.sum((x - x.mean()) ** 2)
    half = stats.t.ppf(0.5 + level / 2, n - 2) * s * np.sqrt(1 + 1 / n + (at - x.mean()) ** 2 / sxx)
    fitted = slope * at + intercept
    return {"slope": float(slope), "intercept": float(intercept), "residual_sd": float(s), "level": level,
            "x": at.tolist(), "fitted": fitted.tolist(), "low": (fitted - half).tolist(),
            "high": (fitted + half).tolist()}
