"""Ambraseys and Menu (1988): the rigid-block displacement from the critical acceleration ratio.

Ambraseys, N. N. and Menu, J. M. (1988). Earthquake-induced ground
displacements. Earthquake Engineering and Structural Dynamics 16, 985-1006.
As SLAMMER 1.1 codes it (``RigidBlockSimplified.AmbraseysAndMenu``), with
u in cm, a_c = k_y and a_max = PGA in g, logarithms base 10:

    log u = 0.90 + log[(1 − a_c/a_max)^2.53 (a_c/a_max)^−1.09],   σ = 0.30.

50 records of 11 earthquakes.  Zero, with the reason, where a_c ≥ a_max.
"""

from __future__ import annotations

import math

from stickslip.estimates.estimate import Estimate, lognormal_estimate, no_sliding, yield_at_or_above

#: The printed constants: intercept, exponents of (1 − r) and of r, σ [log10 units].
INTERCEPT, ONE_MINUS_RATIO_EXPONENT, RATIO_EXPONENT, SIGMA = 0.90, 2.53, -1.09, 0.30


def ambraseys_menu_1988(ky: float, pga: float) -> Estimate:
    """The median displacement [m] at the yield coefficient ``ky`` [g] and peak ground acceleration ``pga`` [g]."""
    reason = yield_at_or_above(ky, pga)
    if reason:
        return no_sliding("10", reason)
    ratio = ky / pga
    log_median = INTERCEPT + ONE_MINUS_RATIO_EXPONENT * math.log10(1.0 - ratio) + RATIO_EXPONENT * math.log10(ratio)
    return lognormal_estimate(log_median, SIGMA, "10")
