"""Which friction ratio to design for: coverage of a fixed μ across records, by PGA band, and the paper's claims.

From a collection study's cube (E_df on the study's μ grid for every record)
and its per-record table:

- :func:`coverage_rows`: for every PGA band (and all records), the share of
  records whose near-optimal range (E_df ≥ q·E_df,max on the grid) contains the
  reference μ (the paper's 0.1), the median efficiency E_df(μ_ref)/E_df,max, the
  single μ of the grid that lies in the most records' ranges, and the design
  μ: the grid μ that reaches at least ``efficiency_target`` (90 %) of E_df,max
  for the largest share of records, with that share, and whether it meets
  ``coverage_target`` (80 %).
- :func:`claims_rows`: the paper's three claims, each with the paper's
  number (from its Table 6, labelled as the paper's), ours on n records, and
  a verdict stated by a fixed rule.
- :func:`near_far_rows`: near-fault against far-field records, when the
  collection has enough of both.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from scipy import stats

from stickslip.analysis import near_optimal_set
from stickslip.reference import paper_tables
from stickslip.collections.members import studied, too_few


def _band_label(low: float, high: float) -> str:
    return f"{low:g}-{high:g} g"


def coverage_rows(cube: xr.Dataset, pga_g: np.ndarray, bands_g: list[float], reference_mu: float, q: float,
                  efficiency_target: float, coverage_target: float, efficiency: np.ndarray,
                  min_records: int) -> list[dict]:
    """The coverage table (see the module's docstring); ``pga_g`` [g] and ``efficiency`` [1] per record of ``cube``.

    ``cube`` holds the records studied only (a record that never slides has no
    near-optimal range).  A group of fewer than ``min_records`` records gets no
    numbers, only the reason.
    """
    mu = cube.mu.values
    energy = cube.energy_dissipated.values
    reference = int(np.argmin(np.abs(mu - reference_mu)))
    in_range = near_optimal_set(energy, q)
    efficient = near_optimal_set(energy, efficiency_target)
    groups = [("all records", np.ones(pga_g.size, bool))]
    groups += [(_band_label(low, high), (pga_g >= low) & (pga_g < high)) for low, high in zip(bands_g, bands_g[1:])]
    rows = []
    for label, members in groups:
        row = {"pga_band": label, "n": int(members.sum())}
        reason = "no records in this band" if not members.any() else too_few(int(members.sum()), min_records,
                                                                                 "a verdict")
        if reason:
            rows.append({**row, "status": reason})
            continue
        share_in_range = in_range[members].mean(axis=0)
        share_efficient = efficient[members].mean(axis=0)
        best, design = int(np.argmax(share_in_range)), int(np.argmax(share_efficient))
        meeting = mu[share_efficient >= coverage_target]
        rows.append({
            **row, "status": "ok",
            "reference_mu": float(mu[reference]),
            "share_reference_in_range": float(share_in_range[reference]),
            "median_efficiency_reference": float(np.median(efficiency[members])),
            "best_single_mu": float(mu[best]), "share_best_single_mu": float(share_in_range[best]),
            "design_mu": float(mu[design]), "share_design_mu": float(share_efficient[design]),
            "design_meets_target": bool(share_efficient[design] >= coverage_target),
            "design_mu_low": float(meeting.min()) if meeting.size else np.nan,
            "design_mu_high": float(meeting.max()) if meeting.size else np.nan,
        })
    return rows


def paper_points() -> list[dict]:
    """The paper's eight (PGA [m s-2], RMS [m s-2], μ_max) points, from its Table 6 as printed."""
    rows = paper_tables()["table6_results"]["rows"]
    return [{"record": name, "pga": values["pga"], "rms_acceleration": values["rms_acceleration"],
             "mu_max": values["mu_max"]} for name, values in rows.items()]


def paper_line() -> dict:
    """The line μ_max = slope·PGA + intercept (PGA in m s-2) fitted to the paper's eight Table 6 points, and its r."""
    points = paper_points()
    fit = stats.linregress([p["pga"] for p in points], [p["mu_max"] for p in points])
    return {"slope": float(fit.slope), "intercept": float(fit.intercept), "r": float(fit.rvalue), "n": len(points),
            "source": "least squares on the paper's Table 6 (PGA, mu_max), as printed"}


def claims_rows(relations: list[dict], coverage: list[dict], n_records: int, reference_mu: float) -> list[dict]:
    """The paper's claims tested on the collection, each with a verdict by a stated rule.

    Every claim has its row; one that the collection cannot test (too few
    records, by the relations' and the coverage's own ``min_records`` rule)
    has the verdict "not tested: " and the reason.
    """
    by_name = {row["predictor"]: row for row in relations}
    paper_fit = paper_line()
    ours = by_name["pga"]
    rows = []
    pga_claim = "mu_max rises with PGA along the paper's line (Fig. 22), r 'relatively low'"
    pga_rule = "confirmed when our Pearson r interval lies above 0 and our slope interval contains the paper's slope"
    pga_paper = (f"slope {paper_fit['slope']:.4f} per m/s², intercept {paper_fit['intercept']:.4f}, "
                 f"r = {paper_fit['r']:.2f} on its {paper_fit['n']} records (fitted to its Table 6)")
    if ours["status"] != "ok":
        rows.append({"claim": pga_claim, "paper": pga_paper, "ours": "", "verdict": f"not tested: {ours['status']}",
                     "rule": pga_rule})
    else:
        rises = ours["pearson_r_low"] > 0
        same_slope = ours["slope_low"] <= paper_fit["slope"] <= ours["slope_high"]
        verdict = ("confirmed" if rises and same_slope else
                   "partly: mu_max rises with PGA, but not at the paper's rate" if rises else "contradicted")
        rows.append({
            "claim": pga_claim, "paper": pga_paper,
            "ours": f"slope {ours['slope']:.4f} [{ours['slope_low']:.4f}, {ours['slope_high']:.4f}] per m/s², "
                    f"intercept {ours['intercept']:.4f}, r = {ours['pearson_r']:.2f} "
                    f"[{ours['pearson_r_low']:.2f}, {ours['pearson_r_high']:.2f}] on {ours['n']} records",
            "verdict": verdict, "rule": pga_rule,
        })
    rms = by_name["rms_acceleration"]
    rms_claim = {"claim": "no clear relation between mu_max and RMS acceleration (Fig. 23)",
                 "paper": "stated from 8 records (Table 6's RMS column is misprinted)",
                 "rule": "contradicted when the 95 % interval of Spearman rho excludes 0"}
    if rms["status"] != "ok":
        rows.append({**rms_claim, "ours": "", "verdict": f"not tested: {rms['status']}"})
    else:
        clear = rms["spearman_rho_low"] > 0 or rms["spearman_rho_high"] < 0
        rows.append({
            **rms_claim,
            "ours": f"Spearman rho = {rms['spearman_rho']:.2f} [{rms['spearman_rho_low']:.2f}, "
                    f"{rms['spearman_rho_high']:.2f}], Pearson r = {rms['pearson_r']:.2f} on {rms['n']} records",
            "verdict": "contradicted: a clear monotonic relation" if clear else "confirmed",
        })
    overall = next(row for row in coverage if row["pga_band"] == "all records")
    ranges = paper_tables()["table7_ranges"]["rows"].values()
    covered = sum(r["mu_low"] <= reference_mu <= r["mu_high"] for r in ranges)
    coverage_claim = {
        "claim": f"mu = {reference_mu:g} covers most seismic records (Table 7)",
        "paper": f"{reference_mu:g} lies in the printed range of {covered} of its {len(ranges)} records (its Table 7)",
        "rule": "confirmed when more than half of the records have the reference mu in their near-optimal range",
    }
    if overall["status"] != "ok":
        rows.append({**coverage_claim, "ours": "", "verdict": f"not tested: {overall['status']}"})
    else:
        most = overall["share_reference_in_range"] > 0.5
        rows.append({
            **coverage_claim,
            "ours": f"{overall['share_reference_in_range']:.0%} of {n_records} records have "
                    f"{overall['reference_mu']:g} in their near-optimal range; median efficiency "
                    f"{overall['median_efficiency_reference']:.0%}; the single mu in the most ranges is "
                    f"{overall['best_single_mu']:g} ({overall['share_best_single_mu']:.0%})",
            "verdict": "confirmed" if most else "contradicted",
        })
    return rows


def _near_and_far(rows: list[dict], near_fault_km: float) -> tuple[list[dict], list[dict]]:
    """The records studied with a rupture distance [km], split at ``near_fault_km``."""
    known = [row for row in studied(rows) if row.get("rupture_distance") not in ("", None)]
    return ([row for row in known if float(row["rupture_distance"]) <= near_fault_km],
            [row for row in known if float(row["rupture_distance"]) > near_fault_km])


def near_far_reason(rows: list[dict], near_fault_km: float, min_records: int) -> str | None:
    """Why near-fault and farther records are not compared (``None`` when they are)."""
    near, far = _near_and_far(rows, near_fault_km)
    if not near and not far:
        return "no record studied has a rupture distance"
    if len(near) < min_records or len(far) < min_records:
        return (f"too few records: {len(near)} within {near_fault_km:g} km and {len(far)} farther, a comparison "
                f"needs at least {min_records} on each side (collection_study.min_records)")
    return None


def near_far_rows(rows: list[dict], near_fault_km: float, min_records: int) -> list[dict]:
    """Near-fault (rupture distance ≤ ``near_fault_km``) against farther records: medians and a Mann-Whitney test.

    Empty when :func:`near_far_reason` gives a reason.
    """
    if near_far_reason(rows, near_fault_km, min_records):
        return []
    near, far = _near_and_far(rows, near_fault_km)
    table = []
    for name, units in (("mu_max_continuous", "1"), ("mu_max_g_over_pga", "1"), ("efficiency", "1"),
                        ("pga", "m s-2"), ("energy_dissipated_max_continuous", "J")):
        a = np.array([float(row[name]) for row in near if row[name] not in ("", None)])
        b = np.array([float(row[name]) for row in far if row[name] not in ("", None)])
        test = stats.mannwhitneyu(a, b)
        table.append({"quantity": name, "units": units, "n_near": a.size, "n_far": b.size,
                      "median_near": float(np.median(a)), "median_far": float(np.median(b)),
                      "mann_whitney_p_value": float(test.pvalue)})
    return table
