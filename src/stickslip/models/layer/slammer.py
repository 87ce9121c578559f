"""SLAMMER 1.1's decoupled and coupled analyses, step for step, to set SLAMMER's numbers beside ours.

The physics is in :mod:`stickslip.models.layer.layer`; this module re-implements
SLAMMER's arithmetic (``DeCoupledCommon.java``, ``Decoupled.java``,
``Coupled.java``, public domain), not the physics: where SLAMMER departs from
the exact solution of the piecewise-linear record, so does this.  Units are
SI here (SLAMMER works in cm); every quantity is per unit mass, since ρ cancels.
``a`` is the ground acceleration [m/s²] in the polarity analysed (the record,
or its sign flipped); a positive ``a`` drives the block downslope, and
``t = k_y·g`` is the yield acceleration [m/s²].

**The layer** (``d_response``): Newmark's average-acceleration method
(β = 1/4, γ = 1/2) in incremental form on ü + 2ξωu̇ + ω²u = −(L/M)·a, from
rest, with the record's first sample reached from a = 0 in one step; the
first step takes ü from the equation of motion, every later one from the
increment.  k(t)·g = a + (L/M_tot)·ü at each sample.

**The decoupled block** (``d_sliding``): a rigid block on the sliding surface
under k(t)·g, downslope only.  At rest at a sample where k·g > t it starts to
slide; over the next interval the relative velocity and displacement are the
exact integrals of the linearly varying k·g − t; the first sample at which the
velocity is no longer downslope stops the block, and that interval's
displacement is discarded (SLAMMER keeps the displacement of the sample before).

**The coupled block** (``Coupled``): the layer and the block move together
until the base shear exceeds the resistance, (a − (L/M_tot)·ü)·M_tot > t·M_tot
(checked after the sample's layer step); while the block slides, the layer
is driven by the constant resisting acceleration (its forcing increment is
zero) with the modal mass reduced by the coupling term,
(1 − L²/(M M_tot))·ü + 2ξωu̇ + ω²u = −(L/M)·(−t), and the block's relative
acceleration s̈ = a − t − (L/M_tot)·ü is integrated by the trapezoid rule.
When the relative velocity turns non-positive at a sample, the stop is placed
at the fraction dd = −ṡ₁/(ṡ₂ − ṡ₁) of the interval: the block's state is
re-integrated to it with s̈ at the interpolated record and the end-of-step ü,
and the layer is carried over the rest of the interval by a Newmark step in
accelerations (``slidestop``).

**Equivalent-linear soil** (``eq``): the layer's response is recomputed with
the properties of :func:`stickslip.models.layer.layer.equivalent_linear_properties`
until they settle (:data:`~stickslip.models.layer.layer.CONVERGENCE_PERCENT`); the
final response and both blocks use the last properties.  SLAMMER computes the
peak strain once per sample of the record (the same number each time, an
O(n²) cost); it is computed once here.

k_max, SLAMMER's "Kmax", is the largest |k| of the final decoupled response,
in g, for both analyses.

**A yield acceleration that varies with displacement**
(:class:`~stickslip.models.yield_table.YieldTable`, given here as the table
of t against s): after each sample the block's t for the next step becomes
t(s) at the displacement s just reached, linear between the table's pairs and
constant past the last, as SLAMMER's rigid block does (``RigidBlock.java``)
and as its help defines the table.  In the coupled analysis the layer's
forcing while the block slides then changes from −t of the last step to −t of
this one (zero for a constant t).  SLAMMER's own flexible analyses
(``residual_mu``) depart from that definition: they step to the k_y of the
next pair once the displacement has reached the current pair's displacement,
only at a sample where the block is stuck, and never interpolate; that rule is
not reproduced.  A constant t is a table of one pair.
"""

from __future__ import annotations

import functools
import sys

import numpy as np

from stickslip.solvers.compilation import compiled_kernels

from stickslip.models.layer.layer import (
    COUPLING,
    PARTICIPATION_OVER_MASS,
    PARTICIPATION_OVER_MODAL_MASS,
    circular_frequency,
    settled_properties,
)
from stickslip.models.yield_table import table_value

#: Newmark's average-acceleration parameters, as SLAMMER's ``beta`` and ``gamma``.
BETA, GAMMA = 0.25, 0.5


