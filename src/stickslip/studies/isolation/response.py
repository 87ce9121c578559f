"""One component's peaks: the one-story building on a fixed base, and on a friction pendulum over μ.

The building is the two-degree-of-freedom design model (docs/structures.md): a superstructure of mass m_s
and fixed-base period T (:func:`~stickslip.solvers.structure.shear_building.uniform_building`, one story,
damping ratio ζ on its fixed-base mode) on a base mass m_b = m_s/(mass ratio) that slides on a pendulum of
radius R [m] with Coulomb friction μ [1], N = (m_b + m_s)·g: the friction-linked structure of
:mod:`~stickslip.solvers.structure.friction_linked`, x = (u_b, u_1) relative to the ground, the interface
the base (d = e₀), solved exactly for every record and μ at once (:func:`isolated_peaks`).

On a fixed base it is the single oscillator of period T.  :func:`fixed_base_peaks` solves it as the same
structure whose bearing holds throughout (μ = :data:`HELD_MU`, checked: it never slides), so that the isolated
and the fixed-base peaks are taken at the same instants (the samples and the scheme's search points between
them); at the samples alone the fixed base would miss up to 1 − cos(π dt/T) of its peak (2 % at T = 0.3 s and
dt = 0.02 s) and bias every ratio by as much.

The peaks, each the largest absolute value over the record:

- the story drift δ = u_1 − u_b [m] (the fixed base: u_b = 0);
- the floor's absolute acceleration ü_1 + a_g [m/s²];
- the isolator's displacement u_b relative to the ground [m].

No peak depends on the masses themselves, only on their ratio: the study's building has a total mass of
:data:`TOTAL_MASS`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

import numpy as np

from stickslip.errors import StickslipError
from stickslip.records.record import Record
from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem, friction_linked_sweep
from stickslip.solvers.structure.shear_building import uniform_building

#: The building's total mass m_b + m_s [kg]: no answer of the study depends on it.
TOTAL_MASS = 1.0

#: A friction ratio [1] no record overcomes: the bearing would need a force of a thousand times the building's
#: weight to slide.  The bearing that holds is the fixed base.
HELD_MU = 1000.0


class Peaks(NamedTuple):
    """The largest absolute values over a record: arrays (records, μ) isolated, scalars on a fixed base."""

    drift: np.ndarray
    """Story drift [m]."""
    floor_acceleration: np.ndarray
    """The floor's absolute acceleration [m/s²]."""
    isolator_displacement: np.ndarray
    """The isolator's displacement relative to the ground [m] (0 on a fixed base)."""


def superstructure(period: float, mass_ratio: float, damping_ratio: float):
    """(the one-story superstructure, its base mass m_b [kg]) of the building of total mass :data:`TOTAL_MASS`,
    fixed-base period ``period`` [s], m_s/m_b = ``mass_ratio`` and damping ratio ``damping_ratio`` [1]."""
    base_mass = TOTAL_MASS / (1.0 + mass_ratio)
    return uniform_building(1, period, TOTAL_MASS - base_mass, damping_ratio), base_mass


def isolated_system(period: float, mass_ratio: float, damping_ratio: float, radius: float, g: float):
    """(the isolated building as a friction-linked structure, its tracked rows: the drift u_1 − u_b and the floor's
    absolute acceleration ü_1 + a_g = −(k δ + c δ̇)/m_s, on (x, ẋ, a_g, Q)); ``g`` [m/s²]."""
    building, base_mass = superstructure(period, mass_ratio, damping_ratio)
    stiffness, damping = building.stiffness_matrix[0, 0], building.damping_matrix[0, 0]
    relative = np.array([[1.0, -1.0], [-1.0, 1.0]])  # Tᵀ T with T = [−1, 1]: the story between base and floor
    system = FrictionLinkedSystem(np.diag([base_mass, building.total_mass]), damping * relative, stiffness * relative,
                                  np.array([1.0, 0.0]), TOTAL_MASS * g, radius)
    drift = [-1.0, 1.0, 0.0, 0.0, 0.0, 0.0]
    floor = np.array([stiffness, -stiffness, damping, -damping, 0.0, 0.0]) / building.total_mass
    return system, np.array([drift, floor])


def isolated_peaks(records: Sequence[Record], period: float, mass_ratio: float, damping_ratio: float, radius: float,
                   mu, g: float) -> Peaks:
    """The isolated building's peaks under every record of ``records`` at every μ of ``mu`` [1] (arrays (records, μ)):
    fixed-base period ``period`` [s], m_s/m_b = ``mass_ratio``, damping ratio ``damping_ratio`` [1], radius
    ``radius`` [m], gravity ``g`` [m/s²]."""
    system, tracked = isolated_system(period, mass_ratio, damping_ratio, radius, g)
    sweep = friction_linked_sweep(system, [record.acceleration for record in records],
                                  [record.dt for record in records], mu, tracked)
    return Peaks(sweep.peaks[..., 0], sweep.peaks[..., 1], sweep.peak_slip)


def fixed_base_peaks(records: Sequence[Record], period: float, mass_ratio: float, damping_ratio: float,
                     g: float) -> Peaks:
    """The building's peaks on a fixed base under every record of ``records`` (arrays (records,)): the isolated
    building of :func:`isolated_peaks` whose bearing holds (μ = :data:`HELD_MU`); an error if it slid."""
    held = isolated_peaks(records, period, mass_ratio, damping_ratio, float("inf"), [HELD_MU], g)
    if np.any(held.isolator_displacement != 0.0):
        raise StickslipError(f"the bearing slid at mu = {HELD_MU:g} (T = {period:g} s): no fixed base to compare with")
    return Peaks(held.drift[:, 0], held.floor_acceleration[:, 0], held.isolator_displacement[:, 0])
