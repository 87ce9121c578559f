"""The response of a building with a friction tuned mass damper to one horizontal component.

A :class:`DamperResponse` holds the solved history of the building and its
damper (energies in J for the whole structure) and the answers of the two
references (:mod:`~stickslip.models.friction_tmd.references`).  Its energy
ledger, in the absolute formulation (docs/structures.md):

    E_k − E_k(0) + E_s + E_ζ + E_p + E_df = E_I   [J],

E_k = ½ Σ m_i (u̇_g + ẋ_i)² the absolute kinetic energy of the floors and the
damper, E_s = ½ xᵀ K x the building's strain energy, E_ζ = ∫ ẋᵀ C ẋ dt its
viscous work, E_p = N s²/(2 R_d) the damper's potential energy on its curved
surface, E_df = ∫ F ṡ dt the friction's work and E_I = ∫ (Σ m_i ü_i,abs) u̇_g dt
the absolute input.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from stickslip.models.friction_tmd.case import DamperCase
from stickslip.models.friction_tmd.references import RESPONSES
from stickslip.models.result import Result

#: The energies of the ledger's end results [J], in order: name -> long name.
ENERGIES = {
    "energy_dissipated": "energy dissipated by friction in the damper E_df at the end of the record",
    "energy_input": "absolute input energy E_I at the end of the record",
    "kinetic_energy": "absolute kinetic energy E_k of the floors and the damper at the end of the record",
    "strain_energy": "strain energy of the building E_s = x'Kx/2 at the end of the record",
    "viscous_energy": "energy dissipated by the building's damping E_zeta at the end of the record",
    "potential_energy": "potential energy of the damper on its curved surface E_p = N s^2/(2 R_d) at the end",
    "balance_residual": "largest |E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I| over the record",
}

#: The end results, in order: name -> (unit, long name).
SCALARS = {
    **{name: ("J", long_name) for name, long_name in ENERGIES.items()},
    "peak_damper_stroke": ("m", "largest |damper displacement relative to its floor| (the stroke)"),
    "residual_damper_stroke": ("m", "damper displacement relative to its floor at the end"),
    **RESPONSES,
    **{f"{name}_reduction": ("1", f"1 - with/without the damper, of the {name.replace('_', ' ')}")
       for name in RESPONSES},
    **{f"{name}_reduction_attached": ("1", f"1 - with the damper/with its mass attached, of the "
                                           f"{name.replace('_', ' ')}") for name in RESPONSES},
    "sliding_path": ("m", "total distance the damper slid on its floor"),
    "slip_fraction": ("1", "fraction of the record duration the damper spent sliding"),
    "n_slip_episodes": ("1", "number of stick-to-slip transitions of the damper"),
}

#: Histories of :meth:`DamperResponse.to_xarray` on ``time``: name -> (unit, long name).
HISTORIES = {
    "ground_acceleration": ("m s-2", "horizontal ground acceleration"),
    "relative_displacement": ("m", "damper displacement relative to its floor s (its stroke)"),
    "phase": ("1", "0 the damper holds, +1 / -1 slides with positive / negative relative velocity (just after the "
                   "time)"),
    "energy_dissipated": ("J", "cumulative energy dissipated by friction in the damper E_df"),
    "energy_input": ("J", "cumulative absolute input energy E_I"),
    "kinetic_energy": ("J", "absolute kinetic energy E_k of the floors and the damper"),
    "strain_energy": ("J", "strain energy of the building E_s"),
    "viscous_energy": ("J", "cumulative energy dissipated by the building's damping E_zeta"),
    "potential_energy": ("J", "potential energy of the damper on its curved surface E_p"),
    "balance_residual": ("J", "energy balance residual E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I"),
}

#: Histories on ``time`` and ``floor`` (1 the lowest): name -> (unit, long name).
FLOOR_HISTORIES = {
    "floor_displacement": ("m", "floor displacement relative to the ground"),
    "floor_acceleration": ("m s-2", "absolute floor acceleration"),
}

#: The terms of :meth:`DamperResponse.energy_ledger`.
LEDGER = ("energy_input", "energy_dissipated", "kinetic_energy", "strain_energy", "viscous_energy",
          "potential_energy", "balance_residual")

LEDGER_NOTE = ("energies [J]: E_k - E_k(0) + E_s + E_zeta + E_p + E_df = E_I; strain_energy E_s and viscous_energy "
               "E_zeta are the building's, potential_energy E_p = N s^2/(2 R_d) the damper's on its curved surface; "
               "each *_reduction is 1 - with/without the damper, *_reduction_attached 1 - with the damper/with its "
               "mass rigidly attached")


@dataclass(frozen=True)
class DamperResponse(Result):
    """One solved building with its damper.

    Attributes
    ----------
    damper:
        The building and its damper (:class:`~stickslip.models.friction_tmd.case.DamperCase`).
    method:
        The scheme.
    history:
        The histories of :data:`HISTORIES` and :data:`FLOOR_HISTORIES` at the samples (energies [J]) with ``time``
        [s], and ``scalars``: the end results of :data:`SCALARS` but ``balance_residual`` (energies [J]).
    references:
        ``bare_structure`` and ``attached_mass``: the references' answers
        (:func:`~stickslip.models.friction_tmd.references.reference_answers`).
    answers:
        The lists per story and floor (``peak_story_drifts`` [m], ``peak_floor_accelerations`` [m/s²]).
    """

    model = "friction-tmd"
    scalar_table = SCALARS
    history_table = HISTORIES
    ledger_terms = LEDGER

    damper: DamperCase
    method: str
    history: dict = field(repr=False)
    references: dict = field(repr=False)
    answers: dict = field(repr=False)

    @property
    def mass(self) -> float:
        """The building's mass m_s [kg]."""
        return self.damper.mass

    @property
    def time(self) -> np.ndarray:
        """Sample times [s]."""
        return self.history["time"]

    def histories(self) -> dict[str, np.ndarray]:
        return {name: self.history[name] for name in HISTORIES}

    def end_values(self) -> dict[str, float]:
        """The end results, energies per kg of the building (the base's :meth:`scalars` multiplies by m_s)."""
        return {name: value / self.mass if SCALARS[name][0] == "J" else value
                for name, value in self.history["scalars"].items()}

    def more_variables(self) -> dict:
        """The floors' histories, on ``time`` and ``floor``."""
        return {name: (("time", "floor"), self.history[name], {"units": unit, "long_name": long_name})
                for name, (unit, long_name) in FLOOR_HISTORIES.items()}

    def extras(self) -> dict:
        """The answers per story and floor, and the references' answers, JSON-ready."""
        return {**self.answers, **self.references}

    def describe(self) -> str:
        return (f"damper {self.damper.describe_sliding()}, mu = {self.damper.mu:g}, building mass = "
                f"{self.mass:g} kg, g = {self.damper.g:g} m/s2, method = {self.method}")

    def case(self) -> dict:
        return {"model": self.model, "method": self.method, "mu": self.damper.mu, **self.damper.settings()}

    def case_units(self) -> dict[str, str]:
        return {"mu": "1", **self.damper.settings_units()}

    @property
    def never_slides(self) -> str | None:
        if self.history["scalars"]["sliding_path"] > 0.0:
            return None
        from stickslip.records.record import Record

        return self.damper.still_reason(Record(self.history["ground_acceleration"],
                                               float(self.time[1] - self.time[0])))

    def notices(self) -> list[str]:
        return [] if self.never_slides is None else [f"the damper never slides: {self.never_slides}, so E_df = 0"]

    def notes(self) -> list[str]:
        return [LEDGER_NOTE]
