"""Rathje and Antonakos (2011): the unified model of the displacement of a flexible (or rigid) sliding mass.

Rathje, E. M. and Antonakos, G. (2011). A unified model for predicting
earthquake-induced sliding displacements of rigid and flexible slopes.
Engineering Geology 122, 51-60.  The rigid-block models of
:mod:`stickslip.estimates.saygili_rathje` are evaluated with the peak of the
sliding mass's average acceleration k_max [g] for PGA and its velocity
counterpart k-vel_max [cm s-1] for PGV, both from the period ratio
T_s/T_m (T_s the mass's fundamental period, T_m the record's mean period
[s]), then shifted by a function of T_s:

    k_max/PGA = 1                                    for T_s/T_m < 0.1,
              = exp[(0.459 − 0.702 PGA) ln(x/0.1) + (−0.228 + 0.076 PGA) ln²(x/0.1)]   otherwise;
    k-vel_max/PGV = 1                                for T_s/T_m < 0.2,
              = exp[0.240 ln(x/0.2) + (−0.091 − 0.171 PGA) ln²(x/0.2)]   otherwise
    (x = T_s/T_m, PGA in g);

* PGV model: ln D = ln D_SR08(k_y, k_max, k-vel_max) + 1.42 T_s for T_s ≤ 0.5 s,
  + 0.71 beyond; σ = 0.400 + 0.284 k_y/k_max;
* M model: ln D = ln D_RS09(k_y, k_max, M) + 3.69 T_s − 1.22 T_s² for T_s ≤ 1.5 s,
  + 2.78 beyond; σ = 0.694 + 0.322 k_y/k_max.

The medians and the cap of T_s/T_m at 8 are SLAMMER 1.1's (``UnifiedModel``);
SLAMMER gives no σ, and the σ above are pyGEEMs' (``slope_disp.py``, lines
135-138; docs/estimates.md).  D is in cm, natural logarithms.  The sliding
mass cannot slide when k_y ≥ k_max (its largest average acceleration): the
estimate is then zero, with the reason.  SLAMMER also zeroes it when
k_y > PGA, although k_max may exceed PGA (a mass that amplifies the motion);
we do not.
"""

from __future__ import annotations

import math

from stickslip.estimates.estimate import Estimate, lognormal_estimate, no_sliding, yield_at_or_above
from stickslip.estimates.saygili_rathje import log_median_cm

#: The period ratio T_s/T_m is capped here (SLAMMER's cap).
MAX_PERIOD_RATIO = 8.0

#: σ of ln D = constant + slope·k_y/k_max, per model.
SIGMA = {"pgv": (0.400, 0.284), "m": (0.694, 0.322)}


def period_ratio(site_period: float, mean_period: float) -> float:
    """T_s/T_m [1], capped at :data:`MAX_PERIOD_RATIO`: T_s and T_m in s."""
    return min(site_period / mean_period, MAX_PERIOD_RATIO)


def kmax_over_pga(ratio: float, pga: float) -> float:
    """k_max/PGA [1] at the period ratio ``ratio`` [1] and ``pga`` [g]."""
    if ratio < 0.1:
        return 1.0
    log_ratio = math.log(ratio / 0.1)
    return math.exp((0.459 - 0.702 * pga) * log_ratio + (-0.228 + 0.076 * pga) * log_ratio**2)


def kvelmax_over_pgv(ratio: float, pga: float) -> float:
    """k-vel_max/PGV [1] at the period ratio ``ratio`` [1] and ``pga`` [g]."""
    if ratio < 0.2:
        return 1.0
    log_ratio = math.log(ratio / 0.2)
    return math.exp(0.240 * log_ratio + (-0.091 - 0.171 * pga) * log_ratio**2)


def _estimate(model: str, ky: float, pga: float, kmax: float, log_median: float) -> Estimate:
    constant, slope = SIGMA[model]
    return lognormal_estimate(log_median, constant + slope * ky / kmax, "e")


def rathje_antonakos_2011_pgv(ky: float, pga: float, pgv: float, site_period: float, mean_period: float) -> Estimate:
    """The PGV model: ``ky`` and ``pga`` [g], ``pgv`` [cm s-1], T_s ``site_period`` and T_m ``mean_period`` [s]."""
    ratio = period_ratio(site_period, mean_period)
    kmax = kmax_over_pga(ratio, pga) * pga
    reason = yield_at_or_above(ky, kmax, "k_max")
    if reason:
        return no_sliding("e", reason)
    shift = 1.42 * site_period if site_period <= 0.5 else 0.71
    log_median = log_median_cm("saygili_rathje_2008_pga_pgv", ky, kmax, pgv=kvelmax_over_pgv(ratio, pga) * pgv) + shift
    return _estimate("pgv", ky, pga, kmax, log_median)


def rathje_antonakos_2011_m(ky: float, pga: float, magnitude: float, site_period: float,
                            mean_period: float) -> Estimate:
    """The magnitude model: ``ky`` and ``pga`` [g], moment magnitude, T_s and T_m ``mean_period`` [s]."""
    ratio = period_ratio(site_period, mean_period)
    kmax = kmax_over_pga(ratio, pga) * pga
    reason = yield_at_or_above(ky, kmax, "k_max")
    if reason:
        return no_sliding("e", reason)
    shift = 3.69 * site_period - 1.22 * site_period**2 if site_period <= 1.5 else 2.78
    log_median = log_median_cm("rathje_saygili_2009_pga_m", ky, kmax, magnitude=magnitude) + shift
    return _estimate("m", ky, pga, kmax, log_median)
