"""The library study's arithmetic: each estimate set against the exact displacement, and the statistics over rows."""

from __future__ import annotations

import math

import pytest

from stickslip.estimates.registry import METHODS
from stickslip.estimates.ranking import ranking_rows
from stickslip.studies.estimates.simplified import estimate_rows, exceedance_rows, summary_rows

G = 9.81


def _rigid_row(record: str, ky: float, polarity: str, displacement_cm: float, pga_g: float = 0.3) -> dict:
    """A row of the Jibson (2007) table, as read from CSV."""
    return {"record": record, "event": "E", "status": "ok", "polarity": polarity, "ky": str(ky),
            "pga": str(pga_g * G), "arias_intensity": "1.5", "newmark_displacement": str(displacement_cm)}


def test_each_record_gets_every_applicable_method_against_both_polarities():
    rigid = [_rigid_row("a", 0.1, "normal", 12.0), _rigid_row("a", 0.1, "inverse", 8.0),
             _rigid_row("a", 0.4, "normal", 0.0), _rigid_row("a", 0.4, "inverse", 0.0)]
    flexible = [{"record": "a", "status": "ok", "site_period": "0.3", "spectral_acceleration": "0.6", "ky": "0.1",
                 "polarity": polarity, "coupled_displacement": "20.0"} for polarity in ("normal", "inverse")]
    rows = estimate_rows(rigid, {"a": {"pgv": "0.4", "mean_period": "0.5"}}, flexible, {"a": 7.0}, [0.1, 0.4], G)
    at = [row for row in rows if row["ky"] == 0.1 and row["site_period"] == 0.0]
    rigid_methods = {name for name, entry in METHODS.items() if entry.kind == "rigid"} | {"bray_travasarou_2007"}
    assert {row["method"] for row in at} == rigid_methods and len(at) == 2 * len(rigid_methods)
    ambraseys = next(row for row in at if row["method"] == "ambraseys_menu_1988" and row["polarity"] == "inverse")
    assert ambraseys["observed_displacement"] == 8.0
    assert ambraseys["estimated_displacement"] == pytest.approx(
        10 ** (0.90 + 2.53 * math.log10(1 - 1 / 3) - 1.09 * math.log10(1 / 3)))
    pgv = next(row for row in at if row["method"] == "saygili_rathje_2008_pga_pgv")
    assert pgv["estimated_displacement"] == pytest.approx(100 * METHODS["saygili_rathje_2008_pga_pgv"].function(
        ky=0.1, pga=0.3, pgv=40.0).median_displacement)
    coupled = [row for row in rows if row["site_period"] == 0.3]
    assert {row["method"] for row in coupled} == {"bray_travasarou_2007", "rathje_antonakos_2011_pgv",
                                                   "rathje_antonakos_2011_m"}
    assert all(row["observed_displacement"] == 20.0 for row in coupled)
    # k_y 0.4 > PGA 0.3 g: every rigid method a certain zero
    above = [row for row in rows if row["ky"] == 0.4 and METHODS[row["method"]].kind == "rigid"]
    assert above and all(row["estimated_displacement"] == 0.0 and row["estimated_p_zero"] == 1.0 for row in above)


def test_a_record_without_a_magnitude_skips_the_methods_that_need_one():
    rows = estimate_rows([_rigid_row("a", 0.1, "normal", 5.0)], {}, [], {"a": None}, [0.1], G)
    assert {row["method"] for row in rows} == {"jibson_1993", "jibson_2000", "jibson_2007_pga", "jibson_2007_ia",
                                               "jibson_2007_ia_pga", "ambraseys_menu_1988", "saygili_rathje_2008_pga"}


def _row(method: str, observed: float, estimated: float, p_zero: float = 0.0, sigma: float = 1.0) -> dict:
    return {"method": method, "record": f"r{observed}", "ky": 0.1, "site_period": 0.0, "polarity": "normal",
            "observed_displacement": observed, "estimated_displacement": estimated, "estimated_sigma_ln": sigma,
            "estimated_p_zero": p_zero}


def test_the_summary_takes_the_log_residual_over_rows_at_or_above_the_floor():
    rows = [_row("jibson_2007_pga", 10.0, 5.0), _row("jibson_2007_pga", 2.0, 4.0), _row("jibson_2007_pga", 40.0, 10.0),
            _row("jibson_2007_pga", 0.5, 2.0), _row("jibson_2007_pga", 0.0, 0.0, p_zero=1.0, sigma=None)]
    (summary,) = summary_rows(rows, floor_cm=1.0, min_rows=3)
    residuals = [math.log(2.0), math.log(0.5), math.log(4.0)]
    mean = sum(residuals) / 3
    assert summary["residual_rows"] == 3 and summary["rows"] == 5 and summary["compared_with"] == "rigid"
    assert summary["bias_ln"] == pytest.approx(mean)
    assert summary["sigma_ln"] == pytest.approx(math.sqrt(sum((r - mean) ** 2 for r in residuals) / 2))
    assert summary["observed_zero_share"] == 0.2 and summary["estimated_zero_share"] == 0.2
    assert summary["observed_below_floor_share"] == 0.4
    below = (0.5 * math.erfc(math.log(1 / 5) / -math.sqrt(2)) + 0.5 * math.erfc(math.log(1 / 4) / -math.sqrt(2))
             + 0.5 * math.erfc(math.log(1 / 10) / -math.sqrt(2)) + 0.5 * math.erfc(math.log(1 / 2) / -math.sqrt(2)) + 1.0)
    assert summary["estimated_below_floor_share"] == pytest.approx(below / 5)
    (few,) = summary_rows(rows, floor_cm=1.0, min_rows=4)
    assert few["bias_ln"] is None and few["sigma_ln"] is None


def test_exceedance_sets_the_observed_share_beside_the_mean_probability():
    rows = [_row("ambraseys_menu_1988", 10.0, 10.0), _row("ambraseys_menu_1988", 2.0, 10.0, p_zero=0.5)]
    (row,) = exceedance_rows(rows, [10.0])
    assert row["observed_share"] == 0.0 and row["estimated_probability"] == pytest.approx((0.5 + 0.25) / 2)


def test_the_ranking_orders_methods_by_their_rms_log_error():
    summary = [{"method": name, "compared_with": "rigid", "ky": "0.1", "site_period": "0.0", "rms_ln": str(rms),
                "bias_ln": "0.1", "sigma_ln": "0.2"} for name, rms in (("jibson_1993", 0.9), ("jibson_2000", 0.4),
                                                                       ("jibson_2007_pga", ""))]
    ranked = ranking_rows(summary)
    assert [(row["rank"], row["method"]) for row in ranked] == [(1, "jibson_2000"), (2, "jibson_1993")]
