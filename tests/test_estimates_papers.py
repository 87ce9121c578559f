"""The simplified estimates against the worked examples of their papers, and the probabilities they give.

The examples are those pyGEEMs' tests take from the papers
(``tests/test_slope_disp.py`` of arkottke/pygeems): Bray and Travasarou
(2007)'s Table 1 (P(D = 0) and the range of D), Rathje et al. (2014)'s
examples of the Saygili-Rathje models, and the values read from their
Fig. 8c for Rathje and Antonakos (2011), with pyGEEMs' tolerances.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import norm

from stickslip.errors import StickslipError
from stickslip.estimates.bray_travasarou import bray_travasarou_2007
from stickslip.estimates.estimate import Estimate, normal_cdf
from stickslip.estimates.jibson import failure_probability, jibson_1993, jibson_2000, jibson_2007_ia
from stickslip.estimates.rathje_antonakos import (kmax_over_pga, rathje_antonakos_2011_m, rathje_antonakos_2011_pgv)
from stickslip.estimates.registry import METHODS, checked_inputs, estimates
from stickslip.estimates.saygili_rathje import rathje_saygili_2009_pga_m, saygili_rathje_2008_pga_pgv

#: The method names of ``stickslip estimate --json``, as the documentation lists them.
METHOD_NAMES = ("jibson_1993", "jibson_2000", "jibson_2007_pga", "jibson_2007_pga_m", "jibson_2007_ia",
                "jibson_2007_ia_pga", "ambraseys_menu_1988", "saygili_rathje_2008_pga", "saygili_rathje_2008_pga_pgv",
                "saygili_rathje_2008_pga_pgv_ia", "rathje_saygili_2009_pga_m", "bray_travasarou_2007",
                "bray_macedo_2019", "bray_macedo_travasarou_2018", "rathje_antonakos_2011_pgv",
                "rathje_antonakos_2011_m")

#: The methods that give a probability of no displacement, P(D = 0): Bray's family.
WITH_P_ZERO = {"bray_travasarou_2007", "bray_macedo_2019", "bray_macedo_travasarou_2018"}

#: Values of every input, to call any method.
ALL_INPUTS = {"ky": 0.1, "pga": 0.35, "pgv": 30.0, "arias_intensity": 1.0, "magnitude": 7.0, "mean_period": 0.45,
              "site_period": 0.2, "spectral_acceleration": 0.6, "spectral_acceleration_13": 0.65}


@pytest.mark.parametrize("ky, site_period, sa, p_zero", [(0.35, 0.45, 0.43, 0.85), (0.08, 0.00, 0.24, 0.1),
                                                        (0.14, 0.33, 0.94, 0.0)])
def test_bray_travasarou_p_zero_matches_their_table_1(ky, site_period, sa, p_zero):
    estimate = bray_travasarou_2007(ky, site_period, sa, magnitude=7.0, pga=sa)
    assert estimate.p_zero == pytest.approx(p_zero, abs=0.02)


@pytest.mark.parametrize("ky, site_period, sa, low_cm, high_cm", [(0.08, 0.00, 0.24, 4, 15), (0.14, 0.33, 0.94, 20, 70)])
def test_bray_travasarou_one_sigma_range_rounds_to_their_table_1(ky, site_period, sa, low_cm, high_cm):
    """The table's range of D is the median times exp(±σ), rounded; with M = 7 ours rounds to it."""
    median_cm = 100.0 * bray_travasarou_2007(ky, site_period, sa, magnitude=7.0, pga=sa).median_displacement
    assert median_cm * math.exp(-0.66) == pytest.approx(low_cm, rel=0.1)
    assert median_cm * math.exp(0.66) == pytest.approx(high_cm, rel=0.05)


def test_bray_travasarou_has_a_magnitude_term_of_0_278_per_unit():
    low = bray_travasarou_2007(0.1, 0.3, 0.5, magnitude=6.0).median_displacement
    high = bray_travasarou_2007(0.1, 0.3, 0.5, magnitude=8.0).median_displacement
    assert math.log(high / low) == pytest.approx(2 * 0.278, abs=1e-12)


