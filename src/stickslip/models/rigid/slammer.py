"""SLAMMER's rigid-block scheme, step for step, to set SLAMMER's number beside the exact one.

The USGS program SLAMMER 1.1 (``RigidBlock.java``, public domain) integrates
Newmark's rigid block sample by sample.  This module re-implements that
scheme, not the physics: where SLAMMER's arithmetic departs from the exact
solution of the piecewise-linear record, so does this.  In SLAMMER's own frame
(u > 0 downslope, so u = −x here; e = a − b the ground acceleration less the
body acceleration, which is SLAMMER's "a + g·sin β" of the two-way case;
t the threshold, k_y·g one-way and k_y·g + g·sin β two-way), at every sample:

1. the sliding direction n: if the block is stuck (|v| below a tiny speed,
   1e-15 cm/s in SLAMMER), n = sgn(e) when |e| > t, else n = e/t (so that the
   relative acceleration below is zero up to round-off); while it slides,
   n = sgn(v), with sgn(0) = +1;
2. the relative acceleration y = e − n·t, and the trapezoid rule over one
   sample interval: v = v_prev + dt·(y + y_prev)/2;
3. the velocity reset: one-way, v ≤ 0 sets v = y = 0 (the block never slides
   upslope); two-way, a velocity that changed sign since the last sample
   (v/v_prev ≤ 0, v_prev not tiny) sets v = y = 0;
4. the displacement u = u_prev + dt·(v + v_prev)/2, also on the step whose
   velocity was just reset (it adds dt·v_prev/2).

A sample whose e is exactly zero is skipped altogether in normal polarity
(SLAMMER tests ``a == 0.0 && mult > 0``): the state is not updated and the
next sample is integrated from the last non-zero one, as if the zero sample
were not there.  In inverse polarity SLAMMER's multiplier is negative and zero
samples are integrated like any other; :func:`stickslip.solve` passes
``skip_zero_samples=False`` when asked for the inverse polarity.

The one-way block's threshold may vary with the displacement (a
:class:`~stickslip.models.yield_table.YieldTable`): as in ``RigidBlock.java``,
after each sample the threshold for the next step becomes t = k_y(u)·g at the
displacement u just reached, linear between the table's pairs and constant
past the last; a constant k_y is a table of one pair.  SLAMMER's g is 9.80665 m/s² and its scaling to a target PGA divides
by the PGA of its database, rounded to 0.001 g; here g is the caller's and
the record is used as given.

Energies (per unit mass, for comparison only; SLAMMER keeps none): E_df = ∫t dp
over the path p of the sampled u (t·p for a constant threshold, the one of
either case; one-way, p is the downslope displacement of the table), and E_I by the
trapezoid rule of ü·u̇_g at the samples, ü = a + ẍ; the balance closes only to
the scheme's accuracy.
"""

from __future__ import annotations

import functools
import math
import sys

import numpy as np

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.errors import StickslipError
from stickslip.solvers.compilation import compiled_kernels
from stickslip.records.process import integrate_linear_acceleration
from stickslip.models.rigid.events import PYTHON_SAMPLES
from stickslip.models.rigid.history import SolverHistory
from stickslip.models.rigid.resistance import Resistance
from stickslip.models.yield_table import table_value

#: SLAMMER's standard gravity [m/s²] (its Gcmss = 980.665 cm/s²).
SLAMMER_GRAVITY = 9.80665

#: The speed [m/s] below which SLAMMER takes the block as stuck (1e-15 cm/s in its units).
STUCK_SPEED = 1e-17


