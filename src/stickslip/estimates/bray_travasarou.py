"""Bray and Travasarou (2007): the displacement of a flexible (or rigid) sliding mass, with its probability of being zero.

Bray, J. D. and Travasarou, T. (2007). Simplified procedure for estimating
earthquake-induced deviatoric slope displacements. Journal of Geotechnical
and Geoenvironmental Engineering 133(4), 381-392.  With D in cm, the yield
coefficient k_y [g], the sliding mass's initial fundamental period T_s [s],
the 5 %-damped spectral acceleration of the input at 1.5 T_s, Sa [g], and the
moment magnitude M, natural logarithms:

    P(D = 0) = 1 − Φ(−1.76 − 3.22 ln k_y − 0.484 T_s ln k_y + 3.52 ln Sa),
    ln D̂ = c0 − 2.83 ln k_y − 0.333 (ln k_y)² + 0.566 ln k_y ln Sa + 3.04 ln Sa
           − 0.244 (ln Sa)² + c_T T_s + 0.278 (M − 7),        σ = 0.66,

with c0 = −1.10 and c_T = 1.50 for T_s ≥ 0.05 s, and, for a rigid sliding mass
(T_s < 0.05 s), c0 = −0.22, no T_s term and Sa = PGA (the paper's rigid
branch).  D̂ is the median of the non-zero displacement: the lognormal
describes D given D > 0, so P(D > d) = (1 − P(D = 0))·P(D > d | D > 0).

Where SLAMMER 1.1 (``CoupledSimplified.BrayAndTravasarou2007``) differs, we
follow the paper (docs/estimates.md): SLAMMER's Φ is the polynomial of
Abramowitz and Stegun 26.2.17 without its symmetry for negative arguments,
which gives P(D = 0) far outside [0, 1] in weak shaking (:func:`slammer_p_zero`
reproduces it, for the comparison); it has no rigid branch; and it prints
the median of the non-zero part as the displacement, without P(D = 0) in it.
"""

from __future__ import annotations

import math

from stickslip.estimates.estimate import Estimate, lognormal_estimate, normal_cdf

#: Below this T_s [s] the sliding mass is rigid: the paper's other constant, no T_s term, PGA for Sa.
RIGID_PERIOD = 0.05

#: σ of ln D [ln units].
SIGMA = 0.66


def probit(ky: float, site_period: float, spectral_acceleration: float) -> float:
    """The argument of Φ in P(D > 0) = Φ(·): ``ky`` [g], T_s [s], Sa [g]."""
    log_ky = math.log(ky)
    return -1.76 - 3.22 * log_ky - 0.484 * site_period * log_ky + 3.52 * math.log(spectral_acceleration)


def log_median_cm(ky: float, site_period: float, spectral_acceleration: float, magnitude: float) -> float:
    """ln D̂ [ln cm] of the non-zero displacement: ``ky`` [g], T_s [s], Sa [g] (PGA when T_s < 0.05 s), M."""
    log_ky, log_sa = math.log(ky), math.log(spectral_acceleration)
    rigid = site_period < RIGID_PERIOD
    return ((-0.22 if rigid else -1.10) - 2.83 * log_ky - 0.333 * log_ky**2 + 0.566 * log_ky * log_sa
            + 3.04 * log_sa - 0.244 * log_sa**2 + (0.0 if rigid else 1.50 * site_period)
            + 0.278 * (magnitude - 7.0))


def bray_travasarou_2007(ky: float, site_period: float, spectral_acceleration: float | None, magnitude: float,
                         pga: float | None = None) -> Estimate:
    """The estimate at ``ky`` [g], T_s ``site_period`` [s], Sa(1.5 T_s) ``spectral_acceleration`` [g], M ``magnitude``.

    For T_s < 0.05 s the paper's rigid branch takes ``pga`` [g] for Sa (Sa
    may then be None).
    """
    sa = pga if site_period < RIGID_PERIOD else spectral_acceleration
    p_zero = 1.0 - normal_cdf(probit(ky, site_period, sa))
    return lognormal_estimate(log_median_cm(ky, site_period, sa, magnitude), SIGMA, "e", p_zero=p_zero)


def slammer_p_zero(ky: float, site_period: float, spectral_acceleration: float) -> float:
    """P(D = 0) as SLAMMER 1.1 computes it: 1 − the polynomial approximation of Φ without its symmetry.

    Abramowitz and Stegun 26.2.17, Φ(x) ≈ 1 − φ(x)(b1 t + … + b5 t⁵) with
    t = 1/(1 + p x), holds for x ≥ 0; SLAMMER applies it to any x.  For the
    comparison with SLAMMER only.
    """
    p, b = 0.2316419, (0.319381530, -0.356563782, 1.781477937, -1.821255978, 1.330274429)
    x = probit(ky, site_period, spectral_acceleration)
    t = 1.0 / (1.0 + p * x)
    density = math.exp(-x * x / 2.0) / math.sqrt(2.0 * math.pi)
    return density * sum(coefficient * t ** (power + 1) for power, coefficient in enumerate(b))
