"""What every simplified estimate returns: a median displacement, its spread, and the probabilities they give.

The empirical (simplified) Newmark estimates are regressions of the logarithm
of the permanent displacement D on intensity measures: log_b D is normal with
mean log_b D̂ (D̂ the median) and standard deviation σ, in the base b of the
paper (10 or e).  Bray and Travasarou (2007) add a probability P(D = 0) of no
displacement, the lognormal then describing the non-zero part only, so that

    P(D > d) = (1 − P(D = 0)) · (1 − Φ((log_b d − log_b D̂) / σ))    for d > 0,

with Φ the standard normal distribution function (:func:`normal_cdf`, from
:func:`math.erfc`, accurate on the whole real line).  Where the method defines
no P(D = 0), it is taken as zero in that formula and reported as ``None``.

A rigid block whose yield acceleration k_y·g is at least the peak ground
acceleration never slides: D = 0 exactly.  Every ratio form (a_c/a_max) is
undefined there (a logarithm of 1 − a_c/a_max ≤ 0, or a polynomial fitted on
0 < a_c/a_max < 1); such an estimate is :func:`no_sliding`: median 0, σ
``None``, P(D = 0) = 1 and the reason, never NaN.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: The bases of the logarithms the papers use: "10" (log10) or "e" (natural).
LOG_BASES = {"10": math.log(10.0), "e": 1.0}

#: Metres per centimetre: the papers give D in cm, the estimates return m.
M_PER_CM = 0.01


def normal_cdf(x: float) -> float:
    """Φ(x), the standard normal distribution function, for any real ``x`` (0 at −∞, 1 at +∞)."""
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


@dataclass(frozen=True)
class Estimate:
    """One method's estimate of the permanent displacement D.

    Attributes
    ----------
    median_displacement:
        The median D̂ [m] (of the non-zero part where ``p_zero`` is given); 0 when the block cannot slide.
    sigma:
        σ of log_b D [log_b units] (it does not depend on the unit of D); ``None`` when D̂ = 0.
    log_base:
        b: ``"10"`` or ``"e"`` (:data:`LOG_BASES`).
    p_zero:
        P(D = 0) [1] where the method defines one (or where the block cannot slide: 1), else ``None``.
    reason:
        Why D̂ = 0 without a regression (``None`` for a regression's estimate).
    """

    median_displacement: float
    sigma: float | None
    log_base: str
    p_zero: float | None = None
    reason: str | None = None

    def probability_of_exceeding(self, displacement: float) -> float:
        """P(D > d) [1] at ``displacement`` d [m] (see the module's docstring); 1 − P(D = 0) for d ≤ 0."""
        p_sliding = 1.0 - (self.p_zero or 0.0)
        if self.median_displacement <= 0.0:
            return 0.0 if displacement >= 0.0 else 1.0
        if displacement <= 0.0:
            return p_sliding
        z = math.log(displacement / self.median_displacement) / LOG_BASES[self.log_base] / self.sigma
        return p_sliding * (1.0 - normal_cdf(z))

    def as_dict(self) -> dict:
        """The four values by name: ``median_displacement`` [m], ``sigma``, ``log_base``, ``p_zero``."""
        return {"median_displacement": self.median_displacement, "sigma": self.sigma, "log_base": self.log_base,
                "p_zero": self.p_zero}


def lognormal_estimate(log_median_cm: float, sigma: float, log_base: str, p_zero: float | None = None) -> Estimate:
    """The estimate of a regression whose log_b D̂ [D in cm] is ``log_median_cm``: D̂ in m."""
    return Estimate(median_displacement=M_PER_CM * math.exp(log_median_cm * LOG_BASES[log_base]), sigma=sigma,
                    log_base=log_base, p_zero=p_zero)


def no_sliding(log_base: str, reason: str) -> Estimate:
    """D = 0 for certain: median 0 m, no σ, P(D = 0) = 1, with ``reason``."""
    return Estimate(median_displacement=0.0, sigma=None, log_base=log_base, p_zero=1.0, reason=reason)


def yield_at_or_above(ky: float, peak: float, peak_name: str = "PGA") -> str | None:
    """The reason a rigid block cannot slide when k_y [g] ≥ ``peak`` [g] (PGA, or k_max), else ``None``."""
    if ky >= peak:
        return f"k_y = {ky:g} >= {peak_name} = {peak:.4g} g: the block never slides"
    return None
