"""The exact scheme: the event-driven solution of :mod:`stickslip.models.rigid.events`, one history.

:func:`sliding_history` runs the event kernel as plain Python for a record of
up to :data:`~stickslip.models.rigid.events.PYTHON_SAMPLES` samples (no numba to
import: a fresh ``stickslip solve`` answers in a fraction of a second) and
compiled (:mod:`stickslip.models.rigid.exact`) for a longer one; both give the same
numbers.  The rigid model's entry (:mod:`stickslip.models.rigid`) declares it:
any resistance, the batched kernel for sweeps, no options.
"""

from __future__ import annotations

import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.records.process import integrate_linear_acceleration
from stickslip.models.rigid import events
from stickslip.models.rigid.history import SolverHistory
from stickslip.models.rigid.resistance import Resistance


def sliding_history(acceleration: np.ndarray, dt: float, resistance: Resistance) -> SolverHistory:
    """Solve the sliding block exactly for one record and one :class:`Resistance`.

    Parameters
    ----------
    acceleration:
        Ground acceleration ü_g [m/s²] at the samples, linear in between; a
        positive value drives the block towards −x (downslope).
    dt:
        Sample interval [s].
    resistance:
        The thresholds T₊, T₋ and the body acceleration b [m/s²].

    Returns
    -------
    SolverHistory
        Per-unit-mass histories at the sample times.  The phase at a sample is
        the phase just after it; energies are in J/kg (E_df as in
        :func:`~stickslip.models.rigid.events.resisting_work`; the body-force work b·x is not in it).
        Records of up to :data:`~stickslip.models.rigid.events.PYTHON_SAMPLES` samples are solved as plain
        Python, longer ones by the compiled kernel; the results are identical.
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    ground_velocity, ground_displacement = integrate_linear_acceleration(acceleration, dt)
    if acceleration.size <= events.PYTHON_SAMPLES:
        outputs = events.history_kernel(acceleration.tolist(), ground_velocity.tolist(), dt, *resistance.thresholds())
    else:
        from stickslip.models.rigid.exact import history_kernel as compiled_history_kernel  # numba, for long records

        outputs = compiled_history_kernel(acceleration, ground_velocity, dt, *resistance.thresholds())
    return SolverHistory.from_kernel_outputs(
        np.arange(acceleration.size) * dt,
        acceleration.copy(),
        ground_velocity,
        ground_displacement,
        outputs,
    )


def solve_history(acceleration: np.ndarray, dt: float, mu: float, g: float) -> SolverHistory:
    """:func:`sliding_history` on a flat surface: friction ratio ``mu`` [-], gravity ``g`` [m/s²] (the paper's Eq. 1)."""
    return sliding_history(acceleration, dt, Resistance.friction(mu, g))
