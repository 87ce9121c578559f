"""The schemes that solve the rigid block, declared once: what each accepts, what it has, what it costs.

A scheme is one module that defines ``sliding_history(acceleration, dt,
resistance, **options)`` (ground acceleration [m/s²] at the samples, sample
interval dt [s], a :class:`~stickslip.solvers.resistance.Resistance`; per
unit mass histories, :class:`~stickslip.solvers.history.SolverHistory`) and
``SCHEME``, its :class:`Scheme`; :data:`SCHEME_MODULES` names the modules.
:func:`stickslip.solve`, :func:`stickslip.sweep`, the μ_max refinement, the
command line and the studies ask the entry what a scheme can do instead of
branching on its name, and each of its rules is checked here, once.  A new
scheme or model is one module and one line of :data:`SCHEME_MODULES`.
"""

from __future__ import annotations

import importlib
import inspect
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from stickslip.errors import StickslipError
from stickslip.limits import HISTORY_BYTES_PER_POINT, check_memory

#: Scheme name -> the module that defines its ``SCHEME`` (imported only when the scheme is used).
SCHEME_MODULES: dict[str, str] = {
    "exact": "stickslip.solvers.exact_scheme",
    "newmark": "stickslip.solvers.newmark",
    "slammer": "stickslip.solvers.slammer",
}


@dataclass(frozen=True)
class Scheme:
    """One scheme's entry: its ``sliding_history`` and what it accepts, has and costs.

    Attributes
    ----------
    name:
        The name users give (``method="exact"``, ``--method exact``).
    summary:
        What it is, in one line (the command line's help, the docs).
    sliding_history:
        ``sliding_history(acceleration, dt, resistance, **options)``; its
        keyword-only parameters are the scheme's options, their defaults the
        scheme's (:attr:`option_defaults`).
    flat_only:
        Solves flat friction only (a :class:`Resistance` from ``mu``), not a
        block given a yield coefficient.
    yield_table:
        Solves a one-way block whose k_y varies with the downslope displacement
        (a :class:`~stickslip.solvers.yield_table.YieldTable`).
    batched:
        Has the batched kernel (:func:`stickslip.solvers.exact.sweep_scalars`)
        that sweeps and the μ_max refinement use instead of one history per case.
    history_points_per_sample:
        Memory of a history, in points per record sample (a sample and about
        as many slip events); ``None`` when the scheme resamples the record and
        checks its own memory.
    inverse_options:
        Options an inverse-polarity solve runs with unless given (SLAMMER skips
        samples of exactly zero in normal polarity only).
    """

    name: str
    summary: str
    sliding_history: Callable
    flat_only: bool = False
    yield_table: bool = False
    batched: bool = False
    history_points_per_sample: float | None = 2.0
    inverse_options: Mapping[str, object] = field(default_factory=dict)

    @property
    def option_defaults(self) -> dict:
        """The scheme's options and their defaults (``None``: computed from the record)."""
        parameters = inspect.signature(self.sliding_history).parameters
        return {name: parameter.default for name, parameter in parameters.items()
                if parameter.kind is inspect.Parameter.KEYWORD_ONLY}

    def options(self, given: Mapping | None = None, inverse: bool = False) -> dict:
        """The options a solve runs with: the defaults that are set, the inverse-polarity ones, then ``given``.

        An option the scheme does not take raises :class:`StickslipError`.
        """
        defaults = self.option_defaults
        unknown = sorted(set(given or {}) - set(defaults))
        if unknown:
            raise StickslipError(f"solver {self.name!r} does not accept option(s) {', '.join(unknown)}; "
                                 f"it accepts: {', '.join(defaults) or 'none'}")
        merged = {**defaults, **(self.inverse_options if inverse else {}), **(given or {})}
        return {name: value for name, value in merged.items() if value is not None}

    def check_resistance(self, resistance) -> None:
        """Refuse a resistance the scheme cannot solve (a slope for a flat-only scheme, a yield table)."""
        if self.flat_only and not resistance.flat:
            takes_slopes = [name for name in SCHEME_MODULES if not scheme(name).flat_only]
            raise StickslipError(f"{self.name} ({self.summary}) solves flat friction only, not "
                                 f"{resistance.describe()}; use method {' or '.join(takes_slopes)}")
        if resistance.threshold_table is not None and not self.yield_table:
            takes_tables = [name for name in SCHEME_MODULES if scheme(name).yield_table]
            raise StickslipError(f"{self.name} ({self.summary}) solves a constant yield coefficient, not "
                                 f"{resistance.describe()}; use method {' or '.join(takes_tables)}")

    def check_memory(self, npts: int) -> None:
        """Refuse a history of ``npts`` samples whose memory exceeds :func:`stickslip.limits.memory_limit`."""
        if self.history_points_per_sample is not None:
            check_memory(int(self.history_points_per_sample * npts) * HISTORY_BYTES_PER_POINT,
                         f"solving {npts:,} samples")


def scheme(name: str) -> Scheme:
    """The entry of the scheme ``name``; an unknown name raises :class:`StickslipError` naming the known ones."""
    if name not in SCHEME_MODULES:
        raise StickslipError(f"unknown solver method {name!r}; known: {', '.join(SCHEME_MODULES)}")
    return importlib.import_module(SCHEME_MODULES[name]).SCHEME


def schemes_with_option(option: str) -> list[str]:
    """The names of the schemes that take the option ``option`` (``time_step``: ``["newmark"]``)."""
    return [name for name in SCHEME_MODULES if option in scheme(name).option_defaults]
