"""The friction pendulum's spherical sliding surface: its curvature 1/R from the radius R given."""

from __future__ import annotations

import math

from stickslip.errors import StickslipError


def surface_curvature(radius: float) -> float:
    """c = 1/R [1/m] of a sliding surface of radius R [m] (``--radius``), positive; ``math.inf`` is flat (c = 0)."""
    try:
        radius = float(radius)
    except (TypeError, ValueError):
        raise StickslipError(f"radius of the sliding surface [m] (--radius) must be a number, got {radius!r}") from None
    if not radius > 0.0:
        raise StickslipError(f"radius of the sliding surface [m] (--radius) must be positive (inf for a flat "
                             f"surface), got {radius!r}")
    return 0.0 if math.isinf(radius) else 1.0 / radius
