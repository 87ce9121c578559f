"""How the pendulum's schemes solve: which kernel for which case, one motion or many.

The ``exact`` scheme takes the closed form where one exists: the pendulum
with Coulomb friction and a constant normal force
(:func:`~stickslip.models.pendulum.exact.pendulum_history`), or a flat
surface with Coulomb friction under a vertical motion
(:func:`~stickslip.models.pendulum.vertical_exact.vertical_history`); every
other case (a velocity law, or a curved surface under a vertical motion), and
every case of the ``integrated`` scheme, goes to the tolerance-controlled
kernel (:func:`~stickslip.models.pendulum.integrated.integrated_history`).
A pair of horizontal components (with or without its vertical) goes, with
either scheme, to the planar kernel (:mod:`~stickslip.models.pendulum.pair`).
"""

from __future__ import annotations

import math

import numpy as np

from stickslip.checks import checked_finite_results
from stickslip.models.pendulum.response import ENERGIES, PendulumResponse
from stickslip.solvers.ledger import SCALAR_NAMES
from stickslip.records.process import record_name
from stickslip.records.vertical import split_vertical

#: How each kernel solves, as a result says it.
CLOSED_FORM = "closed form"


def closed_form(scheme, case, vertical) -> str | None:
    """Which closed form solves ``case`` (``"pendulum"`` or ``"vertical"``), or None: it is integrated."""
    if scheme.integrates_always or not case.friction.is_coulomb:
        return None
    if vertical is None:
        return "pendulum"
    return "vertical" if math.isinf(case.radius) else None


def solve_motion(scheme, motion, case, rtol=None):
    """The response of the slider ``case`` to ``motion``: one component (a :class:`PendulumResponse`) or a pair
    (a :class:`~stickslip.models.pendulum.pair_response.PairPendulumResponse`), with or without its vertical."""
    from stickslip.models.pendulum.case import is_pair
    from stickslip.models.pendulum.normal_force import liftoff_intervals
    from stickslip.models.pendulum.pair import solve_pair_motion

    if is_pair(motion):
        return solve_pair_motion(scheme, motion, case, rtol)

    record, vertical, whole = split_vertical(motion)
    acceleration, dt = record.acceleration, record.dt
    form = closed_form(scheme, case, vertical)
    if form == "pendulum":
        from stickslip.models.pendulum.exact import pendulum_history

        history = pendulum_history(acceleration, dt, case.friction.mu_slow, case.radius, case.g)
    elif form == "vertical":
        from stickslip.models.pendulum.vertical_exact import vertical_history

        history = vertical_history(acceleration, vertical, dt, case.friction.mu_slow, case.g)
    else:
        from stickslip.models.pendulum.integrated import RTOL, integrated_history

        history = integrated_history(acceleration, dt, case.friction, case.radius, vertical, case.g,
                                     rtol=RTOL if rtol is None else rtol)
    liftoff = liftoff_intervals(vertical, dt, case.g) if vertical is not None else np.zeros((0, 2))
    if not form:
        from stickslip.models.pendulum.integrated import integration
    response = PendulumResponse(case, scheme.name, CLOSED_FORM if form else integration(rtol), record_name(record),
                                None if whole is None else record_name(whole.vertical),
                                None if whole is None else whole.sense, acceleration, vertical, history, liftoff)
    with np.errstate(over="ignore", invalid="ignore"):
        checked_finite_results(response.scalars(), f"{record_name(record)}, {case.describe_friction()}")
    return response


def sweep_motions(scheme, motions, case, values, rtol=None) -> dict:
    """End results of every motion (single components, or pairs) at every friction ratio of ``values`` [1]
    (Coulomb's μ, or the velocity law's μ_fast with its shape held: :meth:`PendulumCase.at`), by name, shape
    (motions, values); energies in J for the case's mass, the rest in the units of :data:`stickslip.units.UNITS`."""
    from stickslip.errors import StickslipError
    from stickslip.models.pendulum.case import is_pair
    from stickslip.models.pendulum.pair import sweep_pair_motions

    pairs = [is_pair(motion) for motion in motions]
    if any(pairs):
        if not all(pairs):
            raise StickslipError("a sweep takes pairs of components or single components, not both")
        found = sweep_pair_motions(motions, case, values, rtol)
        for name in ENERGIES:
            found[name] = found[name] * case.mass
        return found
    parts = [split_vertical(motion) for motion in motions]
    accelerations = [record.acceleration for record, _, _ in parts]
    verticals = [vertical for _, vertical, _ in parts]
    dts = [record.dt for record, _, _ in parts]
    values = np.asarray(values, dtype=float)
    forms = {closed_form(scheme, case, vertical) for vertical in verticals}
    if forms == {"pendulum"}:
        from stickslip.models.pendulum.exact import pendulum_sweep

        scalars = pendulum_sweep(accelerations, dts, values, case.radius, case.g)
    elif None not in forms:  # a flat surface, some motions with their vertical: one kernel takes both
        from stickslip.models.pendulum.vertical_exact import vertical_sweep

        scalars = vertical_sweep(accelerations, verticals, dts, values, case.g)
    else:
        from stickslip.models.pendulum.integrated import RTOL, integrated_sweep

        scalars = integrated_sweep(accelerations, verticals, dts, [case.friction.at_mu_fast(value) for value in values],
                                   case.radius, case.g, rtol=RTOL if rtol is None else rtol)
    found = {name: np.array(scalars[..., index]) for index, name in enumerate(SCALAR_NAMES)}
    for name in ENERGIES:
        found[name] *= case.mass
    return found
