"""What the friction pendulum's schemes solve: the surface's radius, the friction law, the block's mass, gravity.

A :class:`PendulumCase` is what the pendulum model's entry builds from its
parameters (:meth:`stickslip.models.pendulum.PendulumModel.case`): a slider
on a concave spherical surface of radius R [m] (``math.inf``: a flat
surface) with a friction law μ(v) (Coulomb, or Constantinou, Mokha and
Reinhorn's velocity law: :class:`~stickslip.solvers.friction_law.FrictionLaw`),
mass m [kg] and gravity g [m/s²].  The vertical ground motion, when there is
one, comes with the motion (:class:`~stickslip.records.vertical.WithVertical`).
:meth:`PendulumCase.at` gives the same slider at another friction ratio μ
(a sweep's coefficient: μ of Coulomb friction, μ_fast of the velocity law
with its ratio μ_slow/μ_fast and rate held), and :meth:`PendulumCase.slides`
tells, from the records alone, whether it leaves rest.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from stickslip.solvers.friction_law import FrictionLaw
from stickslip.units import UNITS


@dataclass(frozen=True)
class PendulumCase:
    """One slider to solve.

    Attributes
    ----------
    friction:
        μ(v) (:class:`FrictionLaw`; Coulomb: μ_slow = μ_fast).
    radius:
        R [m] of the spherical surface; ``math.inf`` for a flat one.
    mass:
        m [kg] (energies scale with it; the motion does not depend on it).
    g:
        Gravitational acceleration [m/s²].
    """

    friction: FrictionLaw
    radius: float
    mass: float
    g: float

    #: A pendulum is solved as the records are given (no inverse polarity).
    inverse = False

    @property
    def period(self) -> float:
        """T = 2π√(R/g) [s], the period of the slider's free swing (independent of its mass); inf when flat."""
        return math.inf if math.isinf(self.radius) else 2.0 * math.pi * math.sqrt(self.radius / self.g)

    def at(self, coefficient: str, value: float) -> PendulumCase:
        """The same slider with its friction ratio ``coefficient`` (``"mu"``) at ``value`` [1]: Coulomb's μ, or the
        velocity law's μ_fast with μ_slow/μ_fast and the rate held (:meth:`FrictionLaw.at_mu_fast`)."""
        return PendulumCase(self.friction.at_mu_fast(value), self.radius, self.mass, self.g)

    def solved(self, acceleration: np.ndarray) -> np.ndarray:
        """The ground acceleration [m/s²] as the solver takes it (as given)."""
        return acceleration

    def slides(self, motion) -> bool:
        """Whether the slider, at rest at the surface's bottom, leaves rest on ``motion`` (one component, with or
        without its vertical).

        At rest at u = 0 the restoring force is zero, so it breaks away where
        |a| exceeds μ(0)·(g + a_v) (a_v [m/s², positive up], zero without a
        vertical); both sides are linear between samples, so the samples tell.
        """
        acceleration, vertical = horizontal_and_vertical(motion)
        normal = self.g if vertical is None else np.maximum(self.g + vertical, 0.0)
        return bool(np.any(np.abs(acceleration) > self.friction.mu_slow * normal))

    def still_reason(self, motion, where: str | None = None) -> str:
        """Why the slider does not leave rest on ``motion``: its peak beside μ(0)·(g + a_v) (of a pair, the peak of
        |a| on its orthogonal axes)."""
        where = where or f"mu = {self.friction.mu_slow:g}"
        acceleration, vertical = horizontal_and_vertical(motion)
        pga = float(np.max(np.abs(acceleration)))
        peak = "its largest |a| on the pair's axes" if is_pair(motion) else "its PGA"
        if vertical is None:
            return (f"{peak} {pga:.4g} m/s2 ({pga / self.g:.4g} g) is at most mu*g = "
                    f"{self.friction.mu_slow * self.g:.4g} m/s2 at {where}")
        normal = self.g + vertical
        ratio = float(np.max(np.abs(acceleration) / np.maximum(normal, np.finfo(float).tiny)))
        return f"|a| stays within mu*(g + a_v) (largest |a|/(g + a_v) = {ratio:.4g}) at {where}"

    def describe_sliding(self) -> str:
        """``friction pendulum R = 2 m (T = 2.84 s)``, or ``flat surface``; with the velocity law's shape as a sweep
        holds it (:meth:`FrictionLaw.describe_shape`)."""
        surface = ("flat surface" if math.isinf(self.radius) else
                   f"friction pendulum R = {self.radius:g} m (T = {self.period:.3g} s)")
        shape = self.friction.describe_shape()
        return f"{surface}; {shape}" if shape else surface

    def describe_friction(self) -> str:
        """``mu = 0.05``, or the velocity law's three numbers."""
        return self.friction.describe()

    def settings(self) -> dict:
        """The slider, JSON-ready, but its coefficient: the radius [m] (null: flat), the friction law (``coulomb``,
        or ``velocity_dependent`` with ``mu_slow_ratio`` [1] and ``rate`` [s/m] held over the grid of μ_fast), mass
        [kg], gravity [m/s²]."""
        return {"radius": None if math.isinf(self.radius) else self.radius, **self.friction.settings(),
                "mass": self.mass, "g": self.g}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {"radius": UNITS["radius"], **self.friction.settings_units(), "mass": UNITS["block_mass"],
                "g": UNITS["gravity"]}


def is_pair(motion) -> bool:
    """Whether ``motion`` is two horizontal components (a :class:`RecordPair`, alone or with its vertical)."""
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    return isinstance(motion.horizontal if isinstance(motion, WithVertical) else motion, RecordPair)


def horizontal_and_vertical(motion) -> tuple[np.ndarray, np.ndarray | None]:
    """The horizontal ground acceleration [m/s²] of a one-component ``motion`` (of a pair, its magnitude |a| on
    the pair's orthogonal axes) and its vertical a_v [m/s², positive up] (None without one).

    |a| of a pair is convex between samples (a is linear there), so, as for
    one component, the samples tell where it exceeds a level linear in time.
    """
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    horizontal, vertical = ((motion.horizontal, motion.vertical.acceleration) if isinstance(motion, WithVertical)
                            else (motion, None))
    if isinstance(horizontal, RecordPair):
        return np.hypot(*horizontal.horizontal()), vertical
    return horizontal.acceleration, vertical
