"""The collection study's tables as its page shows them: words and units in the headings, and few enough columns.

The workflow's CSV tables (``results/collections/{study}/``) keep one
machine-readable column per number, named as in the code, with UDUNITS units
(``relations.csv`` has seventeen).  The page
(``notebooks/collection_study.ipynb``) shows each with a heading in words and
its units in brackets, an interval beside the value it bounds
("0.91 [0.71, 1]"), a share as a percentage, and a row that has no value a
reason in words, so that every table fits the page's width.  Each function
returns ``(rows, columns)`` for :func:`stickslip.reports.notebook_helpers.table`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from stickslip.studies.collections.plots import CHECK_LABELS
from stickslip.reports.design_answer import format_number
from stickslip.units import readable_units

#: The names of the quantities of the near-fault comparison (``near_far.csv`` of the collection study and of the
#: planar study), in words.
NEAR_FAR_QUANTITIES = {"mu_max_continuous": "μ_max, continuous", "mu_max_g_over_pga": "μ_max·g/PGA",
                       "efficiency": "efficiency of the reference μ", "pga": "PGA",
                       "energy_dissipated_max_continuous": "E_df,max",
                       "ratio_components": "R: the plane's stroke over the larger component's",
                       "ratio_azimuths": "R: the plane's stroke over the largest on a turned axis",
                       "mu_max_plane": "μ_max in the plane",
                       "mu_max_plane_over_larger_component": "μ_max in the plane over the larger component's",
                       "mu_max_plane_g_over_pga_plane": "μ_max in the plane·g / PGA of the vector",
                       "energy_ratio_plane_to_worst_azimuth": "E_df,max in the plane over the worst azimuth's",
                       "pga_plane": "PGA of the vector"}

Table = tuple[list[dict], list[tuple[str, str]]]


def _number(value, digits: int = 3) -> str:
    """A cell of a CSV table (text, or a number already) with ``digits`` significant digits; ``-`` when empty."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        return "-"
    return "-" if math.isnan(number) else format_number(number, digits)


def _interval(row: Mapping, name: str, digits: int = 3) -> str:
    """``value [low, high]`` of the columns ``name``, ``name_low`` and ``name_high`` of ``row``."""
    return (f"{_number(row[name], digits)} [{_number(row[f'{name}_low'], digits)}, "
            f"{_number(row[f'{name}_high'], digits)}]")


def _share(value) -> str:
    """A share [1] as a whole percentage, ``-`` when empty."""
    try:
        return f"{float(value):.0%}"
    except (TypeError, ValueError):
        return "-"


def relations_table(relations: Sequence[Mapping]) -> Table:
    """The fitted relations of μ_max (``status`` ok): Pearson r, Spearman ρ and the slope with 95 % intervals,
    the leave-one-event-out errors [1] and the skill."""
    rows = [{"predictor": row["label"], "units": readable_units(row["units"]), "records": int(float(row["n"])),
             "events": int(float(row["n_events"])), "pearson": _interval(row, "pearson_r"),
             "spearman": _interval(row, "spearman_rho"), "slope": _interval(row, "slope"),
             "intercept": _number(row["intercept"]),
             "errors": f"{_number(row['loeo_rmse'])} / {_number(row['loeo_rmse_mean_only'])}",
             "skill": _number(row["loeo_skill"])}
            for row in relations if row["status"] == "ok"]
    return rows, [("predictor", "predictor"), ("units", "units"), ("records", "records"), ("events", "events"),
                  ("pearson", "Pearson r [95 % interval]"), ("spearman", "Spearman ρ [95 % interval]"),
                  ("slope", "slope of the line [1/units]"), ("intercept", "intercept [-]"),
                  ("errors", "leave-one-event-out error [-]: line / mean"), ("skill", "skill [-]")]


def coverage_table(coverage: Sequence[Mapping]) -> Table:
    """Per PGA band: the share of records whose range holds the reference μ, its median efficiency, the single μ
    in the most ranges, the design μ with the share of records it serves (the study's efficiency target met) and
    the μ that serve the coverage target's share; a band without a verdict says why."""
    rows = []
    for row in coverage:
        if row["status"] != "ok":
            rows.append({"band": row["pga_band"], "records": int(float(row["n"])), "reference": row["status"]})
            continue
        meeting = (f"{_number(row['design_mu_low'])} to {_number(row['design_mu_high'])}"
                   if row["design_meets_target"] == "True" else "none")
        rows.append({
            "band": row["pga_band"], "records": int(float(row["n"])),
            "reference": f"{_share(row['share_reference_in_range'])} in range; median efficiency "
                         f"{_number(row['median_efficiency_reference'], 2)}",
            "single": f"{_number(row['best_single_mu'])} ({_share(row['share_best_single_mu'])} of the records)",
            "design": f"{_number(row['design_mu'])} ({_share(row['share_design_mu'])} of the records)",
            "meeting": meeting})
    reference = next((float(row["reference_mu"]) for row in coverage if row.get("reference_mu")), None)
    named = f"μ = {reference:g}" if reference is not None else "the reference μ"
    return rows, [("band", "PGA band"), ("records", "records"), ("reference", named),
                  ("single", "μ in the most near-optimal ranges [-]"), ("design", "design μ [-]"),
                  ("meeting", "μ that meet the coverage target [-]")]


def scaling_law_table(law: Sequence[Mapping]) -> Table:
    """The scaling law's check: per record and factor k, the largest relative energy difference and the μ_max ratio."""
    rows = [{"record": row["record"], "factor": _number(row["factor"]),
             "difference": _number(row["max_relative_energy_difference"], 2), "mu_max": _number(row["mu_max"], 5),
             "scaled": _number(row["mu_max_scaled"], 5), "ratio": _number(row["mu_max_ratio"], 6)} for row in law]
    return rows, [("record", "record"), ("factor", "scale factor k [-]"),
                  ("difference", "largest |E(kμ; ka) − k²E(μ; a)| / k²E [-]"), ("mu_max", "μ_max(a) [-]"),
                  ("scaled", "μ_max(k·a) [-]"), ("ratio", "μ_max(k·a) / (k·μ_max(a)) [-]")]


def near_far_table(near_far: Sequence[Mapping]) -> Table:
    """Near-fault against farther records: the medians of each quantity and the Mann-Whitney p-value."""
    rows = [{"quantity": NEAR_FAR_QUANTITIES.get(row["quantity"], row["quantity"]),
             "units": readable_units(row["units"]), "near": int(float(row["n_near"])), "far": int(float(row["n_far"])),
             "median_near": _number(row["median_near"]), "median_far": _number(row["median_far"]),
             "p": _number(row["mann_whitney_p_value"], 2)} for row in near_far]
    return rows, [("quantity", "quantity"), ("units", "units"), ("near", "near-fault records"),
                  ("far", "farther records"), ("median_near", "median, near-fault"), ("median_far", "median, farther"),
                  ("p", "Mann-Whitney p-value [-]")]


def beyond_table(beyond: Sequence[Mapping]) -> Table:
    """The measures beyond the published values' rounding, each with its explanation."""
    rows = [{"record": row["record"], "measure": CHECK_LABELS.get(row["measure"], row["measure"]),
             "published": _number(row["published"], 4), "ours": _number(row["ours_slammer_convention"], 4),
             "explanation": row["explanation"]} for row in beyond]
    return rows, [("record", "record"), ("measure", "measure"), ("published", "published"),
                  ("ours", "ours, in SLAMMER's definitions"), ("explanation", "explanation")]
