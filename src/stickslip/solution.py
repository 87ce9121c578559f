"""``stickslip.solution``: one record, one friction ratio, one solver -> a :class:`Response`."""

from __future__ import annotations

import importlib
import inspect
from collections.abc import Mapping

import numpy as np

from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.checks import checked_finite_results, checked_positive
from stickslip.limits import HISTORY_BYTES_PER_POINT, check_memory
from stickslip.records.process import record_name
from stickslip.errors import StickslipError
from stickslip.records.record import Record
from stickslip.response import Response

#: Solver name -> module providing ``solve_history(acceleration, dt, mu, g, **options)``.
SOLVERS: dict[str, str] = {
    "exact": "stickslip.solvers.events",
    "newmark": "stickslip.solvers.newmark",
}


def solve(
    record: Record,
    mu: float,
    mass: float = PAPER_BLOCK_MASS,
    method: str = "exact",
    g: float = STANDARD_GRAVITY,
    **options,
) -> Response:
    """Solve the paper's Eq. 1 for a rigid block on ``record``.

    Parameters
    ----------
    record:
        The base acceleration (m/s², linear between samples).
    mu:
        Friction ratio μ [-], positive.
    mass:
        Block mass m [kg], positive (energies and forces scale with it).
    method:
        ``"exact"`` (event-driven, default) or ``"newmark"`` (the paper's Algorithm 1).
    g:
        Gravitational acceleration [m/s²].
    options:
        Passed to the solver, e.g. ``time_step=0.001`` [s] for ``newmark``; ``exact`` takes none.

    Returns
    -------
    Response
        Histories, energies [J] and scalars for the given mass.  Work whose
        memory estimate exceeds :func:`stickslip.limits.memory_limit`, and
        results that are not finite, raise :class:`StickslipError`.
    """
    if method not in SOLVERS:
        raise StickslipError(f"unknown solver method {method!r}; known: {', '.join(SOLVERS)}")
    mu = checked_positive(mu, "friction ratio mu")
    mass = checked_positive(mass, "block mass [kg]")
    g = checked_positive(g, "gravity g [m/s2]")
    solve_history = importlib.import_module(SOLVERS[method]).solve_history
    parameters = inspect.signature(solve_history).parameters
    accepted = [name for name, p in parameters.items() if p.kind is inspect.Parameter.KEYWORD_ONLY]
    unknown = sorted(set(options) - set(accepted))
    if unknown:
        raise StickslipError(
            f"solver {method!r} does not accept option(s) {', '.join(unknown)}; it accepts: {', '.join(accepted) or 'none'}"
        )
    if method == "exact":  # the event-driven history holds the samples and about as many slip events
        check_memory(2 * record.npts * HISTORY_BYTES_PER_POINT, f"solving {record.npts:,} samples")
    history = solve_history(record.acceleration, record.dt, mu, g, **options)
    response = Response(
        history=history, mass=mass, mu=mu, g=g, method=method, record_meta=record.meta, solver_options=dict(options)
    )
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused here, not warned about
        scalars = response.scalars()
    checked_finite_results(scalars, f"{record_name(record)}, mu = {mu:g}")
    return response


def solver_options(method: str, options: Mapping | None = None) -> dict:
    """The options ``method``'s solver runs with: its keyword defaults (those that are set), updated with ``options``.

    An option the solver does not take raises :class:`StickslipError`.
    """
    parameters = inspect.signature(importlib.import_module(SOLVERS[method]).solve_history).parameters
    defaults = {name: parameter.default for name, parameter in parameters.items()
                if parameter.kind is inspect.Parameter.KEYWORD_ONLY}
    unknown = sorted(set(options or {}) - set(defaults))
    if unknown:
        raise StickslipError(f"solver {method!r} does not accept option(s) {', '.join(unknown)}; "
                             f"it accepts: {', '.join(defaults) or 'none'}")
    return {name: value for name, value in {**defaults, **(options or {})}.items() if value is not None}
