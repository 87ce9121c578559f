"""The response of a friction pendulum (or a flat slider) to one horizontal component and its vertical.

A :class:`PendulumResponse` holds a kernel's per-unit-mass history
(:mod:`~stickslip.models.pendulum.exact`, :mod:`~stickslip.models.pendulum.vertical_exact`
or :mod:`~stickslip.models.pendulum.integrated`, as
:func:`~stickslip.solvers.ledger.history_dict` gives it) and gives it
for the slider's mass: the energy ledger

    E_k − E_k(0) + E_p − E_p(0) + E_df = E_I,h + E_I,v   [J],

(E_k the absolute kinetic energy, E_p = m·g·u²/(2R) the potential energy,
E_df the friction's work, E_I,h the horizontal ground motion's absolute input
and E_I,v = W_v the vertical motion's work through the normal force on the
curved surface, zero without a vertical; docs/solvers.md, "The friction
pendulum and the vertical motion"), the displacement demand, the residual displacement, the
peak base shear coefficient V/W and the intervals where the slider lifted off.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from stickslip.models.pendulum.case import PendulumCase
from stickslip.models.result import Result
from stickslip.units import UNITS

#: The end results, in order: name -> (unit, long name), units from :data:`stickslip.units.UNITS`.
SCALARS = {name: (UNITS[name], long_name) for name, long_name in {
    "energy_dissipated": "energy dissipated by friction E_df at the end of the record",
    "energy_input": "absolute input energy of the horizontal ground motion E_I,h at the end of the record",
    "energy_input_vertical": "work of the vertical ground motion through the normal force on the curved surface "
                             "E_I,v = W_v = -int (N - m g) u du / R at the end of the record (0 without a vertical)",
    "kinetic_energy_final": "absolute kinetic energy E_k at the end of the record",
    "potential_energy_final": "potential energy E_p = m g |u|^2 / (2R) at the end of the record",
    "balance_residual": "largest |E_k - E_k(0) + E_p - E_p(0) + E_df - E_I,h - E_I,v| over the record",
    "residual_displacement": "slider displacement relative to the ground at the end (re-centring)",
    "peak_relative_displacement": "largest |slider displacement relative to the ground| (displacement demand)",
    "sliding_path": "total distance slid relative to the ground",
    "slip_fraction": "fraction of the record duration spent sliding",
    "n_slip_episodes": "number of stick-to-slip transitions",
    "peak_base_shear": "peak base shear coefficient V/W = max |mu N z + N u/R| / W",
    "liftoff_time": "time the slider spent lifted off (g + a_v <= 0)",
}.items()}

#: The kernels' energies per unit mass, times the mass in a response [J].
ENERGIES = ("energy_dissipated", "energy_input", "energy_input_vertical", "kinetic_energy_final",
            "potential_energy_final")

#: Histories of :meth:`PendulumResponse.to_xarray`: name -> (unit, long name), units from :data:`stickslip.units.UNITS`.
HISTORIES = {name: (UNITS[name], long_name) for name, long_name in {
    "ground_acceleration": "horizontal ground acceleration",
    "ground_velocity": "horizontal ground velocity",
    "relative_displacement": "slider displacement relative to the ground",
    "relative_velocity": "slider velocity relative to the ground",
    "phase": "0 stick, +1 / -1 sliding with positive / negative relative velocity, 2 lifted off (just after the time)",
    "energy_dissipated": "cumulative energy dissipated by friction E_df",
    "energy_input": "cumulative absolute input energy of the horizontal ground motion E_I,h",
    "energy_input_vertical": "cumulative work of the vertical ground motion through the normal force on the curved "
                             "surface E_I,v = W_v",
    "kinetic_energy": "absolute kinetic energy E_k",
    "potential_energy": "potential energy E_p = m g |u|^2 / (2R)",
    "balance_residual": "energy balance residual E_k - E_k(0) + E_p - E_p(0) + E_df - E_I,h - E_I,v",
    "sliding_path": "cumulative distance slid",
    "vertical_acceleration": "vertical ground acceleration a_v, positive up",
}.items()}


#: The terms of the energy ledger, as :meth:`PendulumResponse.energy_ledger` and the plane's give them.
LEDGER = ("energy_input", "energy_input_vertical", "energy_dissipated", "kinetic_energy", "potential_energy",
          "balance_residual")

#: What the ledger's end results say, in the notes of a solve (one direction and the plane).
LEDGER_NOTE = ("energies [J]: E_k - E_k(0) + E_p - E_p(0) + E_df = E_I,h + E_I,v; potential_energy_final E_p = "
               "m g |u|^2/(2R); energy_input E_I,h is the horizontal ground motion's input, energy_input_vertical "
               "E_I,v = W_v the vertical motion's work through the normal force on the curved surface (0 without a "
               "vertical or on a flat surface)")


class SliderResult:
    """What one solved case of the pendulum says of itself, in one direction or in the plane.

    The class declares its end results (:attr:`scalar_table`), its histories
    (:attr:`history_table`) and its ledger (:data:`LEDGER`), where it slides
    (:attr:`where`: ``""`` or ``"in the plane: "``) and what its case adds
    (:attr:`case_extra`); an instance has ``slider``, ``method``, ``solved_by``,
    ``vertical``, ``vertical_sense`` and ``liftoff`` (the intervals [s]).
    """

    scalar_table: dict = SCALARS
    history_table: dict = HISTORIES
    ledger_terms = LEDGER
    where: str = ""
    case_extra: dict = {}

    @property
    def mass(self) -> float:
        """Slider mass [kg]."""
        return self.slider.mass

    def describe(self) -> str:
        """Where it slides, the surface, the friction, the vertical, the mass, g and the scheme, in one line."""
        vertical = f", with its vertical read {self.vertical_sense}" if self.vertical else ""
        return (f"{self.where}{self.slider.describe_sliding()}, {self.slider.describe_friction()}{vertical}, "
                f"mass = {self.mass:g} kg, g = {self.slider.g:g} m/s2, method = {self.method} ({self.solved_by})")

    def case(self) -> dict:
        """What was solved, JSON-ready: the model, the scheme, the surface, the friction, mass, g, the vertical."""
        law = self.slider.friction
        friction = ({"mu": law.mu_slow} if law.is_coulomb else
                    {"mu_slow": law.mu_slow, "mu_fast": law.mu_fast, "mu_slow_ratio": law.slow_ratio, "rate": law.rate})
        return {"model": self.model, "method": self.method, "solved_by": self.solved_by, **self.case_extra,
                "radius": None if math.isinf(self.slider.radius) else self.slider.radius, **friction,
                "mass": self.mass, "g": self.slider.g, "vertical": self.vertical, "vertical_sense": self.vertical_sense}

    def case_units(self) -> dict[str, str]:
        """The units of :meth:`case`'s numbers."""
        return {name: UNITS["block_mass" if name == "mass" else "gravity" if name == "g" else name]
                for name, value in self.case().items() if isinstance(value, float)}

    def liftoff_notes(self) -> list[str]:
        """When the slider lifted off (g + a_v <= 0), the first six intervals [s]; none when it did not."""
        if not self.liftoff.size:
            return []
        shown = ", ".join(f"{start:.4g}-{end:.4g} s" for start, end in self.liftoff[:6])
        more = f" and {len(self.liftoff) - 6} more" if len(self.liftoff) > 6 else ""
        return [f"lifted off (g + a_v <= 0) {len(self.liftoff)} time(s): {shown}{more}"]

    def motion_notes(self) -> list[str]:
        """When the slider lifted off, one sentence (:meth:`liftoff_notes`); none when it did not."""
        return [f"The slider {note}." for note in self.liftoff_notes()[:1]]

    def more_variables(self) -> dict:
        """The intervals of lift-off [s], (k, 2) on ``liftoff`` and ``bound``."""
        return {"liftoff_intervals": (("liftoff", "bound"), self.liftoff.reshape(-1, 2), {
            "units": UNITS["time"], "long_name": "start and end of each interval of lift-off"})}


