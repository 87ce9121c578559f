"""The yield coefficient of an infinite slope from its static factor of safety (Newmark 1965).

Newmark, N. M. (1965). Effects of earthquakes on dams and embankments.
Géotechnique 15(2), 139-160.  A block on a plane inclined at α [degrees]
whose static factor of safety against sliding is F yields when the ground
accelerates it downslope, parallel to the plane, by

    k_y = (F − 1)·sin α        [g],

the form for an infinite slope with the thrust parallel to it (Newmark 1965;
as Jibson 1993 and Jibson et al. 2000 apply it to landslides, a_c = (F − 1) g
sin α).  F ≤ 1 has no yield coefficient: the slope fails without shaking.
"""

from __future__ import annotations

import math

from stickslip.errors import StickslipError


def yield_coefficient(factor_of_safety: float, slope_angle: float) -> float:
    """k_y [1, in g] = (F − 1)·sin α of a static factor of safety ``factor_of_safety`` F [1] > 1 and a slope angle
    ``slope_angle`` α [degrees], 0 < α < 90; one :class:`StickslipError` naming the input otherwise."""
    if not (math.isfinite(slope_angle) and 0.0 < slope_angle < 90.0):
        raise StickslipError(f"slope angle {slope_angle:g} degrees: expected an angle above 0 and below 90 degrees")
    if not math.isfinite(factor_of_safety):
        raise StickslipError(f"factor of safety {factor_of_safety:g}: expected a finite number above 1")
    if factor_of_safety <= 1.0:
        raise StickslipError(f"factor of safety {factor_of_safety:g} <= 1: the slope fails statically, without "
                             "shaking (k_y = (F - 1) sin(alpha) <= 0); a Newmark analysis needs F > 1")
    return (factor_of_safety - 1.0) * math.sin(math.radians(slope_angle))
