"""What the rigid block's schemes solve: the resistance, the block's mass, gravity and the record's polarity.

A :class:`RigidCase` is what the rigid model's entry builds from its
parameters (:meth:`stickslip.models.rigid.RigidModel.case`): the
:class:`~stickslip.models.rigid.resistance.Resistance` of a friction ratio μ
or a yield coefficient k_y (one-way, or two-way at a thrust angle), the mass
m [kg], gravity g [m/s²] and whether the record is solved with its sign
flipped.  :meth:`RigidCase.at` gives the same block at another value of the
swept coefficient, and :meth:`RigidCase.never_slides` says, from the record's
extremes alone, why the block would not slide.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from stickslip.grids import COEFFICIENTS
from stickslip.models.rigid.resistance import Resistance
from stickslip.units import UNITS


@dataclass(frozen=True)
class RigidCase:
    """One rigid block to solve.

    Attributes
    ----------
    resistance:
        The thresholds and body acceleration [m/s²] (:class:`Resistance`).
    mass:
        Block mass m [kg].
    g:
        Gravitational acceleration [m/s²].
    inverse:
        Solve the record with its sign flipped (SLAMMER's inverse polarity).
    sliding:
        How the block slides besides its coefficient: ``direction`` and
        ``thrust_angle`` [degrees] where given (for :meth:`at`).
    """

    resistance: Resistance
    mass: float
    g: float
    inverse: bool = False
    sliding: dict = field(default_factory=dict, compare=False)

    @classmethod
    def of(cls, mass: float, g: float, inverse: bool = False, **resistance) -> RigidCase:
        """The case of a friction ratio ``mu`` or a yield coefficient ``ky`` (with ``direction``, ``thrust_angle``)."""
        sliding = {key: resistance[key] for key in ("direction", "thrust_angle") if resistance.get(key) is not None}
        return cls(Resistance.from_options(g, **resistance), mass, g, bool(inverse), sliding)

    def at(self, coefficient: str, value: float) -> RigidCase:
        """The same block with the coefficient ``coefficient`` (``"mu"`` or ``"ky"``) at ``value`` [1]."""
        return RigidCase(Resistance.from_options(self.g, **{coefficient: float(value)}, **self.sliding), self.mass,
                         self.g, self.inverse, self.sliding)

    @property
    def level(self) -> str:
        """How the level at which the block starts to slide is written (``mu*g``, ``ky*g``)."""
        return COEFFICIENTS[self.resistance.coefficient].level

    def describe_sliding(self) -> str:
        """How the block slides where it is not flat friction on a record as given: ``one-way (downslope only)``,
        ``two-way, thrust angle 10 deg``, and the polarity; "" for flat friction on a record as given."""
        parameters = self.resistance.parameters
        if not self.resistance.on_slope:
            text = ""
        elif parameters["direction"] == "down":
            text = "one-way (downslope only)"
        else:
            text = f"two-way, thrust angle {parameters['thrust_angle']:g} deg"
        if self.inverse:
            text = (text + "; " if text else "flat surface; ") + "inverse polarity (record sign flipped)"
        return text

    def settings(self) -> dict:
        """The block, JSON-ready, but its coefficient: the sliding direction and thrust angle on a slope, the
        polarity, mass [kg] and gravity [m/s²]."""
        parameters = self.resistance.parameters
        sliding = {key: parameters[key] for key in ("direction", "thrust_angle") if key in parameters}
        if sliding.get("direction") != "both":
            sliding.pop("thrust_angle", None)
        return {**sliding, "inverse": self.inverse, "mass": self.mass, "g": self.g}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {"mass": UNITS["block_mass"], "g": UNITS["gravity"],
                **({"thrust_angle": UNITS["thrust_angle"]} if "thrust_angle" in self.settings() else {})}

    def solved(self, acceleration: np.ndarray) -> np.ndarray:
        """The ground acceleration [m/s²] as the solver takes it: sign flipped in inverse polarity."""
        return -acceleration if self.inverse else acceleration

    def slides(self, record) -> bool:
        """Whether the block, at rest, leaves the stick band somewhere on ``record`` (acceleration [m/s²]).

        It slides only where the ground acceleration (linear between samples)
        rises above the resistance's :attr:`~Resistance.upper` or falls below
        its :attr:`~Resistance.lower`.
        """
        solved = self.solved(np.asarray(record.acceleration, dtype=float))
        return bool(solved.size) and (float(solved.max()) > self.resistance.upper
                                      or float(solved.min()) < self.resistance.lower)

    def never_slides(self, record, where: str | None = None) -> str | None:
        """Why the block never slides on ``record`` [m/s²]: the record's extremes beside the levels; None if it slides.

        ``where`` says at which value (``"mu = 0.5"``; default the case's own).
        A friction ratio compares the PGA with μ·g; a yield coefficient the
        largest a (sign flipped in inverse polarity) with the downslope level
        k_y·g and, two-way, the smallest with the upslope level.
        """
        if self.slides(record):
            return None
        return self.still_reason(record, where)

    def still_reason(self, record, where: str | None = None) -> str:
        """The record's extremes beside the levels of the stick band, in words (see :meth:`never_slides`)."""
        g, resistance = self.g, self.resistance
        acceleration = record.acceleration
        solved = self.solved(np.asarray(acceleration, dtype=float))
        where = where or resistance.value
        if not resistance.on_slope:  # both ways alike: the PGA against the level
            pga = float(np.max(np.abs(acceleration)))
            compared = "is at most" if pga <= resistance.upper else "barely exceeds"
            return (f"its PGA {pga:.4g} m/s2 ({pga / g:.4g} g) {compared} {self.level} = {resistance.upper:.4g} m/s2 "
                    f"at {where}")
        largest = float(solved.max())
        which = "a (the record's sign flipped: inverse polarity)" if self.inverse else "a"
        parts = [f"its largest {which}, {largest:.4g} m/s2 ({largest / g:.4g} g), "
                 f"{'is at most' if largest <= resistance.upper else 'barely exceeds'} the downslope level "
                 f"{self.level} = {resistance.upper:.4g} m/s2"]
        if math.isfinite(resistance.lower):
            smallest = float(solved.min())
            parts.append(f"its smallest, {smallest:.4g} m/s2 ({smallest / g:.4g} g), "
                         f"{'is at least' if smallest >= resistance.lower else 'barely falls below'} the upslope "
                         f"level -({self.level} + 2 g sin(thrust angle)) = {resistance.lower:.4g} m/s2")
            return " and ".join(parts) + f" at {where}"
        return parts[0] + f" at {where} (one-way: the block slides only downslope, where a exceeds {self.level})"
