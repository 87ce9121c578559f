"""The friction coefficient of a sliding surface as a function of the sliding speed.

Coulomb friction keeps μ constant.  The velocity-dependent law of Constantinou,
Mokha and Reinhorn (1990), for PTFE on polished stainless steel and the
``VelDependent`` friction model of OpenSees, is

    μ(v) = μ_fast − (μ_fast − μ_slow)·exp(−a·|v|),

with μ_slow = μ(0) the coefficient at breakaway (the static one), μ_fast the
limit at high speed and a [s/m] the rate at which it is approached (μ is
within 5 % of the way from μ_slow to μ_fast once |v| = 3/a).  Coulomb
friction is the law with μ_slow = μ_fast = μ.  A block sticks while the force
needed to hold it is at most μ(0)·N.

An isolator designer sweeps the sliding coefficient μ_fast (the one a bearing
is specified by and the design procedures use) with the law's shape held:
the ratio μ_slow/μ_fast and the rate a (:meth:`FrictionLaw.at_mu_fast`).

The law is checked against what tests of PTFE-type composites on polished
stainless steel found (:func:`unusual_law_warnings`): μ_slow below μ_fast
(Mokha, Constantinou & Reinhorn 1990, J. Struct. Eng. 116(2) 438-454), and
rates a of the order of :data:`USUAL_RATE` s/m (Constantinou, Mokha &
Reinhorn 1990, J. Struct. Eng. 116(2) 455-474).  Either outside is a
warning, not an error: a test may have found otherwise.

:class:`FrictionLaw` holds the three numbers (checked, each error naming the
command-line option that sets it); :func:`friction_coefficient` is the law in
numba's nopython mode, for the kernels.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

from stickslip.checks import checked_positive
from stickslip.errors import StickslipError
from stickslip.units import UNITS

#: The rates a [s/m] of the velocity law that tests of sliding bearings report: (lowest, highest).  A rate in
#: s/in, as US reports write it, is 39.37 times smaller (0.6 s/in is 24 s/m).
USUAL_RATE = (10.0, 100.0)


@numba.njit(cache=True)
def friction_coefficient(speed, mu_slow, mu_fast, rate):
    """μ [-] at the sliding speed ``speed`` [m/s]: μ_fast − (μ_fast − μ_slow)·exp(−rate·speed), rate [s/m].

    Written without |·| so that it continues analytically to a slightly
    negative speed, as an integrator's trial stage near a stop may ask for.
    """
    if mu_slow == mu_fast:
        return mu_slow
    return mu_fast - (mu_fast - mu_slow) * math.exp(-rate * speed)


@dataclass(frozen=True)
class FrictionLaw:
    """A friction coefficient μ(v) = μ_fast − (μ_fast − μ_slow)·exp(−rate·|v|).

    Attributes
    ----------
    mu_slow:
        μ(0) [-], the coefficient at breakaway and at rest (``--mu-slow``).
    mu_fast:
        μ at high speed [-] (``--mu-fast``); equal to ``mu_slow`` for Coulomb friction.
    rate:
        a [s/m] (``--rate``); 0 for Coulomb friction.
    """

    mu_slow: float
    mu_fast: float
    rate: float = 0.0

    @classmethod
    def coulomb(cls, mu: float) -> FrictionLaw:
        """Constant friction μ [-] (``--mu``)."""
        mu = checked_positive(mu, "friction ratio mu (--mu)")
        return cls(mu, mu, 0.0)

    @classmethod
    def velocity_dependent(cls, mu_slow: float, mu_fast: float, rate: float) -> FrictionLaw:
        """Constantinou, Mokha and Reinhorn's law: μ_slow, μ_fast [-] and the rate a [s/m].

        Either coefficient may be the larger (μ_fast < μ_slow is a friction
        that weakens with speed); μ_slow = μ_fast is Coulomb friction whatever
        the rate.
        """
        mu_slow = checked_positive(mu_slow, "friction ratio at low speed (--mu-slow)")
        mu_fast = checked_positive(mu_fast, "friction ratio at high speed (--mu-fast)")
        rate = checked_positive(rate, "rate of the velocity-dependent friction law [s/m] (--rate)")
        return cls(mu_slow, mu_fast, rate if mu_slow != mu_fast else 0.0)

    @property
    def is_coulomb(self) -> bool:
        """Whether μ does not depend on the speed."""
        return self.mu_slow == self.mu_fast

    def coefficient(self, speed) -> np.ndarray:
        """μ [-] at the sliding speeds ``speed`` [m/s] (their absolute values)."""
        speed = np.abs(np.asarray(speed, dtype=float))
        return self.mu_fast - (self.mu_fast - self.mu_slow) * np.exp(-self.rate * speed)

    @property
    def slow_ratio(self) -> float:
        """μ_slow / μ_fast [1]: 1 for Coulomb friction, below 1 where friction grows with speed (PTFE on steel)."""
        return self.mu_slow / self.mu_fast

    def at_mu_fast(self, mu_fast: float) -> FrictionLaw:
        """The law of the same shape (μ_slow/μ_fast and the rate held) with its sliding coefficient μ_fast [1] at
        ``mu_fast``: Coulomb friction μ = ``mu_fast`` for a Coulomb law."""
        if self.is_coulomb:
            return FrictionLaw.coulomb(mu_fast)
        return FrictionLaw.velocity_dependent(self.slow_ratio * mu_fast, mu_fast, self.rate)

    def describe_shape(self) -> str:
        """The law as a sweep holds it (its μ_fast swept): ``""`` for Coulomb friction, else its ratio and rate."""
        if self.is_coulomb:
            return ""
        return (f"velocity-dependent friction (Constantinou, Mokha & Reinhorn 1990): mu is mu_fast, "
                f"mu_slow = {self.slow_ratio:g} mu_fast, rate {self.rate:g} s/m")

    def describe(self) -> str:
        """``mu = 0.05``, or the velocity law's three numbers."""
        if self.is_coulomb:
            return f"mu = {self.mu_slow:g}"
        return f"mu(v) from {self.mu_slow:g} to {self.mu_fast:g}, rate {self.rate:g} s/m"

    def settings(self) -> dict:
        """The law as a result records it, JSON-ready, but its μ_fast (a sweep's coefficient): ``coulomb``, or
        ``velocity_dependent`` with ``mu_slow_ratio`` [1] and ``rate`` [s/m], held over a grid of μ_fast."""
        if self.is_coulomb:
            return {"friction_law": "coulomb"}
        return {"friction_law": "velocity_dependent", "mu_slow_ratio": self.slow_ratio, "rate": self.rate}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {} if self.is_coulomb else {"mu_slow_ratio": UNITS["mu_slow_ratio"], "rate": UNITS["rate"]}

    def parameters(self) -> tuple[float, float, float]:
        """(μ_slow, μ_fast, rate [s/m]) as the kernels take them."""
        return float(self.mu_slow), float(self.mu_fast), float(self.rate)


