"""Bray and Macedo's successors of Bray and Travasarou (2007): shallow crustal and subduction-zone earthquakes.

The estimates of current practice for the shear-induced displacement D [cm] of
a sliding mass of yield coefficient k_y [g] and initial fundamental period T_s
[s] (0 for a rigid one), with natural logarithms.  Like Bray and Travasarou
(2007) (:mod:`~stickslip.estimates.bray_travasarou`), each gives P(D = 0) and
a lognormal median D̂ and σ of the non-zero part, so that
P(D > d) = (1 − P(D = 0))·P(D > d | D > 0).

**Bray and Macedo (2019)**, shallow crustal earthquakes: Bray, J. D. and
Macedo, J. (2019). Procedure for estimating shear-induced seismic slope
displacement for shallow crustal earthquakes. Journal of Geotechnical and
Geoenvironmental Engineering 145(12), 04019106.  The model of all their
ground motions, ordinary and near-fault (their eqs. 8 and 9), with Sa the
5 %-damped spectral acceleration at the degraded period 1.3 T_s [g] (the PGA
for T_s = 0), M the moment magnitude and PGV [cm/s]:

    P(D = 0) = 1 − Φ(−2.46 − 2.98 ln k_y − 0.12 (ln k_y)² − 0.71 T_s ln k_y + 1.69 T_s + 2.76 ln Sa)  (T_s ≤ 0.7 s)
    P(D = 0) = 1 − Φ(−3.40 − 4.95 ln k_y − 0.30 (ln k_y)² − 0.33 T_s ln k_y − 0.62 T_s + 2.85 ln Sa)  (T_s > 0.7 s)
    ln D̂ = a1 − 2.491 ln k_y − 0.245 (ln k_y)² + 0.344 ln k_y ln Sa + 2.703 ln Sa − 0.089 (ln Sa)²
           + a2 T_s + a3 T_s² + 0.607 M + a4 ln PGV + a5,        σ = 0.74,

a1, a2, a3 = −4.551, −9.690, 0 for T_s < 0.1 s and −5.894, 3.152, −0.910
from 0.1 s; a4, a5 = 0, 0 for PGV ≤ 115 cm/s and 1, −4.75 above (the
near-fault motions' ln(PGV/115)).  P(D = 0) is that of D below 0.5 cm.

**Bray, Macedo and Travasarou (2018)**, subduction-zone earthquakes: Bray,
J. D., Macedo, J. and Travasarou, T. (2018). Simplified procedure for
estimating seismic slope displacements for subduction zone earthquakes.
Journal of Geotechnical and Geoenvironmental Engineering 144(3), 04017124.
With Sa at 1.5 T_s [g] (the PGA for T_s = 0):

    P(D = 0) = 1 − Φ(−2.64 − 3.20 ln k_y − 0.17 (ln k_y)² − 0.49 T_s ln k_y + 2.09 T_s + 2.91 ln Sa)  (T_s ≤ 0.7 s)
    P(D = 0) = 1 − Φ(−3.53 − 4.78 ln k_y − 0.34 (ln k_y)² − 0.30 T_s ln k_y − 0.67 T_s + 2.66 ln Sa)  (T_s > 0.7 s)
    ln D̂ = a1 − 3.353 ln k_y − 0.390 (ln k_y)² + 0.538 ln k_y ln Sa + 3.060 ln Sa − 0.225 (ln Sa)²
           + a2 T_s + a3 T_s² + 0.550 M,        σ = 0.73,

a1, a2, a3 = −5.864, −9.421, 0 for T_s < 0.1 s and −6.896, 3.081, −0.803
from 0.1 s.

Where the coefficients come from, how they were checked against the papers'
examples and where the open codes depart: docs/estimates.md.
"""

from __future__ import annotations

import math

from stickslip.estimates.estimate import Estimate, lognormal_estimate, normal_cdf

#: From this T_s [s] on, the period terms change (a1, a2, a3 of both papers).
STIFF_PERIOD = 0.1

#: Above this T_s [s], the other P(D = 0) (both papers).
LONG_PERIOD = 0.7

#: Bray and Macedo (2019): above this PGV [cm/s] a motion is near-fault-like and ln(PGV/115) enters.
PULSE_PGV = 115.0

#: σ of ln D̂ [ln units]: Bray and Macedo (2019), Bray, Macedo and Travasarou (2018).
SIGMA_CRUSTAL = 0.74
SIGMA_SUBDUCTION = 0.73

#: Bray and Macedo (2019) take Sa at this multiple of T_s, the degraded period (the others at 1.5 T_s).
CRUSTAL_PERIOD_FACTOR = 1.3


