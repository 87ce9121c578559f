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
−β/|β| otherwise.

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
from stickslip.solvers.dop853 import next_step
from stickslip.solvers.plane.interval import MAX_PASSES
from stickslip.solvers.plane.manifold import DENOMINATOR_MARGIN
from stickslip.solvers.plane.record import LOCK_RATIO, RTOL, SWITCH_RATIO, VELOCITY_FLOOR
from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem
from stickslip.solvers.structure.integrated_step import (
    A1, AIM1, FAST, FLIGHT, G1, K1, NORMAL, NORMAL_RATE, PATH, SEGMENT_SIZE, SETTLED, SLOW, STICK, STOPPING, VISCOUS,
    driving, driving_rate, evaluate, layout, step)
from stickslip.solvers.structure.slip_equation import SlipEquation

#: The interface slides off the slow manifold (its steps FAST or SLOW by the speed).
SLIDING = FAST
#: Newton iterations that bring a step onto an event.
_LANDING_ITERATIONS = 16
#: The largest step in σ times the slip's fastest rate there, μ_max·n + |β| (DOP853: stable to about 6 on the real
#: axis).
_SLOW_STABILITY = 4.5


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


class _Solver:
    """The event loop of one record: the state, its regimes, events and stops; the steps are kernels."""

    def __init__(self, structure: SlipEquation, friction, rtol, speed_scale, dt):
        self.structure = structure
        self.law, self.vectors, self.matrices = structure.kernel_arrays(*friction)
        self.mu_slow = friction[0]
        self.mu_max = max(friction[0], friction[1])
        self.rtol = rtol
        self.dt = dt
        self.s_switch = SWITCH_RATIO * speed_scale
        self.s_lock = LOCK_RATIO * speed_scale
        self.floor = VELOCITY_FLOOR * speed_scale
        n = structure.size
        self.n = n
        held, slip, tau, size = layout(n)
        self.X = slice(0, held)
        self.H = slice(held, slip)
        self.W = slice(slip, slip + 2)
        self.W1 = slip
        self.TAU = tau
        self.size = size
        self.y = np.zeros(size)
        self.work = np.zeros((14, size))
        self.motion = STICK
        self.steps = {STICK: dt, SETTLED: dt, FAST: dt, SLOW: 0.1 * dt / max(speed_scale, 1e-300), FLIGHT: dt,
                      STOPPING: dt}
        self.slip_time = 0.0
        self.flight_time = 0.0
        self.episodes = 0

    # ------------------------------------------------------------------ the state and its forces
    def _normal(self, seg, tau):
        return max(seg[NORMAL] + seg[NORMAL_RATE] * tau, 0.0)

    def _limit(self, seg, tau):
        """μ(0)·n [m/s²]: the radius of the friction circle per unit of the interface's effective mass."""
        return self.mu_slow * self.structure.mobility * self._normal(seg, tau)

    def _driving(self, y, seg):
        beta = np.empty(2)
        driving(y, seg, self.law, self.vectors, self.n, self._normal(seg, y[self.TAU]), beta)
        return beta

    def evaluate(self, y, regime, seg):
        """(dy/dt (dy/dσ in SLOW), ẍ_abs (n × 2) [m/s²], F (2) [N], w (2) [m/s]) at y in ``regime``."""
        f = np.empty(self.size)
        absolute = np.empty((self.n, 2))
        friction = np.empty(2)
        w = np.empty(2)
        evaluate(y, regime, seg, self.law, self.vectors, self.matrices, self.n, f, absolute, friction, w)
        return f, absolute, friction, w

    def rhs(self, y, regime, seg):
        return self.evaluate(y, regime, seg)[0]

    # ------------------------------------------------------------------ one step and events
    def step(self, y, f0, h, regime, seg):
        """One DOP853 step of size h (s, or σ in SLOW); returns (y_new, f_new, scaled error)."""
        y_new = np.empty(self.size)
        f_new = np.empty(self.size)
        error = step(y, f0, h, regime, seg, self.law, self.vectors, self.matrices, self.n, self.rtol, self.floor,
                     self.dt, self.work, y_new, f_new)
        return y_new, f_new, error

    def land(self, y, f, h, regime, seg, event, scale, y_new, f_new, error):
        """Bring a step of size h whose end passed the zero of ``event`` (a function of (y, f) giving its value and
        rate) onto it, by safeguarded Newton on h, to 1e-13 of ``scale``; returns (h, y_new, f_new, error)."""
        value, _ = event(y_new, f_new)
        sign = 1.0 if value > 0.0 else -1.0
        short, past = 0.0, h
        for _ in range(_LANDING_ITERATIONS):
            value, rate = event(y_new, f_new)
            if error > 1.0 or abs(value) <= 1e-13 * scale:
                break
            if sign * value > 0.0:
                past = h
            else:
                short = h
            landed = h - value / rate if rate != 0.0 else -1.0
            h = landed if short < landed < past else 0.5 * (short + past)
            y_new, f_new, error = self.step(y, f, h, regime, seg)
        return h, y_new, f_new, error

    # ------------------------------------------------------------------ stick and stops
    def _stick_margin(self, y, f, seg):
        """(|β| − μ(0)·n [m/s²], its rate [m/s³]) while the interface holds, at y with f = rhs(y, STICK)."""
        tau = y[self.TAU]
        beta = self._driving(y, seg)
        rate = np.empty(2)
        driving_rate(y, f, seg, self.law, self.vectors, self.n, rate)
        size = math.hypot(beta[0], beta[1])
        normal_rate = seg[NORMAL_RATE] if seg[NORMAL] + seg[NORMAL_RATE] * tau > 0.0 else 0.0
        along = (beta @ rate) / size if size > 0.0 else math.hypot(rate[0], rate[1])
        return size - self._limit(seg, tau), along - self.mu_slow * self.structure.mobility * normal_rate

    def _breaks_away(self, y, seg):
        """Whether the interface at rest at y breaks away: |β| beyond μ(0)·n, or on it to round-off and rising."""
        margin, rate = self._stick_margin(y, self.rhs(y, STICK, seg), seg)
        return margin > 0.0 or (margin > -1e-12 * max(self._limit(seg, y[self.TAU]), 1e-300) and rate > 0.0)

    def _after_stop(self, seg):
        """The interface at rest (w = 0): holds, or slides on along −β/|β| (SETTLED at s = 0: a slip that turns
        round without holding, which is no new episode)."""
        self.y[self.W] = 0.0
        if self._breaks_away(self.y, seg):
            return SETTLED
        return STICK

    def _stops_straight(self, seg):
        """Whether a slip below s_lock goes straight to its stop; if so, it slides on in STOPPING.

        Straight: it decelerates, and its acceleration across w, times the time to the stop at the present
        deceleration, is a velocity within rtol·(s + the velocity floor) (or s itself is within rtol·(the
        floor)): the direction is then held to the stop.  A slip that still turns goes on in σ, where its
        direction settles on −β/|β| as its speed falls (or it turns round without stopping).
        """
        y = self.y
        f, _, _, w = self.evaluate(y, FAST, seg)
        speed = math.hypot(w[0], w[1])
        acceleration = f[self.W]
        deceleration = -(acceleration @ w) / speed
        if deceleration <= 0.0:
            return False
        across = abs(acceleration[0] * w[1] - acceleration[1] * w[0]) / speed
        if across * speed / deceleration > self.rtol * (speed + self.floor) and speed > self.rtol * self.floor:
            return False
        y[self.W1] = speed
        y[self.W1 + 1] = 0.0
        seg[AIM1:AIM1 + 2] = w / speed
        self.motion = STOPPING
        return True

    def _stopping_step(self, seg, end):
        """One step of a straight slip to its stop, the stop located; back to SLIDING where it speeds up."""
        y = self.y
        start = y[self.TAU]
        speed = y[self.W1]
        f = self.rhs(y, STOPPING, seg)
        if f[self.W1] >= 0.0:
            self._to_sliding(seg)
            return
        h = min(self.steps[STOPPING], end - start, 1.0001 * speed / -f[self.W1])
        y_new, f_new, error = self.step(y, f, h, STOPPING, seg)
        stopped = error <= 1.0 and y_new[self.W1] < 0.0
        if stopped:
            h, y_new, f_new, error = self.land(y, f, h, STOPPING, seg, lambda yy, ff: (yy[self.W1], ff[self.W1]),
                                               self.s_switch, y_new, f_new, error)
        if error > 1.0:
            self.steps[STOPPING] = next_step(h, error)
            return
        if not stopped and h >= end - start:
            y_new[self.TAU] = end
        self.steps[STOPPING] = next_step(h, error)
        self.slip_time += y_new[self.TAU] - start
        self.y = y_new
        if stopped:
            self.motion = self._after_stop(seg)

    # ------------------------------------------------------------------ the events of one sample interval
    def advance_contact(self, seg, end):
        """Advance from y[TAU] to ``end`` [s] of the interval with the interface in contact (N > 0)."""
        passes = 0
        while self.y[self.TAU] < end:
            passes += 1
            if passes > MAX_PASSES:
                raise StickslipError(f"the integrated structure solver gave up at {self.y[self.TAU]:.6g} s into a "
                                     f"sample interval after {MAX_PASSES} passes")
            if self.motion == STICK:
                self._stick_step(seg, end)
            elif self.motion == SETTLED:
                self._settled_step(seg, end)
            elif self.motion == STOPPING:
                self._stopping_step(seg, end)
            else:
                self._sliding_step(seg, end)

    def _stick_step(self, seg, end):
        """One step with the interface held; a breakaway inside it is located."""
        y = self.y
        start = y[self.TAU]
        if self._breaks_away(y, seg):
            self.motion = SETTLED
            self.episodes += 1
            return
        f = self.rhs(y, STICK, seg)
        h = min(self.steps[STICK], end - start)
        y_new, f_new, error = self.step(y, f, h, STICK, seg)
        broke = False
        if error <= 1.0 and self._stick_margin(y_new, f_new, seg)[0] > 0.0:
            h, y_new, f_new, error = self.land(y, f, h, STICK, seg, lambda yy, ff: self._stick_margin(yy, ff, seg),
                                               self._limit(seg, start) + self.s_switch / self.dt, y_new, f_new,
                                               error)
            broke = True
        if error > 1.0:
            self.steps[STICK] = next_step(h, error)
            return
        if not broke and h >= end - start:
            y_new[self.TAU] = end
        self.steps[STICK] = next_step(h, error)
        self.y = y_new
        if broke:
            self.motion = SETTLED
            self.episodes += 1

    def _sliding_step(self, seg, end):
        """One step off the slow manifold: in time (FAST) or in σ (SLOW), or the closed-form stop below s_lock."""
        y = self.y
        start = y[self.TAU]
        speed = math.hypot(y[self.W1], y[self.W1 + 1])
        if speed < self.s_lock and self._stops_straight(seg):
            return
        regime = SLOW if speed < self.s_switch else FAST
        f = self.rhs(y, regime, seg)
        if regime == SLOW:
            # in σ the slip relaxes at rates up to μ_max·n + |β|: steps well inside DOP853's stability,
            # where a tolerance measured near the velocity floor would let them sit on its edge and never decay
            beta = self._driving(y, seg)
            fastest = self.mu_max * self.structure.mobility * self._normal(seg, start) + math.hypot(beta[0], beta[1])
            h = min(self.steps[SLOW], _SLOW_STABILITY / fastest)
        else:
            h = min(self.steps[regime], end - start)
        y_new, f_new, error = self.step(y, f, h, regime, seg)
        if y_new[self.W] @ y[self.W] <= 0.0:  # a step past the stop: shorter
            self.steps[regime] = 0.25 * h
            return
        if regime == SLOW and error <= 1.0 and y_new[self.TAU] > end:
            h, y_new, f_new, error = self.land(y, f, h, regime, seg, lambda yy, ff: (yy[self.TAU] - end, ff[self.TAU]),
                                               self.dt, y_new, f_new, error)
        if error > 1.0:
            self.steps[regime] = next_step(h, error)
            return
        if regime == SLOW:
            if end - y_new[self.TAU] <= 2e-13 * self.dt:
                y_new[self.TAU] = end
        elif h >= end - start:
            y_new[self.TAU] = end
        self.steps[regime] = next_step(h, error)
        self.slip_time += y_new[self.TAU] - start
        self.y = y_new

    def _settled_exit(self, seg):
        """The speed [m/s] up to which the slip stays on the slow manifold's zeroth order (0: leave now).

        The first-order angle φ₁·s, φ₁ = −Ω/D₁ (Ω [rad/s] the rate at which β turns with the slip held,
        D₁ = 2|β| − μ(0)·n), left out, times s, must stay within rtol·(s + the velocity floor); D₁ must keep
        its margin (:data:`~stickslip.solvers.plane.manifold.DENOMINATOR_MARGIN`).  At most s_switch.
        """
        y = self.y
        beta = self._driving(y, seg)
        rate = np.empty(2)
        driving_rate(y, self.rhs(y, STICK, seg), seg, self.law, self.vectors, self.n, rate)
        size2 = beta @ beta
        if size2 == 0.0:
            return 0.0
        limit = self._limit(seg, y[self.TAU])
        denominator = 2.0 * math.sqrt(size2) - limit
        if denominator <= 0.0 or denominator < DENOMINATOR_MARGIN * limit:
            return 0.0
        first = abs(beta[0] * rate[1] - beta[1] * rate[0]) / size2 / denominator  # |φ₁| [rad·s/m]
        if first == 0.0:
            return self.s_switch
        exit_speed = (self.rtol + math.sqrt(self.rtol ** 2 + 4.0 * first * self.rtol * self.floor)) / (2.0 * first)
        return min(exit_speed, self.s_switch)

    def _to_sliding(self, seg):
        """Turn the speed of a slip on the slow manifold (along −β/|β|) or of a straight one (along its angle) into
        the slip velocity (SLIDING), or hold where s = 0."""
        y = self.y
        speed = y[self.W1]
        if self.motion == STOPPING:
            aim = seg[AIM1:AIM1 + 2].copy()
        else:
            beta = self._driving(y, seg)
            size = math.hypot(beta[0], beta[1])
            aim = -beta / size if size > 0.0 else np.zeros(2)
        if speed <= 0.0 or not aim.any():
            self.motion = self._after_stop(seg)
            return
        y[self.W] = speed * aim
        self.motion = SLIDING

    def _settled_step(self, seg, end):
        """One step on the slow manifold's zeroth order: the speed along −β/|β| with the structure."""
        y = self.y
        start = y[self.TAU]
        speed = y[self.W1]
        exit_speed = self._settled_exit(seg)
        if speed == 0.0 and not self._driving(y, seg).any():
            # a breakaway where nothing drives the slip yet (no friction, and the structure at rest): held for
            # 1e-9·dt, β takes the direction the slip will have
            h = min(1e-9 * self.dt, end - start)
            y_new, _, _ = self.step(y, self.rhs(y, STICK, seg), h, STICK, seg)
            if h >= end - start:
                y_new[self.TAU] = end
            self.y = y_new
            return
        if speed >= exit_speed and not (speed == 0.0 and exit_speed > 0.0):
            self._to_sliding(seg)
            return
        f = self.rhs(y, SETTLED, seg)
        if speed == 0.0 and f[self.W1] <= 0.0 and self._stick_margin(y, self.rhs(y, STICK, seg), seg)[1] <= 0.0:
            self.motion = STICK
            return
        h = min(self.steps[SETTLED], end - start)
        if f[self.W1] < 0.0 and speed > 0.0:  # no further than the stop at the present deceleration
            h = min(h, 1.0001 * speed / -f[self.W1])
        y_new, f_new, error = self.step(y, f, h, SETTLED, seg)
        stopped = leave = False
        if error <= 1.0 and (y_new[self.W1] < 0.0 or y_new[self.W1] > exit_speed):
            target = 0.0 if y_new[self.W1] < 0.0 else exit_speed
            h, y_new, f_new, error = self.land(y, f, h, SETTLED, seg,
                                               lambda yy, ff: (yy[self.W1] - target, ff[self.W1]), self.s_switch,
                                               y_new, f_new, error)
            stopped = target == 0.0
            leave = not stopped
        if error > 1.0:
            self.steps[SETTLED] = next_step(h, error)
            return
        if not (stopped or leave) and h >= end - start:
            y_new[self.TAU] = end
        self.steps[SETTLED] = next_step(h, error)
        self.slip_time += y_new[self.TAU] - start
        self.y = y_new
        if stopped:
            self.y[self.W1] = 0.0
            self.motion = self._after_stop(seg)
        elif leave:
            self._to_sliding(seg)

    def fly(self, seg, end):
        """Advance from y[TAU] to ``end`` [s] with the interface off its surface (N ≤ 0): no force on it."""
        if self.motion in (SETTLED, STOPPING):
            self._to_sliding(seg)
        if self.motion == STICK:
            self.y[self.W] = 0.0
        self.motion = FLIGHT
        start = self.y[self.TAU]
        while self.y[self.TAU] < end:
            y = self.y
            h = min(self.steps[FLIGHT], end - y[self.TAU])
            y_new, _, error = self.step(y, self.rhs(y, FLIGHT, seg), h, FLIGHT, seg)
            if error > 1.0:
                self.steps[FLIGHT] = next_step(h, error)
                continue
            if h >= end - y[self.TAU]:
                y_new[self.TAU] = end
            self.steps[FLIGHT] = next_step(h, error)
            self.y = y_new
        self.flight_time += end - start

    def land_on_surface(self, seg):
        """The interface touches its surface again: slides on with its slip velocity, or holds where it has none."""
        w = self.y[self.W]
        self.motion = self._after_stop(seg) if w[0] == 0.0 and w[1] == 0.0 else SLIDING

    def advance_interval(self, seg):
        """Advance over one sample interval [0, dt] [s], lift-off and landing at N's root inside it."""
        self.y[self.TAU] = 0.0
        dt = self.dt
        start_normal = seg[NORMAL]
        end_normal = seg[NORMAL] + seg[NORMAL_RATE] * dt
        if start_normal > 0.0 and end_normal > 0.0:
            if self.motion == FLIGHT:
                self.land_on_surface(seg)
            self.advance_contact(seg, dt)
            return
        if start_normal <= 0.0 and end_normal <= 0.0:
            self.fly(seg, dt)
            return
        crossing = min(max(-start_normal / seg[NORMAL_RATE], 0.0), dt)
        if start_normal > 0.0:  # lifts off inside the interval
            if self.motion == FLIGHT:
                self.land_on_surface(seg)
            self.advance_contact(seg, crossing)
            self.fly(seg, dt)
            return
        self.fly(seg, crossing)  # lands inside the interval
        self.land_on_surface(seg)
        self.advance_contact(seg, dt)

    def sample(self, seg):
        """(x, ẋ (n × 2), ẍ_abs (n × 2), F (2), N, moving) at the state, y[TAU] in ``seg``."""
        _, absolute, friction, w = self.evaluate(self.y, self.motion, seg)
        x = self.y[self.X].reshape(self.n, 2)
        held = self.y[self.H].reshape(self.n, 2)
        normal = 0.0 if self.motion == FLIGHT else self._normal(seg, self.y[self.TAU])
        return (x.copy(), self.structure.velocity(held, w), absolute, friction, normal,
                0.0 if self.motion == STICK else 1.0)


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
    solver = _Solver(structure, friction, rtol, speed_scale, dt)
    n = structure.size
    displacement = np.zeros((samples, n, 2))
    velocity = np.zeros((samples, n, 2))
    absolute = np.zeros((samples, n, 2))
    friction = np.zeros((samples, 2))
    normal_history = np.zeros(samples)
    moving = np.zeros(samples)
    totals = np.zeros((samples, 5))  # E_ζ, E_df, E_I, W_v, path
    slope = np.diff(acceleration, axis=0) / dt
    normal_slope = np.diff(normal) / dt
    segment = np.zeros(SEGMENT_SIZE)
    for i in range(samples - 1):
        segment[A1:A1 + 2] = acceleration[i]
        segment[K1:K1 + 2] = slope[i]
        segment[NORMAL] = normal[i]
        segment[NORMAL_RATE] = normal_slope[i]
        segment[G1:G1 + 2] = ground_velocity[i]
        if i == 0:
            (displacement[0], velocity[0], absolute[0], friction[0], normal_history[0],
             moving[0]) = solver.sample(segment)
        solver.advance_interval(segment)
        (displacement[i + 1], velocity[i + 1], absolute[i + 1], friction[i + 1], normal_history[i + 1],
         moving[i + 1]) = solver.sample(segment)
        totals[i + 1] = solver.y[solver.TAU + VISCOUS:solver.TAU + PATH + 1]
    viscous, dissipated, inputs, vertical_work, path = totals.T
    slip = np.einsum("i,kij->kj", structure.direction, displacement)
    kinetic = 0.5 * np.einsum("kij,i->k", (velocity + ground_velocity[:, None, :]) ** 2, structure.masses)
    strain = 0.5 * np.einsum("kij,il,klj->k", displacement, structure.stiffness, displacement)
    potential = 0.5 * structure.normal_force * structure.inverse_radius * np.sum(slip ** 2, axis=1)
    residual = kinetic - kinetic[0] + strain + viscous + potential + dissipated - inputs - vertical_work
    interface_force = (normal_history * structure.inverse_radius)[:, None] * slip + friction
    return PlaneStructureHistory(displacement, velocity, absolute, slip, friction, interface_force, normal_history,
                                 moving, kinetic, strain, viscous, potential, dissipated, inputs, vertical_work,
                                 residual, path, solver.slip_time, solver.flight_time, solver.episodes,
                                 float(np.max(np.hypot(slip[:, 0], slip[:, 1]))))
