"""Near-fault against far-field components in the isolation study, on a small synthetic set of cases.

The components split at the near-fault distance (at it: near-fault; no rupture distance: neither, counted); each
group's median and 84th percentile and the two-sided Mann–Whitney U test are numpy's and scipy's on the same
numbers, and an exact case by hand (every near-fault value below every far-field one: U = 0, p = 2 / C(12, 6));
a group too small gives no row and a sentence saying what it needs, and with near-fault records alone (the
library's near-fault folder, offline) the sentence says how to add the far-field ones; the index and the figure
follow the rows.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from stickslip.reports.plots import NotDrawn
from stickslip.studies.isolation.index import near_far_sentence
from stickslip.studies.isolation.near_far import (distance_groups, far_field_status, near_far_reason, near_far_rows,
                                                  near_far_summary)
from stickslip.studies.isolation.plots import plot_near_far
from stickslip.studies.isolation.tables import SUMMARISED

NEAR_FAULT_KM = 20.0
MIN_RECORDS = 5
#: Rupture distances [km] of the synthetic components: six near-fault (20 km among them), six far-field, and two
#: three-component stations of no rupture distance.
DISTANCES = {"N1": 0.5, "N2": 3.0, "N3": 8.0, "N4": 12.0, "N5": 15.0, "N6": 20.0,
             "F1": 20.5, "F2": 30.0, "F3": 45.0, "F4": 60.0, "F5": 90.0, "F6": 150.0, "S.H1": math.nan,
             "S.H2": math.nan}
MUS = (0.03, 0.06)


def synthetic_cases(distances=DISTANCES, seed=7) -> list[dict]:
    """One row per component and μ at T = 0.5 s, R = 2 m, as ``isolation_cases.csv`` reads (strings): random
    ratios and displacements, near-fault components' drift ratios below every far-field one at μ = 0.03."""
    rng = np.random.default_rng(seed)
    rows = []
    for mu in MUS:
        for record, distance in distances.items():
            drift = rng.uniform(0.1, 0.4)
            if mu == MUS[0]:
                drift += 0.0 if record.startswith("N") else 1.0
            rows.append({"library": "three_component" if record.startswith("S") else "slammer", "record": record,
                         "rupture_distance": f"{distance!r}", "period": "0.5", "radius": "2.0", "mu": f"{mu!r}",
                         "drift_ratio": f"{drift!r}", "floor_acceleration_ratio": f"{rng.uniform(0.1, 1.2)!r}",
                         "peak_isolator_displacement": f"{rng.lognormal(-2.5, 0.8)!r}"})
    return rows


def test_the_components_split_at_the_near_fault_distance_and_those_without_one_are_counted():
    groups = distance_groups(synthetic_cases(), NEAR_FAULT_KM)
    assert groups == {"near": {"N1", "N2", "N3", "N4", "N5", "N6"}, "far": {"F1", "F2", "F3", "F4", "F5", "F6"},
                      "unknown": {"S.H1", "S.H2"}}
    assert near_far_reason(groups, NEAR_FAULT_KM, MIN_RECORDS) is None
    status = far_field_status(synthetic_cases(), NEAR_FAULT_KM, MIN_RECORDS)
    assert status == ("Near-fault against far-field: 6 components within 20 km of the rupture against 6 farther "
                      "(2 without a rupture distance, in neither group), per T, R and μ (isolation_near_far.csv).")


def test_each_cell_s_statistics_are_numpy_s_and_scipy_s_on_the_same_numbers():
    cases = synthetic_cases()
    rows = near_far_rows(cases, SUMMARISED, NEAR_FAULT_KM, MIN_RECORDS)
    assert [(row["mu"], row["quantity"]) for row in rows] == [(mu, quantity) for mu in MUS for quantity in SUMMARISED]
    for row in rows:
        cell = [case for case in cases if float(case["mu"]) == row["mu"]]
        near = [float(case[row["quantity"]]) for case in cell if case["record"].startswith("N")]
        far = [float(case[row["quantity"]]) for case in cell if case["record"].startswith("F")]
        expected = stats.mannwhitneyu(near, far, alternative="two-sided")
        assert (row["n_near"], row["n_far"], row["units"]) == (6, 6, SUMMARISED[row["quantity"]])
        assert row["median_near"] == np.median(near) and row["p84_far"] == np.percentile(far, 84)
        assert row["median_far"] == np.median(far) and row["p84_near"] == np.percentile(near, 84)
        assert row["mann_whitney_u"] == expected.statistic and row["mann_whitney_p_value"] == expected.pvalue


