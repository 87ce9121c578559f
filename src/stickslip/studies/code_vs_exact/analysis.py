"""The codes' equivalent-linear displacement against the exact one, over the library: bias, scatter, unconservative share.

:func:`write_code_vs_exact_analysis` joins the case tables of the jobs
(:mod:`stickslip.studies.code_vs_exact.cases`) into ``cases.csv`` and writes:

- ``bias.csv``: per grouping (:data:`GROUPINGS`) and group, per code: the
  number of cases n, the bias (mean) and σ (standard deviation, n − 1) of
  ln(D_exact/D_code), its root mean square, and the share of cases with
  D_exact > ``unconservative_factor`` · D_code (the code unconservative by
  more than 20 % for 1.2);
- ``code_vs_exact.json``: what was studied and what is missing, and which
  code's damping reduction comes closest (smallest RMS of the log ratio over
  every case without a vertical).

Every grouping but ``vertical`` pools the cases without a vertical (the
SLAMMER pairs have none; the three-component stations enter once);
``vertical`` compares the three-component stations without and with theirs.
A case with D_exact = 0 (the slider never slides) has no log ratio and
counts in the unconservative share as conservative; a case without a code D
(no fixed point found, said in its ``note``) counts in neither.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from stickslip.plumbing.files import provenance, read_csv_rows, write_csv_atomic, write_text_atomic
from stickslip.studies.code_vs_exact.displacement import CODES
from stickslip.studies.code_vs_exact.cases import CASE_COLUMNS, PULSE_UNKNOWN

#: The groupings of bias.csv, in order.
GROUPINGS = ("all", "library", "direction", "radius", "mu", "d_code_over_r", "distance", "pulse", "vertical")

#: The groupings by a case's number in the column of that name (R [m], μ [1]), and by its text.
BY_NUMBER, BY_TEXT = ("radius", "mu"), ("library", "pulse")

#: Columns of bias.csv.
BIAS_COLUMNS = ("grouping", "group", "code", "n", "bias", "sigma", "rms", "unconservative_share", "no_slip",
                "no_code_displacement")


def _number(text: str) -> float:
    return float(text) if text not in ("", None) else math.nan


def _group(row: dict, grouping: str, near_fault_km: float, edges: Sequence[float]) -> str | None:
    """The group of ``row`` in ``grouping`` (None: not in it)."""
    if grouping == "vertical":
        return row["vertical"] if row["library"] == "three_component" else None
    if row["vertical"] != "none":
        return None
    if grouping == "all":
        return "all"
    if grouping == "direction":
        return "plane" if row["direction"] == "plane" else "one direction"
    if grouping in BY_TEXT:
        return row[grouping]
    if grouping in BY_NUMBER:
        return f"{float(row[grouping]):g}"
    if grouping == "distance":
        distance = _number(row["rupture_distance"])
        return "unknown" if math.isnan(distance) else "near-fault" if distance <= near_fault_km else "far-field"
    ratio = _number(row["d_code_over_r"])
    if math.isnan(ratio):
        return None
    index = int(np.searchsorted(edges, ratio, side="right"))
    low, high = ([0.0, *edges][index], [*edges, math.inf][index])
    return f"{low:g}-{high:g}"


def bias_rows(rows: Sequence[dict], near_fault_km: float, d_over_r_edges: Sequence[float],
              unconservative_factor: float) -> list[dict]:
    """The rows of bias.csv (module docstring) from the case rows (as read from CSV: strings)."""
    cells: dict[tuple, list[dict]] = {}
    for row in rows:
        for grouping in GROUPINGS:
            group = _group(row, grouping, near_fault_km, d_over_r_edges)
            if group is not None:
                cells.setdefault((grouping, group, row["code"]), []).append(row)
    out = []
    order = {name: index for index, name in enumerate(GROUPINGS)}
    for (grouping, group, code), members in sorted(cells.items(), key=lambda item: (order[item[0][0]], _key(item[0][1]),
                                                                                   list(CODES).index(item[0][2]))):
        exact = np.array([_number(row["d_exact"]) for row in members])
        code_d = np.array([_number(row["d_code"]) for row in members])
        designed = np.isfinite(code_d)
        logs = np.log(exact[designed & (exact > 0.0)] / code_d[designed & (exact > 0.0)])
        out.append({"grouping": grouping, "group": group, "code": code, "n": int(logs.size),
                    "bias": float(logs.mean()) if logs.size else math.nan,
                    "sigma": float(logs.std(ddof=1)) if logs.size > 1 else math.nan,
                    "rms": float(np.sqrt(np.mean(logs**2))) if logs.size else math.nan,
                    "unconservative_share": (float(np.mean(exact[designed] > unconservative_factor * code_d[designed]))
                                             if designed.any() else math.nan),
                    "no_slip": int(np.sum(designed & (exact <= 0.0))), "no_code_displacement": int(np.sum(~designed))})
    return out


def _key(group: str):
    """Groups in numeric order where they are numbers or ranges, else by name."""
    try:
        return (0, float(group.split("-")[0]), "")
    except ValueError:
        return (1, 0.0, group)


def summary(rows: Sequence[dict], bias: Sequence[dict], pairs_path: str | Path, settings: dict,
            three_component_message: str) -> dict:
    """code_vs_exact.json: the counts, what is missing, the pooled statistics per code and the closest code."""
    pooled = {row["code"]: row for row in bias if row["grouping"] == "all"}
    ranked = sorted((row for row in pooled.values() if row["n"]), key=lambda row: row["rms"])
    pairs = read_csv_rows(pairs_path)
    libraries = {name: sorted({row["station"] for row in rows if row["library"] == name})
                 for name in ("slammer", "three_component")}
    distances = [_number(row["rupture_distance"]) for row in rows if row["library"] == "slammer"]
    far = sum(1 for value in distances if value > settings["near_fault_km"])
    return {
        **settings,
        "pairs": len(libraries["slammer"]),
        "pairs_listed": len(pairs),
        "pairs_not_read": sum(1 for row in pairs if row["status"] != "ok"),
        "three_component_stations": len(libraries["three_component"]),
        "three_component_status": three_component_message or "ok",
        "cases": len(rows),
        "no_code_displacement": sum(1 for row in rows if row["d_code"] in ("", "nan")),
        "bracketed": sum(1 for row in rows if row["method"] == "bracketed"),
        "far_field_cases": far,
        "far_field_status": ("ok" if far else f"No far-field record (rupture distance > {settings['near_fault_km']:g}"
                             " km) is here: the near-fault against far-field comparison needs the SLAMMER library's "
                             "records beyond it (collection_study.download: true, or the full library's folder)."),
        "pulse_status": (f"not known: neither the SLAMMER library's database nor the three-component manifest says "
                         f"which records are pulse-like (every case is '{PULSE_UNKNOWN}')"),
        "by_code": {code: {key: row[key] for key in ("n", "bias", "sigma", "rms", "unconservative_share")}
                    for code, row in pooled.items()},
        "closest_code": ranked[0]["code"] if ranked else None,
        "available": bool(rows),
        "provenance": provenance(),
    }


def write_code_vs_exact_analysis(case_paths: Sequence[str | Path], pairs_path: str | Path, cases_path: str | Path,
                                 bias_path: str | Path, summary_path: str | Path, near_fault_km: float,
                                 d_over_r_edges: Sequence[float], unconservative_factor: float, radii, mu,
                                 three_component_message: str = "") -> list[Path]:
    """Join the jobs' case tables and write cases.csv, bias.csv and code_vs_exact.json (module docstring)."""
    rows = [row for path in case_paths for row in read_csv_rows(path)]
    write_csv_atomic(cases_path, rows, list(CASE_COLUMNS))
    bias = bias_rows(rows, near_fault_km, d_over_r_edges, unconservative_factor)
    write_csv_atomic(bias_path, bias, list(BIAS_COLUMNS))
    settings = {"near_fault_km": near_fault_km, "d_over_r_edges": list(d_over_r_edges),
                "unconservative_factor": unconservative_factor, "radii_m": [float(r) for r in radii],
                "mu": [float(m) for m in mu], "codes": list(CODES)}
    document = summary(rows, bias, pairs_path, settings, three_component_message)
    write_text_atomic(summary_path, json.dumps(document, indent=2, default=_plain) + "\n")
    return [Path(cases_path), Path(bias_path), Path(summary_path)]


def _plain(value):
    return value.item() if hasattr(value, "item") else str(value)

