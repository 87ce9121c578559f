"""The isolated building in the plane: a pair of components, the vertical, μ(v); integrated to a tolerance.

The building of :class:`~stickslip.models.isolated.case.IsolatedCase` in both
horizontal directions, its isolator under N = W·(1 + a_v/g) (W the total
weight; lift-off where N vanishes) with Coulomb friction or μ(v), solved by
:func:`~stickslip.solvers.structure.integrated.solve_structure_in_plane`
(docs/structures.md, "In the plane").  The answers are the one direction's,
as vector magnitudes over the samples: the peak |u_b|, each story's peak
|drift vector|, each floor's peak |absolute acceleration vector|, the peak
|V_b|/W and |V_s|/W_s; the residual isolator displacement is |u_b| at the
end.  The ledger [J]: E_k − E_k(0) + E_s + E_ζ + E_p + E_df = E_I + W_v, W_v
the vertical motion's work through the normal force on the curved surface.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from stickslip.models.isolated.response import HISTORIES, SCALARS, _answers
from stickslip.models.result import Result

#: The end results in the plane: name -> (unit, long name).
PLANE_SCALARS = {
    **{name: SCALARS[name] for name in ("peak_isolator_displacement",)},
    "residual_isolator_displacement": ("m", "|isolator displacement u_b| at the end of the record"),
    "peak_drift": ("m", "largest peak |story drift vector| over the stories"),
    "peak_floor_acceleration": ("m s-2", "largest peak |absolute floor acceleration vector| over the floors 1..n"),
    "base_shear_coefficient": ("1", "peak |isolator force vector| over the weight, V_b/W"),
    "superstructure_shear_coefficient": ("1", "peak |superstructure shear on the base| over its weight, V_s/W_s"),
    **{name: SCALARS[name] for name in ("energy_dissipated", "energy_input")},
    "energy_input_vertical": ("J", "work of the vertical ground motion through the normal force on the curved "
                                   "surface W_v at the end of the record"),
    **{name: SCALARS[name] for name in ("viscous_energy", "kinetic_energy", "strain_energy", "potential_energy")},
    "balance_residual": ("J", "largest |E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I - W_v| over the record"),
    "sliding_path": ("m", "length of the path slid by the isolator"),
    "slip_fraction": ("1", "fraction of the record duration the isolator slides (lift-off apart)"),
    "n_slip_episodes": SCALARS["n_slip_episodes"],
    "liftoff_time": ("s", "total time the isolator is lifted off its surface (N = W (1 + a_v/g) <= 0)"),
}

#: The histories in the plane: name -> (unit, long name); vectors on ``time`` and ``component`` (the axes).
PLANE_HISTORIES = {
    "isolator_displacement": ("m", "isolator displacement u_b relative to the ground, on the pair's axes"),
    "isolator_force": ("N", "isolator force V_b = (N/R) u_b + F, on the pair's axes"),
    "largest_story_drift": ("m", "largest |story drift vector| over the stories"),
    "largest_floor_acceleration": ("m s-2", "largest |absolute floor acceleration vector| over the floors"),
    "normal_force": ("N", "normal force on the isolator N = W (1 + a_v/g), 0 lifted off"),
    **{name: HISTORIES[name] for name in ("energy_input", "energy_dissipated")},
    "energy_input_vertical": ("J", "cumulative work of the vertical ground motion through the normal force W_v"),
    **{name: HISTORIES[name] for name in ("viscous_energy", "kinetic_energy", "strain_energy", "potential_energy")},
    "balance_residual": ("J", "energy balance residual E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I - W_v"),
}

#: The ledger's terms in the plane.
PLANE_LEDGER = ("energy_input", "energy_input_vertical", "energy_dissipated", "viscous_energy", "kinetic_energy",
                "strain_energy", "potential_energy", "balance_residual")

#: The energies at the end of the record, from the solver's history.
ENERGIES = ("energy_dissipated", "energy_input", "energy_input_vertical", "viscous_energy", "kinetic_energy",
            "strain_energy", "potential_energy")


def plane_end_values(case, motion, history) -> dict:
    """The end results of :data:`PLANE_SCALARS` but ``balance_residual``, energies in J, of the solved ``history``
    (:class:`~stickslip.solvers.structure.integrated.PlaneStructureHistory`) of ``case`` on the
    :class:`~stickslip.solvers.structure.plane_motion.PlaneMotion` ``motion``; with ``answers``, the
    peak answers of :func:`~stickslip.models.isolated.response._answers`."""
    from stickslip.solvers.structure.plane_motion import plane_peaks

    answers = _answers(case, plane_peaks(case.tracked, history, motion.ground_acceleration))
    duration = (history.slip.shape[0] - 1) * motion.dt
    return {"peak_isolator_displacement": history.peak_slip,
            "residual_isolator_displacement": float(np.hypot(*history.slip[-1])),
            **{name: float(answers[name]) for name in ("peak_drift", "peak_floor_acceleration",
                                                       "base_shear_coefficient", "superstructure_shear_coefficient")},
            **{name: float(getattr(history, name)[-1]) for name in ENERGIES},
            "sliding_path": float(history.sliding_path[-1]),
            "slip_fraction": history.slip_time / duration if duration > 0 else 0.0,
            "n_slip_episodes": history.n_slip_episodes, "liftoff_time": history.flight_time, "answers": answers}


@dataclass(frozen=True)
class IsolatedPlaneResponse(Result):
    """One isolated building solved in the plane: the case, the motion on its axes and the solver's history."""

    model = "isolated"
    scalar_table = PLANE_SCALARS
    history_table = PLANE_HISTORIES
    ledger_terms = PLANE_LEDGER
    response_panels = (("isolator displacement\nu_b [m]", ("isolator_displacement",)),
                       ("largest story\ndrift [m]", ("largest_story_drift",)),
                       ("largest absolute floor\nacceleration [m/s2]", ("largest_floor_acceleration",)))
    hysteresis = ("isolator_displacement", "isolator_force", "the isolator's force V_b [N] against u_b [m], per axis")

    building: object
    method: str
    motion: object = field(repr=False)
    history: object = field(repr=False)

    @property
    def mass(self) -> float:
        """The building's total mass m_b + m_s [kg]."""
        return self.building.mass

    @property
    def time(self) -> np.ndarray:
        """Sample times [s]."""
        return np.arange(self.history.slip.shape[0]) * self.motion.dt

    @cached_property
    def solved(self) -> dict:
        """:func:`plane_end_values` of the history."""
        return plane_end_values(self.building, self.motion, self.history)

    def _vectors(self) -> tuple[np.ndarray, np.ndarray]:
        """(story drift vectors (samples, n, 2) [m], story 1 first; floor absolute accelerations (samples, n, 2)
        [m/s²], floor 1 first)."""
        x = self.history.displacement
        return np.diff(x, axis=1), self.history.absolute_acceleration[:, 1:]

    def histories(self) -> dict[str, np.ndarray]:
        history = self.history
        drifts, accelerations = self._vectors()
        return {"isolator_displacement": history.slip, "isolator_force": history.interface_force,
                "largest_story_drift": np.max(np.linalg.norm(drifts, axis=2), axis=1),
                "largest_floor_acceleration": np.max(np.linalg.norm(accelerations, axis=2), axis=1),
                "normal_force": history.normal_force, **{name: getattr(history, name) for name in PLANE_LEDGER}}

    def coordinates(self) -> dict:
        """``component``: the axes (the pair's components); ``story``: j = 1 … n of the drifts and floors."""
        return {"component": ("component", list(self.motion.axes)),
                "story": ("story", np.arange(1, self.building.stories + 1),
                          {"long_name": "story j (drift) or floor j (acceleration), 1 the lowest"})}

    def more_variables(self) -> dict:
        """The story drift and floor acceleration vectors on ``time``, ``story`` and ``component``."""
        drifts, accelerations = self._vectors()
        return {"story_drift": (("time", "story", "component"), drifts, {
                    "units": "m", "long_name": "story drift (story j: floor j less the floor below)"}),
                "floor_acceleration": (("time", "story", "component"), accelerations, {
                    "units": "m s-2", "long_name": "absolute floor acceleration (floor j)"})}

    def end_values(self) -> dict[str, float]:
        """The end results, energies per unit of the total mass (the base scales them back)."""
        return {name: value / self.mass if PLANE_SCALARS[name][0] == "J" else value
                for name, value in self.solved.items() if name in PLANE_SCALARS}

    def extras(self) -> dict:
        """``peak_story_drifts`` [m] and ``peak_floor_accelerations`` [m/s²] (story, floor 1 first), the residual
        isolator displacement on the axes [m]."""
        answers = self.solved["answers"]
        return {"peak_story_drifts": answers["peak_story_drifts"].tolist(),
                "peak_floor_accelerations": answers["peak_floor_accelerations"].tolist(),
                "residual_isolator_displacement_components": self.history.slip[-1].tolist()}

    def describe(self) -> str:
        return (f"{self.motion.name}: {self.building.describe_sliding()}, {self.building.friction.describe()}, "
                f"mass = {self.mass:g} kg, g = {self.building.g:g} m/s2, method = {self.method} (integrated in the plane, events located)")

    def case(self) -> dict:
        return {"model": self.model, "method": self.method, "mu": self.building.mu, **self.building.settings(),
                "motion": self.motion.kind}

    def case_units(self) -> dict[str, str]:
        return {"mu": "1", **self.building.settings_units()}

    @property
    def never_slides(self) -> str | None:
        if self.history.n_slip_episodes or self.history.flight_time:
            return None
        return self.building.still_reason(self.motion)

    def notices(self) -> list[str]:
        reason = self.never_slides
        return [] if reason is None else [f"the isolator never slides: {reason}, so E_df = 0"]

    def notes(self) -> list[str]:
        return ["in the plane: peaks are of vector magnitudes at the samples; energies [J]: E_k - E_k(0) + E_s + "
                "E_zeta + E_p + E_df = E_I + W_v (W_v the vertical's work through the normal force on the curved "
                "surface); peak_story_drifts and peak_floor_accelerations list story (floor) 1 first"]


