"""The building with its damper solved: one record (its histories), or many records over a grid of μ (end results).

Both run the exact friction-linked solver
(:mod:`stickslip.solvers.structure.friction_linked`) on the damper's
structure with the rows of :attr:`~stickslip.models.friction_tmd.case.DamperCase.tracked`,
and the two references once per record (:mod:`~stickslip.models.friction_tmd.references`).
"""

from __future__ import annotations

import numpy as np

from stickslip.models.friction_tmd.references import RESPONSES, reductions, reference_answers, structure_answers
from stickslip.models.friction_tmd.response import DamperResponse


def _end_results(case, sliding: dict, answers: dict, references: dict, durations) -> dict:
    """The end results of :data:`~stickslip.models.friction_tmd.response.SCALARS` (but ``balance_residual``) from
    the solver's end values ``sliding`` (stroke, ledger, path, time slid, episodes), the damper's ``answers`` and
    the ``references``' (numbers, or arrays over records and μ)."""
    return {**{name: sliding[name] for name in ("energy_dissipated", "energy_input", "kinetic_energy",
                                                "strain_energy", "viscous_energy", "potential_energy")},
            "peak_damper_stroke": sliding["peak_slip"], "residual_damper_stroke": sliding["residual_slip"],
            **{name: answers[name] for name in RESPONSES}, **reductions(answers, references),
            "sliding_path": sliding["sliding_path"], "slip_fraction": sliding["slip_time"] / durations,
            "n_slip_episodes": sliding["n_slip_episodes"]}


def solve_motion(motion, case, method: str) -> DamperResponse:
    """The :class:`DamperResponse` of the building and damper ``case`` on one component ``motion``."""
    from stickslip.solvers.structure.friction_linked import friction_linked_history

    acceleration, dt = motion.acceleration, float(motion.dt)
    solved = friction_linked_history(case.system, acceleration, dt, case.mu, case.tracked)
    references = reference_answers(case, acceleration, dt)
    answers = {name: np.asarray(value).tolist() for name, value in structure_answers(case, solved.peaks).items()}
    ledger = ("kinetic_energy", "strain_energy", "viscous_energy", "potential_energy", "energy_dissipated",
              "energy_input")
    sliding = {**{name: float(getattr(solved, name)[-1]) for name in ledger}, "peak_slip": solved.peak_slip,
               "residual_slip": float(solved.slip[-1]), "sliding_path": float(solved.sliding_path[-1]),
               "slip_time": solved.slip_time, "n_slip_episodes": solved.n_slip_episodes}
    scalars = {name: float(value) for name, value in
               _end_results(case, sliding, answers, references, (acceleration.size - 1) * dt).items()}
    n = case.stories
    history = {"time": np.arange(acceleration.size) * dt, "ground_acceleration": acceleration,
               "relative_displacement": solved.slip, "phase": solved.phase,
               "floor_displacement": solved.displacement[:, :n],
               "floor_acceleration": solved.absolute_acceleration[:, :n], "scalars": scalars,
               **{name: getattr(solved, name) for name in (*ledger, "balance_residual")}}
    lists = {name: answers[name] for name in ("peak_story_drifts", "peak_floor_accelerations")}
    return DamperResponse(case, method, history, references, lists)


def sweep_motions(motions, case, values) -> dict:
    """End results of every motion at every friction ratio of ``values`` [1], by name, shape (motions, values);
    energies in J."""
    from stickslip.solvers.structure.friction_linked import friction_linked_sweep

    motions = list(motions)
    swept = friction_linked_sweep(case.system, [motion.acceleration for motion in motions],
                                  [motion.dt for motion in motions], values, tracked=case.tracked)
    each = [reference_answers(case, motion.acceleration, motion.dt) for motion in motions]
    references = {name: {response: np.array([found[name][response] for found in each])[:, None]
                         for response in RESPONSES} for name in ("bare_structure", "attached_mass")}
    durations = np.array([(motion.acceleration.size - 1) * motion.dt for motion in motions])[:, None]
    sliding = {name: getattr(swept, name) for name in swept._fields}
    return _end_results(case, sliding, structure_answers(case, swept.peaks), references, durations)
