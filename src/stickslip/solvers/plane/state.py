"""The arrays the plane's kernels pass one another: the state of a slip, one sample interval, the regimes and motions.

Plain indices into plain arrays (numba's kernels take no objects): a slip's
state ``y`` (:data:`N_STATE` floats), a sample interval's data ``segment``
(:data:`SEGMENT_SIZE` floats, filled per interval by
:mod:`~stickslip.solvers.plane.record`), which regime of the speed a step is
taken in and what the block does at the end of a pass.
"""

from __future__ import annotations

#: The state of a slip (indices): v₁, v₂ [m/s], τ [s] from the interval's start, u₁, u₂ [m], path [m],
#: E_I/m, E_df/m, W_v/m [J/kg].
V1, V2, TAU, U1, U2, PATH, INPUT, DISSIPATED, VERTICAL = range(9)
N_STATE = 9
#: The states that enter the right-hand side (v, τ, u), formed at every stage; the others are quadratures.
N_DYNAMIC = 5
#: One sample interval (indices into the ``segment`` array): a [m/s²] and its slope [m/s³] at the interval's start,
#: the normal force per unit mass n = g + a_v [m/s²] and its slope [m/s³], the ground velocity [m/s], g [m/s²].
A1, A2, K1, K2, NORMAL, NORMAL_RATE, G1, G2, GRAVITY = range(9)
SEGMENT_SIZE = 9
#: The regimes of the speed (:mod:`stickslip.solvers.plane`): which right-hand side
#: :func:`~stickslip.solvers.plane.stepping.rhs` evaluates.
FAST, SLOW, SETTLED = 0, 1, 2
#: What the block does: sticks, slides, slides on the slow manifold of its direction, or flies (n ≤ 0); STALLED:
#: the solver gave up in a sample interval (:data:`~stickslip.solvers.plane.interval.MAX_PASSES`).
STICK, SLIDING, SETTLED_SLIDING, FLIGHT, STALLED = 0, 1, 2, 3, 4
