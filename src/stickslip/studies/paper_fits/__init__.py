"""The paper's μ_max lines recomputed from its own Table 6, beside ours on the same records (Figs. 22 and 23).

``paper_fits.csv`` has one row per (source, record set, x): the least-squares
line μ_max = slope·x + intercept (x = PGA or RMS acceleration [m/s²], slope
in 1/(m/s²), intercept [1]), its 95 % slope intervals (bootstrap over the
points as :func:`stickslip.analysis.linear_fit` does, and Student's t from
:func:`scipy.stats.linregress`), Pearson r with its 95 % interval (Fisher z,
:meth:`scipy.stats._result_classes.PearsonRResult.confidence_interval`) and
p-value.  Sources:

- ``paper``: the paper's printed Table 6 (``paper.yaml``), all eight records
  and the records we have (status ``ok`` in ``table6_results.csv``);
- ``ours``: our Table 6 (``table6_results.csv``) on the records we have.

The paper's printed RMS column is Table 4's model column (erratum E1,
``errata.csv``), so the paper's μ_max–RMS line is computed from the printed
numbers and marked as such: it is not the paper's Fig. 23, whose RMS values
the paper does not give (save Chi Chi's, in its text).
"""

from __future__ import annotations

from pathlib import Path

from scipy import stats

from stickslip.analysis import linear_fit
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.reference import paper_tables

#: The abscissae of the fits (columns of Table 6), in [m/s²].
X_COLUMNS = ("pga", "rms_acceleration")


def fit_row(source: str, records: list[str], x: list[float], y: list[float], x_name: str, n_boot: int,
            seed: int, note: str = "") -> dict:
    """One line μ_max = slope·x + intercept with r, intervals and the record names."""
    fit = linear_fit(x, y, n_boot=n_boot, seed=seed)
    regression = stats.linregress(x, y)
    t = stats.t.ppf(0.975, len(x) - 2)
    pearson = stats.pearsonr(x, y)
    r_interval = pearson.confidence_interval(0.95)
    return {"source": source, "records": " ".join(records), "n": len(x), "x": x_name, "x_units": "m s-2",
            "slope": fit.slope, "intercept": fit.intercept,
            "slope_low_bootstrap": fit.slope_interval[0], "slope_high_bootstrap": fit.slope_interval[1],
            "slope_low_t": regression.slope - t * regression.stderr,
            "slope_high_t": regression.slope + t * regression.stderr,
            "r": fit.r, "r_low": float(r_interval.low), "r_high": float(r_interval.high),
            "p_value": float(pearson.pvalue), "note": note}


def fit_rows(results: list[dict[str, str]], n_boot: int, seed: int) -> list[dict]:
    """The paper's fits (all its records, and the ones we have) and ours on the ones we have."""
    printed = paper_tables()["table6_results"]["rows"]
    ours = {row["record"]: row for row in results if row["status"] == "ok"}
    have = [record for record in printed if record in ours]
    rows = []
    for x_name in X_COLUMNS:
        note = ("x is the printed RMS column, which repeats Table 4's model E_df (erratum E1): "
                "not the paper's Fig. 23" if x_name == "rms_acceleration" else "")
        for label, records in (("all its records", list(printed)), ("the records we have", have)):
            if len(records) < 3:
                continue
            rows.append(fit_row(f"paper ({label})", records, [printed[r][x_name] for r in records],
                                [printed[r]["mu_max"] for r in records], x_name, n_boot, seed, note))
        if len(have) >= 3:
            rows.append(fit_row("ours (the records we have)", have, [float(ours[r][x_name]) for r in have],
                                [float(ours[r]["mu_max"]) for r in have], x_name, n_boot, seed))
    return rows


def write_paper_fits(results_path, fits_path, n_boot: int, seed: int) -> Path:
    """``paper_fits.csv`` from ``table6_results.csv`` and the paper's Table 6."""
    return write_csv_atomic(fits_path, fit_rows(read_csv_rows(results_path), n_boot, seed))

