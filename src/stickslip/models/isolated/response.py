"""The isolated building solved: its answers (the designer's), its histories and its energy ledger.

:func:`solve_motion` solves one building on one record with the exact
friction-linked solver (:mod:`stickslip.solvers.structure.friction_linked`),
:func:`sweep_motions` many records over a grid of μ with its parallel
end-values kernel; :class:`IsolatedResponse` is the result.  Energies in J for
the whole building, the ledger E_k − E_k(0) + E_s + E_ζ + E_p + E_df = E_I
(docs/structures.md).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from stickslip.models.result import Result

#: The end results: name -> (unit, long name).
SCALARS = {
    "peak_isolator_displacement": ("m", "largest |isolator displacement u_b| relative to the ground"),
    "residual_isolator_displacement": ("m", "isolator displacement u_b at the end of the record"),
    "peak_drift": ("m", "largest peak story drift over the stories"),
    "peak_floor_acceleration": ("m s-2", "largest peak absolute floor acceleration over the floors 1..n"),
    "base_shear_coefficient": ("1", "peak isolator force over the weight, V_b/W"),
    "superstructure_shear_coefficient": ("1", "peak superstructure shear on the base over its weight, V_s/W_s"),
    "energy_dissipated": ("J", "energy dissipated by the isolator's friction E_df at the end of the record"),
    "energy_input": ("J", "absolute input energy E_I at the end of the record"),
    "viscous_energy": ("J", "energy dissipated by the superstructure's damping E_zeta at the end of the record"),
    "kinetic_energy": ("J", "absolute kinetic energy E_k at the end of the record"),
    "strain_energy": ("J", "strain energy of the superstructure E_s at the end of the record"),
    "potential_energy": ("J", "potential energy on the isolator's surface E_p at the end of the record"),
    "balance_residual": ("J", "largest |E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I| over the record"),
    "sliding_path": ("m", "total distance slid by the isolator"),
    "slip_fraction": ("1", "fraction of the record duration the isolator slides"),
    "n_slip_episodes": ("1", "number of hold-to-slide transitions of the isolator"),
}

#: The histories: name -> (unit, long name); a story's drift and a floor's acceleration on ``component``.
HISTORIES = {
    "isolator_displacement": ("m", "isolator displacement u_b relative to the ground"),
    "isolator_force": ("N", "isolator force V_b = (W/R) u_b + F"),
    "story_drift": ("m", "story drift (story j: floor j less the floor below)"),
    "floor_acceleration": ("m s-2", "absolute floor acceleration (floor j)"),
    "energy_input": ("J", "cumulative absolute input energy E_I"),
    "energy_dissipated": ("J", "cumulative energy dissipated by friction E_df"),
    "viscous_energy": ("J", "cumulative energy dissipated by the superstructure's damping E_zeta"),
    "kinetic_energy": ("J", "absolute kinetic energy E_k"),
    "strain_energy": ("J", "strain energy of the superstructure E_s"),
    "potential_energy": ("J", "potential energy on the isolator's surface E_p"),
    "balance_residual": ("J", "energy balance residual E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I"),
}

#: The ledger's terms: E_k − E_k(0) + E_s + E_ζ + E_p + E_df − E_I = residual.
LEDGER = ("energy_input", "energy_dissipated", "viscous_energy", "kinetic_energy", "strain_energy",
          "potential_energy", "balance_residual")


def _answers(case, peaks: np.ndarray) -> dict:
    """The peak answers from the tracked rows' peaks (:attr:`IsolatedCase.tracked`), trailing axis the rows."""
    n = case.stories
    drifts, accelerations = peaks[..., :n], peaks[..., n:2 * n]
    return {"peak_drift": drifts.max(axis=-1), "peak_floor_acceleration": accelerations.max(axis=-1),
            "base_shear_coefficient": peaks[..., 2 * n] / case.weight,
            "superstructure_shear_coefficient": peaks[..., 2 * n + 1] / (case.superstructure_mass * case.g),
            "peak_story_drifts": drifts, "peak_floor_accelerations": accelerations}


