"""The simplified estimates ranked by how close each came to the rigorous answers.

The library study (:mod:`stickslip.studies.estimates.simplified`) writes, per
method, k_y and T_s, the statistics of the log residual ln(D / D_est); the
index and the study's page rank the methods on them.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence


def ranking_rows(summary: Sequence[Mapping]) -> list[dict]:
    """Per comparison (rigid D_n or coupled D), k_y and T_s: the methods in order of their RMS log error.

    ``summary``: rows of the summary (strings or numbers); groups without a
    residual statistic are left out.  Each row: ``compared_with``, ``ky``,
    ``site_period``, ``rank`` (1 the smallest RMS of ln(D / D_est)), ``method``,
    ``rms_ln``, ``bias_ln``, ``sigma_ln``.
    """
    groups: dict[tuple, list[Mapping]] = {}
    for row in summary:
        if row["rms_ln"] not in (None, ""):
            groups.setdefault((row["compared_with"], float(row["ky"]), float(row["site_period"])), []).append(row)
    ranked = []
    for (compared_with, ky, period), members in sorted(groups.items()):
        for rank, row in enumerate(sorted(members, key=lambda row: float(row["rms_ln"])), start=1):
            ranked.append({"compared_with": compared_with, "ky": ky, "site_period": period, "rank": rank,
                           "method": row["method"], "rms_ln": float(row["rms_ln"]), "bias_ln": float(row["bias_ln"]),
                           "sigma_ln": float(row["sigma_ln"])})
    return ranked
