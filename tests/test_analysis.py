"""Analysis of sweeps on synthetic data with known answers: μ_max, ranges, refinement, fits."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from scipy import optimize

from stickslip.analysis import (
    consistent_q_interval,
    linear_fit,
    mu_max_on_grid,
    mu_max_on_grid_edge,
    near_optimal_range,
    near_optimal_set,
    refine_maximum,
    relation_summary,
)
from stickslip.errors import StickslipError

MU = np.array([0.050, 0.075, 0.100, 0.125, 0.150, 0.175, 0.200])


def parabola(mu, peak):
    """A concave energy curve [J] with its maximum at ``peak``."""
    return 1.0 - 40.0 * (mu - peak) ** 2


def test_mu_max_on_grid_of_one_curve_is_the_argmax():
    assert mu_max_on_grid(parabola(MU, 0.13), MU) == pytest.approx(0.125)


def test_mu_max_on_grid_runs_along_mu_of_a_dataarray():
    peaks = np.array([0.06, 0.12, 0.19])
    energy = xr.DataArray(
        parabola(MU[None, :], peaks[:, None]),
        dims=("record", "mu"),
        coords={"record": ["a", "b", "c"], "mu": MU},
    ).transpose("mu", "record")
    result = mu_max_on_grid(energy)
    assert isinstance(result, xr.DataArray)
    assert result.dims == ("record",)
    np.testing.assert_allclose(result.sel(record=["a", "b", "c"]).values, [0.050, 0.125, 0.200])


@pytest.mark.parametrize("peak, on_edge", [(0.03, True), (0.12, False), (0.26, True), (0.17, False)])
def test_mu_max_on_grid_edge_flags_a_maximum_at_either_end(peak, on_edge):
    energy = xr.DataArray(parabola(MU, peak), dims="mu", coords={"mu": MU})
    assert mu_max_on_grid_edge(energy) is on_edge


def test_mu_max_on_grid_rejects_mismatched_lengths():
    with pytest.raises(StickslipError, match="7 friction ratios"):
        mu_max_on_grid(np.ones(5), MU)


def test_refine_maximum_finds_a_smooth_peak_between_grid_points():
    grid = np.linspace(0.01, 0.40, 40)
    found = refine_maximum(lambda mu: parabola(mu, 0.1234), grid, xatol=1e-8)
    assert found.argument == pytest.approx(0.1234, abs=1e-6)
    assert found.value >= found.grid_value
    assert found.grid_argument == pytest.approx(0.12, abs=0.005)


def two_peaks(x):
    """A narrow global maximum (1.0 at 0.3) beside a broad, lower one (0.8 at 0.1)."""
    return np.exp(-(((x - 0.3) / 0.01) ** 2)) + 0.8 * np.exp(-(((x - 0.1) / 0.05) ** 2))


def test_the_two_peak_function_fools_an_unbracketed_search():
    naive = optimize.minimize_scalar(lambda x: -two_peaks(x), bounds=(0.01, 0.40), method="bounded")
    assert naive.x == pytest.approx(0.1, abs=0.01)  # the trap is real: a plain bounded search ends on the lower peak


def test_refine_maximum_is_not_fooled_by_a_second_local_maximum():
    grid = np.arange(0.01, 0.40 + 1e-12, 0.001)
    found = refine_maximum(two_peaks, grid)
    assert found.argument == pytest.approx(0.3, abs=1e-5)
    assert found.value == pytest.approx(1.0, rel=1e-6)


def test_refine_maximum_keeps_the_grid_point_at_a_kink():
    grid = np.linspace(0.0, 0.4, 41)  # holds the kink at 0.2 exactly
    found = refine_maximum(lambda x: -abs(x - 0.2), grid)
    assert found.argument == grid[20]
    assert found.value == 0.0


def test_refine_maximum_rejects_an_unordered_grid():
    with pytest.raises(StickslipError, match="strictly increasing"):
        refine_maximum(two_peaks, [0.2, 0.1, 0.3])


def test_near_optimal_range_of_a_parabola():
    energy = parabola(MU, 0.125)  # 1.0 at 0.125; 0.975 at ±0.025; 0.9 at ±0.05
    assert near_optimal_range(energy, MU, q=0.95) == (0.100, 0.150, True)
    assert near_optimal_range(energy, MU, q=0.85) == (0.075, 0.175, True)
    assert near_optimal_range(energy, MU, q=1.0) == (0.125, 0.125, True)


def test_the_near_optimal_set_is_one_rule_for_arrays_and_dataarrays():
    energy = np.stack([parabola(MU, 0.1), parabola(MU, 0.15)])
    expected = energy >= 0.95 * energy.max(axis=1, keepdims=True)
    np.testing.assert_array_equal(near_optimal_set(energy, 0.95), expected)
    labelled = xr.DataArray(energy, dims=("record", "mu"), coords={"mu": MU})
    np.testing.assert_array_equal(near_optimal_set(labelled, 0.95).values, expected)
    low, high, _ = near_optimal_range(energy, MU, q=0.95)
    np.testing.assert_array_equal(low, [MU[row].min() for row in expected])
    np.testing.assert_array_equal(high, [MU[row].max() for row in expected])


def test_near_optimal_range_reports_a_gap():
    energy = np.array([0.97, 0.50, 1.00, 0.2, 0.1, 0.1, 0.1])
    low, high, contiguous = near_optimal_range(energy, MU, q=0.95)
    assert (low, high, contiguous) == (0.050, 0.100, False)


def test_near_optimal_range_on_a_dataarray_per_record():
    energy = xr.DataArray(
        np.stack([parabola(MU, 0.075), parabola(MU, 0.175)]),
        dims=("record", "mu"),
        coords={"record": ["a", "b"], "mu": MU},
    )
    low, high, contiguous = near_optimal_range(energy, q=0.95)
    np.testing.assert_allclose(low.values, [0.050, 0.150])
    np.testing.assert_allclose(high.values, [0.100, 0.200])
    assert contiguous.values.tolist() == [True, True]


@pytest.mark.parametrize("q", [0.0, 1.5])
def test_near_optimal_range_rejects_q_outside_zero_one(q):
    with pytest.raises(StickslipError, match="fraction q"):
        near_optimal_range(parabola(MU, 0.1), MU, q=q)


def test_consistent_q_interval_brackets_the_range():
    energy = parabola(MU, 0.125)
    q_above, q_at_most = consistent_q_interval(energy, MU, 0.100, 0.150)
    assert q_above == pytest.approx(0.9)
    assert q_at_most == pytest.approx(0.975)
    for q in (0.91, 0.95, 0.975):
        assert near_optimal_range(energy, MU, q=q)[:2] == (0.100, 0.150)


def test_linear_fit_of_an_exact_line():
    x = np.array([3.1, 4.1, 4.3, 5.7, 5.9, 6.5, 8.8])
    fit = linear_fit(x, 0.02 * x - 0.01, n_boot=200)
    assert fit.slope == pytest.approx(0.02, rel=1e-10)
    assert fit.intercept == pytest.approx(-0.01, abs=1e-12)
    assert fit.r == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(fit.band_low, 0.02 * fit.band_x - 0.01, atol=1e-12)
    np.testing.assert_allclose(fit.band_high, 0.02 * fit.band_x - 0.01, atol=1e-12)


def test_linear_fit_band_covers_the_true_line_under_noise():
    """Over 20 noisy data sets the 95 % bands hold the true slope and line in most cases."""
    rng = np.random.default_rng(7)
    slope_covered, line_covered = [], []
    for trial in range(20):
        x = rng.uniform(3.0, 9.0, 40)
        fit = linear_fit(x, 0.015 * x + 0.02 + rng.normal(0.0, 0.01, x.size), n_boot=300, seed=trial)
        assert fit.slope == pytest.approx(0.015, abs=0.004)
        assert 0.0 < fit.r < 1.0
        assert np.all(fit.band_high > fit.band_low)
        slope_covered.append(fit.slope_interval[0] < 0.015 < fit.slope_interval[1])
        true_line = 0.015 * fit.band_x + 0.02
        line_covered.append(np.mean((fit.band_low <= true_line) & (true_line <= fit.band_high)))
    assert np.mean(slope_covered) >= 0.8
    assert np.mean(line_covered) >= 0.8


def test_linear_fit_is_reproducible_with_a_seed():
    x, y = np.arange(6.0), np.array([0.1, 0.3, 0.2, 0.5, 0.4, 0.7])
    first, second = linear_fit(x, y, seed=3), linear_fit(x, y, seed=3)
    np.testing.assert_array_equal(first.band_low, second.band_low)


def test_linear_fit_rejects_too_few_or_constant_x():
    with pytest.raises(StickslipError, match="three points"):
        linear_fit([1.0, 1.0, 1.0], [1.0, 2.0, 3.0])
    with pytest.raises(StickslipError, match="equal length"):
        linear_fit([1.0, 2.0, 3.0], [1.0, 2.0])


def test_relation_summary_separates_monotonic_from_linear():
    x = np.linspace(0.5, 3.0, 8)
    summary = relation_summary(x, np.exp(3 * x), labels=[f"r{i}" for i in range(8)], n_boot=100)
    assert summary["spearman_rho"] == pytest.approx(1.0)
    assert summary["pearson_r"] < 0.95
    assert summary["points"][2] == {"label": "r2", "x": x[2], "y": np.exp(3 * x[2])}
    assert summary["linear_fit"]["n"] == 8
