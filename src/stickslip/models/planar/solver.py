"""What the flat block gives the plane solver (:mod:`stickslip.solvers.plane`): μ·g, nothing else.

On a flat surface (κ = 0) under Coulomb friction and no vertical motion only
the product μ·n enters the slip, so the block is solved with n = 1 and
μ = μ·g [m/s²]: :func:`~stickslip.solvers.plane.solve_pair_on_surface` with
the first nine end results (:data:`~stickslip.solvers.plane.PLANAR_SCALAR_NAMES`)
and the first eight columns of the history
(:data:`~stickslip.solvers.plane.HISTORY_NAMES`), per unit mass.
"""

from __future__ import annotations

import numpy as np

from stickslip.solvers import plane

#: No vertical motion: the normal force per unit mass is n = 1 throughout.
_NO_VERTICAL = np.zeros(0)


def solve_pair(ax, ay, dt, mug, rtol, lock_ratio, history, out):
    """Solve one record pair (a₁, a₂ [m/s²] at the samples, interval dt [s]) at μ·g = ``mug`` [m/s²].

    ``out`` receives the scalars of :data:`~stickslip.solvers.plane.PLANAR_SCALAR_NAMES`;
    ``history``, of shape (n, 8) or (0, 8), the state just after each sample:
    x₁, x₂ [m], v₁, v₂ [m/s], sliding (1) or not (0), E_df/m, E_I/m [J/kg],
    path [m].  Returns NaN, or the record's time [s] at which the solver gave
    up (:func:`~stickslip.solvers.plane.check_progress`).
    """
    return plane.solve_pair_on_surface(ax, ay, _NO_VERTICAL, dt, 1.0, mug, mug, 0.0, 0.0, rtol, lock_ratio, history,
                                       out)


def sweep_pairs(samples_1, samples_2, offsets, dts, mugs, rtol, lock_ratio, out):
    """:func:`solve_pair` for every (pair, μ·g) in parallel; ``out`` has shape (pairs, len(mugs), 9).

    ``samples_1``, ``samples_2`` [m/s²] hold the pairs one after the other,
    pair p in ``offsets[p]:offsets[p + 1]``, with intervals ``dts`` [s];
    ``mugs`` [m/s²] are the values of μ·g.  Returns the times [s] at which the
    solver gave up, NaN where it did not, shape (pairs, len(mugs))
    (:func:`~stickslip.solvers.plane.check_progress`).
    """
    mugs = np.asarray(mugs, dtype=float)
    cases = np.zeros((mugs.size, 4))
    cases[:, 0] = mugs
    cases[:, 1] = mugs
    return plane.sweep_pairs_on_surface(samples_1, samples_2, _NO_VERTICAL, offsets, dts, 1.0, cases, rtol, lock_ratio,
                                        out)
