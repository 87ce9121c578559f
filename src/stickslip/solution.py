"""``stickslip.solution``: one record, one resistance (friction ratio or yield coefficient), one solver -> a :class:`Response`."""

from __future__ import annotations

import numpy as np

from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.checks import checked_finite_results, checked_positive
from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.records.process import inverse_polarity, record_name
from stickslip.records.record import Record
from stickslip.response import Response
from stickslip.solvers.registry import scheme
from stickslip.solvers.resistance import Resistance
from stickslip.solvers.yield_table import YieldTable


def solve(
    record: Record | RecordPair,
    mu: float | None = None,
    mass: float = PAPER_BLOCK_MASS,
    method: str = "exact",
    g: float = STANDARD_GRAVITY,
    *,
    ky: float | YieldTable | None = None,
    direction: str | None = None,
    thrust_angle: float | None = None,
    inverse: bool = False,
    **options,
) -> Response:
    """Solve a rigid sliding block on ``record``: flat friction ``mu``, or a yield coefficient ``ky``.

    Parameters
    ----------
    record:
        The base acceleration (m/s², linear between samples); a positive value
        drives the block towards −x, which is downslope.  A
        :class:`~stickslip.records.pair.RecordPair` of two horizontal
        components solves the block sliding in the plane on a flat surface
        (:func:`stickslip.solvers.planar.solve_planar`, friction ratio ``mu``
        only) and returns a :class:`~stickslip.solvers.planar.PlanarResponse`.
    mu:
        Friction ratio μ [-], positive: a flat surface (the paper's Eq. 1).
    mass:
        Block mass m [kg], positive (energies and forces scale with it).
    method:
        The scheme (:mod:`stickslip.solvers.registry`): ``"exact"``
        (event-driven, default), ``"newmark"`` (the paper's Algorithm 1; flat
        friction only) or ``"slammer"`` (SLAMMER's rigid-block scheme).
    g:
        Gravitational acceleration [m/s²] (SLAMMER's is 9.80665).
    ky:
        Instead of ``mu``: the yield coefficient k_y [-] (yield acceleration / g)
        of a block on a slope, which slides downslope when the ground
        acceleration exceeds k_y·g.  A :class:`~stickslip.solvers.yield_table.YieldTable`
        makes k_y vary with the accumulated downslope displacement (one-way;
        ``method="slammer"``).
    direction:
        With ``ky``: ``"down"`` (default, one-way: never upslope) or ``"both"``
        (two-way, SLAMMER's "downslope and upslope").
    thrust_angle:
        With ``direction="both"``: the thrust angle β [degrees, 0 to 90]; the
        block slides upslope past k_y·g + 2·g·sin β (default 0).
    inverse:
        Solve the record with its sign flipped (SLAMMER's inverse polarity).
    options:
        Passed to the solver, e.g. ``time_step=0.001`` [s] for ``newmark``;
        ``exact`` takes none.

    Returns
    -------
    Response
        Histories, energies [J] and scalars for the given mass; with ``ky``
        also the permanent ``downslope_displacement`` [m] (SLAMMER's number,
        positive downslope).  Work whose memory estimate exceeds
        :func:`stickslip.limits.memory_limit`, and results that are not
        finite, raise :class:`StickslipError`.
    """
    if isinstance(record, RecordPair):
        return _solve_pair(record, mu, mass, method, g, ky=ky, direction=direction, thrust_angle=thrust_angle,
                           inverse=inverse, **options)
    solver = scheme(method)
    resistance = Resistance.from_options(g, mu=mu, ky=ky, direction=direction, thrust_angle=thrust_angle)
    solver.check_resistance(resistance)
    mass = checked_positive(mass, "block mass [kg]")
    g = checked_positive(g, "gravity g [m/s2]")
    options = solver.options(options, inverse)
    if inverse:
        record = inverse_polarity(record)
    solver.check_memory(record.npts)
    history = solver.sliding_history(record.acceleration, record.dt, resistance, **options)
    response = Response(
        history=history, mass=mass, resistance=resistance, g=g, method=method, record_meta=record.meta,
        solver_options=dict(options),
    )
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused here, not warned about
        scalars = response.scalars()
    checked_finite_results(scalars, f"{record_name(record)}, {resistance.describe()}")
    return response


def _solve_pair(pair: RecordPair, mu, mass, method, g, *, ky, direction, thrust_angle, inverse, **options):
    """:func:`solve` for a record pair: flat friction in the plane, the planar model's one scheme."""
    from stickslip.solvers.flexible import model
    from stickslip.solvers.planar import solve_planar

    schemes = model("planar").schemes
    if method not in schemes:
        raise StickslipError(f"sliding in the plane is solved by method {', '.join(schemes)}, not {method!r}")
    if ky is not None or direction is not None or thrust_angle is not None or inverse:
        raise StickslipError("sliding in the plane takes a friction ratio mu on a flat surface: no ky, direction, "
                             "thrust_angle or inverse polarity")
    if mu is None:
        raise StickslipError("give a friction ratio mu for sliding in the plane")
    unknown = sorted(set(options) - {"rtol"})
    if unknown:
        raise StickslipError(f"sliding in the plane does not accept option(s) {', '.join(unknown)}; it accepts: rtol")
    return solve_planar(pair, mu, mass=mass, g=g, **options)