def _probit(ky: float, site_period: float, sa: float, short: tuple, long: tuple) -> float:
    """The argument of Φ in P(D > 0) = Φ(·), with the coefficients (c0, c_ky, c_ky², c_Tky, c_T, c_Sa) of T_s."""
    c0, c_ky, c_ky2, c_tky, c_t, c_sa = short if site_period <= LONG_PERIOD else long
    log_ky = math.log(ky)
    return (c0 + c_ky * log_ky + c_ky2 * log_ky**2 + c_tky * site_period * log_ky + c_t * site_period
            + c_sa * math.log(sa))


def _period_terms(site_period: float, short: tuple, stiff: tuple) -> float:
    """a1 + a2 T_s + a3 T_s² with (a1, a2, a3) ``short`` below :data:`STIFF_PERIOD` and ``stiff`` from it."""
    a1, a2, a3 = short if site_period < STIFF_PERIOD else stiff
    return a1 + a2 * site_period + a3 * site_period**2


def crustal_probit(ky: float, site_period: float, spectral_acceleration: float) -> float:
    """Bray and Macedo (2019): the argument of Φ in P(D > 0); ``ky`` [g], T_s [s], Sa(1.3 T_s) [g]."""
    return _probit(ky, site_period, spectral_acceleration, (-2.46, -2.98, -0.12, -0.71, 1.69, 2.76),
                   (-3.40, -4.95, -0.30, -0.33, -0.62, 2.85))


def crustal_log_median_cm(ky: float, site_period: float, spectral_acceleration: float, magnitude: float,
                          pgv: float) -> float:
    """Bray and Macedo (2019): ln D̂ [ln cm]; ``ky`` [g], T_s [s], Sa(1.3 T_s) [g], M, PGV [cm/s]."""
    log_ky, log_sa = math.log(ky), math.log(spectral_acceleration)
    pulse = math.log(pgv) - 4.75 if pgv > PULSE_PGV else 0.0
    return (_period_terms(site_period, (-4.551, -9.690, 0.0), (-5.894, 3.152, -0.910))
            - 2.491 * log_ky - 0.245 * log_ky**2 + 0.344 * log_ky * log_sa + 2.703 * log_sa - 0.089 * log_sa**2
            + 0.607 * magnitude + pulse)


def subduction_probit(ky: float, site_period: float, spectral_acceleration: float) -> float:
    """Bray, Macedo and Travasarou (2018): the argument of Φ in P(D > 0); ``ky`` [g], T_s [s], Sa(1.5 T_s) [g]."""
    return _probit(ky, site_period, spectral_acceleration, (-2.64, -3.20, -0.17, -0.49, 2.09, 2.91),
                   (-3.53, -4.78, -0.34, -0.30, -0.67, 2.66))


def subduction_log_median_cm(ky: float, site_period: float, spectral_acceleration: float, magnitude: float) -> float:
    """Bray, Macedo and Travasarou (2018): ln D̂ [ln cm]; ``ky`` [g], T_s [s], Sa(1.5 T_s) [g], M."""
    log_ky, log_sa = math.log(ky), math.log(spectral_acceleration)
    return (_period_terms(site_period, (-5.864, -9.421, 0.0), (-6.896, 3.081, -0.803))
            - 3.353 * log_ky - 0.390 * log_ky**2 + 0.538 * log_ky * log_sa + 3.060 * log_sa - 0.225 * log_sa**2
            + 0.550 * magnitude)


def bray_macedo_2019(ky: float, site_period: float, spectral_acceleration_13: float | None, magnitude: float,
                     pgv: float, pga: float | None = None) -> Estimate:
    """Shallow crustal earthquakes: the estimate at ``ky`` [g], T_s ``site_period`` [s], Sa(1.3 T_s)
    ``spectral_acceleration_13`` [g], M ``magnitude`` and PGV ``pgv`` [cm/s]; for T_s = 0, ``pga`` [g] is Sa."""
    sa = pga if site_period == 0.0 else spectral_acceleration_13
    p_zero = 1.0 - normal_cdf(crustal_probit(ky, site_period, sa))
    return lognormal_estimate(crustal_log_median_cm(ky, site_period, sa, magnitude, pgv), SIGMA_CRUSTAL, "e",
                              p_zero=p_zero)


def bray_macedo_travasarou_2018(ky: float, site_period: float, spectral_acceleration: float | None, magnitude: float,
                                pga: float | None = None) -> Estimate:
    """Subduction-zone earthquakes: the estimate at ``ky`` [g], T_s ``site_period`` [s], Sa(1.5 T_s)
    ``spectral_acceleration`` [g] and M ``magnitude``; for T_s = 0, ``pga`` [g] is Sa."""
    sa = pga if site_period == 0.0 else spectral_acceleration
    p_zero = 1.0 - normal_cdf(subduction_probit(ky, site_period, sa))
    return lognormal_estimate(subduction_log_median_cm(ky, site_period, sa, magnitude), SIGMA_SUBDUCTION, "e",
                              p_zero=p_zero)
