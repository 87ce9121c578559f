"""The simplified estimates against SLAMMER 1.1's own printed values, and SLAMMER's value beside ours where we depart.

The reference table ``fixtures/slammer_simplified/slammer_simplified.csv`` is
SLAMMER's Java (RigidBlockSimplified, CoupledSimplified, UnifiedModel) run on
a grid of inputs by ``fixtures/slammer_simplified/Table.java`` (which says
how).  SLAMMER prints displacements [cm] to 0.1 cm (the unified model to
0.001 cm), probabilities to 0.01 or 0.001; ours must round to its digits.
"""

from __future__ import annotations

import math

import pytest

from conftest import FIXTURES
from stickslip.estimates.bray_travasarou import probit, slammer_p_zero
from stickslip.estimates.jibson import failure_probability
from stickslip.estimates.registry import AFTER_SLAMMER, INPUTS, METHODS
from stickslip.plumbing.files import read_csv_rows

TABLE = read_csv_rows(FIXTURES / "slammer_simplified" / "slammer_simplified.csv")


def _inputs(row: dict) -> dict:
    return {name: float(row[name]) for name in INPUTS if row.get(name)}


def _half_unit(printed: str) -> float:
    """Half a unit of the last digit SLAMMER printed: its rounding."""
    decimals = len(printed.split(".")[1]) if "." in printed else 0
    return 0.5 * 10.0**-decimals + 1e-9


def _agrees_with_slammer(row: dict) -> bool:
    """Rows where SLAMMER computes what the paper says (the departures are tested one by one below)."""
    if row["slammer_value"] == "NaN":
        return False  # a_c >= a_max
    if row["method"] == "bray_travasarou_2007" and float(row["site_period"]) < 0.05:
        return False  # SLAMMER has no rigid branch
    if row["method"] == "saygili_rathje_2008_pga" and float(row["ky"]) >= float(row["pga"]):
        return False  # SLAMMER extrapolates the polynomial past a_c = a_max
    return row["method"] in METHODS


AGREEING = [row for row in TABLE if _agrees_with_slammer(row)]


def test_the_table_covers_every_method_slammer_offers():
    assert {row["method"] for row in TABLE} == set(METHODS) - set(AFTER_SLAMMER) | {"failure_probability"}
    assert len(AGREEING) > 500


@pytest.mark.parametrize("row", AGREEING, ids=lambda row: f"{row['method']}-{row['ky']}-{row['pga'] or row['site_period']}")
def test_each_median_rounds_to_slammer_s_printed_value(row):
    estimate = METHODS[row["method"]].function(**{name: value for name, value in _inputs(row).items()
                                                  if name in METHODS[row["method"]].inputs})
    printed = row["slammer_value"]
    assert abs(100.0 * estimate.median_displacement - float(printed)) <= _half_unit(printed), (
        100.0 * estimate.median_displacement, printed)


def test_the_probability_of_failure_rounds_to_slammer_s():
    rows = [row for row in TABLE if row["method"] == "failure_probability"]
    assert len(rows) == 5
    for row in rows:
        ours = failure_probability(float(row["displacement_cm"]) / 100.0)
        assert abs(ours - float(row["slammer_value"])) <= _half_unit(row["slammer_value"]), row


def test_bray_travasarou_p_zero_agrees_with_slammer_where_its_normal_cdf_holds():
    """For a non-negative argument SLAMMER's polynomial is Abramowitz and Stegun 26.2.17 (error below 7.5e-8)."""
    rows = [row for row in TABLE if row["method"] == "bray_travasarou_2007" and float(row["site_period"]) >= 0.05
            and probit(float(row["ky"]), float(row["site_period"]), float(row["spectral_acceleration"])) >= 0.0]
    assert len(rows) >= 30
    for row in rows:
        estimate = METHODS["bray_travasarou_2007"].function(**_inputs(row))
        assert abs(estimate.p_zero - float(row["slammer_p_zero"])) <= _half_unit(row["slammer_p_zero"]), row


def test_slammer_s_p_zero_leaves_zero_to_one_in_weak_shaking_and_ours_does_not():
    """k_y 0.2, T_s 0.3 s, Sa 0.1 g, M 7: SLAMMER prints P(D = 0) = -1042.06; the paper's Φ gives 0.99999569."""
    row = next(row for row in TABLE if row["method"] == "bray_travasarou_2007" and row["ky"] == "0.2"
               and row["site_period"] == "0.3" and row["spectral_acceleration"] == "0.1" and row["magnitude"] == "7.0")
    assert row["slammer_p_zero"] == "-1042.06"
    assert slammer_p_zero(0.2, 0.3, 0.1) == pytest.approx(-1042.06, abs=0.005)  # we reproduce SLAMMER's arithmetic
    ours = METHODS["bray_travasarou_2007"].function(ky=0.2, site_period=0.3, spectral_acceleration=0.1, magnitude=7.0)
    assert ours.p_zero == pytest.approx(1.0 - 0.5 * math.erfc(4.4487 / math.sqrt(2.0)), abs=1e-6)
    assert 0.999995 < ours.p_zero < 1.0


def test_every_slammer_p_zero_with_a_negative_argument_is_wrong_and_ours_is_a_probability():
    rows = [row for row in TABLE if row["method"] == "bray_travasarou_2007" and float(row["site_period"]) >= 0.05
            and probit(float(row["ky"]), float(row["site_period"]), float(row["spectral_acceleration"])) < -1.5]
    assert rows
    for row in rows:
        ours = METHODS["bray_travasarou_2007"].function(**_inputs(row)).p_zero
        slammer = float(row["slammer_p_zero"])
        assert 0.0 <= ours <= 1.0
        assert not 0.0 <= slammer <= 1.0 or abs(slammer - ours) > 0.01, row


def test_the_paper_s_rigid_branch_gives_7_5_cm_where_slammer_prints_3_1():
    """Bray and Travasarou's rigid-slope example: k_y 0.08, T_s = 0, PGA 0.24 g, M 7."""
    row = next(row for row in TABLE if row["method"] == "bray_travasarou_2007" and row["site_period"] == "0.0")
    assert row["slammer_value"] == "3.1"
    ours = METHODS["bray_travasarou_2007"].function(ky=0.08, site_period=0.0, spectral_acceleration=None,
                                                     magnitude=7.0, pga=0.24)
    assert 100.0 * ours.median_displacement == pytest.approx(7.45, abs=0.005)
    # SLAMMER's 3.1 cm is the flexible form (constant -1.10) with T_s = 0
    assert math.exp(math.log(100.0 * ours.median_displacement) - 0.88) == pytest.approx(3.1, abs=0.05)


@pytest.mark.parametrize("method", ["jibson_2007_pga", "ambraseys_menu_1988", "saygili_rathje_2008_pga"])
def test_where_the_yield_acceleration_reaches_the_pga_slammer_prints_nan_or_extrapolates_and_ours_is_zero(method):
    row = next(row for row in TABLE if row["method"] == method and row["ky"] == "0.3" and row["pga"] == "0.2")
    assert row["slammer_value"] == ("0.0" if method == "saygili_rathje_2008_pga" else "NaN")
    ours = METHODS[method].function(ky=0.3, pga=0.2)
    assert ours.median_displacement == 0.0 and ours.p_zero == 1.0 and ours.sigma is None
    assert ours.reason == "k_y = 0.3 >= PGA = 0.2 g: the block never slides"