def test_every_near_fault_value_below_every_far_field_one_is_u_zero_and_the_exact_p_value():
    row = next(row for row in near_far_rows(synthetic_cases(), SUMMARISED, NEAR_FAULT_KM, MIN_RECORDS)
               if row["quantity"] == "drift_ratio" and row["mu"] == MUS[0])
    assert row["mann_whitney_u"] == 0.0
    # two orderings of the twelve values as extreme as this one, out of C(12, 6)
    assert row["mann_whitney_p_value"] == pytest.approx(2 / math.comb(12, 6), rel=1e-12)


def test_a_group_too_small_gives_no_row_and_says_what_it_needs():
    few = {record: distance for record, distance in DISTANCES.items() if record not in ("F5", "F6")}
    cases = synthetic_cases(few)
    assert near_far_rows(cases, SUMMARISED, NEAR_FAULT_KM, MIN_RECORDS) == []
    assert near_far_reason(distance_groups(cases, NEAR_FAULT_KM), NEAR_FAULT_KM, MIN_RECORDS) == (
        "too few components: 6 within 20 km of the rupture and 4 farther, a comparison needs at least 5 on each "
        "side (collection_study.min_records)")
    status = far_field_status(cases, NEAR_FAULT_KM, MIN_RECORDS)
    assert status.startswith("Near-fault against far-field is not compared: too few components: 6 within 20 km")
    assert "collection_study.download: true" in status and "STICKSLIP_SLAMMER_DIR" in status
    # too few near-fault components: the far-field records are not what is missing
    far_only = synthetic_cases({record: distance for record, distance in DISTANCES.items() if record[0] != "N"})
    assert "STICKSLIP_SLAMMER_DIR" not in far_field_status(far_only, NEAR_FAULT_KM, MIN_RECORDS)


def test_with_the_near_fault_records_alone_the_far_field_ones_are_said_missing():
    near_only = synthetic_cases({record: distance for record, distance in DISTANCES.items() if record[0] != "F"})
    status = far_field_status(near_only, NEAR_FAULT_KM, MIN_RECORDS)
    assert status == (
        "Near-fault against far-field is not compared: too few components: 6 within 20 km of the rupture and 0 "
        "farther, a comparison needs at least 5 on each side (collection_study.min_records). The SLAMMER library's "
        "far-field records (rupture distance > 20 km) are not in its folder: collection_study.download: true, where "
        "the internet is reachable, or STICKSLIP_SLAMMER_DIR set to a folder holding the whole library adds them.")
    assert near_far_rows(near_only, SUMMARISED, NEAR_FAULT_KM, MIN_RECORDS) == []


def test_the_summary_and_the_index_count_the_cells_the_rows_show():
    rows = near_far_rows(synthetic_cases(), SUMMARISED, NEAR_FAULT_KM, MIN_RECORDS)
    summary = near_far_summary(rows)
    drift = [row for row in rows if row["quantity"] == "drift_ratio"]
    assert summary["drift_ratio"]["cells"] == 2
    assert summary["drift_ratio"]["near_larger"] == sum(row["median_near"] > row["median_far"] for row in drift)
    assert summary["drift_ratio"]["significant"] == sum(row["mann_whitney_p_value"] < 0.05 for row in drift) >= 1
    ratios = [row["median_near"] / row["median_far"] for row in drift]
    assert summary["drift_ratio"]["median_ratio_min"] == min(ratios)
    sentence = near_far_sentence({"compared": True, "quantities": summary})
    assert f"drift ratio: near-fault median the larger in {summary['drift_ratio']['near_larger']} of 2" in sentence
    assert near_far_sentence({"compared": False, "quantities": {}}) == ""


def test_the_figure_sets_each_component_at_its_rupture_distance():
    figure = plot_near_far(synthetic_cases(), 0.5, 2.0, NEAR_FAULT_KM)
    drift_axes = figure.axes[0]
    assert drift_axes.get_xscale() == "log" and len(figure.axes) == 2
    dots = [line for line in drift_axes.lines if line.get_linestyle() == "None" and line.get_xdata().size]
    assert sorted(x for line in dots for x in line.get_xdata()) == sorted(
        [value for value in DISTANCES.values() if math.isfinite(value)] * len(MUS))
    not_drawn = plot_near_far(synthetic_cases(), 1.0, 2.0, NEAR_FAULT_KM)
    assert isinstance(not_drawn, NotDrawn)
    assert not_drawn.reason == "no component of known rupture distance was available"
