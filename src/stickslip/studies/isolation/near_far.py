"""Near-fault against far-field components in the isolation study, per fixed-base period T, radius R and μ.

The components of the case table (:func:`stickslip.studies.isolation.tables.case_rows`, one row per component, T,
R and μ; numbers or the strings of its CSV) are split by their rupture distance [km]: near-fault at most
``near_fault_km``, far-field beyond it, and neither where the source gives none (the three-component stations),
counted.  Where both groups hold at least ``min_records`` components, :func:`near_far_rows` gives per T, R, μ and
quantity each group's number of components, median and 84th percentile (numpy's linear interpolation between
order statistics) and the two-sided Mann–Whitney U test of the two groups (:func:`scipy.stats.mannwhitneyu`: U of
the near-fault group and its p-value); else :func:`near_far_reason` says why not and :func:`far_field_status` how
to add the records.  ``isolation_near_far.csv`` holds the rows (:data:`NEAR_FAR_FIELDS`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from scipy import stats

#: Each cell's statistics, NaN where a group has no finite value there.
STATISTICS = ["median_near", "p84_near", "median_far", "p84_far", "mann_whitney_u", "mann_whitney_p_value"]
NEAR_FAR_FIELDS = ["period", "radius", "mu", "quantity", "units", "n_near", "n_far", *STATISTICS]
#: The groups of :func:`distance_groups`.
GROUPS = ("near", "far", "unknown")


def distance_group(distance: float, near_fault_km: float) -> str:
    """``near`` within ``near_fault_km`` [km] of the rupture, ``far`` beyond it, ``unknown`` where the rupture
    distance ``distance`` [km] is not known (NaN)."""
    if not math.isfinite(distance):
        return "unknown"
    return "near" if distance <= near_fault_km else "far"


def distance_groups(cases: Sequence[Mapping], near_fault_km: float) -> dict[str, set[str]]:
    """The components (record ids) of ``cases`` in each group of :func:`distance_group`."""
    groups = {name: set() for name in GROUPS}
    for row in cases:
        distance = float(row["rupture_distance"]) if row["rupture_distance"] not in ("", None) else math.nan
        groups[distance_group(distance, near_fault_km)].add(row["record"])
    return groups


def near_far_reason(groups: Mapping[str, set], near_fault_km: float, min_records: int) -> str | None:
    """Why near-fault and far-field components are not compared (``None`` when they are)."""
    near, far = len(groups["near"]), len(groups["far"])
    if near < min_records or far < min_records:
        return (f"too few components: {near} within {near_fault_km:g} km of the rupture and {far} farther, a "
                f"comparison needs at least {min_records} on each side (collection_study.min_records)")
    return None


def far_field_status(cases: Sequence[Mapping], near_fault_km: float, min_records: int) -> str:
    """One sentence on the near-fault against far-field comparison: what was compared, or why not and what it needs
    (the far-field records, where they are missing)."""
    groups = distance_groups(cases, near_fault_km)
    near, far, unknown = (len(groups[name]) for name in GROUPS)
    reason = near_far_reason(groups, near_fault_km, min_records)
    if reason is None:
        return (f"Near-fault against far-field: {near} components within {near_fault_km:g} km of the rupture against "
                f"{far} farther ({unknown} without a rupture distance, in neither group), per T, R and μ "
                "(isolation_near_far.csv).")
    sentence = f"Near-fault against far-field is not compared: {reason}."
    if far < min_records:
        sentence += (f" The SLAMMER library's far-field records (rupture distance > {near_fault_km:g} km) are not in "
                     "its folder: collection_study.download: true, where the internet is reachable, or "
                     "STICKSLIP_SLAMMER_DIR set to a folder holding the whole library adds them.")
    return sentence


def near_far_rows(cases: Sequence[Mapping], quantities: Mapping[str, str], near_fault_km: float,
                  min_records: int) -> list[dict]:
    """Per T [s], R [m], μ [1] and quantity (``quantities``: column -> units) of ``cases``, each group's number
    of finite values, median and 84th percentile and the two-sided Mann–Whitney U test (U of the near-fault group,
    p-value); empty where :func:`near_far_reason` gives a reason."""
    groups = distance_groups(cases, near_fault_km)
    if near_far_reason(groups, near_fault_km, min_records):
        return []
    group_of = {record: group for group in ("near", "far") for record in groups[group]}
    cells: dict[tuple, dict[str, list[Mapping]]] = {}
    for row in cases:
        if row["record"] in group_of:
            cell = cells.setdefault((float(row["period"]), float(row["radius"]), float(row["mu"])),
                                    {"near": [], "far": []})
            cell[group_of[row["record"]]].append(row)
    rows = []
    for (period, radius, mu), members in sorted(cells.items()):
        for quantity, units in quantities.items():
            near, far = (_finite([row[quantity] for row in members[group]]) for group in ("near", "far"))
            compared = {"n_near": near.size, "n_far": far.size, **dict.fromkeys(STATISTICS, math.nan)}
            if near.size and far.size:
                test = stats.mannwhitneyu(near, far, alternative="two-sided")
                compared.update({"median_near": float(np.median(near)), "p84_near": float(np.percentile(near, 84)),
                                 "median_far": float(np.median(far)), "p84_far": float(np.percentile(far, 84)),
                                 "mann_whitney_u": float(test.statistic),
                                 "mann_whitney_p_value": float(test.pvalue)})
            rows.append({"period": period, "radius": radius, "mu": mu, "quantity": quantity, "units": units,
                         **compared})
    return rows


def near_far_summary(rows: Sequence[Mapping], significance: float = 0.05) -> dict[str, dict]:
    """Per quantity over the cells of :func:`near_far_rows`: the number of cells, those where the near-fault median
    is the larger, those of p-value below ``significance``, and the smallest and largest ratio of the medians
    near-fault / far-field."""
    summary = {}
    for quantity in dict.fromkeys(row["quantity"] for row in rows):
        chosen = [row for row in rows if row["quantity"] == quantity and float(row["median_far"]) > 0]
        ratios = [float(row["median_near"]) / float(row["median_far"]) for row in chosen]
        summary[quantity] = {"cells": len(chosen),
                             "near_larger": sum(float(row["median_near"]) > float(row["median_far"])
                                                for row in chosen),
                             "significant": sum(float(row["mann_whitney_p_value"]) < significance for row in chosen),
                             "significance": significance, "median_ratio_min": min(ratios),
                             "median_ratio_max": max(ratios)}
    return summary


def _finite(values) -> np.ndarray:
    values = np.asarray([float(value) for value in values], dtype=float)
    return values[np.isfinite(values)]