@dataclass(frozen=True)
class PendulumResponse(SliderResult, Result):
    """One solved case of the pendulum model.

    Attributes
    ----------
    slider:
        The slider (:class:`~stickslip.models.pendulum.case.PendulumCase`).
    method:
        The scheme (``"exact"`` or ``"integrated"``).
    solved_by:
        How: ``"closed form"`` or ``"integration to a relative tolerance of 1e-10"``.
    motion:
        The motion's name.
    vertical:
        The vertical component's file, or None.
    vertical_sense:
        How the vertical's sense was read (``"positive up (UP in its component)"``), or None.
    ground_acceleration:
        The horizontal ground acceleration [m/s²] at the samples.
    vertical_acceleration:
        The vertical ground acceleration a_v [m/s², positive up] at the samples, or None.
    history:
        The kernel's history per unit mass (:func:`~stickslip.solvers.ledger.history_dict`).
    liftoff:
        The intervals of lift-off, (k, 2) start and end times [s].
    """

    model = "pendulum"

    slider: PendulumCase
    method: str
    solved_by: str
    motion: str
    vertical: str | None
    vertical_sense: str | None
    ground_acceleration: np.ndarray = field(repr=False)
    vertical_acceleration: np.ndarray | None = field(repr=False)
    history: dict = field(repr=False)
    liftoff: np.ndarray = field(repr=False)

    @property
    def time(self) -> np.ndarray:
        """Sample times [s]."""
        return self.history["time"]

    def histories(self) -> dict[str, np.ndarray]:
        """Every history of :data:`HISTORIES`, energies for the slider's mass [J]; a_v [m/s²] with a vertical."""
        values = {"ground_acceleration": self.ground_acceleration}
        values.update({name: self.history[name] * (self.mass if unit == "J" else 1.0)
                       for name, (unit, _) in HISTORIES.items()
                       if name not in ("ground_acceleration", "vertical_acceleration")})
        if self.vertical_acceleration is not None:
            values["vertical_acceleration"] = self.vertical_acceleration
        return values

    def end_values(self) -> dict[str, float]:
        """The kernel's end results per unit mass."""
        return self.history["scalars"]

    @property
    def never_slides(self) -> str | None:
        """Why the slider never left rest (its peak beside μ(0)·(g + a_v)); None when it slid."""
        from stickslip.records.record import Record
        from stickslip.records.vertical import WithVertical

        if self.history["scalars"]["n_slip_episodes"] or self.history["scalars"]["liftoff_time"]:
            return None
        horizontal = Record(self.ground_acceleration, float(self.time[1] - self.time[0]))
        motion = horizontal if self.vertical_acceleration is None else WithVertical(
            horizontal, Record(self.vertical_acceleration, horizontal.dt), "")
        return self.slider.still_reason(motion)

    def notes(self) -> list[str]:
        """What the energies are, and when the slider lifted off."""
        return [LEDGER_NOTE + "; peak_base_shear is V/W", *self.liftoff_notes()]