def law_columns(laws) -> np.ndarray:
    """The (n, 3) array of (μ_slow, μ_fast, rate [s/m]) of :class:`FrictionLaw` objects, as the kernels take it."""
    if not laws:
        raise StickslipError("friction: expected at least one friction ratio")
    return np.array([law.parameters() for law in laws], dtype=np.float64)



def unusual_law_warnings(law: FrictionLaw, slow: str = "mu_slow=", rate: str = "rate=") -> list[str]:
    """What is unusual in the velocity law ``law``, one sentence each (none for Coulomb friction): μ_slow above
    μ_fast (friction that weakens with speed), a rate outside :data:`USUAL_RATE`.  ``slow`` and ``rate`` name
    what set them (``mu_slow=``, ``mu_slow_ratio=``)."""
    if law.is_coulomb:
        return []
    found = []
    if law.mu_slow > law.mu_fast:
        given = (f"{slow}{law.slow_ratio:g}" if "ratio" in slow else f"{slow}{law.mu_slow:g} above mu_fast "
                 f"{law.mu_fast:g}")
        found.append(f"{given}: friction that weakens with speed, unusual for PTFE-type liners on polished "
                     "stainless steel, whose friction grows with speed (mu_slow < mu_fast; Mokha, Constantinou & "
                     "Reinhorn 1990)")
    low, high = USUAL_RATE
    if not low <= law.rate <= high:
        found.append(f"{rate}{law.rate:g} s/m is outside the {low:g} to {high:g} s/m that tests of sliding bearings "
                     "report (Constantinou, Mokha & Reinhorn 1990); check that it is in s/m (1 s/in = 39.37 s/m)")
    return found
