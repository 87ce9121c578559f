"""What the friction tuned mass damper's scheme solves: a shear building on a fixed base and a mass sliding on it.

A :class:`DamperCase` is a uniform shear building of n stories
(:func:`~stickslip.solvers.structure.shear_building.uniform_building`: its
fundamental period T [s], damping ratio ζ on its modes, total mass m_s [kg]
in equal floors) and a mass m_d = (mass ratio)·m_s [kg] sliding on floor j
(the top by default) on a surface of radius R_d [m] (inf: flat) with
friction μ.  The friction-linked structure it makes (docs/friction_tmd.md):
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
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from stickslip.solvers.structure.shear_building import ShearBuilding, uniform_building


@dataclass(frozen=True)
class DamperCase:
    """One building with its damper.

    Attributes
    ----------
    mu:
        Friction ratio μ [1] between the damper and its floor.
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

    #: The records are solved as given (no inverse polarity).
    inverse = False

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

    def at(self, coefficient: str, value: float) -> DamperCase:
        """The same building and damper with the friction ratio μ at ``value`` [1]."""
        return replace(self, mu=float(value))

    def solved(self, acceleration: np.ndarray) -> np.ndarray:
        """The ground acceleration [m/s²] as the scheme takes it (as given)."""
        return acceleration

    def held_floor_acceleration(self, motion) -> float:
        """The largest |absolute acceleration| [m/s²] of floor j at the samples while the damper is held to it:
        the building with the mass attached, whose floor j needs the friction force m_d·ü_j to carry the damper."""
        from stickslip.models.friction_tmd.references import attached_history

        return float(np.max(np.abs(attached_history(self, motion.acceleration, motion.dt)
                                   .absolute_acceleration[:, self.damper_story - 1])))

    def slides(self, motion) -> bool:
        """Whether the damper, at rest on its floor, leaves it on ``motion``: while it holds, the building moves
        with the mass attached and the damper needs the force m_d·|ü_j| ≤ μ·m_d·g (at the samples)."""
        return self.held_floor_acceleration(motion) > self.mu * self.g

    def still_reason(self, motion, where: str | None = None) -> str:
        """Why the damper never leaves rest: its floor's peak absolute acceleration with the mass held, beside μg."""
        peak = self.held_floor_acceleration(motion)
        return (f"floor {self.damper_story}'s peak absolute acceleration with the damper held, {peak:.4g} m/s2, is "
                f"at most mu*g = {self.mu * self.g:.4g} m/s2 at {where or f'mu = {self.mu:g}'}")

    def describe_sliding(self) -> str:
        """``on floor 1 of a 1-story building T = 1 s, m_d/m_s = 0.05, R_d = inf``."""
        return (f"on floor {self.damper_story} of a {self.stories}-story building T = {self.structure_period:g} s "
                f"(zeta = {self.structure_damping:g}, {self.damping_model}), m_d/m_s = {self.mass_ratio:g}, "
                f"R_d = {self.radius:g} m")

    def settings(self) -> dict:
        """The building and its damper but the friction ratio, JSON-ready."""
        return {"structure_period": self.structure_period, "stories": self.stories,
                "structure_damping": self.structure_damping, "damping_model": self.damping_model,
                "mass_ratio": self.mass_ratio, "radius": self.radius, "damper_story": self.damper_story,
                "mass": self.mass, "g": self.g}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {"structure_period": "s", "stories": "1", "structure_damping": "1", "mass_ratio": "1", "radius": "m",
                "damper_story": "1", "mass": "kg", "g": "m s-2"}
