"""What the friction tuned mass damper's scheme solves: a shear building on a fixed base and a mass sliding on it.

A :class:`DamperCase` is a uniform shear building of n stories
(:func:`~stickslip.solvers.structure.shear_building.uniform_building`: its
fundamental period T [s], damping ratio ζ on its modes, total mass m_s [kg]
in equal floors) and a mass m_d = (mass ratio)·m_s [kg] sliding on floor j
(the top by default) on a surface of radius R_d [m] (inf: flat) with
friction μ.  The friction-linked structure it makes (docs/structures.md):
x = (u_1 … u_n, u_d) [m] relative to the ground,

    M = diag(m_1 … m_n, m_d),  C = blockdiag(C_b, 0),  K = blockdiag(K_b, 0),

slip s = dᵀx = u_d − u_j (d = e_d − e_j), normal force N = m_d·g [N], the
surface's restoring force (N/R_d)·s and the friction force F, |F| ≤ μN.
The same building without the damper (bare) and with its mass rigidly
attached to floor j (M_b + m_d e_j e_jᵀ, the same C_b and K_b) are the
references the damper's reductions are measured against.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from stickslip.models.structure_scheme import StructureCase
from stickslip.records.record import Record
from stickslip.solvers.structure.shear_building import ShearBuilding, uniform_building


@dataclass(frozen=True)
class DamperCase(StructureCase):
    """One building with its damper.

    Attributes
    ----------
    mu:
        Friction ratio μ [1] between the damper and its floor: Coulomb's, or the velocity law's μ_fast.
    structure_period:
        The building's fundamental fixed-base period T [s].
    stories:
        n, the number of stories.
    structure_damping:
        ζ [1] of the building's modes.
    damping_model:
        ``"modal"`` or ``"rayleigh"`` (:mod:`~stickslip.solvers.structure.shear_building`).
    mass_ratio:
        m_d/m_s [1].
    radius:
        R_d [m] of the damper's surface; ``math.inf`` for a flat one.
    damper_story:
        j, the floor the damper sits on (1 the lowest, n the top).
    mass:
        m_s [kg], the building's mass (energies scale with it; the motion does not depend on it).
    g:
        Gravitational acceleration [m/s²].
    mu_slow:
        The velocity law's μ_slow [1]; None: Coulomb friction μ.
    rate:
        The velocity law's rate [s/m] (0 for Coulomb friction).
    """

    mu: float
    structure_period: float
    stories: int
    structure_damping: float
    damping_model: str
    mass_ratio: float
    radius: float
    damper_story: int
    mass: float
    g: float
    mu_slow: float | None = None
    rate: float = 0.0

    @cached_property
    def building(self) -> ShearBuilding:
        """The bare building: n equal floors of m_s/n [kg], period T [s]."""
        return uniform_building(self.stories, self.structure_period, self.mass, self.structure_damping,
                                self.damping_model)

    @property
    def damper_mass(self) -> float:
        """m_d [kg]."""
        return self.mass_ratio * self.mass

    @property
    def normal_force(self) -> float:
        """N = m_d·g [N], the damper's weight on its surface."""
        return self.damper_mass * self.g

    @property
    def surface_stiffness(self) -> float:
        """N/R_d [N/m], the curved surface's restoring stiffness (0 on a flat one)."""
        return 0.0 if math.isinf(self.radius) else self.normal_force / self.radius

    @property
    def slip_vector(self) -> np.ndarray:
        """d [1] (n + 1 entries): s = dᵀx = u_d − u_j."""
        d = np.zeros(self.stories + 1)
        d[-1], d[self.damper_story - 1] = 1.0, -1.0
        return d

    @cached_property
    def mass_matrix(self) -> np.ndarray:
        """M = diag(m_1 … m_n, m_d) [kg]."""
        return np.diag(np.append(self.building.floor_masses, self.damper_mass))

    @cached_property
    def damping_matrix(self) -> np.ndarray:
        """C = blockdiag(C_b, 0) [N·s/m]."""
        return self._bordered(self.building.damping_matrix)

    @cached_property
    def stiffness_matrix(self) -> np.ndarray:
        """K = blockdiag(K_b, 0) [N/m], the structure's own (no surface term)."""
        return self._bordered(self.building.stiffness_matrix)

    def _bordered(self, matrix: np.ndarray) -> np.ndarray:
        bordered = np.zeros((self.stories + 1, self.stories + 1))
        bordered[:-1, :-1] = matrix
        return bordered

    @cached_property
    def attached_mass_matrix(self) -> np.ndarray:
        """M_b + m_d e_j e_jᵀ [kg]: the building with the damper's mass rigidly attached to floor j."""
        masses = self.building.floor_masses.copy()
        masses[self.damper_story - 1] += self.damper_mass
        return np.diag(masses)

    @cached_property
    def system(self):
        """The building with its damper as a friction-linked structure
        (:class:`~stickslip.solvers.structure.friction_linked.FrictionLinkedSystem`)."""
        from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem

        return FrictionLinkedSystem(self.mass_matrix, self.damping_matrix, self.stiffness_matrix, self.slip_vector,
                                    self.normal_force, self.radius)

    @cached_property
    def tracked(self) -> np.ndarray:
        """The rows on (x, ẋ, a_g, Q) whose peaks are the answers, n rows each but the last two: the floors'
        displacements x_j, the story drifts δ_j, the floors' absolute accelerations
        ü_j = (−(Kx + Cẋ)_j + Q on the damper's floor)/m_j, the base shear V_b = 1ᵀ(K_b x + C_b ẋ) and the
        damper's force Q = (N/R_d)s + F."""
        n, size = self.stories, self.stories + 1
        rows = np.zeros((3 * n + 2, 2 * size + 2))
        rows[:n, :n] = np.eye(n)
        rows[n:2 * n, :n] = np.eye(n) - np.eye(n, k=-1)
        masses = self.building.floor_masses
        rows[2 * n:3 * n, :size] = -self.stiffness_matrix[:n] / masses[:, None]
        rows[2 * n:3 * n, size:2 * size] = -self.damping_matrix[:n] / masses[:, None]
        rows[2 * n + self.damper_story - 1, -1] = 1.0 / masses[self.damper_story - 1]
        rows[3 * n, :size] = self.stiffness_matrix.sum(axis=0)
        rows[3 * n, size:2 * size] = self.damping_matrix.sum(axis=0)
        rows[3 * n + 1, -1] = 1.0
        return rows

    def holding_ratio(self, motion) -> float:
        """The largest |force| that holds the damper on its floor while the building moves with the damper's mass
        attached, over its normal force [1]: on one component over m_d·g, exactly (at the solver's samples, search
        points and events); on a pair or with the vertical |m_d·ü_j| over N = m_d·(g + a_v) at the samples, the
        building linear in each direction (inf where N vanishes: the damper lifts off)."""
        from stickslip.models.friction_tmd.references import attached_history
        from stickslip.solvers.structure.linear_response import linear_history
        from stickslip.solvers.structure.plane_motion import plane_motion

        if isinstance(motion, Record):
            return float(attached_history(self, motion.acceleration, motion.dt).peaks[-1]) / self.normal_force
        plane = plane_motion(motion)
        building = self.building
        floor = [linear_history(self.attached_mass_matrix, building.damping_matrix, building.stiffness_matrix,
                                np.ones(self.stories), axis, plane.dt).absolute_acceleration[:, self.damper_story - 1]
                 for axis in plane.ground_acceleration.T]
        normal = self.g if plane.vertical is None else self.g + plane.vertical
        with np.errstate(divide="ignore"):
            return float(np.max(np.hypot(*floor) / np.maximum(normal, 0.0)))

    def still_reason(self, motion, where: str | None = None) -> str:
        """Why the damper never leaves rest: the force that holds it on its floor, beside μ(0)·N."""
        weight = "its weight" if isinstance(motion, Record) else "its normal force m_d (g + a_v)"
        return (f"holding the damper on floor {self.damper_story} needs at most {self.holding_ratio(motion):.4g} "
                f"times {weight}, within mu*N at {where or f'mu = {self.friction.mu_slow:g}'}")

    def describe_sliding(self) -> str:
        """``on floor 1 of a 1-story building T = 1 s (zeta = 0.02, modal), m_d/m_s = 0.05, flat``."""
        surface = "flat" if math.isinf(self.radius) else f"R_d = {self.radius:g} m"
        shape = self.friction.describe_shape()
        return (f"on floor {self.damper_story} of a {self.stories}-story building T = {self.structure_period:g} s "
                f"(zeta = {self.structure_damping:g}, {self.damping_model}), m_d/m_s = {self.mass_ratio:g}, {surface}"
                + (f"; {shape}" if shape else ""))

    def settings(self) -> dict:
        """The building and its damper but the friction ratio, JSON-ready (a flat surface's radius None)."""
        return {"structure_period": self.structure_period, "stories": self.stories,
                "structure_damping": self.structure_damping, "damping_model": self.damping_model,
                "mass_ratio": self.mass_ratio, "radius": None if math.isinf(self.radius) else self.radius,
                "damper_story": self.damper_story,
                "mass": self.mass, "g": self.g, **self.friction.settings()}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {"structure_period": "s", "stories": "1", "structure_damping": "1", "mass_ratio": "1", "radius": "m",
                "damper_story": "1", "mass": "kg", "g": "m s-2", **self.friction.settings_units()}
