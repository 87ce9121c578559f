"""Relations of μ_max with PGA and RMS acceleration across records (the paper's Figs. 22 and 23).

Reads ``table6_results.csv`` (:mod:`stickslip.studies.mu_max`) and writes
``fits.json``: for μ_max on the paper's grid and the continuous μ_max, against
PGA [m/s²] and against RMS acceleration [m/s²], the raw points, the
least-squares line with its bootstrap band, Pearson r and Spearman ρ
(:func:`stickslip.analysis.relation_summary`).  With fewer available records
than ``min_records`` a relation says so (``"status": "too few records: …"``)
instead of a fit, so that the figures and the index can show why it is absent.
"""

from __future__ import annotations

import json
from pathlib import Path

from stickslip.analysis import relation_summary
from stickslip.plumbing.files import read_csv_rows, write_text_atomic
from stickslip.units import UNITS

#: (y, x) pairs related, in the order of fits.json.
RELATIONS = [(y, x) for x in ("pga", "rms_acceleration") for y in ("mu_max", "mu_max_continuous")]


def relations(rows: list[dict[str, str]], n_boot: int, seed: int, min_records: int = 3) -> dict:
    """The fits.json document from the rows of ``table6_results.csv``."""
    ok = [row for row in rows if row["status"] == "ok"]
    labels = [row["record"] for row in ok]
    summary = {
        "units": {name: UNITS[name] for name in ("pga", "rms_acceleration", "mu_max", "mu_max_continuous")},
        "records": labels,
        "missing_records": {row["record"]: row["status"] for row in rows if row["status"] != "ok"},
    }
    for y_name, x_name in RELATIONS:
        key = f"{y_name}_vs_{x_name}"
        if len(ok) < min_records:
            summary[key] = {"status": f"too few records: {len(ok)} available, a fit needs at least {min_records}",
                            "points": [{"label": row["record"], "x": float(row[x_name]), "y": float(row[y_name])}
                                       for row in ok]}
            continue
        summary[key] = {"status": "ok", **relation_summary([float(row[x_name]) for row in ok],
                                                           [float(row[y_name]) for row in ok],
                                                           labels=labels, n_boot=n_boot, seed=seed)}
    return summary


def write_relations(results_path: str | Path, fits_path: str | Path, n_boot: int, seed: int,
                    min_records: int = 3) -> Path:
    """Write ``fits.json`` from ``table6_results.csv``, atomically."""
    rows = read_csv_rows(results_path)
    write_text_atomic(fits_path, json.dumps(relations(rows, n_boot, seed, min_records), indent=2) + "\n")
    return Path(fits_path)
