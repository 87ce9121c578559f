"""A scheme of the rigid block: its ``sliding_history``, what it accepts and costs, and how it solves and sweeps.

Each scheme is one module that defines ``sliding_history(acceleration, dt,
resistance, **options)`` (ground acceleration [m/s²] at the samples, sample
interval dt [s], a :class:`~stickslip.models.rigid.resistance.Resistance`;
per-unit-mass histories, :class:`~stickslip.models.rigid.history.SolverHistory`);
the rigid model's entry (:mod:`stickslip.models.rigid`) declares it as a
:class:`RigidScheme`, which imports the module only when the scheme is used.
Every rule of a scheme (what it solves, its options, its memory) is checked
here, once, for every caller.
"""

from __future__ import annotations

import importlib
import inspect
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from stickslip.errors import StickslipError
from stickslip.limits import HISTORY_BYTES_PER_POINT, check_memory
from stickslip.models.entry import Scheme


@dataclass(frozen=True)
class RigidScheme(Scheme):
    """One scheme of the rigid block.

    Attributes
    ----------
    name, summary:
        The name users give (``method="exact"``) and what it is, in one line.
    history:
        ``"module:function"``, the scheme's ``sliding_history``; its keyword-only
        parameters are the scheme's options, their defaults the scheme's.
    flat_only:
        Solves flat friction only (a :class:`Resistance` from ``mu``), not a
        block given a yield coefficient.
    yield_table:
        Solves a one-way block whose k_y varies with the downslope displacement
        (a :class:`~stickslip.models.yield_table.YieldTable`).
    batched:
        Has the batched kernel (:func:`stickslip.models.rigid.exact.sweep_scalars`)
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
    history: str
    flat_only: bool = False
    yield_table: bool = False
    batched: bool = False
    history_points_per_sample: float | None = 2.0
    inverse_options: Mapping[str, object] = field(default_factory=dict)

    @property
    def sliding_history(self) -> Callable:
        """The scheme's ``sliding_history`` (its module is imported on first use)."""
        module, function = self.history.split(":")
        return getattr(importlib.import_module(module), function)

    @property
    def options(self) -> dict:
        """The scheme's options and their defaults (``None``: computed from the record)."""
        parameters = inspect.signature(self.sliding_history).parameters
        return {name: parameter.default for name, parameter in parameters.items()
                if parameter.kind is inspect.Parameter.KEYWORD_ONLY}

    def run_options(self, given: Mapping | None, case) -> dict:
        """The options a solve of ``case`` runs with: the defaults that are set, the inverse-polarity ones (where the
        case is solved in inverse polarity), then ``given``."""
        merged = {**self.options, **(self.inverse_options if case.inverse else {}), **self.checked_options(given)}
        return {name: value for name, value in merged.items() if value is not None}

    def check(self, case) -> None:
        """Refuse a block the scheme cannot solve (:meth:`check_resistance`)."""
        self.check_resistance(case.resistance)

    def check_resistance(self, resistance) -> None:
        """Refuse a resistance the scheme cannot solve (a slope for a flat-only scheme, a yield table)."""
        from stickslip.models.rigid import SCHEMES

        if self.flat_only and not resistance.flat:
            takes_slopes = [scheme.name for scheme in SCHEMES if not scheme.flat_only]
            raise StickslipError(f"{self.name} ({self.summary}) solves flat friction only, not "
                                 f"{resistance.describe()}; use method {' or '.join(takes_slopes)}")
        if resistance.threshold_table is not None and not self.yield_table:
            takes_tables = [scheme.name for scheme in SCHEMES if scheme.yield_table]
            raise StickslipError(f"{self.name} ({self.summary}) solves a constant yield coefficient, not "
                                 f"{resistance.describe()}; use method {' or '.join(takes_tables)}")

    def check_memory(self, npts: int) -> None:
        """Refuse a history of ``npts`` samples whose memory exceeds :func:`stickslip.limits.memory_limit`."""
        if self.history_points_per_sample is not None:
            check_memory(int(self.history_points_per_sample * npts) * HISTORY_BYTES_PER_POINT,
                         f"solving {npts:,} samples")

    def solve(self, record, case, **options):
        """The :class:`~stickslip.models.rigid.response.Response` of the block ``case`` on ``record`` [m/s²]."""
        import numpy as np

        from stickslip.checks import checked_finite_results
        from stickslip.models.rigid.response import Response
        from stickslip.records.process import inverse_polarity, record_name

        self.check(case)
        options = self.run_options(options, case)
        if case.inverse:
            record = inverse_polarity(record)
        self.check_memory(record.npts)
        history = self.sliding_history(record.acceleration, record.dt, case.resistance, **options)
        response = Response(history=history, mass=case.mass, resistance=case.resistance, g=case.g, method=self.name,
                            record_meta=record.meta, solver_options=dict(options), inverse=case.inverse)
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused here, not warned about
            scalars = response.scalars()
        checked_finite_results(scalars, f"{record_name(record)}, {case.resistance.describe()}")
        return response

    def sweep(self, records, case, coefficient: str, values) -> dict:
        """The batched kernel's end results by name, each of shape (records, values), for the block ``case`` with
        its ``coefficient`` at each of ``values`` [1].

        The :data:`~stickslip.models.rigid.history.SCALAR_NAMES` (energies in J for the case's mass, lengths in m)
        and, on a slope, the permanent ``downslope_displacement`` [m] and ``body_force_work`` [J], as
        :class:`~stickslip.models.rigid.response.Response` gives them; ``records`` as given (their sign flipped
        here in inverse polarity).  One record at one value runs the kernel serially, without starting threads.
        """
        import numpy as np

        from stickslip.models.rigid.exact import record_scalars, sweep_scalars
        from stickslip.models.rigid.history import SCALAR_NAMES

        if not self.batched:
            raise NotImplementedError(f"the {self.name} scheme has no batched kernel")
        cases = [case.at(coefficient, value) for value in values]
        accelerations = [case.solved(record.acceleration) for record in records]
        if len(records) == 1 and len(cases) == 1:
            scalars = record_scalars(accelerations[0], records[0].dt, resistance=cases[0].resistance)[None, None, :]
        else:
            scalars = sweep_scalars(accelerations, [record.dt for record in records],
                                    resistances=[each.resistance for each in cases])
        found = {name: np.array(scalars[..., index]) for index, name in enumerate(SCALAR_NAMES)}
        for name in ("energy_dissipated", "energy_input", "kinetic_energy_final"):
            found[name] *= case.mass
        if case.resistance.on_slope:
            displacement = found["residual_displacement"]
            body = np.array([each.resistance.body for each in cases])
            found["downslope_displacement"] = -displacement
            found["body_force_work"] = np.where(body == 0.0, 0.0, case.mass * body * displacement)
        return found
