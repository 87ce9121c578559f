"""The friction pendulum's spherical sliding surface: its radius R checked, and its curvature 1/R."""

from __future__ import annotations

import math

from stickslip.errors import StickslipError


def checked_radius(value) -> float:
    """A surface radius R [m] (``--radius``): positive, ``math.inf`` for a flat surface; one error line otherwise."""
    try:
        radius = float(value)
    except (TypeError, ValueError):
        raise StickslipError(f"radius of the sliding surface [m] (--radius) must be a number, got {value!r}") from None
    if not radius > 0.0:
        raise StickslipError(f"radius of the sliding surface [m] (--radius) must be positive (inf for a flat "
                             f"surface), got {value!r}")
    return radius


def surface_curvature(radius: float) -> float:
    """c = 1/R [1/m] of a sliding surface of radius R [m] (:func:`checked_radius`); ``math.inf`` is flat (c = 0)."""
    radius = checked_radius(radius)
    return 0.0 if math.isinf(radius) else 1.0 / radius
