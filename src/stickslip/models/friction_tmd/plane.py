"""The building with its friction damper in the plane: a pair of components, the vertical, μ(v); integrated.

The building and damper of :class:`~stickslip.models.friction_tmd.case.DamperCase`
in both horizontal directions; the damper's normal force is N = m_d·(g + a_v)
(the building itself has no vertical degree of freedom), and where it
vanishes the damper lifts off its floor.  Solved by
:func:`~stickslip.solvers.structure.integrated.solve_structure_in_plane`
(docs/structures.md, "In the plane").  The answers are the one direction's
as vector magnitudes over the samples (the peak |floor displacement|, |drift|,
|floor acceleration|, |base shear|/W, the stroke |s|), each beside the two
linear references solved in each direction
(:func:`~stickslip.models.friction_tmd.references.plane_reference_answers`).
The ledger [J]: E_k − E_k(0) + E_s + E_ζ + E_p + E_df = E_I + W_v.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from stickslip.models.friction_tmd.references import plane_reference_answers, structure_answers
from stickslip.models.friction_tmd.response import HISTORIES, LEDGER_NOTE, SCALARS, DamperResponse
from stickslip.models.friction_tmd.solve import _end_results

#: The end results in the plane: the one direction's, the vertical's work and the time lifted off.
PLANE_SCALARS = {
    **{name: SCALARS[name] for name in ("energy_dissipated", "energy_input")},
    "energy_input_vertical": ("J", "work of the vertical ground motion through the damper's normal force on its "
                                   "curved surface W_v at the end of the record"),
    **{name: value for name, value in SCALARS.items() if name not in ("energy_dissipated", "energy_input",
                                                                       "balance_residual", "residual_damper_stroke")},
    "residual_damper_stroke": ("m", "|damper displacement relative to its floor| at the end"),
    "balance_residual": ("J", "largest |E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I - W_v| over the record"),
    "liftoff_time": ("s", "total time the damper is lifted off its floor (g + a_v <= 0)"),
}

#: The histories in the plane: name -> (unit, long name); vectors on ``time`` and ``component`` (the axes).
PLANE_HISTORIES = {
    "ground_acceleration": ("m s-2", "horizontal ground acceleration, on the pair's axes"),
    "relative_displacement": ("m", "damper displacement relative to its floor s (its stroke), on the pair's axes"),
    "phase": ("1", "0 the damper holds, 1 slides, 2 lifted off (just after the time)"),
    "normal_force": ("N", "the damper's normal force N = m_d (g + a_v), 0 lifted off"),
    **{name: value for name, value in HISTORIES.items() if name not in ("ground_acceleration",
                                                                         "relative_displacement", "phase",
                                                                         "balance_residual")},
    "energy_input_vertical": ("J", "cumulative work of the vertical ground motion through the normal force W_v"),
    "balance_residual": ("J", "energy balance residual E_k - E_k(0) + E_s + E_zeta + E_p + E_df - E_I - W_v"),
}

#: The ledger's terms in the plane.
PLANE_LEDGER = ("energy_input", "energy_input_vertical", "energy_dissipated", "kinetic_energy", "strain_energy",
                "viscous_energy", "potential_energy", "balance_residual")


def _solved(case, plane, history, references: dict) -> tuple[dict, dict]:
    """(the end results of :data:`PLANE_SCALARS` but ``balance_residual``, energies in J; the damper's answers) of
    the plane's ``history`` of ``case`` on the :class:`~stickslip.solvers.structure.plane_motion.PlaneMotion`
    ``plane`` beside the ``references``' answers."""
    from stickslip.solvers.structure.plane_motion import plane_peaks

    answers = structure_answers(case, plane_peaks(case.tracked, history, plane.ground_acceleration))
    sliding = {**{name: float(getattr(history, name)[-1]) for name in (
                  "kinetic_energy", "strain_energy", "viscous_energy", "potential_energy", "energy_dissipated",
                  "energy_input")},
               "peak_slip": history.peak_slip, "residual_slip": float(np.hypot(*history.slip[-1])),
               "sliding_path": float(history.sliding_path[-1]), "slip_time": history.slip_time,
               "n_slip_episodes": history.n_slip_episodes}
    found = _end_results(case, sliding, answers, references, (history.slip.shape[0] - 1) * plane.dt)
    found.update(energy_input_vertical=float(history.energy_input_vertical[-1]), liftoff_time=history.flight_time)
    return {name: float(found[name]) for name in PLANE_SCALARS if name != "balance_residual"}, answers


@dataclass(frozen=True)
class DamperPlaneResponse(DamperResponse):
    """One building with its damper solved in the plane; ``history`` holds the plane's histories (vectors (samples,
    2), the floors' (samples, n, 2)) and ``motion`` the :class:`~stickslip.solvers.structure.plane_motion.PlaneMotion`."""

    scalar_table = PLANE_SCALARS
    history_table = PLANE_HISTORIES
    ledger_terms = PLANE_LEDGER
    response_panels = (("ground acceleration\n[m/s2]", ("ground_acceleration",)),
                       ("damper stroke s\n[m]", ("relative_displacement",)),
                       ("normal force on\nthe damper N [N]", ("normal_force",)))

    motion: object = None

    def histories(self) -> dict[str, np.ndarray]:
        return {name: self.history[name] for name in PLANE_HISTORIES}

    def end_values(self) -> dict[str, float]:
        return {name: value / self.mass if PLANE_SCALARS[name][0] == "J" else value
                for name, value in self.history["scalars"].items()}

    def coordinates(self) -> dict:
        """``component``: the axes (the pair's components); ``floor``: 1 … n."""
        return {"component": ("component", list(self.motion.axes)),
                "floor": ("floor", np.arange(1, self.damper.stories + 1), {"long_name": "floor j, 1 the lowest"})}

    def more_variables(self) -> dict:
        """The floors' vectors, on ``time``, ``floor`` and ``component``."""
        return {name: (("time", "floor", "component"), self.history[name], {"units": unit, "long_name": long_name})
                for name, (unit, long_name) in {
                    "floor_displacement": ("m", "floor displacement relative to the ground"),
                    "floor_acceleration": ("m s-2", "absolute floor acceleration")}.items()}

    def describe(self) -> str:
        return (f"{self.motion.name}: damper {self.damper.describe_sliding()}, {self.damper.friction.describe()}, "
                f"building mass = {self.mass:g} kg, g = {self.damper.g:g} m/s2, method = {self.method} (integrated in the plane, events located)")

    def case(self) -> dict:
        return {**super().case(), "motion": self.motion.kind}

    @property
    def never_slides(self) -> str | None:
        scalars = self.history["scalars"]
        if scalars["sliding_path"] > 0.0 or scalars["liftoff_time"] > 0.0:
            return None
        return self.damper.still_reason(self.motion)

    def notes(self) -> list[str]:
        return [LEDGER_NOTE.replace("= E_I;", "= E_I + W_v (W_v the vertical's work through the normal force);")
                + "; in the plane, peaks are of vector magnitudes at the samples, the references' too"]


def solve_in_plane(motion, case, method: str, rtol=None) -> DamperPlaneResponse:
    """The :class:`DamperPlaneResponse` of the building and damper ``case`` on ``motion`` (a component or a pair,
    either with its vertical), ``rtol`` the relative tolerance per step (default 1e-10)."""
    from stickslip.solvers.plane.record import RTOL
    from stickslip.solvers.structure.plane_motion import plane_motion, solve_on_motion

    plane = plane_motion(motion)
    solved = solve_on_motion(case.system, plane, case.friction, case.g, RTOL if rtol is None else rtol)
    references = plane_reference_answers(case, plane.ground_acceleration, plane.dt)
    scalars, answers = _solved(case, plane, solved, references)
    n = case.stories
    flying = solved.normal_force <= 0.0
    history = {"time": np.arange(solved.slip.shape[0]) * plane.dt, "ground_acceleration": plane.ground_acceleration,
               "relative_displacement": solved.slip,
               "phase": np.where(flying, 2, np.where(solved.moving > 0.5, 1, 0)).astype(np.int8),
               "floor_displacement": solved.displacement[:, :n], "floor_acceleration":
                   solved.absolute_acceleration[:, :n], "scalars": scalars,
               **{name: getattr(solved, name) for name in ("normal_force", *PLANE_LEDGER)}}
    lists = {name: np.asarray(answers[name]).tolist() for name in ("peak_story_drifts", "peak_floor_accelerations")}
    return DamperPlaneResponse(case, method, history, references, lists, plane)


def sweep_in_plane(motions, case, values, rtol=None) -> dict:
    """End results of every motion at every friction ratio of ``values`` [1] (μ_fast of a velocity law), by name,
    shape (motions, values), energies in J: one integration per motion and value, the references once per motion."""
    from stickslip.solvers.plane.record import RTOL
    from stickslip.solvers.structure.plane_motion import integration_progress, plane_motion, solve_on_motion

    found = {name: np.empty((len(motions), len(values))) for name in PLANE_SCALARS if name != "balance_residual"}
    with integration_progress(len(motions) * len(values)) as bar:
        for i, motion in enumerate(motions):
            plane = plane_motion(motion)
            references = plane_reference_answers(case, plane.ground_acceleration, plane.dt)
            for j, value in enumerate(values):
                at = case.at("mu", value)
                solved = solve_on_motion(at.system, plane, at.friction, at.g, RTOL if rtol is None else rtol)
                for name, number in _solved(at, plane, solved, references)[0].items():
                    found[name][i, j] = number
                bar.update()
    return found
