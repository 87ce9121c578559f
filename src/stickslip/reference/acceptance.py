"""pySLAMMER's acceptance rules: when a displacement we compute agrees with SLAMMER 1.1's own.

The verification studies (:mod:`stickslip.studies.verification.slammer`,
:mod:`stickslip.studies.verification.flexible`) judge every analysis by them,
and the verification's figures draw their pass band.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class AcceptanceRules:
    """pySLAMMER's acceptance rules (its ``tests/verification/config/verification_config.toml``); lengths in cm.

    One analysis passes when |computed − expected| is within
    :meth:`tolerance`: above ``small_displacement`` the smaller of
    ``relative_tolerance``·expected and ``absolute_tolerance``, else
    ``small_tolerance``.  A group (one scheme) passes when at least
    ``pass_rate`` of its analyses pass, overall and in each polarity, and in
    each polarity the least-squares line of computed on expected has a slope
    within 1 ± ``slope_tolerance``, an intercept within ± ``intercept_tolerance``
    and R² ≥ ``min_r_squared``.
    """

    small_displacement: float = 0.5  # cm
    small_tolerance: float = 0.05  # cm
    relative_tolerance: float = 0.02  # 1
    absolute_tolerance: float = 1.0  # cm
    pass_rate: float = 0.95  # 1
    slope_tolerance: float = 0.01  # 1
    intercept_tolerance: float = 0.1  # cm
    min_r_squared: float = 0.99  # 1

    def tolerance(self, expected):
        """The tolerance [cm] of an analysis whose expected displacement is ``expected`` [cm] (scalar or array)."""
        expected = np.asarray(expected, dtype=float)
        large = np.minimum(self.relative_tolerance * np.abs(expected), self.absolute_tolerance)
        tolerance = np.where(expected > self.small_displacement, large, self.small_tolerance)
        return float(tolerance) if tolerance.ndim == 0 else tolerance

    def passes(self, computed, expected):
        """Whether |computed − expected| [cm] is within :meth:`tolerance` (scalar or array)."""
        within = np.abs(np.asarray(computed, dtype=float) - np.asarray(expected, dtype=float)) <= self.tolerance(expected)
        return bool(within) if np.ndim(within) == 0 else within

    def regression(self, computed: Sequence[float], expected: Sequence[float]) -> dict:
        """The least-squares line of ``computed`` on ``expected`` [cm]: slope [1], intercept [cm], R² [1], and which rule each meets.

        As ``scipy.stats.linregress`` (which pySLAMMER uses) computes it, without importing ``scipy.stats``.
        """
        x, y = np.asarray(expected, dtype=float), np.asarray(computed, dtype=float)
        dx, dy = x - x.mean(), y - y.mean()
        sxx, sxy, syy = float(dx @ dx), float(dx @ dy), float(dy @ dy)
        slope = sxy / sxx
        intercept = float(y.mean()) - slope * float(x.mean())
        r_squared = sxy * sxy / (sxx * syy) if syy > 0.0 else 1.0
        return {"slope": slope, "intercept": intercept, "r_squared": r_squared,
                "slope_ok": abs(slope - 1.0) <= self.slope_tolerance,
                "intercept_ok": abs(intercept) <= self.intercept_tolerance,
                "r_squared_ok": r_squared >= self.min_r_squared}


#: The rules every scheme is judged by.
PYSLAMMER_RULES = AcceptanceRules()
