"""Saygili and Rathje (2008) and Rathje and Saygili (2009): rigid-block displacement from a polynomial in a_c/a_max.

Saygili, G. and Rathje, E. M. (2008). Empirical predictive models for
earthquake-induced sliding displacements of slopes. Journal of Geotechnical
and Geoenvironmental Engineering 134(6), 790-803.  Rathje, E. M. and
Saygili, G. (2009). Probabilistic assessment of earthquake-induced sliding
displacements of natural slopes. Bulletin of the New Zealand Society for
Earthquake Engineering 42(1), 18-27.

Every model is, with r = a_c/a_max = k_y/PGA in (0, 1), D in cm, PGA in g,
PGV in cm s-1, I_a in m s-1, M the moment magnitude and natural logarithms,

    ln D = a0 + a1 r + a2 r² + a3 r³ + a4 r⁴ + (its intensity-measure terms),

with the coefficients of :data:`MODELS` (SLAMMER 1.1's, ``RigidBlockSimplified``,
which are the papers'):

* PGA: 5.52, −4.43, −20.39, 42.61, −28.74; + 0.72 ln PGA; σ = 1.13;
* PGA, PGV: −1.56, −4.58, −20.84, 44.75, −30.50; − 0.64 ln PGA + 1.55 ln PGV;
  σ = 0.405 + 0.524 r;
* PGA, PGV, I_a: −0.74, −4.93, −19.91, 43.75, −30.12; − 1.30 ln PGA + 1.04 ln PGV
  + 0.67 ln I_a; σ = 0.20 + 0.79 r;
* PGA, M (Rathje and Saygili 2009): 4.89, −4.85, −19.64, 42.49, −29.06;
  + 0.72 ln PGA + 0.89 (M − 6); σ = 0.732 + 0.789 r − 0.539 r².

SLAMMER's help text gives the last σ as 0.95, a constant; we use the
r-dependent σ of Rathje and Saygili (2009) that USGS groundfailure also codes
(docs/estimates.md).  The polynomial holds for 0 < r < 1: at r ≥ 1 the block
never slides, and the estimate is zero with the reason.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from stickslip.estimates.estimate import Estimate, lognormal_estimate, no_sliding, yield_at_or_above


@dataclass(frozen=True)
class PolynomialModel:
    """One model: the polynomial's coefficients a0..a4, each intensity measure's coefficient, σ(r) coefficients."""

    polynomial: tuple[float, float, float, float, float]
    log_pga: float
    log_pgv: float = 0.0
    log_arias_intensity: float = 0.0
    magnitude_minus_6: float = 0.0
    sigma: tuple[float, ...] = ()

    def sigma_at(self, ratio: float) -> float:
        """σ of ln D [ln units] at r = ``ratio``: Σ sigma[k]·r^k."""
        return sum(coefficient * ratio**power for power, coefficient in enumerate(self.sigma))


#: The models by method name.
MODELS = {
    "saygili_rathje_2008_pga": PolynomialModel((5.52, -4.43, -20.39, 42.61, -28.74), log_pga=0.72, sigma=(1.13,)),
    "saygili_rathje_2008_pga_pgv": PolynomialModel((-1.56, -4.58, -20.84, 44.75, -30.50), log_pga=-0.64,
                                                   log_pgv=1.55, sigma=(0.405, 0.524)),
    "saygili_rathje_2008_pga_pgv_ia": PolynomialModel((-0.74, -4.93, -19.91, 43.75, -30.12), log_pga=-1.30,
                                                      log_pgv=1.04, log_arias_intensity=0.67, sigma=(0.20, 0.79)),
    "rathje_saygili_2009_pga_m": PolynomialModel((4.89, -4.85, -19.64, 42.49, -29.06), log_pga=0.72,
                                                 magnitude_minus_6=0.89, sigma=(0.732, 0.789, -0.539)),
}


def log_median_cm(name: str, ky: float, pga: float, pgv: float = 1.0, arias_intensity: float = 1.0,
                  magnitude: float = 6.0) -> float:
    """ln D̂ [ln cm] of model ``name`` at ``ky`` and ``pga`` [g], ``pgv`` [cm s-1], ``arias_intensity`` [m s-1], M.

    ``ky`` < ``pga`` (r < 1); the intensity measures the model does not use are ignored.
    """
    model = MODELS[name]
    ratio = ky / pga
    return (sum(coefficient * ratio**power for power, coefficient in enumerate(model.polynomial))
            + model.log_pga * math.log(pga) + model.log_pgv * math.log(pgv)
            + model.log_arias_intensity * math.log(arias_intensity) + model.magnitude_minus_6 * (magnitude - 6.0))


def _estimate(name: str, ky: float, pga: float, **measures) -> Estimate:
    reason = yield_at_or_above(ky, pga)
    if reason:
        return no_sliding("e", reason)
    return lognormal_estimate(log_median_cm(name, ky, pga, **measures), MODELS[name].sigma_at(ky / pga), "e")


def saygili_rathje_2008_pga(ky: float, pga: float) -> Estimate:
    """Saygili and Rathje (2008), PGA model: ``ky`` and ``pga`` [g]."""
    return _estimate("saygili_rathje_2008_pga", ky, pga)


def saygili_rathje_2008_pga_pgv(ky: float, pga: float, pgv: float) -> Estimate:
    """Saygili and Rathje (2008), PGA and PGV model: ``ky`` and ``pga`` [g], ``pgv`` [cm s-1]."""
    return _estimate("saygili_rathje_2008_pga_pgv", ky, pga, pgv=pgv)


def saygili_rathje_2008_pga_pgv_ia(ky: float, pga: float, pgv: float, arias_intensity: float) -> Estimate:
    """Saygili and Rathje (2008), PGA, PGV and I_a model: ``ky``, ``pga`` [g], ``pgv`` [cm s-1], I_a [m s-1]."""
    return _estimate("saygili_rathje_2008_pga_pgv_ia", ky, pga, pgv=pgv, arias_intensity=arias_intensity)


def rathje_saygili_2009_pga_m(ky: float, pga: float, magnitude: float) -> Estimate:
    """Rathje and Saygili (2009), PGA and magnitude model: ``ky`` and ``pga`` [g], moment magnitude M."""
    return _estimate("rathje_saygili_2009_pga_m", ky, pga, magnitude=magnitude)
