"""The friction pendulum in the plane: a slider on a spherical surface under both horizontal components (and the vertical).

Per unit mass, relative to the ground, with u, v ∈ ℝ² the slider's
displacement and velocity, a(t) ∈ ℝ² the horizontal ground acceleration on
the pair's orthogonal axes (:meth:`~stickslip.records.pair.RecordPair.horizontal`)
and n(t) = g + a_v(t) the normal force per unit mass (a_v positive up, zero
without a vertical), in small-angle geometry:

    v̇ = −a − (n/R)·u − μ(|v|)·n·v/|v|   while sliding,

stuck while |a + (n/R)·u| ≤ μ(0)·n, lifted off where n ≤ 0
(:mod:`stickslip.solvers.plane`, which integrates it to a relative
tolerance of 1e-10 with the events located; docs/solvers.md, "The friction
pendulum in the plane").  One scheme solves every case (there is no closed
form in the plane): both of the pendulum's schemes come here.
:func:`solve_pair_motion` gives a :class:`PairPendulumResponse`;
:func:`sweep_pair_motions` the end results of many pairs over a friction grid.
"""

from __future__ import annotations

import numpy as np

from stickslip.checks import checked_finite_results, checked_pair_axes
from stickslip.records.vertical import split_vertical


def solve_pair_motion(scheme, motion, case, rtol=None):
    """The :class:`~stickslip.models.pendulum.pair_response.PairPendulumResponse` of ``case`` on a pair (and its
    vertical), ``rtol`` the relative tolerance per step (default 1e-10)."""
    from stickslip.models.pendulum.normal_force import liftoff_intervals, normal_acceleration
    from stickslip.models.pendulum.integrated import integration
    from stickslip.models.pendulum.pair_response import PairPendulumResponse, kernel_case
    from stickslip.records.process import integrate_linear_acceleration, record_name
    from stickslip.solvers import plane

    pair, vertical, whole = split_vertical(motion)
    first, second = checked_pair_axes(pair)
    if vertical is not None:
        normal_acceleration(vertical, first.size, case.g)  # one line for a vertical that is not a record's
    rtol = plane.RTOL if rtol is None else rtol
    history = np.zeros((pair.npts, len(plane.HISTORY_NAMES)))
    out = np.zeros(len(plane.SURFACE_SCALAR_NAMES))
    stalled_at = plane.solve_pair_on_surface(
        first, second, np.zeros(0) if vertical is None else np.ascontiguousarray(vertical), pair.dt, case.g,
        *kernel_case(case), rtol, plane.LOCK_RATIO, history, out)
    plane.check_progress(stalled_at, lambda _: _described(motion, case))
    velocity = np.column_stack([integrate_linear_acceleration(axis, pair.dt)[0] for axis in (first, second)])
    response = PairPendulumResponse(
        slider=case, method=scheme.name, solved_by=integration(rtol), pair=pair,
        vertical=None if whole is None else record_name(whole.vertical),
        vertical_sense=None if whole is None else whole.sense,
        ground_acceleration=np.column_stack([first, second]), ground_velocity=velocity,
        vertical_acceleration=vertical, history=history,
        kernel_scalars=dict(zip(plane.SURFACE_SCALAR_NAMES, map(float, out))),
        liftoff=liftoff_intervals(vertical, pair.dt, case.g) if vertical is not None else np.zeros((0, 2)))
    with np.errstate(over="ignore", invalid="ignore"):
        checked_finite_results(response.scalars(), f"{pair.name}, {case.describe_friction()}")
    return response


def sweep_pair_motions(motions, case, values, rtol=None) -> dict[str, np.ndarray]:
    """End results of every pair (with or without its vertical) at every friction ratio of ``values`` [1] (Coulomb's
    μ, or the velocity law's μ_fast with its shape held: :meth:`PendulumCase.at`), by name, shape (motions, values),
    per unit mass (the caller multiplies the energies by the mass)."""
    from stickslip.models.pendulum.normal_force import normal_acceleration
    from stickslip.solvers import plane

    parts = [split_vertical(motion) for motion in motions]
    axes = [checked_pair_axes(pair) for pair, _, _ in parts]
    verticals = [vertical for _, vertical, _ in parts]
    if any(vertical is not None for vertical in verticals) and any(vertical is None for vertical in verticals):
        from stickslip.errors import StickslipError

        raise StickslipError("a sweep of pairs takes the vertical for every pair or for none")
    for (first, _), vertical in zip(axes, verticals):
        if vertical is not None:
            normal_acceleration(vertical, first.size, case.g)
    from stickslip.models.pendulum.pair_response import end_results, kernel_case

    values = np.asarray(values, dtype=float)
    cases = np.array([kernel_case(case.at("mu", value)) for value in values], dtype=np.float64).reshape(-1, 4)
    curvature = kernel_case(case)[3]  # 1/R [1/m], the same at every mu
    sizes = [first.size for first, _ in axes]
    offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    out = np.empty((len(axes), values.size, len(plane.SURFACE_SCALAR_NAMES)))
    stalled_at = plane.sweep_pairs_on_surface(
        np.concatenate([first for first, _ in axes]), np.concatenate([second for _, second in axes]),
        np.zeros(0) if verticals[0] is None else np.concatenate(verticals), offsets,
        np.array([pair.dt for pair, _, _ in parts]), case.g, cases, plane.RTOL if rtol is None else rtol,
        plane.LOCK_RATIO, out)
    plane.check_progress(stalled_at, lambda index: _described(motions[index[0]], case.at("mu", values[index[1]])))
    return end_results(out, case.g, curvature)


def _described(motion, case) -> str:
    """``A-000 + A-090 with its vertical, friction pendulum R = 1 m (T = 2.01 s), mu = 0.0005``: what a message
    names."""
    pair, vertical, _ = split_vertical(motion)
    return (f"{pair.name}{'' if vertical is None else ' with its vertical'}, {case.describe_sliding()}, "
            f"{case.describe_friction()}")
