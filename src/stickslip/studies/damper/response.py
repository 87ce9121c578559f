"""One record's one-story building bare and with a flat friction damper on its floor, over μ.

The building (docs/structures.md): mass m_s, fixed-base period T [s], damping ratio ζ on its mode
(:func:`~stickslip.solvers.structure.shear_building.uniform_building`, one story); the damper a mass
m_d = (mass ratio)·m_s on a flat surface on the floor, friction μ [1], N = m_d·g: the friction-linked
structure of :mod:`~stickslip.solvers.structure.friction_linked`, x = (u_1, u_d) relative to the ground, the
interface s = u_d − u_1, solved exactly for every record and μ at once (:func:`damper_curves`).  The answers:

- the peak story drift [m], the floor's largest |x_1| relative to the ground (one story: the drift);
- the energy E_df [J] dissipated by the damper's friction.

E_df grows with the masses (J for a structure of :data:`STRUCTURE_MASS`); the drifts and the optima do not
depend on them, only on their ratio.

The bare building is the single oscillator of period T.  :func:`bare_peak_drifts` solves it as the same structure
with a damper on which nothing rubs (μ = 0 on a flat surface: no force between them), so that the drift with and
without the damper is taken at the same instants (the samples and the scheme's search points between them).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

import numpy as np

from stickslip.records.record import Record
from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem, friction_linked_sweep
from stickslip.solvers.structure.shear_building import uniform_building

#: The structure's mass m_s [kg]: E_df is in J for this mass; no drift and no optimum depends on it.
STRUCTURE_MASS = 1.0


class DamperCurves(NamedTuple):
    """One building and damper mass: arrays (records, μ)."""

    energy_dissipated: np.ndarray
    """E_df [J]."""
    peak_drift: np.ndarray
    """The structure's peak story drift [m]."""


def building(period: float, damping_ratio: float):
    """The one-story building of mass :data:`STRUCTURE_MASS`, fixed-base period ``period`` [s], damping ratio
    ``damping_ratio`` [1]."""
    return uniform_building(1, period, STRUCTURE_MASS, damping_ratio)


def damper_system(period: float, mass_ratio: float, damping_ratio: float, g: float) -> FrictionLinkedSystem:
    """The building of period ``period`` [s] and damping ratio ``damping_ratio`` [1] with a flat damper of m_d/m_s =
    ``mass_ratio`` on its floor, as a friction-linked structure; ``g`` [m/s²]."""
    bare = building(period, damping_ratio)
    damper_mass = mass_ratio * STRUCTURE_MASS
    bordered = lambda matrix: np.pad(matrix, ((0, 1), (0, 1)))  # noqa: E731  the damper's row and column: zeros
    return FrictionLinkedSystem(np.diag([STRUCTURE_MASS, damper_mass]), bordered(bare.damping_matrix),
                                bordered(bare.stiffness_matrix), np.array([-1.0, 1.0]), damper_mass * g)


def damper_curves(records: Sequence[Record], period: float, mass_ratio: float, damping_ratio: float, mu,
                  g: float) -> DamperCurves:
    """E_df [J] and the peak drift [m] under every record of ``records`` at every μ of ``mu`` [1], the building of
    period ``period`` [s] and damping ratio ``damping_ratio`` [1], m_d/m_s = ``mass_ratio``, ``g`` [m/s²]."""
    sweep = friction_linked_sweep(damper_system(period, mass_ratio, damping_ratio, g),
                                  [record.acceleration for record in records], [record.dt for record in records], mu,
                                  [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0]])
    return DamperCurves(sweep.energy_dissipated, sweep.peaks[..., 0])


def bare_peak_drifts(records: Sequence[Record], period: float, damping_ratio: float, g: float) -> np.ndarray:
    """The bare building's peak drift [m] under every record of ``records``: a damper at μ = 0 on a flat surface
    exerts no force on it (its mass, here m_s, does not matter)."""
    return damper_curves(records, period, 1.0, damping_ratio, [0.0], g).peak_drift[:, 0]
