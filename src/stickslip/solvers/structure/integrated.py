"""The friction-linked structure in the plane, with the vertical and μ(v): integrated to a tolerance, events located.

The structure and its interface are :mod:`~stickslip.solvers.structure.friction_linked`'s,
in both horizontal directions, the slip's equation :mod:`~stickslip.solvers.structure.slip_equation`'s:
n degrees of freedom per horizontal direction, one friction interface whose
slip s ∈ ℝ² is held while the force needed to hold it stays inside the
friction circle |F| ≤ μ(0)·N and slides against F = μ(|w|)·N·w/|w| otherwise,
the curved surface's restoring force (N/R)·s, the normal force
N(t) = N₀·(1 + a_v(t)/g) and, where N ≤ 0, flight (the interface carries no
force: the slip moves freely).  The ground accelerations are linear between
samples.

Between events nothing has a closed form: the state is integrated with the
Dormand–Prince 8(5,3) pair (:mod:`stickslip.solvers.dop853`) to the relative
tolerance ``rtol`` on the velocities, in the regimes of the slip's speed
s = |w| that the block in the plane uses (:mod:`stickslip.solvers.plane`), with
the speed scale S = 2·(max|a| + μ·max n)·dt (n = μ̃·N, μ̃ the interface's
inverse effective mass):

* **stick** (w = 0): the structure with the interface held, in time; the
  breakaway, where |β| rises past μ(0)·n, is located by Newton's method on the
  step;
* **settled** (just after a breakaway, below the speed where the slow manifold's
  zeroth order stops holding): the slip points along −β/|β| (the slow manifold
  of the direction, :mod:`stickslip.solvers.plane.manifold`, to order zero) and
  only its speed is integrated with the structure; the slip leaves the manifold
  where the first-order angle φ₁·s, φ₁ = −Ω/D₁ (Ω the rate at which β turns,
  D₁ = 2|β| − μ(0)·n), times s, would exceed rtol·(s + the velocity floor), or
  where D₁ falls below its margin; a stop (s = 0) on it is located;
* **slow** (s < s_switch = :data:`~stickslip.solvers.plane.record.SWITCH_RATIO`·S off
  the manifold): the independent variable is σ with dt = s·dσ (a Sundman
  transformation), in which the slip's direction relaxes at a finite rate; a
  step past a sample is brought onto it;
* **stopping** (s < s_lock = :data:`~stickslip.solvers.plane.record.LOCK_RATIO`·S,
  decelerating, straight: the acceleration across the slip, times the time
  to the stop, within rtol·(s + the velocity floor)): the last of the slip
  with its direction held, in time, the stop located; a slip that still turns
  goes on in σ;
* **fast** (s ≥ s_switch): in time, steps ending on the samples;
* **flight** (N ≤ 0): the structure with a free interface, in time; lift-off and
  landing at the root of the linear N in the sample interval.

At a stop the interface holds if |β| ≤ μ(0)·n and breaks away again along
−β/|β| otherwise.  The event loop over the record is compiled
(:mod:`~stickslip.solvers.structure.integrated_events`), its steps the kernels
of :mod:`~stickslip.solvers.structure.integrated_step`.

The ledger [J], each term a quadrature of its own so that its closure checks the
integration: E_k − E_k(0) + E_s + E_ζ + E_p + E_df = E_I + W_v with
E_k = ½·Σ m_i·|u̇_g + ẋ_i|², E_s = ½·Σ xᵀK x (both directions), E_ζ = ∫ẋᵀC ẋ dt,
E_p = N₀·|s|²/(2R), E_df = ∫μ·N·|w| dt, E_I = ∫(Σ m_i·ü_i,abs)·u̇_g dt and the
work of the vertical motion through the normal force on the curved surface
W_v = −∫((N − N₀)/R)·s·w dt (N = 0 in flight), docs/definitions.md's
``energy_input_vertical``.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.records.process import integrate_linear_acceleration
from stickslip.solvers.plane.interval import MAX_PASSES
from stickslip.solvers.plane.record import LOCK_RATIO, RTOL, SWITCH_RATIO, VELOCITY_FLOOR
from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem
from stickslip.solvers.structure.integrated_events import EPISODES, FLIGHT_TIME, SLIP_TIME, solve_record
from stickslip.solvers.structure.integrated_step import A1, G1, K1, NORMAL, NORMAL_RATE, SEGMENT_SIZE
from stickslip.solvers.structure.slip_equation import SlipEquation


class PlaneStructureHistory(NamedTuple):
    """The response at every sample, the state just after it: arrays (samples, n, 2), (samples, 2) or
    (samples,), the last axis the two horizontal directions; energies in J.  The names are
    :class:`~stickslip.solvers.structure.friction_linked.FrictionLinkedHistory`'s."""

    displacement: np.ndarray
    """x [m], relative to the ground."""
    velocity: np.ndarray
    """ẋ [m/s], relative to the ground."""
    absolute_acceleration: np.ndarray
    """ẍ + ι a [m/s²]."""
    slip: np.ndarray
    """s = dᵀx [m], (samples, 2)."""
    friction_force: np.ndarray
    """F [N], (samples, 2): μ(|w|)·N·w/|w| sliding, the force the hold needs holding, 0 in flight."""
    interface_force: np.ndarray
    """Q = (N/R)·s + F [N], (samples, 2), the interface's whole force."""
    normal_force: np.ndarray
    """N [N], (samples,): N₀·(1 + a_v/g), 0 where that is not positive (flight)."""
    moving: np.ndarray
    """1 while the interface slips or flies, 0 while it holds, (samples,)."""
    kinetic_energy: np.ndarray
    strain_energy: np.ndarray
    viscous_energy: np.ndarray
    potential_energy: np.ndarray
    """N₀·|s|²/(2R) [J]."""
    energy_dissipated: np.ndarray
    energy_input: np.ndarray
    """E_I [J], through the horizontal ground motion."""
    energy_input_vertical: np.ndarray
    """W_v [J], the vertical motion's work through the normal force on the curved surface."""
    balance_residual: np.ndarray
    """E_k − E_k(0) + E_s + E_ζ + E_p + E_df − E_I − W_v [J]."""
    sliding_path: np.ndarray
    """∫|w| dt [m], cumulative."""
    slip_time: float
    """Time spent slipping [s], flight apart."""
    flight_time: float
    """Time with N ≤ 0 [s]."""
    n_slip_episodes: int
    """Hold-to-slip transitions."""
    peak_slip: float
    """max |s| [m] over the samples."""