def test_the_rigid_branch_starts_below_0_05_s():
    rigid = bray_travasarou_2007(0.1, 0.049, 0.5, magnitude=7.0, pga=0.4)
    flexible = bray_travasarou_2007(0.1, 0.05, 0.4, magnitude=7.0, pga=0.4)
    assert math.log(rigid.median_displacement / flexible.median_displacement) == pytest.approx(0.88 - 1.5 * 0.05)


@pytest.mark.parametrize("ky, pga, magnitude, pgv, expected_cm", [(0.1, 0.54, 6.75, None, 43), (0.1, 0.54, None, 42, 29),
                                                                  (0.1, 0.88, 6.75, None, 113), (0.1, 0.88, None, 71, 81)])
def test_saygili_rathje_match_the_examples_of_rathje_et_al_2014(ky, pga, magnitude, pgv, expected_cm):
    estimate = (rathje_saygili_2009_pga_m(ky, pga, magnitude) if magnitude else saygili_rathje_2008_pga_pgv(ky, pga, pgv))
    assert 100.0 * estimate.median_displacement == pytest.approx(expected_cm, abs=2.0)


@pytest.mark.parametrize("ky, magnitude, pgv, expected_cm", [(0.05, 7.0, None, 87.5), (0.10, 7.0, None, 22.0),
                                                             (0.05, None, 30, 43.5), (0.10, None, 30, 10.5)])
def test_rathje_antonakos_match_the_values_of_rathje_et_al_2014_fig_8c(ky, magnitude, pgv, expected_cm):
    """PGA 0.35 g, T_s 0.2 s, T_m 0.45 s."""
    estimate = (rathje_antonakos_2011_m(ky, 0.35, magnitude, 0.2, 0.45) if magnitude
                else rathje_antonakos_2011_pgv(ky, 0.35, pgv, 0.2, 0.45))
    assert 100.0 * estimate.median_displacement == pytest.approx(expected_cm, abs=1.0)


def test_rathje_antonakos_m_model_stays_flat_past_1_5_s():
    """Its period term is 3.69 T_s - 1.22 T_s² up to 1.5 s, 2.78 beyond: never falling (pyGEEMs' min() falls)."""
    values = [rathje_antonakos_2011_m(0.05, 0.5, 7.0, period, 0.1).median_displacement for period in (1.6, 2.0, 3.0)]
    kmax = [kmax_over_pga(min(period / 0.1, 8.0), 0.5) for period in (1.6, 2.0, 3.0)]
    assert kmax[0] == kmax[1] == kmax[2]  # the period ratio is capped at 8
    assert values[0] == values[1] == values[2]


def test_rathje_antonakos_is_zero_only_where_k_y_reaches_k_max():
    """k_max may exceed the PGA (a mass that amplifies): k_y 0.21 > PGA 0.2 g slides, k_max being 1.126 PGA."""
    kmax = kmax_over_pga(0.11 / 0.5, 0.2) * 0.2
    assert kmax == pytest.approx(0.2253, abs=5e-5)
    assert rathje_antonakos_2011_pgv(0.21, 0.2, 30.0, 0.11, 0.5).median_displacement > 0.0
    zero = rathje_antonakos_2011_pgv(kmax * 1.01, 0.2, 30.0, 0.11, 0.5)
    assert zero.median_displacement == 0.0 and "k_max" in zero.reason


def test_jibson_forms_as_printed():
    """log D_n [cm] = 1.460 log I_a - 6.642 a_c + 1.546; 1.521 log I_a - 1.993 log a_c - 1.546; 2.401 log I_a - 3.481 log a_c - 3.230."""
    assert 100 * jibson_1993(0.1, 2.0).median_displacement == pytest.approx(10 ** (1.460 * math.log10(2) - 0.6642 + 1.546))
    assert 100 * jibson_2000(0.1, 2.0).median_displacement == pytest.approx(10 ** (1.521 * math.log10(2) + 1.993 - 1.546))
    assert 100 * jibson_2007_ia(0.1, 2.0).median_displacement == pytest.approx(10 ** (2.401 * math.log10(2) + 3.481 - 3.23))


