"""A linear shear building of n stories: floor masses, story stiffnesses, fixed-base modes, classical damping.

Floor j (j = 1 … n, 1 the lowest) has mass m_j [kg]; story j joins floor j to
floor j − 1 (floor 0 the base) with stiffness k_j [N/m], so that the story
drift is δ_j = x_j − x_{j−1} and its shear k_j·δ_j.  On a fixed base the
stiffness matrix is the tridiagonal

    K[j, j] = k_j + k_{j+1},   K[j, j+1] = K[j+1, j] = −k_{j+1}   (k_{n+1} = 0),

and the fixed-base modes solve K φ = ω² M φ (:func:`scipy.linalg.eigh`,
mass-normalised: φᵀ M φ = I).

Damping is classical and on the fixed-base modes by default ("modal"): each
mode gets the damping ratio ζ, C = M Φ diag(2ζω) Φᵀ M.  That is what the
two-degree-of-freedom design model of isolated buildings (Naeim and Kelly 1999,
ch. 2) and the codes' response-history rules assume: every mode of the
superstructure has the ratio ζ one names.  Rayleigh damping ("rayleigh",
C = α M + β K with ζ on the first and the last mode) gives the modes between
them less than ζ and those above more; for one story the two are the same.

:func:`uniform_building` is the usual design building: equal floor masses and
equal story stiffnesses, scaled so that the fundamental fixed-base period is
the one given.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy import linalg

from stickslip.errors import StickslipError

#: The damping models a building takes, by name (the first is the default).
DAMPING_MODELS = ("modal", "rayleigh")


@dataclass(frozen=True)
class ShearBuilding:
    """A shear building on a fixed base.

    Attributes
    ----------
    floor_masses:
        m_j [kg], floor 1 (the lowest) first.
    story_stiffnesses:
        k_j [N/m], story 1 (between the base and floor 1) first.
    damping_ratio:
        ζ [1] of the fixed-base modes (of the first and the last for Rayleigh damping), in [0, 1).
    damping_model:
        ``"modal"`` (every fixed-base mode ζ, the default) or ``"rayleigh"``.
    """

    floor_masses: np.ndarray
    story_stiffnesses: np.ndarray
    damping_ratio: float = 0.02
    damping_model: str = "modal"

    def __post_init__(self):
        masses = np.atleast_1d(np.asarray(self.floor_masses, dtype=float))
        stiffnesses = np.atleast_1d(np.asarray(self.story_stiffnesses, dtype=float))
        if masses.ndim != 1 or masses.size == 0 or masses.shape != stiffnesses.shape:
            raise StickslipError(f"a shear building needs one floor mass per story stiffness, got {masses.size} "
                                 f"masses and {stiffnesses.size} stiffnesses")
        if not (np.all(np.isfinite(masses)) and np.all(masses > 0)):
            raise StickslipError(f"floor masses [kg] must be positive finite numbers, got {masses.tolist()}")
        if not (np.all(np.isfinite(stiffnesses)) and np.all(stiffnesses > 0)):
            raise StickslipError(f"story stiffnesses [N/m] must be positive finite numbers, got {stiffnesses.tolist()}")
        if not 0.0 <= self.damping_ratio < 1.0:
            raise StickslipError(f"superstructure damping ratio {self.damping_ratio!r}: expected a number in [0, 1)")
        if self.damping_model not in DAMPING_MODELS:
            raise StickslipError(f"damping model {self.damping_model!r}: expected one of {', '.join(DAMPING_MODELS)}")
        object.__setattr__(self, "floor_masses", masses)
        object.__setattr__(self, "story_stiffnesses", stiffnesses)

    @property
    def stories(self) -> int:
        """n, the number of stories (and floors)."""
        return self.floor_masses.size

    @property
    def total_mass(self) -> float:
        """Σ m_j [kg]."""
        return float(self.floor_masses.sum())

    @cached_property
    def mass_matrix(self) -> np.ndarray:
        """M = diag(m_j) [kg]."""
        return np.diag(self.floor_masses)

    @cached_property
    def stiffness_matrix(self) -> np.ndarray:
        """K [N/m] on a fixed base (module docstring)."""
        k = self.story_stiffnesses
        above = np.append(k[1:], 0.0)
        return np.diag(k + above) - np.diag(k[1:], 1) - np.diag(k[1:], -1)

    @cached_property
    def modes(self) -> tuple[np.ndarray, np.ndarray]:
        """(ω [rad/s], Φ): the fixed-base circular frequencies, ascending, and the mass-normalised mode shapes
        (one column per mode, φᵀ M φ = I)."""
        squares, shapes = linalg.eigh(self.stiffness_matrix, self.mass_matrix)
        return np.sqrt(squares), shapes

    @property
    def periods(self) -> np.ndarray:
        """The fixed-base periods T_i = 2π/ω_i [s], the fundamental first."""
        return 2.0 * np.pi / self.modes[0]

    @property
    def participation_factors(self) -> np.ndarray:
        """Γ_i = φ_iᵀ M 1 [kg^½] of each fixed-base mode under a horizontal ground motion."""
        return self.modes[1].T @ self.floor_masses

    @cached_property
    def damping_matrix(self) -> np.ndarray:
        """C [N·s/m]: classical modal damping (ζ on every fixed-base mode) or Rayleigh (ζ on the first and last)."""
        omega, shapes = self.modes
        zeta = self.damping_ratio
        if self.damping_model == "rayleigh" and self.stories > 1:
            first, last = omega[0], omega[-1]
            alpha, beta = 2.0 * zeta * first * last / (first + last), 2.0 * zeta / (first + last)
            return alpha * self.mass_matrix + beta * self.stiffness_matrix
        weighted = self.mass_matrix @ shapes
        return weighted @ np.diag(2.0 * zeta * omega) @ weighted.T


def uniform_building(stories: int, period: float, mass: float, damping_ratio: float = 0.02,
                     damping_model: str = "modal") -> ShearBuilding:
    """A building of ``stories`` equal floors of ``mass``/n [kg] and equal story stiffnesses, the fundamental
    fixed-base period ``period`` [s]."""
    if not (isinstance(stories, (int, np.integer)) and stories >= 1):
        raise StickslipError(f"number of stories {stories!r}: expected a whole number of at least 1")
    if not (np.isfinite(period) and period > 0):
        raise StickslipError(f"fixed-base period [s] must be a positive finite number, got {period!r}")
    if not (np.isfinite(mass) and mass > 0):
        raise StickslipError(f"superstructure mass [kg] must be a positive finite number, got {mass!r}")
    floors = np.full(stories, mass / stories)
    unit = ShearBuilding(floors, np.ones(stories), damping_ratio, damping_model)
    scale = (2.0 * np.pi / period / unit.modes[0][0]) ** 2
    return ShearBuilding(floors, np.full(stories, scale), damping_ratio, damping_model)
