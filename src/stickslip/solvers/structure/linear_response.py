"""The exact response of a linear structure to a ground acceleration linear between samples.

A structure of n degrees of freedom x [m], each relative to the ground,

    M ẍ + C ẋ + K x = −M ι a(t),

ι the influence vector (ones for a horizontal motion), has the state
z = (x, ẋ) with ż = A z + B a(t), A = [[0, I], [−M⁻¹K, −M⁻¹C]], B = (0, −ι).
With a(t) linear between samples the state steps exactly, as the response
spectrum's oscillator does (:mod:`stickslip.response_spectrum`, Nigam and
Jennings 1969) and as :func:`scipy.signal.cont2discrete`'s first-order hold:

    z_{k+1} = E z_k + (F₁ − F₂) a_k + F₂ a_{k+1},

E = exp(A dt) and F₁, F₂ the blocks of the exponential of the augmented
matrix [[A dt, B dt, 0], [0, 0, 1], [0, 0, 0]].  No damping model is assumed:
the building with a damper's mass attached is not classically damped, and
steps the same way.  :func:`modal_displacements` is the classically damped
building's independent closed form, mode by mode, for the oracles.
"""

from __future__ import annotations

from typing import NamedTuple

import numba
import numpy as np
from scipy import linalg

from stickslip.response_spectrum import relative_displacements


class LinearHistory(NamedTuple):
    """The response at every sample: arrays (samples, n)."""

    displacement: np.ndarray
    """x [m], relative to the ground."""
    velocity: np.ndarray
    """ẋ [m/s], relative to the ground."""
    absolute_acceleration: np.ndarray
    """ẍ + ι a [m/s²]: −M⁻¹(C ẋ + K x)."""


def first_order_hold(state_matrix: np.ndarray, input_vector: np.ndarray, dt: float):
    """(E, F₁ − F₂, F₂) of ż = A z + B a(t) with a linear over a step of ``dt`` [s] (module docstring)."""
    size = state_matrix.shape[0]
    augmented = np.zeros((size + 2, size + 2))
    augmented[:size, :size] = state_matrix * dt
    augmented[:size, size] = input_vector * dt
    augmented[size, size + 1] = 1.0
    blocks = linalg.expm(augmented)
    return blocks[:size, :size], blocks[:size, size] - blocks[:size, size + 1], blocks[:size, size + 1]


def linear_history(mass_matrix, damping_matrix, stiffness_matrix, influence, acceleration, dt: float) -> LinearHistory:
    """The structure's exact response, at rest at t = 0, to ``acceleration`` [m/s²] sampled every ``dt`` [s].

    ``mass_matrix`` [kg], ``damping_matrix`` [N·s/m] and ``stiffness_matrix`` [N/m] are n × n; ``influence``
    ι has n entries.
    """
    mass_matrix, influence = np.asarray(mass_matrix, dtype=float), np.asarray(influence, dtype=float)
    acceleration = np.asarray(acceleration, dtype=float)
    n = influence.size
    flexibility = np.linalg.solve(mass_matrix, np.hstack([stiffness_matrix, damping_matrix]))
    state_matrix = np.block([[np.zeros((n, n)), np.eye(n)], [-flexibility]])
    step, first, second = first_order_hold(state_matrix, np.concatenate([np.zeros(n), -influence]), dt)
    states = _stepped_states(step, first, second, np.ascontiguousarray(acceleration))
    displacement, velocity = states[:, :n], states[:, n:]
    return LinearHistory(displacement, velocity, -(states @ flexibility.T))


@numba.njit(cache=True)
def _stepped_states(step, first, second, acceleration):
    """The states z_k (samples, 2n) from z_0 = 0 by z_{k+1} = E z_k + (F₁ − F₂) a_k + F₂ a_{k+1} (``step`` E,
    ``first`` F₁ − F₂, ``second`` F₂: :func:`first_order_hold`)."""
    size = step.shape[0]
    states = np.zeros((acceleration.size, size))
    for k in range(acceleration.size - 1):
        for i in range(size):
            total = first[i] * acceleration[k] + second[i] * acceleration[k + 1]
            for j in range(size):
                total += step[i, j] * states[k, j]
            states[k + 1, i] = total
    return states


def modal_displacements(building, acceleration, dt: float) -> np.ndarray:
    """x [m] (samples, n) of a classically damped ``building`` (a
    :class:`~stickslip.solvers.structure.shear_building.ShearBuilding` with modal damping) on a fixed base:
    Σ_i Γ_i φ_i q_i(t), each modal oscillator solved exactly by :mod:`stickslip.response_spectrum`."""
    _, shapes = building.modes
    modal = np.stack(list(relative_displacements(np.asarray(acceleration, dtype=float)[None, :], dt,
                                                 building.periods, building.damping_ratio)))[:, 0, :]
    return (modal.T * building.participation_factors) @ shapes.T