def test_the_probability_of_failure_rises_from_zero_to_0_335():
    assert failure_probability(0.0) == 0.0
    assert failure_probability(0.10) == pytest.approx(0.335 * (1 - math.exp(-0.048 * 10**1.565)))
    assert failure_probability(10.0) == pytest.approx(0.335)
    with pytest.raises(StickslipError, match="Newmark displacement -0.1 m: expected a number >= 0"):
        failure_probability(-0.1)


def test_the_normal_cdf_is_exact_on_both_sides():
    x = np.linspace(-8.0, 8.0, 161)
    assert np.allclose([normal_cdf(value) for value in x], norm.cdf(x), rtol=1e-12, atol=1e-300)


def test_probability_of_exceeding():
    estimate = Estimate(median_displacement=0.10, sigma=0.5, log_base="10", p_zero=0.2)
    assert estimate.probability_of_exceeding(0.10) == pytest.approx(0.8 * 0.5)
    assert estimate.probability_of_exceeding(0.10 * 10**0.5) == pytest.approx(0.8 * norm.sf(1.0))
    assert estimate.probability_of_exceeding(0.0) == pytest.approx(0.8)
    natural = Estimate(median_displacement=0.10, sigma=0.66, log_base="e")
    assert natural.probability_of_exceeding(0.10 * math.exp(0.66)) == pytest.approx(norm.sf(1.0))
    never = METHODS["jibson_2007_pga"].function(ky=0.4, pga=0.3)
    assert never.probability_of_exceeding(1e-9) == 0.0 and never.probability_of_exceeding(0.0) == 0.0


def test_the_registry_has_every_method_with_its_log_base():
    assert tuple(METHODS) == METHOD_NAMES
    found, lacking = estimates(ALL_INPUTS)
    assert set(found) == set(METHOD_NAMES) and not lacking
    for name, estimate in found.items():
        assert estimate.log_base == METHODS[name].log_base, name
        assert estimate.median_displacement > 0.0 and estimate.sigma > 0.0, name
        assert (estimate.p_zero is not None) == (name in WITH_P_ZERO), name


@pytest.mark.parametrize("name", [name for name in METHOD_NAMES if METHODS[name].kind == "rigid"])
def test_every_rigid_method_is_zero_with_the_reason_where_k_y_reaches_the_pga(name):
    found, _ = estimates({**ALL_INPUTS, "ky": 0.35})
    assert found[name].median_displacement == 0.0 and found[name].p_zero == 1.0
    assert found[name].reason == "k_y = 0.35 >= PGA = 0.35 g: the block never slides"


def test_a_method_lacking_inputs_names_them():
    found, lacking = estimates({"ky": 0.1, "pga": 0.3})
    assert set(found) == {"jibson_2007_pga", "ambraseys_menu_1988", "saygili_rathje_2008_pga"}
    assert lacking["bray_travasarou_2007"] == ("site_period", "magnitude")
    assert lacking["rathje_antonakos_2011_pgv"] == ("pgv", "site_period", "mean_period")
    # T_s < 0.05 s is the rigid branch: PGA, no Sa
    found, lacking = estimates({"ky": 0.1, "pga": 0.3, "magnitude": 7.0, "site_period": 0.0})
    assert "bray_travasarou_2007" in found


@pytest.mark.parametrize("values, message", [
    ({"ky": 0.1, "pga": -0.3}, "peak ground acceleration -0.3 [g]: expected a positive number"),
    ({"ky": 0.1, "site_period": -1.0}, "fundamental period T_s of the sliding mass -1.0 [s]: expected a number >= 0"),
    ({"ky": 0.1, "magnitude": math.nan}, "moment magnitude M nan [1]: expected a finite number"),
    ({"ky": 0.1, "pgd": 3.0}, "unknown input 'pgd'"),
    ({"pga": 0.3}, "the simplified estimates need the yield coefficient k_y [g]"),
])
def test_bad_inputs_are_one_clear_error(values, message):
    with pytest.raises(StickslipError, match=message.replace("[", r"\[").replace("]", r"\]")):
        estimates(values)
    assert checked_inputs({"ky": 0.1, "magnitude": -1.0})["magnitude"] == -1.0
