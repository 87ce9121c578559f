"""The friction-linked structure in the plane as a block sliding on its interface: the slip's equation.

The structure of :class:`~stickslip.solvers.structure.friction_linked.FrictionLinkedSystem`
in both horizontal directions, x ∈ ℝ^{n×2} [m] relative to the ground (the
same M, C, K in both, uncoupled but through the interface), the ground
acceleration a(t) ∈ ℝ², and one friction interface whose slip is the vector
s = dᵀx ∈ ℝ²:

    M ẍ + C ẋ + K x + d·((N/R)·s + F)ᵀ = −M ι aᵀ,

N(t) [N] the interface's normal force, R [m] its surface's radius and F ∈ ℝ²
the friction force, |F| ≤ μ·N (the friction circle), F = μ(|w|)·N·w/|w| while
the interface slips at w = ṡ.

Split the velocity into the slip and what the structure does while the
interface holds: with g = M⁻¹d and μ̃ = dᵀg [1/kg],

    ẋ = h + g·wᵀ/μ̃,   dᵀh = 0,

h the *held velocity*.  The projection P = I − g·dᵀ/μ̃ removes F from h's
equation, ḣ = P·ẍ, and the slip obeys the equation of a block sliding in the
plane (:mod:`stickslip.solvers.plane`) of unit mass:

    ẇ = −β − c̃·w − μ̃·F,   β = dᵀM⁻¹(C h + K x) + μ̃·(N/R)·s + (dᵀι)·a,

with c̃ = gᵀC g/μ̃ [1/s] the interface's own viscous rate and μ̃·F = μ·n·w/|w|,
n = μ̃·N [m/s²] the normal force per unit of the interface's effective mass
1/μ̃.  β [m/s²] is the block's driving acceleration b: the interface holds
(w = 0, F = −β/μ̃) while |β| ≤ μ(0)·n.  :class:`SlipEquation` holds these terms
and packs them for the kernels of :mod:`~stickslip.solvers.structure.integrated_step`.
"""

from __future__ import annotations

import numpy as np

from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem


class SlipEquation:
    """The terms of the slip's equation of a :class:`FrictionLinkedSystem` (module docstring); ι = ones."""

    def __init__(self, system: FrictionLinkedSystem):
        self.system = system
        self.masses = np.diag(system.mass_matrix).copy()  # [kg]
        self.damping = system.damping_matrix  # C [N·s/m]
        self.stiffness = system.stiffness_matrix  # K [N/m]
        self.direction = system.interface  # d [1]
        self.influence = np.ones(system.size)  # ι [1]
        self.size = system.size
        self.normal_force = system.normal_force  # N₀ [N]
        self.inverse_radius = 1.0 / system.radius  # 1/R [1/m], 0 flat
        self.mass_damping = self.damping / self.masses[:, None]  # M⁻¹C [1/s]
        self.mass_stiffness = self.stiffness / self.masses[:, None]  # M⁻¹K [1/s²]
        self.slip_mode = self.direction / self.masses  # g = M⁻¹d [1/kg]
        self.mobility = float(self.direction @ self.slip_mode)  # μ̃ [1/kg]
        self.slip_damping_row = self.direction @ self.mass_damping  # dᵀM⁻¹C [1/s]
        self.slip_stiffness_row = self.direction @ self.mass_stiffness  # dᵀM⁻¹K [1/s²]
        self.ground_share = float(self.direction @ self.influence)  # dᵀι [1]

    def velocity(self, held, slip_velocity):
        """ẋ [m/s] (n × 2) from the held velocity h (n × 2) and the slip velocity w (2) [m/s]."""
        return held + np.outer(self.slip_mode, slip_velocity) / self.mobility

    def kernel_arrays(self, mu_slow: float, mu_fast: float, rate: float):
        """(law, vectors, matrices) of :mod:`~stickslip.solvers.structure.integrated_step` for the friction law
        μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} [1, 1, s/m]."""
        law = np.array([mu_slow, mu_fast, rate, self.inverse_radius, self.mobility, self.ground_share,
                        self.normal_force])
        vectors = np.stack([self.masses, self.slip_mode, self.direction, self.influence, self.slip_damping_row,
                            self.slip_stiffness_row])
        matrices = np.stack([self.mass_damping, self.mass_stiffness, self.damping, self.stiffness])
        return law, vectors, matrices
