"""The inputs of the simplified estimates measured on a record, in the papers' units.

PGA [g] and PGV [cm s-1] (the velocity integrated from the acceleration
without baseline correction), Arias intensity [m s-1] and the mean period T_m
[s] are :func:`stickslip.measures.intensity_measures`'; Sa(1.5 T_s) and
Sa(1.3 T_s) [g] (Bray and Macedo 2019) are the 5 %-damped pseudo-spectral
acceleration of
:func:`stickslip.response_spectrum.pseudo_spectral_acceleration`.  Gravity g
[m s-2] turns m s-2 into g.
"""

from __future__ import annotations

import math

from stickslip.constants import STANDARD_GRAVITY
from stickslip.estimates.bray_macedo import CRUSTAL_PERIOD_FACTOR
from stickslip.measures import intensity_measures
from stickslip.records.record import Record
from stickslip.response_spectrum import DEFAULT_DAMPING, pseudo_spectral_acceleration

#: Centimetres per metre (PGV in cm s-1).
CM_PER_M = 100.0

#: Sa is taken at this multiple of the sliding mass's period T_s (Bray and Travasarou 2007).
PERIOD_FACTOR = 1.5


def spectral_acceleration_g(record: Record, site_period: float, g: float = STANDARD_GRAVITY,
                            factor: float = PERIOD_FACTOR) -> float:
    """Sa(factor·T_s) [g] of ``record`` at 5 % damping (Sa(1.5 T_s) by default), for the sliding mass's period
    ``site_period`` T_s [s] > 0."""
    return pseudo_spectral_acceleration(record.acceleration, record.dt, factor * site_period, DEFAULT_DAMPING) / g


def estimate_inputs(record: Record, g: float = STANDARD_GRAVITY, site_period: float | None = None) -> dict:
    """``pga`` [g], ``pgv`` [cm s-1], ``arias_intensity`` [m s-1], ``mean_period`` [s], ``spectral_acceleration`` and
    ``spectral_acceleration_13`` [g].

    ``spectral_acceleration`` is Sa(1.5 T_s) and ``spectral_acceleration_13``
    Sa(1.3 T_s) for a ``site_period`` T_s > 0 [s], else None; ``mean_period``
    is None for a record too short for it.
    """
    measures = intensity_measures(record, g)
    flexible = site_period is not None and site_period > 0.0
    return {"pga": measures.pga / g, "pgv": CM_PER_M * measures.pgv, "arias_intensity": measures.arias_intensity,
            "mean_period": measures.mean_period if math.isfinite(measures.mean_period) else None,
            "spectral_acceleration": spectral_acceleration_g(record, site_period, g) if flexible else None,
            "spectral_acceleration_13": (spectral_acceleration_g(record, site_period, g, CRUSTAL_PERIOD_FACTOR)
                                         if flexible else None)}
