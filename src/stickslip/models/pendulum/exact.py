"""The friction pendulum in one direction, Coulomb friction and a constant normal force: solved exactly.

A slider on a concave surface of radius R [m] (Zayas, Low and Mahin 1987),
per unit mass, relative to the ground, with a(t) the ground acceleration
[m/s²] linear between samples, at small angles: the restoring force is the
horizontal component N·u/R of the normal force with N = m·g, where the
spherical surface at u = R·sin θ gives N ≈ m·g/cos θ, and the friction's
projection and the slider's vertical acceleration on the bowl are left out
(docs/solvers.md, "The friction pendulum and the vertical motion"):

* **stick** (u̇ = 0) while the force that holds it, |a + ω²·u|, is at most
  μ·g, ω² = g/R: the ground acceleration stays inside the band
  [−ω²u − μg, −ω²u + μg], shifted by the displacement it sticks at;
* **slip** in the direction s = ±1 (u̇ ≷ 0): ü = −a(t) − ω²·u − s·μ·g;
* **breakaway** where a leaves the band, along the force; **stop** where u̇
  returns to zero, then stick or slide back.

R = ∞ (ω = 0) is the flat block of :mod:`stickslip.models.rigid.events`.  Each
slip is a linear oscillator under a linear force, solved in closed form per
sub-interval with its stops located to round-off, and breakaway is the linear
crossing of a band edge (:mod:`stickslip.solvers.restoring` derives it).

The ledger per unit mass, every term integrated on its own: E_df = μ·g·(path),
E_p = ½·ω²·u² (the slider's potential energy g·u²/(2R)), E_k = ½·(u̇_g + u̇)²,
W_v = 0 (N = m·g: no vertical), and E_I = ∫ü·u̇_g dt, closed in the same
functions.  E_k − E_k(0) + E_p − E_p(0) + E_df = E_I then closes to round-off.

This is a slider with Coulomb friction and a restoring stiffness ω² = g/R:
the model gives its parameters, and :mod:`stickslip.solvers.restoring` (its
phase functions on the event engine, :mod:`stickslip.solvers.events`) solves it.
"""

from __future__ import annotations

import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.models.pendulum.surface import surface_curvature
from stickslip.solvers.restoring import restoring_history, restoring_sweep


def pendulum_history(acceleration, dt: float, mu: float, radius: float, g: float = STANDARD_GRAVITY, *,
                     initial_displacement: float = 0.0, initial_velocity: float = 0.0) -> dict:
    """The exact history of a friction pendulum (Coulomb friction, N = m·g) under one horizontal component.

    Parameters
    ----------
    acceleration:
        Ground acceleration a [m/s²] at the samples, linear in between; a
        positive value drives the slider towards −u.
    dt:
        Sample interval [s].
    mu:
        Friction ratio μ [-].
    radius:
        Radius R of the sliding surface [m]; ``math.inf`` for a flat surface.
    g:
        Gravity [m/s²].
    initial_displacement, initial_velocity:
        u [m] and u̇ [m/s] relative to the ground at t = 0 (the ground starts at rest).

    Returns
    -------
    dict
        Per unit mass (:func:`~stickslip.solvers.ledger.history_dict`):
        ``time`` [s], ``ground_velocity`` [m/s], ``relative_displacement`` [m],
        ``relative_velocity`` [m/s], ``phase`` (0 stick, ±1 slip), the
        cumulative ``energy_dissipated`` E_df = μ·g·path, ``energy_input`` E_I,
        ``potential_energy`` E_p = ½·(g/R)·u², ``energy_input_vertical`` W_v = 0
        (the normal force is the weight), ``kinetic_energy`` E_k [J/kg],
        ``sliding_path`` [m], ``balance_residual`` [J/kg] and ``scalars``.
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    g = checked_positive(g, "gravity g [m/s2]")
    mu = checked_positive(mu, "friction ratio mu (--mu)")
    return restoring_history(acceleration, dt, mu * g, g * surface_curvature(radius), g, initial_displacement,
                             initial_velocity)


def pendulum_sweep(accelerations, dts, mu, radius, g: float = STANDARD_GRAVITY) -> np.ndarray:
    """End-of-record scalars of friction pendulums for every record and column (μ, R), in parallel.

    Parameters
    ----------
    accelerations:
        The records' ground accelerations [m/s²], a list of 1-D arrays.
    dts:
        Their sample intervals [s] (one number for all, or one per record).
    mu:
        Friction ratios μ [-], 1-D: one column each.
    radius:
        Radius R [m] of every column (one number) or of each (as long as ``mu``); ``math.inf`` is flat.
    g:
        Gravity [m/s²].

    Returns
    -------
    numpy.ndarray
        Shape (records, columns, len(SCALAR_NAMES)), per unit mass in the
        units of :data:`~stickslip.solvers.ledger.SCALAR_UNITS`.
    """
    g = checked_positive(g, "gravity g [m/s2]")
    records = [checked_acceleration(a, f"record {i}") for i, a in enumerate(accelerations)]
    if not records:
        raise StickslipError("pendulum sweep: no records given")
    dts = np.ascontiguousarray([checked_positive(dt, f"time step of record {i} [s]")
                                for i, dt in enumerate(np.broadcast_to(np.asarray(dts, dtype=float),
                                                                       (len(records),)))])
    mu = np.atleast_1d(np.asarray(mu, dtype=float))
    if mu.ndim != 1 or mu.size == 0:
        raise StickslipError(f"friction ratios mu: expected a non-empty 1-D array, got shape {mu.shape}")
    try:
        radii = np.broadcast_to(np.asarray(radius, dtype=float), mu.shape)
    except ValueError:
        raise StickslipError(f"--radius: expected one radius or {mu.size} (one per friction ratio)") from None
    columns = np.array([[checked_positive(m, "friction ratio mu (--mu)") * g, g * surface_curvature(r)]
                        for m, r in zip(mu, radii)])
    return restoring_sweep(records, dts, columns, g)
