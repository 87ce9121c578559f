"""What the isolated building's scheme solves: a shear building on a base mass that slides on a friction pendulum.

x = (u_b, u_1 … u_n) [m] relative to the ground: the base mass m_b and the
superstructure's floors (equal masses m_s/n, equal story stiffnesses scaled
to the fixed-base period, :func:`~stickslip.solvers.structure.shear_building.uniform_building`);
the superstructure's forces depend on the floors' motion relative to the
base, K = Tᵀ K_b T and C = Tᵀ C_b T with T = [−1 | I].  The base slides on a
surface of radius R [m] (R = ∞ flat) under N = W = (m_b + m_s)·g (with a
vertical, N = W·(1 + a_v/g)) with Coulomb friction μ or the velocity law
μ(v) (:class:`~stickslip.solvers.friction_law.FrictionLaw`): a
:class:`~stickslip.solvers.structure.friction_linked.FrictionLinkedSystem` with
d = e₀ (docs/structures.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from stickslip.models.parameters import HELD
from stickslip.models.structure_scheme import StructureCase
from stickslip.records.record import Record


@dataclass(frozen=True)
class IsolatedCase(StructureCase):
    """One isolated building.

    Attributes
    ----------
    mu:
        Friction ratio μ [1] of the isolator: Coulomb's, or the velocity law's μ_fast.
    superstructure_period:
        The superstructure's fundamental fixed-base period [s].
    stories:
        n, its stories (1: the two-degree-of-freedom design model).
    superstructure_damping:
        ζ [1] of its fixed-base modes (modal) or of its first and last (Rayleigh).
    damping_model:
        ``"modal"`` or ``"rayleigh"``.
    mass_ratio:
        m_s/m_b [1], the superstructure's mass over the base's.
    radius:
        R [m] of the isolator's surface; ``math.inf``: a flat slider.
    mass:
        m_b + m_s [kg], the total.
    g:
        Gravity [m/s²].
    mu_slow:
        The velocity law's μ_slow [1]; None: Coulomb friction μ.
    rate:
        The velocity law's rate [s/m] (0 for Coulomb friction).
    """

    mu: float
    superstructure_period: float
    stories: int
    superstructure_damping: float
    damping_model: str
    mass_ratio: float
    radius: float
    mass: float
    g: float
    mu_slow: float | None = None
    rate: float = 0.0

    @property
    def base_mass(self) -> float:
        """m_b [kg]."""
        return self.mass / (1.0 + self.mass_ratio)

    @property
    def superstructure_mass(self) -> float:
        """m_s [kg]."""
        return self.mass - self.base_mass

    @property
    def weight(self) -> float:
        """W = (m_b + m_s)·g [N], the isolator's normal force."""
        return self.mass * self.g

    @cached_property
    def building(self):
        """The superstructure on a fixed base (:class:`~stickslip.solvers.structure.shear_building.ShearBuilding`)."""
        from stickslip.solvers.structure.shear_building import uniform_building

        return uniform_building(self.stories, self.superstructure_period, self.superstructure_mass,
                                self.superstructure_damping, self.damping_model)

    @cached_property
    def system(self):
        """The building on its isolator as a friction-linked structure."""
        from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem

        building, n = self.building, self.stories
        relative = np.hstack([-np.ones((n, 1)), np.eye(n)])
        return FrictionLinkedSystem(np.diag(np.concatenate([[self.base_mass], building.floor_masses])),
                                    relative.T @ building.damping_matrix @ relative,
                                    relative.T @ building.stiffness_matrix @ relative, np.eye(n + 1)[0],
                                    self.weight, self.radius)

    @cached_property
    def tracked(self) -> np.ndarray:
        """The rows on (x, ẋ, a_g, Q) whose peaks are the answers: the story drifts δ_j (story 1 first), the floors'
        absolute accelerations (floor 1 first), the isolator's force V_b = Q and the superstructure's shear on the
        base V_s = −(Cẋ + Kx)₀."""
        n = self.stories
        system = self.system
        size = n + 1
        rows = np.zeros((2 * n + 2, 2 * size + 2))
        for story in range(n):
            rows[story, story], rows[story, story + 1] = -1.0, 1.0
        masses = np.diag(system.mass_matrix)
        for floor in range(1, size):
            rows[n + floor - 1, :size] = -system.stiffness_matrix[floor] / masses[floor]
            rows[n + floor - 1, size:2 * size] = -system.damping_matrix[floor] / masses[floor]
        rows[2 * n, 2 * size + 1] = 1.0
        rows[2 * n + 1, :size] = -system.stiffness_matrix[0]
        rows[2 * n + 1, size:2 * size] = -system.damping_matrix[0]
        return rows

    def fixed_base_shear(self, motion) -> float:
        """The largest |force| [N] the isolator must hold for the building never to slide on ``motion``: the base
        shear of the building held on its isolator, at the samples, search points and events of the solver."""
        from stickslip.solvers.structure.friction_linked import friction_linked_history

        held = friction_linked_history(self.system, motion.acceleration, motion.dt, HELD,
                                       tracked=self.tracked[2 * self.stories:2 * self.stories + 1])
        return float(held.peaks[0])

    def holding_ratio(self, motion) -> float:
        """The largest |force| the building held on its isolator needs, over the normal force [1]: on one component,
        the exact base shear over W (:meth:`fixed_base_shear`); on a pair or with the vertical, |V_b| over
        N = W·(1 + a_v/g) at the samples, the superstructure on a fixed base in each direction (inf where N
        vanishes: the isolator lifts off)."""
        from stickslip.solvers.structure.linear_response import linear_history
        from stickslip.solvers.structure.plane_motion import plane_motion

        if isinstance(motion, Record):
            return self.fixed_base_shear(motion) / self.weight
        plane = plane_motion(motion)
        building = self.building
        shear = [self.base_mass * axis + linear_history(building.mass_matrix, building.damping_matrix,
                                                        building.stiffness_matrix, np.ones(self.stories), axis,
                                                        plane.dt).absolute_acceleration @ building.floor_masses
                 for axis in plane.ground_acceleration.T]
        normal = np.ones(len(shear[0])) if plane.vertical is None else 1.0 + plane.vertical / self.g
        with np.errstate(divide="ignore"):
            return float(np.max(np.hypot(*shear) / np.maximum(normal, 0.0))) / self.weight

    def still_reason(self, motion, where: str | None = None) -> str:
        """Why the isolator does not slide: the base shear of the building held on it against μ(0)·N."""
        weight = ("W, within mu*W" if isinstance(motion, Record) else
                  "times the normal force N = W (1 + a_v/g), within mu*N")
        return (f"the building held on its isolator needs a base shear of at most {self.holding_ratio(motion):.4g} "
                f"{weight} at {where or f'mu = {self.friction.mu_slow:g}'}")

    def describe_sliding(self) -> str:
        """``2-story building T = 0.5 s (modal damping 0.02, m_s/m_b = 4) on a friction pendulum R = 2 m``."""
        surface = "a flat slider" if math.isinf(self.radius) else f"a friction pendulum R = {self.radius:g} m"
        shape = self.friction.describe_shape()
        return (f"{self.stories}-story building T = {self.superstructure_period:g} s ({self.damping_model} damping "
                f"{self.superstructure_damping:g}, m_s/m_b = {self.mass_ratio:g}) on {surface}"
                + (f"; {shape}" if shape else ""))

    def settings(self) -> dict:
        """The building but its friction ratio, JSON-ready (radius null: flat)."""
        return {"superstructure_period": self.superstructure_period, "stories": self.stories,
                "superstructure_damping": self.superstructure_damping, "damping_model": self.damping_model,
                "mass_ratio": self.mass_ratio, "radius": None if math.isinf(self.radius) else self.radius,
                "mass": self.mass, "g": self.g, **self.friction.settings()}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {"superstructure_period": "s", "stories": "1", "superstructure_damping": "1", "mass_ratio": "1",
                "radius": "m", "mass": "kg", "g": "m s-2", **self.friction.settings_units()}