def solve_in_plane(motion, case, method: str, rtol=None) -> IsolatedPlaneResponse:
    """The :class:`IsolatedPlaneResponse` of the building ``case`` on ``motion`` (a component or a pair, either with
    its vertical), ``rtol`` the relative tolerance per step (default 1e-10)."""
    from stickslip.solvers.plane.record import RTOL
    from stickslip.solvers.structure.plane_motion import plane_motion, solve_on_motion

    plane = plane_motion(motion)
    history = solve_on_motion(case.system, plane, case.friction, case.g, RTOL if rtol is None else rtol)
    return IsolatedPlaneResponse(case, method, plane, history)


def sweep_in_plane(motions, case, values, rtol=None) -> dict:
    """End results of every motion at every friction ratio of ``values`` [1] (μ_fast of a velocity law), by name,
    shape (motions, values), energies in J: one integration per motion and value."""
    from stickslip.solvers.structure.plane_motion import integration_progress

    found = {name: np.empty((len(motions), len(values))) for name in PLANE_SCALARS if name != "balance_residual"}
    with integration_progress(len(motions) * len(values)) as bar:
        for i, motion in enumerate(motions):
            for j, value in enumerate(values):
                solved = solve_in_plane(motion, case.at("mu", value), "", rtol).solved
                for name in found:
                    found[name][i, j] = solved[name]
                bar.update()
    return found