def layer_response(a, dt, omega, damping, participation, coupling_mass):
    """SLAMMER's ``d_response`` over the record: modal u [m], u̇ [m/s], ü [m/s²] and k·g [m/s²] at the samples.

    ``participation`` L/M, ``coupling_mass`` L/M_tot (module constants, passed for numba).
    """
    n = a.size
    u, velocity, acceleration, average = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    khat = omega * omega + 2.0 * damping * omega * GAMMA / (BETA * dt) + 1.0 / (BETA * dt * dt)
    a_coefficient = 1.0 / (BETA * dt) + 2.0 * damping * omega * GAMMA / BETA
    b_coefficient = 1.0 / (2.0 * BETA) + dt * 2.0 * damping * omega * (GAMMA / (2.0 * BETA) - 1.0)
    u1, v1, w1, previous = 0.0, 0.0, 0.0, 0.0
    for i in range(n):
        if i == 0:
            du = -participation * (a[0] - previous) / khat
            u2, v2 = du, GAMMA / (BETA * dt) * du
            w2 = -participation * a[0] - 2.0 * damping * omega * v2 - omega * omega * u2
        else:
            du = (-participation * (a[i] - previous) + a_coefficient * v1 + b_coefficient * w1) / khat
            dv = GAMMA / (BETA * dt) * du - GAMMA / BETA * v1 + dt * (1.0 - GAMMA / (2.0 * BETA)) * w1
            dw = 1.0 / (BETA * dt * dt) * du - 1.0 / (BETA * dt) * v1 - 0.5 / BETA * w1
            u2, v2, w2 = u1 + du, v1 + dv, w1 + dw
        u[i], velocity[i], acceleration[i] = u2, v2, w2
        average[i] = a[i] + coupling_mass * w2
        u1, v1, w1, previous = u2, v2, w2, a[i]
    return u, velocity, acceleration, average


def decoupled_sliding(average, dt, table_displacement, table_threshold):
    """SLAMMER's ``d_sliding``: the block's downslope displacement s [m] and velocity ṡ [m/s] (ṡ ≤ 0) at the samples.

    The yield acceleration t [m/s²] is the table (``table_displacement`` [m],
    ``table_threshold`` [m/s²]) at s, updated after each sample.
    """
    n = average.size
    s, sdot = np.zeros(n), np.zeros(n)
    threshold = table_threshold[0]
    slide = False
    for i in range(n):
        if i > 0:
            if slide:
                change = average[i] - average[i - 1]
                sdot[i] = sdot[i - 1] + (threshold - average[i - 1]) * dt - 0.5 * change * dt
                s[i] = (s[i - 1] - sdot[i - 1] * dt - 0.5 * dt * dt * (threshold - average[i - 1])
                        + change * dt * dt / 6.0)
            else:
                s[i] = s[i - 1]
        if not slide:
            if average[i] > threshold:
                slide = True
        elif sdot[i] >= 0.0:
            slide = False
            s[i] = s[i - 1] if i > 0 else 0.0
            sdot[i] = 0.0
        threshold = table_value(s[i], table_displacement, table_threshold)
    return s, sdot