@dataclass(frozen=True)
class IsolatedResponse(Result):
    """One solved isolated building: the solver's history (``history``) and the case."""

    model = "isolated"
    scalar_table = SCALARS
    history_table = HISTORIES
    ledger_terms = LEDGER
    response_panels = (("isolator displacement\nu_b [m]", ("isolator_displacement",)),
                       ("story drift [m]", ("story_drift",)),
                       ("absolute floor\nacceleration [m/s2]", ("floor_acceleration",)))
    hysteresis = ("isolator_displacement", "isolator_force", "the isolator's force V_b [N] against u_b [m]")

    building: object
    method: str
    history: object = field(repr=False)
    dt: float = 0.0
    ground_acceleration: np.ndarray = field(default=None, repr=False)

    @property
    def mass(self) -> float:
        """The building's total mass m_b + m_s [kg]."""
        return self.building.mass

    @property
    def time(self) -> np.ndarray:
        """Sample times [s]."""
        return np.arange(self.history.slip.size) * self.dt

    @property
    def answers(self) -> dict:
        """The peak answers (:func:`_answers`)."""
        return _answers(self.building, self.history.peaks)

    def histories(self) -> dict[str, np.ndarray]:
        history = self.history
        x = history.displacement
        return {"isolator_displacement": x[:, 0], "isolator_force": history.interface_force,
                "story_drift": np.diff(x, axis=1), "floor_acceleration": history.absolute_acceleration[:, 1:],
                **{name: getattr(history, name) for name in LEDGER}}

    def coordinates(self) -> dict:
        """``component``: the story (and floor) j = 1 … n of the drifts and floor accelerations."""
        return {"component": ("component", np.arange(1, self.building.stories + 1),
                              {"long_name": "story j (drift) or floor j (acceleration), 1 the lowest"})}

    def end_values(self) -> dict[str, float]:
        """The end results, energies per unit of the total mass (the base scales them back)."""
        history, answers = self.history, self.answers
        duration = (history.slip.size - 1) * self.dt
        energies = {name: float(getattr(history, name)[-1]) / self.mass
                    for name in ("energy_dissipated", "energy_input", "viscous_energy", "kinetic_energy",
                                 "strain_energy", "potential_energy")}
        return {"peak_isolator_displacement": history.peak_slip,
                "residual_isolator_displacement": float(history.slip[-1]),
                **{name: float(answers[name]) for name in ("peak_drift", "peak_floor_acceleration",
                                                           "base_shear_coefficient",
                                                           "superstructure_shear_coefficient")},
                **energies, "sliding_path": float(history.sliding_path[-1]),
                "slip_fraction": history.slip_time / duration if duration > 0 else 0.0,
                "n_slip_episodes": history.n_slip_episodes}

    def extras(self) -> dict:
        """``peak_story_drifts`` [m] (story 1 first) and ``peak_floor_accelerations`` [m/s²] (floor 1 first)."""
        answers = self.answers
        return {"peak_story_drifts": answers["peak_story_drifts"].tolist(),
                "peak_floor_accelerations": answers["peak_floor_accelerations"].tolist()}

    def describe(self) -> str:
        return (f"{self.building.describe_sliding()}, mu = {self.building.mu:g}, mass = {self.mass:g} kg, "
                f"g = {self.building.g:g} m/s2, method = {self.method}")

    def case(self) -> dict:
        return {"model": self.model, "method": self.method, "mu": self.building.mu, **self.building.settings()}

    def case_units(self) -> dict[str, str]:
        return {"mu": "1", **self.building.settings_units()}

    @property
    def never_slides(self) -> str | None:
        if self.history.n_slip_episodes:
            return None
        from stickslip.records.record import Record

        return self.building.still_reason(Record(self.ground_acceleration, self.dt))

    def notices(self) -> list[str]:
        reason = self.never_slides
        return [] if reason is None else [f"the isolator never slides: {reason}, so E_df = 0"]

    def notes(self) -> list[str]:
        return ["energies [J]: E_k - E_k(0) + E_s + E_zeta + E_p + E_df = E_I (strain, viscous, potential on the "
                "surface, friction); peak_story_drifts and peak_floor_accelerations list story (floor) 1 first"]


def solve_motion(motion, case, method: str) -> IsolatedResponse:
    """The :class:`IsolatedResponse` of the building ``case`` on one component ``motion``."""
    from stickslip.solvers.structure.friction_linked import friction_linked_history

    history = friction_linked_history(case.system, motion.acceleration, motion.dt, case.mu, tracked=case.tracked)
    return IsolatedResponse(case, method, history, float(motion.dt), motion.acceleration)


def sweep_motions(motions, case, values) -> dict:
    """End results of every motion at every friction ratio of ``values`` [1], by name, shape (motions, values);
    energies in J."""
    from stickslip.solvers.structure.friction_linked import friction_linked_sweep

    sweep = friction_linked_sweep(case.system, [motion.acceleration for motion in motions],
                                  [motion.dt for motion in motions], values, tracked=case.tracked)
    answers = _answers(case, sweep.peaks)
    durations = np.array([(motion.acceleration.size - 1) * motion.dt for motion in motions])[:, None]
    found = {"peak_isolator_displacement": sweep.peak_slip, "residual_isolator_displacement": sweep.residual_slip,
             **{name: answers[name] for name in ("peak_drift", "peak_floor_acceleration", "base_shear_coefficient",
                                                 "superstructure_shear_coefficient")},
             "energy_dissipated": sweep.energy_dissipated, "energy_input": sweep.energy_input,
             "viscous_energy": sweep.viscous_energy, "kinetic_energy": sweep.kinetic_energy,
             "strain_energy": sweep.strain_energy, "potential_energy": sweep.potential_energy,
             "sliding_path": sweep.sliding_path, "slip_fraction": sweep.slip_time / durations,
             "n_slip_episodes": sweep.n_slip_episodes}
    return found
