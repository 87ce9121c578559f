"""The response of one block to one record: time histories, energy balance and scalars.

A :class:`Response` wraps a solver's per-unit-mass
:class:`~stickslip.models.rigid.history.SolverHistory` with the block mass, the
:class:`~stickslip.models.rigid.resistance.Resistance` (friction ratio or yield
coefficient) and the record's provenance, and gives every quantity in SI units
for that mass:

* absolute motion u = u_g + x, u̇ = u̇_g + ẋ, ü = ü_g + ẍ [m, m/s, m/s²];
* friction force F_f = −m·ü [N] (Eq. 1: m·ẍ + F_f = −m·ü_g), |F_f| ≤ μ·m·g on a
  flat surface; on a slope −m·ü is the resisting force less the body force m·b;
* kinetic energy E_k = ½·m·u̇² [J] (the paper's Eq. 14 with its missing square);
* dissipated energy E_df and absolute input energy E_I [J], as the solver computed them;
* body-force work W_b = m·b·x [J] (gravity along a slope; zero on a flat surface);
* balance residual E_k − E_k(0) + E_df − E_I − W_b [J], which is round-off for ``exact``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from stickslip.models.result import Result
from stickslip.models.rigid.history import SolverHistory
from stickslip.models.rigid.resistance import Resistance
from stickslip.records.record import Record, RecordMeta
from stickslip.units import UNITS

#: Scalars of :meth:`Response.scalars`, with units (:data:`~stickslip.units.UNITS`) and long names.
SCALAR_ATTRS: dict[str, tuple[str, str]] = {name: (UNITS[name], long_name) for name, long_name in (
    ("energy_dissipated", "energy dissipated by friction E_df at the end of the record"),
    ("energy_input", "absolute input energy E_I at the end of the record"),
    ("kinetic_energy_final", "absolute kinetic energy E_k at the end of the record"),
    ("balance_residual", "largest |E_k - E_k(0) + E_df - E_I - W_b| over the record (W_b: body-force work)"),
    ("residual_displacement", "block displacement relative to the base at the end"),
    ("peak_relative_displacement", "largest |block displacement relative to the base|"),
    ("sliding_path", "total distance slid relative to the base"),
    ("slip_fraction", "fraction of the record duration spent sliding"),
    ("n_slip_episodes", "number of stick-to-slip transitions (a reversal without sticking is not counted)"),
)}

#: Scalars of a block given a yield coefficient k_y (on a slope), after :data:`SCALAR_ATTRS`.
SLOPE_SCALAR_ATTRS: dict[str, tuple[str, str]] = {name: (UNITS[name], long_name) for name, long_name in (
    ("downslope_displacement", "permanent displacement downslope at the end (SLAMMER's; negative if upslope)"),
    ("body_force_work", "work W_b = m b x of the body force (gravity along the slope) at the end"),
)}

#: Time histories of :meth:`Response.to_xarray`, with units (:data:`~stickslip.units.UNITS`) and long names.
HISTORY_ATTRS: dict[str, tuple[str, str]] = {name: (UNITS[name], long_name) for name, long_name in (
    ("ground_acceleration", "base acceleration"),
    ("ground_velocity", "base velocity"),
    ("ground_displacement", "base displacement"),
    ("relative_acceleration", "block acceleration relative to the base"),
    ("relative_velocity", "block velocity relative to the base"),
    ("relative_displacement", "block displacement relative to the base"),
    ("absolute_acceleration", "absolute block acceleration"),
    ("absolute_velocity", "absolute block velocity"),
    ("absolute_displacement", "absolute block displacement"),
    ("friction_force", "friction force on the block, -m * absolute acceleration"),
    ("phase", "0 stick, +1 / -1 sliding with positive / negative relative velocity (just after the time)"),
    ("kinetic_energy", "absolute kinetic energy E_k = m u_dot^2 / 2"),
    ("energy_dissipated", "cumulative energy dissipated by friction E_df"),
    ("energy_input", "cumulative absolute input energy E_I"),
    ("body_force_work", "work W_b = m b x of the constant body force on the relative displacement"),
    ("balance_residual", "energy balance residual E_k - E_k(0) + E_df - E_I - W_b"),
)}


@dataclass(frozen=True)
class Response(Result):
    """One solved case of the rigid model: a block of ``mass`` [kg] resisted by ``resistance`` on a record.

    Attributes
    ----------
    history:
        The solver's per-unit-mass histories.
    mass:
        Block mass m [kg].
    resistance:
        The thresholds and body acceleration [m/s²], with the friction ratio
        or yield coefficient they were built from.
    g:
        Gravitational acceleration [m/s²].
    method:
        The solver's name (``"exact"``, ``"newmark"``, ``"slammer"``).
    record_meta:
        Provenance of the record that was solved.
    solver_options:
        Options passed to the solver (for example Newmark's ``time_step``), kept as attributes.
    inverse:
        Whether the record was solved with its sign flipped (SLAMMER's inverse polarity).
    """

    model = "rigid"
    history_table = HISTORY_ATTRS
    ledger_terms = ("energy_input", "energy_dissipated", "kinetic_energy", "body_force_work", "balance_residual")
    per_unit_mass = False  # the end results are the block's, energies for its mass
    scalars_as_attributes = True
    time_attrs = {"units": UNITS["time"], "long_name": "time"}
    response_figure = "absolute"

    history: SolverHistory
    mass: float
    resistance: Resistance
    g: float
    method: str
    record_meta: RecordMeta = field(default_factory=RecordMeta)
    solver_options: dict = field(default_factory=dict)
    inverse: bool = False

    @property
    def mu(self) -> float | None:
        """The friction ratio μ [-] of a flat surface; None for a yield coefficient."""
        return self.resistance.parameters.get("mu")

    # Time histories ------------------------------------------------------------------

    @property
    def time(self) -> np.ndarray:
        """Times of the solver's grid [s]."""
        return self.history.time

    @property
    def ground_acceleration(self) -> np.ndarray:
        """Base acceleration ü_g [m/s²]."""
        return self.history.ground_acceleration

    @property
    def ground_velocity(self) -> np.ndarray:
        """Base velocity u̇_g [m/s], zero at t = 0."""
        return self.history.ground_velocity

    @property
    def ground_displacement(self) -> np.ndarray:
        """Base displacement u_g [m], zero at t = 0."""
        return self.history.ground_displacement

    @property
    def relative_acceleration(self) -> np.ndarray:
        """Block acceleration relative to the base ẍ [m/s²] (just after each time)."""
        return self.history.relative_acceleration

    @property
    def relative_velocity(self) -> np.ndarray:
        """Block velocity relative to the base ẋ [m/s]."""
        return self.history.relative_velocity

    @property
    def relative_displacement(self) -> np.ndarray:
        """Block displacement relative to the base x [m]."""
        return self.history.relative_displacement

    @property
    def absolute_acceleration(self) -> np.ndarray:
        """Absolute block acceleration ü = ü_g + ẍ [m/s²]."""
        return self.ground_acceleration + self.relative_acceleration

    @property
    def absolute_velocity(self) -> np.ndarray:
        """Absolute block velocity u̇ = u̇_g + ẋ [m/s]."""
        return self.ground_velocity + self.relative_velocity

    @property
    def absolute_displacement(self) -> np.ndarray:
        """Absolute block displacement u = u_g + x [m]."""
        return self.ground_displacement + self.relative_displacement

    @property
    def friction_force(self) -> np.ndarray:
        """Friction force F_f = −m·ü [N]; |F_f| ≤ μ·m·g."""
        return -self.mass * self.absolute_acceleration

    @property
    def phase(self) -> np.ndarray:
        """0 stick, ±1 sliding with ẋ ≷ 0, just after each time [-]."""
        return self.history.phase

    @property
    def kinetic_energy(self) -> np.ndarray:
        """Absolute kinetic energy E_k = ½·m·u̇² [J]."""
        return 0.5 * self.mass * self.absolute_velocity**2

    @property
    def energy_dissipated_history(self) -> np.ndarray:
        """Cumulative energy dissipated by friction E_df [J]."""
        return self.mass * self.history.energy_dissipated

    @property
    def energy_input_history(self) -> np.ndarray:
        """Cumulative absolute input energy E_I [J]."""
        return self.mass * self.history.energy_input

    @property
    def body_force_work_history(self) -> np.ndarray:
        """W_b = m·b·x [J]: work of the constant body force over the relative displacement (zeros when b = 0)."""
        if self.resistance.body == 0.0:
            return np.zeros_like(self.relative_displacement)
        return self.mass * self.resistance.body * self.relative_displacement

    @property
    def balance_residual_history(self) -> np.ndarray:
        """E_k − E_k(0) + E_df − E_I − W_b [J]."""
        kinetic = self.kinetic_energy
        return (kinetic - kinetic[0] + self.energy_dissipated_history - self.energy_input_history
                - self.body_force_work_history)

    # Scalars -------------------------------------------------------------------------

    @property
    def energy_dissipated(self) -> float:
        """E_df at the end of the record [J]."""
        return float(self.energy_dissipated_history[-1])

    @property
    def energy_input(self) -> float:
        """E_I at the end of the record [J]."""
        return float(self.energy_input_history[-1])

    @property
    def kinetic_energy_final(self) -> float:
        """E_k at the end of the record [J]."""
        return float(self.kinetic_energy[-1])

    @property
    def body_force_work(self) -> float:
        """W_b at the end of the record [J]."""
        return float(self.body_force_work_history[-1])

    @property
    def balance_residual(self) -> float:
        """Largest |E_k − E_k(0) + E_df − E_I − W_b| over the record [J]."""
        return float(np.max(np.abs(self.balance_residual_history)))

    @property
    def residual_displacement(self) -> float:
        """Relative displacement x at the end of the record [m]."""
        return float(self.relative_displacement[-1])

    @property
    def downslope_displacement(self) -> float:
        """Permanent displacement downslope, −x at the end [m] (SLAMMER's number; positive downslope)."""
        return -self.residual_displacement

    @property
    def peak_relative_displacement(self) -> float:
        """max |x| [m]: the solver's own peak (``exact`` includes stops between samples), else over the samples."""
        if self.history.peak_relative_displacement is not None:
            return float(self.history.peak_relative_displacement)
        return float(np.max(np.abs(self.relative_displacement)))

    @property
    def sliding_path(self) -> float:
        """Total distance slid, ∫|ẋ| dt [m]."""
        return self.history.sliding_path

    @property
    def slip_fraction(self) -> float:
        """Time spent sliding / record duration [-]."""
        return self.history.slip_time / float(self.time[-1] - self.time[0])

    @property
    def n_slip_episodes(self) -> int:
        """Number of separate sliding episodes."""
        return self.history.n_slip_episodes

    def histories(self) -> dict[str, np.ndarray]:
        """Every time history, keyed as in :data:`HISTORY_ATTRS` (energies in J, see there for units)."""
        energy_names = {"energy_dissipated", "energy_input", "body_force_work", "balance_residual"}
        return {name: getattr(self, f"{name}_history" if name in energy_names else name) for name in HISTORY_ATTRS}

    @property
    def never_slides(self) -> str | None:
        """Why the block never left the stick band (the record's extremes beside the levels); None when it slid."""
        from stickslip.models.rigid.case import RigidCase

        if self.n_slip_episodes:
            return None
        recorded = -self.ground_acceleration if self.inverse else self.ground_acceleration  # the record as given
        return RigidCase(self.resistance, self.mass, self.g, self.inverse).never_slides(Record(recorded, 1.0))

    def notices(self) -> list[str]:
        """That the block never slid, where and why (the record's extremes beside the levels)."""
        if self.never_slides is None:
            return []
        return [f"the block never slides at {self.resistance.value}: {self.never_slides}, so E_df = 0 there"]

    def describe(self) -> str:
        """``mu = 0.1, mass = 5.1 kg, g = 9.81 m/s2, method = exact`` (a yield coefficient with its yield
        acceleration, the polarity)."""
        polarity = ", inverse polarity" if self.inverse else ""
        return (f"{self.resistance.describe(self.g)}{polarity}, mass = {self.mass:g} kg, g = {self.g:g} m/s2, "
                f"method = {self.method}")

    def case(self) -> dict:
        """The model, the resistance's parameters, the polarity, mass [kg], g [m/s²], the scheme and its options."""
        return {"model": self.model, **self.resistance.parameters,
                "polarity": "inverse" if self.inverse else "normal", "mass": self.mass, "g": self.g,
                "method": self.method, **self.solver_options}

    def case_units(self) -> dict[str, str]:
        """The units of :meth:`case`'s numbers: mass [kg], g [m s-2], k_y or μ [1], the options' (``time_step`` [s])."""
        return {"mass": UNITS["block_mass"], "g": UNITS["gravity"],
                **{name: UNITS[name] for name in (*self.resistance.parameters, *self.solver_options) if name in UNITS}}

    @property
    def scalar_table(self) -> dict[str, tuple[str, str]]:
        """The end results' units and long names: :data:`SCALAR_ATTRS`, and on a slope :data:`SLOPE_SCALAR_ATTRS`."""
        return {**SCALAR_ATTRS, **SLOPE_SCALAR_ATTRS} if self.resistance.on_slope else SCALAR_ATTRS

    def end_values(self) -> dict[str, float | int]:
        """The end results of :attr:`scalar_table` for the block's mass (energies [J])."""
        return {name: getattr(self, name) for name in self.scalar_table if name != "balance_residual"}

    def title(self) -> str:
        """``stickslip response of a sliding block to RECORD``."""
        return f"stickslip response of a sliding block to {self.record_meta.record_id or 'a record'}"

    def case_attrs(self) -> dict:
        """The scheme, the resistance's parameters, mass [kg] and g [m/s²] with their units, the record's
        provenance and the scheme's options given (``solver_time_step``; one not plain as its text)."""
        options = {f"solver_{option}": value if isinstance(value, (int, float, str)) and not isinstance(value, bool)
                   else str(value) for option, value in self.solver_options.items() if value is not None}
        return {"method": self.method, **self.resistance.parameters, "mass": self.mass,
                "mass_units": UNITS["block_mass"], "g": self.g, "g_units": UNITS["gravity"],
                "record_id": self.record_meta.record_id, "record_source": self.record_meta.source,
                "record_sha256": self.record_meta.sha256, "record_processing": "; ".join(self.record_meta.processing),
                **options}
