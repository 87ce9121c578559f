"""The common per-unit-mass output of every solver."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


#: End-of-record scalars of a solve, in the column order of the batched exact
#: kernel (:func:`stickslip.models.rigid.exact.sweep_scalars`).  Energies per unit
#: mass [J/kg], displacements and path [m], slip_fraction dimensionless.
SCALAR_NAMES = (
    "energy_dissipated",
    "energy_input",
    "kinetic_energy_final",
    "residual_displacement",
    "peak_relative_displacement",
    "sliding_path",
    "slip_fraction",
    "n_slip_episodes",
)


@dataclass(frozen=True)
class SolverHistory:
    """Time histories of one solve, per unit block mass, on the solver's time grid.

    The block mass cancels from the equation of motion, so solvers work per
    unit mass; :class:`stickslip.models.rigid.response.Response` multiplies energies and
    forces by the mass.

    Attributes
    ----------
    time:
        Sample times [s].
    ground_acceleration, ground_velocity, ground_displacement:
        Base motion ü_g [m/s²], u̇_g [m/s], u_g [m] at the samples (u̇_g(0) = u_g(0) = 0).
    relative_displacement, relative_velocity, relative_acceleration:
        Block motion relative to the base x [m], ẋ [m/s], ẍ [m/s²].
    phase:
        0 where the block sticks at the sample, +1 / −1 where it slides with ẋ > 0 / ẋ < 0.
    energy_dissipated:
        Cumulative friction work per unit mass, E_df/m [J/kg].
    energy_input:
        Cumulative absolute input energy per unit mass, E_I/m = ∫ ü·du_g [J/kg].
    sliding_path:
        Total distance slid, ∫|ẋ| dt [m].
    slip_time:
        Total time spent sliding [s].
    n_slip_episodes:
        Number of separate intervals of sliding (a reversal without sticking does not start a new one).
    peak_relative_displacement:
        max |x| over the whole motion [m], including stops between samples; ``None`` when the
        solver does not track it (then the maximum over the samples is used).
    """

    time: np.ndarray
    ground_acceleration: np.ndarray
    ground_velocity: np.ndarray
    ground_displacement: np.ndarray
    relative_displacement: np.ndarray
    relative_velocity: np.ndarray
    relative_acceleration: np.ndarray
    phase: np.ndarray
    energy_dissipated: np.ndarray
    energy_input: np.ndarray
    sliding_path: float
    slip_time: float
    n_slip_episodes: int
    peak_relative_displacement: float | None = None

    @classmethod
    def from_kernel_outputs(
        cls,
        time: np.ndarray,
        ground_acceleration: np.ndarray,
        ground_velocity: np.ndarray,
        ground_displacement: np.ndarray,
        outputs: tuple,
    ) -> SolverHistory:
        """The history of a solver kernel's ``outputs`` on the grid ``time`` [s] with the base motion there.

        ``outputs`` is ``(relative_displacement [m], relative_velocity [m/s],
        relative_acceleration [m/s²], phase, energy_dissipated [J/kg],
        energy_input [J/kg], sliding_path [m], slip_time [s], n_slip_episodes)``,
        optionally followed by ``peak_relative_displacement`` [m], the order in
        which the solvers' numba kernels return them.
        """
        x, xd, xdd, phase, e_df, e_i, path, slip_time, episodes, *peak = outputs
        return cls(
            time=time,
            ground_acceleration=ground_acceleration,
            ground_velocity=ground_velocity,
            ground_displacement=ground_displacement,
            relative_displacement=x,
            relative_velocity=xd,
            relative_acceleration=xdd,
            phase=phase,
            energy_dissipated=e_df,
            energy_input=e_i,
            sliding_path=float(path),
            slip_time=float(slip_time),
            n_slip_episodes=int(episodes),
            peak_relative_displacement=float(peak[0]) if peak else None,
        )
