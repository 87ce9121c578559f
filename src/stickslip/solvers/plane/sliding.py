"""The fast and slow regimes: the equations of a slip off the slow manifold, in time or in the Sundman variable.

Per unit mass, relative to the ground, the block slides with
v̇ = −b − μ(|v|)·n·v/|v| (:mod:`~stickslip.solvers.plane.resistance`).  Fast
(s ≥ s_switch) the time t is the independent variable; slow (below s_switch,
off the manifold) it is σ with dt = s·dσ (a Sundman transformation):
dv/dσ = −s·b − μ·n·v, every right-hand side polynomial in v and s, and s decays
towards zero without reaching it.  The ledger's rates come with the motion's:
E_df/m = ∫μ·n·s dt, W_v/m = −∫κ·(n − g)·u·v dt, E_I/m = ∫ü·u̇_g dt.
"""

from __future__ import annotations

import math

import numba

from stickslip.solvers.plane.resistance import friction_coefficient
from stickslip.solvers.plane.state import DISSIPATED, INPUT, PATH, TAU, U1, U2, V1, V2, VERTICAL


@numba.njit(cache=True, error_model="numpy", _nrt=False, inline="always")
def rhs_sliding(y, slow, a1, a2, k1, k2, n0, nu, g1, g2, gravity, curvature, mu_slow, mu_fast, rate, out, row):
    """The right-hand side d y/dt (``slow`` false) or d y/dσ = s·d y/dt (``slow`` true) of a slip off the manifold.

    The interval's data as scalars (:data:`~stickslip.solvers.plane.state.A1` ... of the segment, κ and the
    friction law), so that the compiler keeps them in registers; the result
    goes into ``out[row]`` (no view of ``out`` is made: views cost reference
    counting).
    """
    tau = y[TAU]
    normal = n0 + nu * tau
    gx = g1 + tau * (a1 + 0.5 * k1 * tau)
    gy = g2 + tau * (a2 + 0.5 * k2 * tau)
    stiffness = curvature * normal
    rx = stiffness * y[U1]  # the restoring force per unit mass is −(rx, ry)
    ry = stiffness * y[U2]
    bx = a1 + k1 * tau + rx
    by = a2 + k2 * tau + ry
    vx = y[V1]
    vy = y[V2]
    s = math.sqrt(vx * vx + vy * vy)
    m = friction_coefficient(s, mu_slow, mu_fast, rate) * normal
    excess = -curvature * (normal - gravity)  # W_v's rate is excess·u·v
    if slow:
        out[row, V1] = -s * bx - m * vx
        out[row, V2] = -s * by - m * vy
        out[row, TAU] = s
        out[row, U1] = s * vx
        out[row, U2] = s * vy
        out[row, PATH] = s * s
        out[row, DISSIPATED] = m * s * s
        out[row, VERTICAL] = s * excess * (y[U1] * vx + y[U2] * vy)
        out[row, INPUT] = -(s * (rx * gx + ry * gy) + m * (vx * gx + vy * gy))
    else:
        f = m / s
        out[row, V1] = -bx - f * vx
        out[row, V2] = -by - f * vy
        out[row, TAU] = 1.0
        out[row, U1] = vx
        out[row, U2] = vy
        out[row, PATH] = s
        out[row, DISSIPATED] = m * s
        out[row, VERTICAL] = excess * (y[U1] * vx + y[U2] * vy)
        out[row, INPUT] = -((rx + f * vx) * gx + (ry + f * vy) * gy)
