"""Analysis of friction-ratio sweeps: μ_max, near-optimal ranges and fits.

Energies are in J (or J/kg when the caller passes energies per unit mass:
nothing here depends on the energy unit), friction ratios μ are
dimensionless.  The functions take plain NumPy arrays or
:class:`xarray.DataArray` objects with a ``mu`` dimension, as the sweep cubes
of :mod:`stickslip.sweeps` hold them.  The rules are computed on NumPy arrays
(along the last axis) and applied to a DataArray along its ``mu`` dimension,
so this module imports neither xarray nor SciPy until a caller needs them:
``stickslip optimum`` runs without either.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from stickslip.errors import StickslipError


def _is_dataarray(value) -> bool:
    """Whether ``value`` is an :class:`xarray.DataArray` (it cannot be one while xarray is not imported)."""
    xarray = sys.modules.get("xarray")
    return xarray is not None and isinstance(value, xarray.DataArray)


def _curves(energy, mu) -> tuple[np.ndarray, np.ndarray]:
    """``energy`` as a float array whose last axis runs over the friction ratios ``mu`` [1], and ``mu``."""
    energy = np.asarray(energy, dtype=float)
    if mu is None:
        raise StickslipError("the friction ratios mu are needed with a plain array of energies")
    mu = np.asarray(mu, dtype=float)
    if energy.shape[-1:] != mu.shape:
        raise StickslipError(f"energy has {energy.shape[-1:]} values along mu, but {mu.size} friction ratios were given")
    return energy, mu


def _along_mu(rule: Callable, energy, dim: str, outputs: int, **kwargs):
    """``rule(energy_array, mu_array, **kwargs)`` applied to the DataArray ``energy`` along ``dim``."""
    import xarray as xr

    return xr.apply_ufunc(rule, energy, energy[dim], input_core_dims=[[dim], [dim]],
                          output_core_dims=[[]] * outputs, kwargs=kwargs)


def _plain(values: np.ndarray):
    """A NumPy result as a Python scalar for a single curve, else the array."""
    return values.item() if values.ndim == 0 else values


def grid_maximum_index(energy: np.ndarray) -> np.ndarray:
    """Index along the last axis of the largest dissipated energy [J] of each curve (ties: the first, smallest μ).

    -1 for a curve with no finite value.
    """
    energy = np.asarray(energy, dtype=float)
    finite = np.isfinite(energy)
    best = np.argmax(np.where(finite, energy, -np.inf), axis=-1)
    return np.where(finite.any(axis=-1), best, -1)


def _mu_max(energy: np.ndarray, mu: np.ndarray) -> np.ndarray:
    best = grid_maximum_index(energy)
    return np.where(best >= 0, mu[np.maximum(best, 0)], np.nan)


def mu_max_on_grid(energy, mu=None, dim: str = "mu"):
    """The friction ratio of largest dissipated energy on the swept grid.

    Parameters
    ----------
    energy:
        Dissipated energy E_df [J or J/kg]: a DataArray with dimension ``dim``,
        or an array whose last axis runs over ``mu``.
    mu:
        Friction ratios [1] of the last axis (arrays only; a DataArray carries them).
    dim:
        Name of the friction-ratio dimension.

    Returns
    -------
    μ_max [1] for each curve: a DataArray without ``dim``, a NumPy array, or a
    float for a single curve.  Ties go to the smallest μ; a curve with no
    finite value gives NaN.
    """
    if _is_dataarray(energy):
        return _along_mu(_mu_max, energy, dim, 1)
    return _plain(_mu_max(*_curves(energy, mu)))


def mu_max_on_grid_edge(energy, mu=None, dim: str = "mu"):
    """Whether μ_max of ``energy`` [J] is the smallest or largest μ of its grid.

    On an edge, the true maximum may lie outside the swept range: μ_max is
    then a bound, not a value.  ``energy`` as for :func:`mu_max_on_grid`;
    a bool for one curve, else booleans (False for a curve with no finite value).
    """
    def on_edge(curves: np.ndarray, grid: np.ndarray) -> np.ndarray:
        best = grid_maximum_index(curves)
        return (best == 0) | (best == grid.size - 1)

    if _is_dataarray(energy):
        result = _along_mu(on_edge, energy, dim, 1)
        return bool(result) if result.ndim == 0 else result
    return _plain(on_edge(*_curves(energy, mu)))


@dataclass(frozen=True)
class Maximum:
    """A refined maximum of a function of one variable.

    Attributes
    ----------
    argument, value:
        The continuous maximiser and the function value there.
    grid_argument, grid_value:
        The best point of the grid that bracketed the search.
    """

    argument: float
    value: float
    grid_argument: float
    grid_value: float


#: How much steeper than its neighbours a grid cell's curve may be assumed to rise inside it
#: (:func:`cells_within_reach`): the margin of the reach test, a factor on the largest neighbouring slope.
REACH_SLOPE_FACTOR = 2.0


def cells_within_reach(grid: np.ndarray, values: np.ndarray, slope_factor: float = REACH_SLOPE_FACTOR) -> np.ndarray:
    """Indices i of the grid cells [grid[i], grid[i+1]] inside which the curve could rise above its grid maximum.

    Inside a cell of width h whose ends hold a and b, a curve whose slope is at
    most L rises at most to (a + b + L·h)/2.  L is taken as ``slope_factor``
    times the largest finite-difference slope of the cell and its two
    neighbours: E_df(μ) is continuous but not smooth (a slip episode appears
    or vanishes at a kink), so the bound is an estimate with a margin, not a
    proof; :func:`refine_maximum` searches every cell it admits.
    """
    width = np.diff(grid)
    slope = np.abs(np.diff(values)) / width
    neighbours = np.maximum(slope, np.maximum(np.r_[0.0, slope[:-1]], np.r_[slope[1:], 0.0]))
    ceiling = (values[:-1] + values[1:] + slope_factor * neighbours * width) / 2.0
    return np.flatnonzero(ceiling >= values.max())


#: Points each cell within reach is resampled with, per round of :func:`refine_maximum` (at most).
CELL_SAMPLES = 64

#: Relative slack of the tolerance on the argument: a spacing within xatol·(1 + slack) is xatol (round-off of linspace).
SPACING_SLACK = 1e-9


def cell_steps(width: float, xatol: float) -> int:
    """How many equal steps a cell of ``width`` is resampled with: :data:`CELL_SAMPLES`, or fewer where they reach ``xatol``.

    A cell at most :data:`CELL_SAMPLES` tolerances wide needs one round of
    ⌈width/xatol⌉ steps, not :data:`CELL_SAMPLES`: the spacing is within
    ``xatol`` either way (both in the units of the argument).
    """
    return int(min(CELL_SAMPLES, max(1, math.ceil(width / (xatol * (1.0 + SPACING_SLACK))))))


def refine_maximum(function: Callable[[float], float], grid, values=None, xatol: float = 1e-6,
                   on_points: Callable[[np.ndarray], np.ndarray] | None = None) -> Maximum:
    """The maximum of ``function`` over the span of a grid, its argument found to ``xatol``.

    Round by round, every cell that could hold a point above the best value
    found so far (:func:`cells_within_reach`) is resampled with equal steps
    (:data:`CELL_SAMPLES`, or as few as reach ``xatol``: :func:`cell_steps`),
    until the cells left are at most ``xatol`` wide; the best point sampled is the answer.  A second, lower
    local maximum cannot capture the search, and a higher one a few cells
    away from the grid's best point is found as well (E_df(μ) has kinks and
    small-scale bumps, which a local search inside one bracket misses).  The
    grid's best point stays a candidate throughout, so the answer is never
    below it.

    Parameters
    ----------
    function:
        The function to maximise.
    grid:
        Increasing arguments to evaluate first.
    values:
        ``function`` on ``grid`` when already known (saves the evaluations).
    xatol:
        Absolute tolerance on the argument: the spacing of the last round.
    on_points:
        ``function`` on an increasing array of arguments at once (a batched
        kernel); by default ``function`` is called at each.
    """
    grid = np.asarray(grid, dtype=float)
    if grid.ndim != 1 or grid.size < 2 or np.any(np.diff(grid) <= 0):
        raise StickslipError("the refinement grid must hold at least two strictly increasing values")
    if not xatol > 0.0:
        raise StickslipError(f"the tolerance xatol must be positive, got {xatol}")
    evaluate = on_points or (lambda points: np.array([function(x) for x in points]))
    values = evaluate(grid) if values is None else np.asarray(values, dtype=float)
    best = int(np.argmax(values))
    grid_argument, grid_value = float(grid[best]), float(values[best])
    points = grid
    while True:
        cells = cells_within_reach(points, values)
        if np.diff(points)[cells].max() <= xatol * (1.0 + 2.0 * SPACING_SLACK):
            break
        resampled = np.unique(np.concatenate([np.linspace(points[cell], points[cell + 1],
                                                          cell_steps(points[cell + 1] - points[cell], xatol) + 1)
                                              for cell in cells]))
        known = np.isin(resampled, points)  # the cells' ends: evaluated in the round before
        new_values = np.empty(resampled.size)
        new_values[known] = values[np.searchsorted(points, resampled[known])]
        new_values[~known] = evaluate(resampled[~known])
        points, values = resampled, new_values
    best = int(np.argmax(values))
    return Maximum(argument=float(points[best]), value=float(values[best]), grid_argument=grid_argument,
                   grid_value=grid_value)


def near_optimal_set(energy, q: float = 0.95, dim: str = "mu"):
    """Which friction ratios are near-optimal: E_df ≥ ``q`` times the curve's maximum.

    The one rule of the near-optimal set, shared by :func:`near_optimal_range`,
    the collection study's coverage and its figures.

    Parameters
    ----------
    energy:
        Dissipated energy E_df [J or J/kg]: DataArray with dimension ``dim``,
        or an array whose last axis runs over the friction ratios.
    q:
        Fraction of the maximum, 0 < q ≤ 1.

    Returns
    -------
    Booleans of the shape of ``energy``: a DataArray, or a NumPy array for an array.
    """
    if not 0.0 < q <= 1.0:
        raise StickslipError(f"the near-optimal fraction q must be in (0, 1], got {q}")
    if _is_dataarray(energy):
        return energy >= q * energy.max(dim)
    energy = np.asarray(energy, dtype=float)
    return energy >= q * energy.max(axis=-1, keepdims=True)


def _near_optimal_range(energy: np.ndarray, mu: np.ndarray, q: float):
    """(mu_low, mu_high, contiguous) of the curves ``energy`` along their last axis, over the grid ``mu``."""
    qualifies = near_optimal_set(energy, q)
    with np.errstate(invalid="ignore"):
        mu_low = np.where(qualifies, mu, np.inf).min(axis=-1)
        mu_high = np.where(qualifies, mu, -np.inf).max(axis=-1)
    none = ~qualifies.any(axis=-1)
    mu_low, mu_high = np.where(none, np.nan, mu_low), np.where(none, np.nan, mu_high)
    inside = (mu >= mu_low[..., None]) & (mu <= mu_high[..., None])
    contiguous = (qualifies | ~inside).all(axis=-1)
    return mu_low, mu_high, contiguous


def near_optimal_range(energy, mu=None, q: float = 0.95, dim: str = "mu"):
    """The friction ratios whose dissipated energy is at least ``q`` times the maximum.

    This is the paper's Table 7 ("a whole range of values for which energy
    dissipation is almost equal").

    Parameters
    ----------
    energy:
        Dissipated energy E_df [J or J/kg]: DataArray with dimension ``dim``,
        or an array whose last axis runs over ``mu``.
    mu:
        Friction ratios [1] (arrays only).
    q:
        Fraction of the maximum, 0 < q ≤ 1.

    Returns
    -------
    ``(mu_low, mu_high, contiguous)``: the smallest and largest qualifying μ
    [1], and whether every grid μ between them qualifies too (False means the
    qualifying set has a gap, which a plain "low – high" range would hide).
    NaN bounds for a curve of which no μ qualifies (no finite energy).
    """
    if not 0.0 < q <= 1.0:
        raise StickslipError(f"the near-optimal fraction q must be in (0, 1], got {q}")
    if _is_dataarray(energy):
        return _along_mu(_near_optimal_range, energy, dim, 3, q=q)
    return tuple(_plain(values) for values in _near_optimal_range(*_curves(energy, mu), q))


def consistent_q_interval(energy, mu, mu_low: float, mu_high: float) -> tuple[float, float]:
    """The fractions q for which :func:`near_optimal_range` gives exactly [mu_low, mu_high].

    For one energy curve E_df(μ) [J] on the grid ``mu`` [1], the set
    {μ : E ≥ q·E_max} equals the grid points in [mu_low, mu_high] when
    ``q_above < q ≤ q_at_most`` with q_at_most = min inside / E_max and
    q_above = max outside / E_max.  An empty interval (q_above ≥ q_at_most)
    means no q reproduces the range.

    Returns
    -------
    ``(q_above, q_at_most)`` [1]; q_above is 0 when every grid point is inside.
    """
    energy = np.asarray(energy, dtype=float)
    mu = np.asarray(mu, dtype=float)
    spacing = np.min(np.diff(mu))
    inside = (mu >= mu_low - 1e-6 * spacing) & (mu <= mu_high + 1e-6 * spacing)
    if not inside.any():
        raise StickslipError(f"no grid friction ratio lies in [{mu_low}, {mu_high}]")
    peak = energy.max()
    q_at_most = energy[inside].min() / peak
    q_above = energy[~inside].max() / peak if (~inside).any() else 0.0
    return float(q_above), float(q_at_most)


@dataclass(frozen=True)
class LinearFit:
    """A least-squares line y = slope·x + intercept with a bootstrap confidence band.

    Attributes
    ----------
    slope, intercept:
        The fitted line (units of y per unit of x, units of y).
    r:
        Pearson correlation coefficient [1].
    n:
        Number of points.
    band_x:
        Abscissae of the band (units of x).
    band_low, band_high:
        Pointwise 2.5 % and 97.5 % quantiles of the bootstrap lines at ``band_x``.
    slope_interval:
        2.5 % and 97.5 % bootstrap quantiles of the slope.
    """

    slope: float
    intercept: float
    r: float
    n: int
    band_x: np.ndarray
    band_low: np.ndarray
    band_high: np.ndarray
    slope_interval: tuple[float, float]

    def as_dict(self) -> dict:
        """Plain JSON-ready values."""
        return {
            "slope": self.slope,
            "intercept": self.intercept,
            "r": self.r,
            "n": self.n,
            "band_x": self.band_x.tolist(),
            "band_low": self.band_low.tolist(),
            "band_high": self.band_high.tolist(),
            "slope_interval": list(self.slope_interval),
        }


def _check_pairs(x, y) -> tuple[np.ndarray, np.ndarray]:
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    if x.shape != y.shape or x.ndim != 1:
        raise StickslipError(f"x and y must be 1-D of equal length, got shapes {x.shape} and {y.shape}")
    if x.size < 3 or np.ptp(x) == 0:
        raise StickslipError("a line needs at least three points with at least two distinct x values")
    return x, y


def linear_fit(x, y, n_boot: int = 2000, seed: int = 0, band_points: int = 50) -> LinearFit:
    """Least-squares line through (x, y), Pearson r and a 95 % bootstrap band (the paper's Fig. 22).

    The band resamples the (x, y) pairs with replacement ``n_boot`` times
    (resamples with a single distinct x are drawn again), refits the line and
    takes the pointwise 2.5 % and 97.5 % quantiles over ``band_points`` values
    of x spanning the data.

    Parameters
    ----------
    x, y:
        The points (any units; the slope is in units of y per unit of x).
    n_boot:
        Number of bootstrap resamples.
    seed:
        Seed of the random generator (the band is reproducible).
    """
    x, y = _check_pairs(x, y)
    slope, intercept = np.polyfit(x, y, 1)
    r = float(np.corrcoef(x, y)[0, 1]) if np.ptp(y) > 0 else float("nan")
    rng = np.random.default_rng(seed)
    band_x = np.linspace(x.min(), x.max(), band_points)
    slopes = np.empty(n_boot)
    lines = np.empty((n_boot, band_points))
    drawn = 0
    while drawn < n_boot:
        pick = rng.integers(0, x.size, x.size)
        if np.ptp(x[pick]) == 0:
            continue
        boot_slope, boot_intercept = np.polyfit(x[pick], y[pick], 1)
        slopes[drawn] = boot_slope
        lines[drawn] = boot_slope * band_x + boot_intercept
        drawn += 1
    band_low, band_high = np.quantile(lines, [0.025, 0.975], axis=0)
    slope_low, slope_high = np.quantile(slopes, [0.025, 0.975])
    return LinearFit(
        slope=float(slope),
        intercept=float(intercept),
        r=r,
        n=int(x.size),
        band_x=band_x,
        band_low=band_low,
        band_high=band_high,
        slope_interval=(float(slope_low), float(slope_high)),
    )


def relation_summary(x, y, labels=None, n_boot: int = 2000, seed: int = 0) -> dict:
    """Describe how y depends on x without assuming the shape (the paper's Fig. 23).

    Returns the raw points (with ``labels``), the least-squares line with its
    bootstrap band (:func:`linear_fit`), Pearson r, and Spearman's rank
    correlation ρ with its p-value, which catches a monotonic but non-linear
    trend, and whose small magnitude flags the absence of any monotonic trend.
    """
    from scipy import stats

    x, y = _check_pairs(x, y)
    spearman = stats.spearmanr(x, y)
    labels = list(labels) if labels is not None else [str(i) for i in range(x.size)]
    fit = linear_fit(x, y, n_boot=n_boot, seed=seed)
    return {
        "points": [{"label": label, "x": float(xi), "y": float(yi)} for label, xi, yi in zip(labels, x, y)],
        "linear_fit": fit.as_dict(),
        "pearson_r": fit.r,
        "spearman_rho": float(spearman.statistic),
        "spearman_p_value": float(spearman.pvalue),
    }