def coupled_steps(a, dt, omega, damping, table_displacement, table_threshold, participation, coupling_mass, coupling):
    """SLAMMER's ``Coupled`` loop: block s [m], ṡ [m/s], and the layer's u [m], ü [m/s²] at the samples.

    The yield acceleration t [m/s²] is the table (``table_displacement`` [m],
    ``table_threshold`` [m/s²]) at s, updated after each sample;
    ``participation`` L/M, ``coupling_mass`` L/M_tot, ``coupling`` L²/(M M_tot).
    """
    n = a.size
    s_out, sdot_out, u_out, w_out = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    threshold = previous_threshold = table_threshold[0]
    slide = False
    u2 = v2 = w2 = 0.0
    s2 = sdot2 = sdotdot2 = 0.0
    for i in range(n):
        u1, v1, w1 = u2, v2, w2
        s1, sdot1, sdotdot1 = s2, sdot2, sdotdot2
        # the layer's forcing −(L/M)·load: the ground while stuck, the resisting acceleration while sliding
        if i == 0:
            load1, load2 = 0.0, -a[0]
        elif not slide:
            load1, load2 = -a[i - 1], -a[i]
        else:
            load1, load2 = -previous_threshold, -threshold
        mass = 1.0 - coupling if slide else 1.0
        khat = omega * omega + 2.0 * damping * omega * GAMMA / (BETA * dt) + mass / (BETA * dt * dt)
        a_coefficient = mass / (BETA * dt) + 2.0 * damping * omega * GAMMA / BETA
        b_coefficient = mass / (2.0 * BETA) + dt * 2.0 * damping * omega * (GAMMA / (2.0 * BETA) - 1.0)
        if i == 0:
            du = -participation * (load2 - load1) / khat
            u2, v2 = du, GAMMA / (BETA * dt) * du
        else:
            du = (-participation * (load2 - load1) + a_coefficient * v1 + b_coefficient * w1) / khat
            u2 = u1 + du
            v2 = v1 + GAMMA / (BETA * dt) * du - GAMMA / BETA * v1 + dt * (1.0 - GAMMA / (2.0 * BETA)) * w1
        w2 = (-participation * load2 - 2.0 * damping * omega * v2 - omega * omega * u2) / mass
        u_out[i] = u2
        w_out[i] = w2
        if slide:
            sdotdot2 = a[i] - threshold - coupling_mass * w2
            sdot2 = sdot1 + 0.5 * dt * (sdotdot2 + sdotdot1)
            s2 = s1 + 0.5 * dt * (sdot2 + sdot1)
        if not slide:
            if a[i] - coupling_mass * w2 > threshold:  # the base shear exceeds the resistance
                slide = True
        elif sdot2 <= 0.0:
            fraction = -sdot1 / (sdot2 - sdot1)
            if fraction != 0.0:  # SLAMMER's slidestop: the block to the stop, the layer stuck for the rest
                u1, v1, w1 = u2, v2, w2
                stop_load = a[i - 1] + fraction * (a[i] - a[i - 1])
                part = fraction * dt
                sdotdot2 = stop_load - threshold - coupling_mass * w2
                sdot2 = sdot1 + 0.5 * part * (sdotdot2 + sdotdot1)
                s2 = s1 + 0.5 * part * (sdot1 + sdot2)
                rest = (1.0 - fraction) * dt
                khat = 1.0 + 2.0 * damping * omega * GAMMA * rest + omega * omega * BETA * rest * rest
                a_coefficient = ((1.0 - coupling) + 2.0 * damping * omega * rest * (GAMMA - 1.0)
                                 + omega * omega * rest * rest * (BETA - 0.5))
                b_coefficient = omega * omega * rest
                w2 = (-participation * (-a[i] + threshold) + a_coefficient * w1 - b_coefficient * v1) / khat
                v2 = v1 + (1.0 - GAMMA) * rest * w1 + GAMMA * rest * w2
                u2 = u1 + v1 * rest + (0.5 - BETA) * rest * rest * w1 + BETA * rest * rest * w2
            slide = False
            sdot2 = 0.0
            sdotdot2 = 0.0
        s_out[i], sdot_out[i] = s2, sdot2
        previous_threshold = threshold
        threshold = table_value(s2, table_displacement, table_threshold)
    return s_out, sdot_out, u_out, w_out


@functools.cache
def _compiled():
    """The three loops compiled by numba (cached on disk), and :func:`table_value`, which two of them call."""
    return compiled_kernels(sys.modules[__name__],
                            ("table_value", "layer_response", "decoupled_sliding", "coupled_steps"), cache=True)


def response(a: np.ndarray, dt: float, vs: float, height: float, damping: float):
    """The layer's response (:func:`layer_response`, compiled) with V_s [m/s], H [m] and damping ξ [1]."""
    return _compiled()["layer_response"](a, dt, circular_frequency(vs, height), damping,
                                         PARTICIPATION_OVER_MODAL_MASS, PARTICIPATION_OVER_MASS)


def flexible_steps(coupled: bool, a: np.ndarray, dt: float, yield_thresholds, layer) -> dict:
    """SLAMMER's ``coupled`` or decoupled analysis of ``a`` [m/s²] (one polarity) at the yield acceleration t.

    ``yield_thresholds`` is (D_i [m], t_i [m/s²]), t against the block's
    downslope displacement (:meth:`~stickslip.models.yield_table.YieldTable.thresholds`;
    one pair for a constant t).

    Returns the settled ``vs`` [m/s] and ``damping`` [1], ``iterations``, the
    final layer response ``u`` [m], ``average_acceleration`` k·g [m/s²], its
    largest magnitude ``sample_peak`` [m/s²], and the block's ``displacement``
    s [m] and ``velocity`` [m/s] (s ≥ 0 downslope) at the samples.
    """
    a = np.ascontiguousarray(a, dtype=float)
    vs, damping, iterations = settled_properties(
        layer, lambda vs, damping: float(np.max(np.abs(response(a, dt, vs, layer.height, damping)[0]))))
    u, _, _, average = response(a, dt, vs, layer.height, damping)
    kernels = _compiled()
    omega = circular_frequency(vs, layer.height)
    table = tuple(np.array(column, dtype=float) for column in yield_thresholds)
    if not coupled:
        s, sdot = kernels["decoupled_sliding"](average, dt, *table)
        sdot = -sdot  # SLAMMER integrates the velocity negative downslope, the displacement positive
    else:
        s, sdot, u, _ = kernels["coupled_steps"](a, dt, omega, damping, *table, PARTICIPATION_OVER_MODAL_MASS,
                                                 PARTICIPATION_OVER_MASS, COUPLING)
    return {"vs": vs, "damping": damping, "iterations": iterations, "u": u, "average_acceleration": average,
            "sample_peak": float(np.max(np.abs(average))), "displacement": s, "velocity": sdot}