def _checked_law(mu_slow, mu_fast, rate) -> tuple[float, float, float]:
    """The friction law's (μ_slow, μ_fast, rate), each a finite number ≥ 0; else one line naming it."""
    law = []
    for name, value in (("mu_slow", mu_slow), ("mu_fast", mu_fast), ("rate [s/m]", rate)):
        try:
            number = float(value)
        except (TypeError, ValueError):
            number = math.nan
        if not (math.isfinite(number) and number >= 0.0):
            raise StickslipError(f"friction law {name} must be a finite number >= 0, got {value!r}")
        law.append(number)
    return law[0], law[1], law[2]


def solve_structure_in_plane(system: FrictionLinkedSystem, first, second, dt: float, *, vertical=None,
                             gravity: float = STANDARD_GRAVITY, mu_slow: float, mu_fast: float | None = None,
                             rate: float = 0.0, rtol: float = RTOL) -> PlaneStructureHistory:
    """The response of ``system`` in the plane, at rest at t = 0, to a record pair and its vertical.

    Parameters
    ----------
    system:
        The structure and its interface; its ``normal_force`` is N₀ [N], the normal force with no vertical motion.
    first, second:
        The horizontal ground acceleration on two orthogonal axes at the samples [m/s²].
    dt:
        The sample interval [s].
    vertical:
        The vertical ground acceleration at the samples [m/s², positive up], or None: the normal force is
        N = N₀·(1 + a_v/g).
    gravity:
        g [m/s²].
    mu_slow, mu_fast, rate:
        The friction law μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} [1, 1, s/m] of the slip speed s;
        Coulomb's μ = ``mu_slow`` where ``mu_fast`` is None.
    rtol:
        The relative tolerance of the velocities per step.
    """
    first = checked_acceleration(first, "first horizontal acceleration")
    second = checked_acceleration(second, "second horizontal acceleration")
    samples = first.size
    if second.size != samples or (vertical is not None and np.size(vertical) != samples):
        raise StickslipError(f"the components must have as many samples as the first ({samples})")
    dt = checked_positive(dt, "time step dt [s]")
    gravity = checked_positive(gravity, "g [m/s²]")
    friction = _checked_law(mu_slow, mu_slow if mu_fast is None else mu_fast, rate)
    mu_slow, mu_fast, rate = friction
    ratio = np.ones(samples) if vertical is None else 1.0 + checked_acceleration(vertical, "vertical acceleration") \
        / gravity
    structure = SlipEquation(system)
    normal = structure.normal_force * ratio
    acceleration = np.stack([first, second], axis=1)
    ground_velocity = np.stack([integrate_linear_acceleration(first, dt)[0],
                                integrate_linear_acceleration(second, dt)[0]], axis=1)
    peak_friction = max(mu_slow, mu_fast) * structure.mobility * max(float(np.max(normal)), 0.0)
    speed_scale = 2.0 * (float(np.max(np.hypot(first, second))) + peak_friction) * dt
    law, vectors, matrices = structure.kernel_arrays(*friction)
    setting = np.array([rtol, VELOCITY_FLOOR * speed_scale, dt, SWITCH_RATIO * speed_scale, LOCK_RATIO * speed_scale,
                        speed_scale])
    segments = np.zeros((samples - 1, SEGMENT_SIZE))
    segments[:, A1:A1 + 2] = acceleration[:-1]
    segments[:, K1:K1 + 2] = np.diff(acceleration, axis=0) / dt
    segments[:, NORMAL] = normal[:-1]
    segments[:, NORMAL_RATE] = np.diff(normal) / dt
    segments[:, G1:G1 + 2] = ground_velocity[:-1]
    n = structure.size
    displacement = np.zeros((samples, n, 2))
    velocity = np.zeros((samples, n, 2))
    absolute = np.zeros((samples, n, 2))
    friction = np.zeros((samples, 2))
    normal_history = np.zeros(samples)
    moving = np.zeros(samples)
    totals = np.zeros((samples, 5))  # E_ζ, E_df, E_I, W_v, path
    times = np.zeros(2)
    counts = np.zeros(2, dtype=np.int64)
    interval, into = solve_record(segments, law, vectors, matrices, setting, displacement, velocity, absolute,
                                  friction, normal_history, moving, totals, times, counts)
    if interval >= 0:
        raise StickslipError(f"the integrated structure solver gave up at {into:.6g} s into a sample interval "
                             f"(the one from {interval * dt:.6g} s) after {MAX_PASSES} passes")
    viscous, dissipated, inputs, vertical_work, path = totals.T
    slip = np.einsum("i,kij->kj", structure.direction, displacement)
    kinetic = 0.5 * np.einsum("kij,i->k", (velocity + ground_velocity[:, None, :]) ** 2, structure.masses)
    strain = 0.5 * np.einsum("kij,il,klj->k", displacement, structure.stiffness, displacement)
    potential = 0.5 * structure.normal_force * structure.inverse_radius * np.sum(slip ** 2, axis=1)
    residual = kinetic - kinetic[0] + strain + viscous + potential + dissipated - inputs - vertical_work
    interface_force = (normal_history * structure.inverse_radius)[:, None] * slip + friction
    return PlaneStructureHistory(displacement, velocity, absolute, slip, friction, interface_force, normal_history,
                                 moving, kinetic, strain, viscous, potential, dissipated, inputs, vertical_work,
                                 residual, path, float(times[SLIP_TIME]), float(times[FLIGHT_TIME]),
                                 int(counts[EPISODES]), float(np.max(np.hypot(slip[:, 0], slip[:, 1]))))
