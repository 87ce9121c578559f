"""Scaling a suite of pairs to a target: the average not below the target over the range and touching it, each
pair to the target at T_M, the period range and the suite's statistic (stickslip.codes.suite_scaling)."""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.codes.suite_scaling import (
    period_range,
    scale_suite,
    statistic_of,
    suite_periods,
    suite_statistic,
)
from stickslip.errors import StickslipError

PERIODS = suite_periods(np.geomspace(0.05, 8.0, 60), (1.5, 3.5), 2.5)
SPAN = (1.5, 3.5)
TARGET = np.minimum(1.5, 1.0 / PERIODS)


def suite(count: int = 4, seed: int = 3) -> np.ndarray:
    """``count`` rough spectra [g]: the target's shape times a random tilt and ripple."""
    rng = np.random.default_rng(seed)
    tilt = rng.uniform(-0.6, 0.6, (count, 1)) * np.log(PERIODS / 2.0)
    ripple = 0.2 * np.sin(rng.uniform(2.0, 6.0, (count, 1)) * np.log(PERIODS) + rng.uniform(0, 6, (count, 1)))
    return rng.uniform(0.2, 3.0, (count, 1)) * TARGET * np.exp(tilt + ripple)


def inside() -> np.ndarray:
    return (PERIODS >= SPAN[0]) & (PERIODS <= SPAN[1])


@pytest.mark.parametrize("method", ["pairs", "common"])
def test_the_scaled_average_is_not_below_the_target_over_the_range_and_touches_it(method):
    spectra = suite()
    scaling = scale_suite(PERIODS, spectra, TARGET, SPAN, method)
    ratio = np.mean(scaling.factors[:, None] * spectra, axis=0)[inside()] / TARGET[inside()]
    assert ratio.min() == pytest.approx(1.0, rel=1e-12)
    assert np.all(ratio >= 1.0 - 1e-12)
    assert scaling.passed and scaling.smallest_ratio == pytest.approx(1.0, rel=1e-12)
    assert scaling.at_period == PERIODS[inside()][np.argmin(ratio)]
    smaller = scale_suite(PERIODS, spectra * 1.001, TARGET, SPAN, method)  # the factors are the smallest that pass
    assert np.allclose(smaller.factors, scaling.factors / 1.001, rtol=1e-12)


def test_outside_the_range_the_average_may_fall_below_the_target():
    spectra = suite()
    spectra[:, PERIODS > SPAN[1]] *= 0.2  # a suite poor at long periods, beyond the range
    scaling = scale_suite(PERIODS, spectra, TARGET, SPAN, "common")
    assert scaling.passed
    ratio = np.mean(scaling.factors[:, None] * spectra, axis=0) / TARGET
    assert ratio[PERIODS > SPAN[1]].max() < 0.6  # only the range binds the factor


def test_a_common_factor_is_one_for_every_pair():
    scaling = scale_suite(PERIODS, suite(), TARGET, SPAN, "common")
    assert np.ptp(scaling.factors) == 0.0


def test_pairs_are_fitted_to_the_target_shape_before_the_suite_factor():
    """Each pair's factor is proportional to exp(mean over the range of ln(target/S_i))."""
    spectra = suite()
    scaling = scale_suite(PERIODS, spectra, TARGET, SPAN, "pairs")
    fits = np.exp(np.mean(np.log(TARGET[inside()] / spectra[:, inside()]), axis=1))
    assert np.allclose(scaling.factors / fits, scaling.factors[0] / fits[0], rtol=1e-12)


def test_period_scaling_puts_each_pair_on_the_target_at_t_m():
    spectra = suite()
    scaling = scale_suite(PERIODS, spectra, TARGET, SPAN, "period", match_period=2.5)
    at = np.flatnonzero(PERIODS == 2.5)[0]
    assert np.allclose(scaling.factors * spectra[:, at], TARGET[at], rtol=1e-13)
    expected = np.min(np.mean(scaling.factors[:, None] * spectra, axis=0)[inside()] / TARGET[inside()])
    assert scaling.smallest_ratio == pytest.approx(expected, rel=1e-13)
    assert scaling.passed == (expected >= 1.0 - 1e-9)


def test_the_range_runs_from_three_quarters_of_the_shorter_t_m_to_five_quarters_of_the_longer():
    assert period_range(2.230, 2.687) == pytest.approx((0.75 * 2.230, 1.25 * 2.687), rel=1e-15)
    assert period_range(2.687, 2.230) == pytest.approx((0.75 * 2.230, 1.25 * 2.687), rel=1e-15)


def test_the_range_is_sampled_at_its_ends_and_at_t_m():
    periods = suite_periods([0.1, 1.0, 10.0], (1.6725, 3.35875), 2.5467)
    assert {1.6725, 3.35875, 2.5467, 0.1, 10.0} <= set(periods.tolist())
    assert np.all(np.diff(periods) > 0.0)


def test_seven_pairs_take_the_mean_fewer_the_maximum():
    assert suite_statistic(7) == "mean" and suite_statistic(11) == "mean"
    assert suite_statistic(6) == "max" and suite_statistic(1) == "max"
    assert statistic_of([0.2, 0.4, 0.9], "mean") == pytest.approx(0.5, rel=1e-15)
    assert statistic_of([0.2, 0.4, 0.9], "max") == 0.9


def test_bad_suites_are_one_line_errors():
    with pytest.raises(StickslipError, match="scaling 'nearest': expected one of pairs, common, period"):
        scale_suite(PERIODS, suite(), TARGET, SPAN, "nearest")
    with pytest.raises(StickslipError, match="no period of the spectra lies in the range 20-30 s"):
        scale_suite(PERIODS, suite(), TARGET, (20.0, 30.0), "pairs")
    spectra = suite()
    spectra[1, inside()] = 0.0
    with pytest.raises(StickslipError, match="RotD100 is zero somewhere in the period range"):
        scale_suite(PERIODS, spectra, TARGET, SPAN, "common")
    with pytest.raises(StickslipError, match="the period 2.6 s to match is not among the spectra's periods"):
        scale_suite(PERIODS, suite(), TARGET, SPAN, "period", match_period=2.6)
