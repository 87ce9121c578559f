"""Scaling a suite of station pairs to a code's target spectrum, and the suite's statistic.

The rule coded is ASCE 7-22 §17.3.3 as we know it (ASCE 7-16 §17.3.3, which
7-22 keeps; the printed text could not be read here, docs/isolation_design.md,
"Suites"): the suite's average of the pairs' maximum-direction spectra
(RotD100, :mod:`stickslip.spectra`) does not fall below the target spectrum
[g] at any period of the range from 0.75 T_M of the upper-bound properties
(the shorter T_M) to 1.25 T_M of the lower-bound properties (the longer):
:func:`period_range`.  The factors, one per pair [1] (:data:`SCALINGS`):

- ``pairs``: each pair first fitted to the target's shape over the range,
  f₀ᵢ = exp(mean over the range of ln(target/Sᵢ)), then one suite factor c
  for all, the smallest that keeps the average of cf₀ᵢSᵢ at or above the
  target over the range: fᵢ = c f₀ᵢ;
- ``common``: one factor for every pair, the smallest that keeps the
  average at or above the target over the range;
- ``period``: each pair to the target at one period (T_M at nominal
  friction): fᵢ = target(T_M)/Sᵢ(T_M); the average is then checked, not
  forced.

With ``pairs`` and ``common`` the scaled average touches the target at one
period of the range (the factor is the smallest that passes).

The statistic of a response over the suite (:func:`suite_statistic`) is the
mean over :data:`MINIMUM_PAIRS_FOR_MEAN` or more pairs and the maximum over
fewer (ASCE 7-10 §17.6.4.4's rule; 7-16 and 7-22 ask for seven pairs at least).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from stickslip.errors import StickslipError

#: The range of periods over which the suite's average may not fall below the target: from this multiple of the
#: shorter T_M (upper-bound properties) to that multiple of the longer (lower-bound properties) [1].
RANGE_FACTORS = (0.75, 1.25)

#: The suite size from which the mean of the pairs' responses is the statistic; below it, the maximum.
MINIMUM_PAIRS_FOR_MEAN = 7

#: The ways to scale a suite (module docstring), the default first.
SCALINGS = ("pairs", "common", "period")

#: Periods [s] on which the range is sampled besides the spectra's own: this many, evenly spaced in log T.
RANGE_SAMPLES = 41

#: The scaled average passes where it is at least the target times (1 - this) [1] (round-off of the factors).
RATIO_TOLERANCE = 1e-9


def period_range(upper_bound_period: float, lower_bound_period: float) -> tuple[float, float]:
    """(0.75 min(T_M), 1.25 max(T_M)) [s] of the two bounds' effective periods T_M [s] (module docstring)."""
    shorter, longer = sorted((upper_bound_period, lower_bound_period))
    return RANGE_FACTORS[0] * shorter, RANGE_FACTORS[1] * longer


def suite_statistic(size: int) -> str:
    """``"mean"`` for a suite of :data:`MINIMUM_PAIRS_FOR_MEAN` pairs or more, else ``"max"``."""
    return "mean" if size >= MINIMUM_PAIRS_FOR_MEAN else "max"


def statistic_of(values, statistic: str) -> float:
    """The ``statistic`` (``"mean"`` or ``"max"``) of ``values``."""
    return float(np.mean(values) if statistic == "mean" else np.max(values))


def suite_periods(periods, span: tuple[float, float], *extra: float) -> np.ndarray:
    """``periods`` [s] with :data:`RANGE_SAMPLES` periods spread over ``span`` (its ends included) and ``extra``,
    sorted, without repeats."""
    return np.unique(np.concatenate([np.asarray(periods, float), np.geomspace(*span, RANGE_SAMPLES), extra]))


@dataclass(frozen=True)
class SuiteScaling:
    """The factors of a suite and its check against the target.

    Attributes
    ----------
    method:
        One of :data:`SCALINGS`.
    factors:
        One scale factor per pair [1].
    span:
        The period range [s] of the check.
    smallest_ratio, at_period:
        The smallest ratio of the scaled average to the target over the range [1], and its period [s].
    """

    method: str
    factors: np.ndarray
    span: tuple[float, float]
    smallest_ratio: float
    at_period: float

    @property
    def passed(self) -> bool:
        """Whether the scaled average is nowhere in the range below the target (to :data:`RATIO_TOLERANCE`)."""
        return self.smallest_ratio >= 1.0 - RATIO_TOLERANCE


def scale_suite(periods, spectra, target, span: tuple[float, float], method: str = SCALINGS[0],
                match_period: float | None = None) -> SuiteScaling:
    """Scale the suite whose pairs have the RotD100 ``spectra`` [g] (pairs × periods) at ``periods`` [s] to the
    ``target`` [g] at the same periods over ``span`` [s] by ``method`` (module docstring); ``match_period`` [s],
    one of ``periods``, is where ``period`` matches each pair."""
    periods, spectra, target = np.asarray(periods, float), np.atleast_2d(np.asarray(spectra, float)), np.asarray(target, float)
    if method not in SCALINGS:
        raise StickslipError(f"scaling {method!r}: expected one of {', '.join(SCALINGS)}")
    inside = (periods >= span[0] * (1.0 - 1e-12)) & (periods <= span[1] * (1.0 + 1e-12))
    if not inside.any():
        raise StickslipError(f"no period of the spectra lies in the range {span[0]:.4g}-{span[1]:.4g} s")
    if not np.all(spectra[:, inside] > 0.0):
        raise StickslipError("a pair's RotD100 is zero somewhere in the period range: it cannot be scaled")
    if method == "period":
        at = np.flatnonzero(np.isclose(periods, match_period, rtol=1e-12, atol=0.0))
        if at.size == 0:
            raise StickslipError(f"the period {match_period!r} s to match is not among the spectra's periods")
        factors = target[at[0]] / spectra[:, at[0]]
    else:
        shapes = (np.exp(np.mean(np.log(target[inside] / spectra[:, inside]), axis=1)) if method == "pairs"
                  else np.ones(len(spectra)))
        suite = np.max(target[inside] / np.mean(shapes[:, None] * spectra[:, inside], axis=0))
        factors = suite * shapes
    ratios = np.mean(factors[:, None] * spectra[:, inside], axis=0) / target[inside]
    lowest = int(np.argmin(ratios))
    return SuiteScaling(method, factors, span, float(ratios[lowest]), float(periods[inside][lowest]))