def rigid_block_steps(acceleration, dt, table_displacement, table_threshold, body, one_way, skip_zero_samples):
    """SLAMMER's sample-by-sample rigid block; see the module docstring.

    ``acceleration`` [m/s²] (a list of floats as Python, an array when
    compiled), ``dt`` [s], the threshold t [m/s²] as a table against SLAMMER's u
    (``table_displacement`` [m], ``table_threshold`` [m/s²]; one pair for a
    constant t), ``body`` b [m/s²].  Returns arrays of SLAMMER's u [m], v [m/s]
    and y [m/s²] at the samples (u and v positive downslope, towards −x).
    """
    threshold = table_threshold[0]
    n = len(acceleration)
    displacement = np.zeros(n)
    velocity = np.zeros(n)
    relative_acceleration = np.zeros(n)
    u_prev, v_prev, y_prev = 0.0, 0.0, 0.0
    for i in range(n):
        e = acceleration[i] - body
        if e == 0.0 and skip_zero_samples:
            displacement[i], velocity[i], relative_acceleration[i] = u_prev, v_prev, y_prev
            continue
        if abs(v_prev) < STUCK_SPEED:
            if abs(e) > threshold:
                direction = 1.0 if e >= 0.0 else -1.0
            else:
                direction = e / threshold
        else:
            direction = 1.0 if v_prev >= 0.0 else -1.0
        y = e - direction * threshold
        v = v_prev + dt / 2.0 * (y + y_prev)
        if one_way:
            reset = v <= 0.0
        else:
            reset = not (abs(v_prev) < STUCK_SPEED or v / v_prev > 0.0)
        if reset:
            v = 0.0
            y = 0.0
        u = u_prev + dt / 2.0 * (v + v_prev)
        displacement[i], velocity[i], relative_acceleration[i] = u, v, y
        u_prev, v_prev, y_prev = u, v, y
        threshold = table_value(u, table_displacement, table_threshold)
    return displacement, velocity, relative_acceleration


@functools.cache
def _compiled_steps():
    """:func:`rigid_block_steps` compiled by numba (imported only for a record too long for Python)."""
    return compiled_kernels(sys.modules[__name__], ("table_value", "rigid_block_steps"), cache=True)["rigid_block_steps"]


def sliding_history(
    acceleration: np.ndarray, dt: float, resistance: Resistance, *, skip_zero_samples: bool = True
) -> SolverHistory:
    """SLAMMER's rigid-block scheme for one record and one :class:`Resistance`.

    Parameters
    ----------
    acceleration:
        Ground acceleration [m/s²] at the samples; a positive value drives the
        block downslope (towards −x).
    dt:
        Sample interval [s].
    resistance:
        One-way (:meth:`Resistance.one_way`, SLAMMER's rigid block, with a
        constant k_y or a :class:`~stickslip.models.yield_table.YieldTable`) or with
        equal thresholds both ways (:meth:`Resistance.two_way`, SLAMMER's
        "downslope and upslope" at a thrust angle; a flat :meth:`Resistance.friction`
        is its thrust angle 0).
    skip_zero_samples:
        Skip samples where a − b is exactly zero, as SLAMMER does in normal
        polarity (True) but not in inverse polarity (False).

    Returns
    -------
    SolverHistory
        Per unit mass at the samples, x = −u, ẋ = −v, ẍ = −y; phase −sgn(v)
        where |v| ≥ :data:`STUCK_SPEED`, else 0.  The sliding time counts the
        sample intervals with the block sliding at either end, an episode
        starts at each sample where it starts to slide.
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    one_way = resistance.positive == math.inf
    if not (one_way or resistance.positive == resistance.negative):
        raise StickslipError(
            f"the slammer scheme takes SLAMMER's cases only, one-way or with equal thresholds both ways; "
            f"got {resistance.describe()}"
        )
    table = resistance.downslope_thresholds()
    flags = (resistance.body, one_way, bool(skip_zero_samples))
    if acceleration.size <= PYTHON_SAMPLES:
        u, v, y = rigid_block_steps(acceleration.tolist(), dt, *table, *flags)
    else:
        u, v, y = _compiled_steps()(acceleration, dt, *(np.array(column) for column in table), *flags)
    ground_velocity, ground_displacement = integrate_linear_acceleration(acceleration, dt)
    steps = np.abs(np.diff(u, prepend=0.0))
    path = np.cumsum(steps)
    power = (acceleration - y) * ground_velocity  # ü·u̇_g, ü = a + ẍ = a − y
    energy_input = np.concatenate(([0.0], np.cumsum(0.5 * dt * (power[1:] + power[:-1]))))
    moving = np.abs(v) >= STUCK_SPEED  # as SLAMMER tells a stuck block from a sliding one
    sliding_intervals = moving[1:] | moving[:-1]
    outputs = (
        -u, -v, -y, np.where(moving, -np.sign(v), 0.0).astype(np.int8), resistance.downslope_work(path), energy_input,
        float(path[-1]), float(np.count_nonzero(sliding_intervals) * dt),
        int(np.count_nonzero(moving[1:] & ~moving[:-1]) + moving[0]), float(np.max(np.abs(u))),
    )
    return SolverHistory.from_kernel_outputs(np.arange(acceleration.size) * dt, acceleration.copy(),
                                             ground_velocity, ground_displacement, outputs)
