"""The elastic response spectrum of a record: exact for the record taken piecewise linear between its samples.

A single-degree-of-freedom oscillator of period T [s] and damping ratio ξ
[1], at rest at t = 0, driven by the ground acceleration a(t) [m/s²]:

    ü + 2ξω u̇ + ω² u = −a(t),        ω = 2π/T,

u the displacement relative to the ground [m].  Between two samples a is
linear, and the state x = (u, u̇) steps exactly (Nigam and Jennings 1969):

    x_{k+1} = E x_k + (F1 − F2) a_k + F2 a_{k+1},

with E = exp(A dt) and F1, F2 the blocks of the exponential of the augmented
matrix [[A dt, B dt, 0], [0, 0, 1], [0, 0, 0]] (A = [[0, 1], [−ω², −2ξω]],
B = (0, −1)), computed with :func:`scipy.linalg.expm`, as
:func:`scipy.signal.cont2discrete` does for its first-order hold.  The
recursion is run as a second-order filter by :func:`scipy.signal.lfilter`.
The pseudo-spectral acceleration is PSA = ω² max|u| [m/s²].

Why not pyrotd: its response is computed in the frequency domain by a
Fourier transform of the record without zero padding, so the free vibration
that follows the record's end wraps around onto its start; and pyrotd 0.6.1
imports ``pkg_resources``, which the setuptools of our environment no longer
has (docs/estimates.md gives the measured difference).
"""

from __future__ import annotations

import numpy as np
from scipy import linalg, signal

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.constants import DEFAULT_DAMPING
from stickslip.errors import StickslipError


def relative_displacement(acceleration, dt: float, period: float, damping: float = DEFAULT_DAMPING) -> np.ndarray:
    """u(t_k) [m]: the oscillator's displacement relative to the ground at every sample, exactly (module docstring).

    ``acceleration`` [m/s²] at steps of ``dt`` [s]; ``period`` T [s] > 0; ``damping`` ξ in [0, 1).
    """
    values = checked_acceleration(acceleration, "ground acceleration")
    periods = [checked_positive(period, "oscillator period T [s]")]
    return next(relative_displacements(values[None, :], dt, periods, damping))[0]


def relative_displacements(accelerations: np.ndarray, dt: float, periods, damping: float = DEFAULT_DAMPING):
    """For each period T [s] of ``periods`` in turn, u(t_k) [m] of the oscillator under each row of
    ``accelerations`` (components × samples, [m/s²], at steps of ``dt`` [s]), as an array of the same shape.

    The transition matrices of all periods come from one stacked :func:`scipy.linalg.expm`, so a spectrum pays
    for one call, not one per period; one row of ``accelerations`` per component.
    """
    dt = checked_positive(dt, "time step dt [s]")
    if not 0.0 <= damping < 1.0:
        raise StickslipError(f"damping ratio {damping!r}: expected a number in [0, 1)")
    omega = 2.0 * np.pi / np.asarray(periods, dtype=float)
    augmented = np.zeros((omega.size, 4, 4))
    augmented[:, 0, 1] = dt
    augmented[:, 1, 0], augmented[:, 1, 1], augmented[:, 1, 2] = -omega**2 * dt, -2.0 * damping * omega * dt, -dt
    augmented[:, 2, 3] = 1.0
    blocks = linalg.expm(augmented)
    impulse = np.zeros_like(accelerations)
    impulse[:, 0] = accelerations[:, 0]
    for block in blocks:
        step, first, second = block[:2, :2], block[:2, 2] - block[:2, 3], block[:2, 3]
        # u = first row of x; the recursion's z-transform with x_0 = 0 and a_0 given:
        # U(z) = [z − E22, E12]·((first + z·second) A(z) − z·second·a_0) / det(zI − E)
        denominator = [1.0, -np.trace(step), linalg.det(step)]
        numerator = [second[0], first[0] - step[1, 1] * second[0] + step[0, 1] * second[1],
                     -step[1, 1] * first[0] + step[0, 1] * first[1]]
        start = [second[0], -step[1, 1] * second[0] + step[0, 1] * second[1]]
        yield (signal.lfilter(numerator, denominator, accelerations, axis=-1)
               - signal.lfilter(start, denominator, impulse, axis=-1))


def pseudo_spectral_acceleration(acceleration, dt: float, period: float, damping: float = DEFAULT_DAMPING) -> float:
    """PSA = ω² max|u| [m/s²] of the oscillator of ``period`` T [s] and ``damping`` ξ under ``acceleration`` [m/s²].

    ``dt`` [s] is the record's time step; see :func:`relative_displacement`.
    """
    omega = 2.0 * np.pi / checked_positive(period, "oscillator period T [s]")
    return float(omega**2 * np.max(np.abs(relative_displacement(acceleration, dt, period, damping))))
