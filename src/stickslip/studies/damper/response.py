"""Records under a one-story building bare and with a flat friction damper on its floor, over μ.

The building (docs/structures.md): mass m_s, fixed-base period T [s], damping ratio ζ on its mode
(:func:`~stickslip.solvers.structure.shear_building.uniform_building`, one story); the damper a mass
m_d = (mass ratio)·m_s on a flat surface on the floor, friction μ [1], N = m_d·g: the friction-linked
structure of :mod:`~stickslip.solvers.structure.friction_linked`, x = (u_1, u_d) relative to the ground, the
interface s = u_d − u_1, solved exactly.  The answers:

- the peak story drift [m], the floor's largest |x_1| relative to the ground (one story: the drift);
- the energy E_df [J] dissipated by the damper's friction.

E_df grows with the masses (J for a structure of :data:`STRUCTURE_MASS`); the drifts and the optima do not
depend on them, only on their ratio.

**The bare building** is the single oscillator of period T.  :func:`bare_peaks` solves it as the same structure
with a damper on which nothing rubs (μ = 0 on a flat surface: no force between them), so that the drift with and
without the damper is taken at the same instants (the samples and the scheme's search points between them).

**Friction levels.**  Each record's μ grid is a fixed set of levels η [1] times its bare floor's peak absolute
acceleration in g, μ = η·PFA_bare/g: the damper slides only where its floor's acceleration passes μg, so a
grid of μ that is fine where one record's optima lie is all stuck, or all free, for another's.  The
equations are homogeneous of degree one in (x, a_g, μ) (Coulomb friction: F = μN, N fixed), so a record scaled
by c at μ·c is the same motion scaled by c, and E_df scaled by c²: :func:`damper_curves` solves every record
scaled to PFA_bare = g at the levels η themselves, all in one parallel sweep, and scales the answers back.
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
    """One building and damper mass: arrays (records, levels)."""

    energy_dissipated: np.ndarray
    """E_df [J]."""
    peak_drift: np.ndarray
    """The structure's peak story drift [m]."""


class BarePeaks(NamedTuple):
    """The bare building's peaks: arrays (records,)."""

    drift: np.ndarray
    """Story drift [m]."""
    floor_acceleration: np.ndarray
    """The floor's absolute acceleration [m/s²]."""


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


#: The tracked row of the drift u_1 on (x, ẋ, a_g, Q).
DRIFT_ROW = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0)


def bare_peaks(records: Sequence[Record], period: float, damping_ratio: float, g: float) -> BarePeaks:
    """The bare building's peak drift [m] and floor acceleration [m/s²] under every record of ``records``: a damper
    at μ = 0 on a flat surface exerts no force on it (its mass, here m_s, does not matter)."""
    bare = building(period, damping_ratio)
    # the floor's absolute acceleration −(k u_1 + c u̇_1)/m_s: no force from the damper
    floor = -np.array([bare.stiffness_matrix[0, 0], 0.0, bare.damping_matrix[0, 0], 0.0, 0.0, 0.0]) / STRUCTURE_MASS
    sweep = friction_linked_sweep(damper_system(period, 1.0, damping_ratio, g),
                                  [record.acceleration for record in records], [record.dt for record in records],
                                  [0.0], [DRIFT_ROW, floor])
    return BarePeaks(sweep.peaks[:, 0, 0], sweep.peaks[:, 0, 1])


def damper_curves(records: Sequence[Record], period: float, mass_ratio: float, damping_ratio: float, levels,
                  floor_accelerations, g: float) -> DamperCurves:
    """E_df [J] and the peak drift [m] under every record of ``records`` at μ = η·PFA/g for every level η of
    ``levels`` [1], PFA the record's ``floor_accelerations`` [m/s²] (its bare floor's peak): the building of period
    ``period`` [s] and damping ratio ``damping_ratio`` [1], m_d/m_s = ``mass_ratio``, ``g`` [m/s²].

    Solved on the records scaled to PFA = g at μ = η (module docstring) and scaled back: drift × PFA/g,
    E_df × (PFA/g)².
    """
    scales = np.asarray(floor_accelerations, dtype=float) / g
    sweep = friction_linked_sweep(damper_system(period, mass_ratio, damping_ratio, g),
                                  [record.acceleration / scale for record, scale in zip(records, scales)],
                                  [record.dt for record in records], levels, [DRIFT_ROW])
    return DamperCurves(sweep.energy_dissipated * scales[:, None] ** 2, sweep.peaks[..., 0] * scales[:, None])
