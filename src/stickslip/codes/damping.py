"""The damping factors by which the codes turn a 5 %-damped spectrum into one of another damping.

ASCE 7-22 and AASHTO divide the 5 % spectrum by a factor B ≥ 1 above 5 %;
EN 1998-1 multiplies it by η ≤ 1.  Damping ratios ξ, β are fractions of
critical [1] (0.05 is 5 %).
"""

from __future__ import annotations

import math

import numpy as np

from stickslip.errors import StickslipError

#: ASCE 7-22 Table 17.5-1 (as ASCE 7-16's): effective damping β [1] and the damping coefficient B_M [1].
ASCE_DAMPING = np.array([0.02, 0.05, 0.10, 0.20, 0.30, 0.40, 0.50])
ASCE_COEFFICIENT = np.array([0.8, 1.0, 1.2, 1.5, 1.7, 1.9, 2.0])

#: AASHTO Guide Specifications for Seismic Isolation Design (3rd ed. 2010), Eq. 7.1-3: B_L = (β/0.05)^0.3 ≤ 1.7.
AASHTO_EXPONENT, AASHTO_LARGEST_COEFFICIENT = 0.3, 1.7

#: EN 1998-1 §3.2.2.2(3), Eq. 3.6: η = sqrt(10/(5 + ξ[%])) ≥ 0.55.
EUROCODE_SMALLEST_CORRECTION = 0.55


def _checked(damping: float, who: str) -> float:
    if not (math.isfinite(damping) and damping >= 0.0):
        raise StickslipError(f"{who}: damping ratio {damping!r}: expected a number >= 0 (0.05 is 5 %)")
    return float(damping)


def asce_damping_coefficient(damping: float) -> float:
    """B_M [1] of ASCE 7-22 Table 17.5-1 at the effective damping β [1]: linear between the table's rows, 0.8 below
    β = 2 % and 2.0 above 50 % (the table's rows ≤ 2 and ≥ 50)."""
    return float(np.interp(_checked(damping, "ASCE 7-22 Table 17.5-1"), ASCE_DAMPING, ASCE_COEFFICIENT))


def aashto_damping_coefficient(damping: float) -> float:
    """B_L = (β/0.05)^0.3 ≤ 1.7 [1] (AASHTO Guide Specifications for Seismic Isolation Design, Eq. 7.1-3; the
    bound is reached at β = 0.294)."""
    damping = _checked(damping, "AASHTO Eq. 7.1-3")
    return min((damping / 0.05) ** AASHTO_EXPONENT, AASHTO_LARGEST_COEFFICIENT)


def eurocode_damping_correction(damping: float) -> float:
    """η = sqrt(0.10/(0.05 + ξ)) ≥ 0.55 [1] (EN 1998-1 Eq. 3.6, ξ as a fraction; EN 1998-2 Eq. 7.9 as η_eff)."""
    damping = _checked(damping, "EN 1998-1 Eq. 3.6")
    return max(math.sqrt(0.10 / (0.05 + damping)), EUROCODE_SMALLEST_CORRECTION)
