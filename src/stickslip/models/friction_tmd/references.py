"""The building's answers, with the damper and without: peaks of displacement, drift, floor acceleration, base shear.

The damper is judged against two linear buildings, each solved exactly by
the first-order hold of :func:`~stickslip.solvers.structure.linear_response.linear_history`:
the **bare** building (no damper) and the building with the damper's mass
**attached** rigidly to its floor (μ → ∞).  For each response r of
:data:`RESPONSES`, the reduction is 1 − r/r_bare (``{r}_reduction``) and
1 − r/r_attached (``{r}_reduction_attached``): positive where the damper
does better.
"""

from __future__ import annotations

import math

import numpy as np

from stickslip.solvers.structure.linear_response import LinearHistory, linear_history

#: The building's answers: name -> (unit, long name); the lists per story or floor are the ``..._drifts`` and
#: ``..._accelerations`` of :func:`structure_answers`, floor 1 (story 1) first.
RESPONSES = {
    "peak_structure_displacement": ("m", "largest |floor displacement relative to the ground| over the floors"),
    "peak_drift": ("m", "largest |story drift| over the stories"),
    "peak_floor_acceleration": ("m s-2", "largest |absolute floor acceleration| over the floors"),
    "base_shear_coefficient": ("1", "peak base shear of the building over its weight, V_b/W (W = m_s g)"),
}


def structure_answers(building, displacement: np.ndarray, velocity: np.ndarray, absolute_acceleration: np.ndarray,
                      g: float) -> dict:
    """The peaks of the ``building``'s floors, given their ``displacement`` [m] and ``velocity`` [m/s] relative to
    the ground and their ``absolute_acceleration`` [m/s²] at the samples, arrays (samples, n); ``g`` [m/s²].

    The story drifts are δ_1 = x_1, δ_j = x_j − x_{j−1}; the base shear is the first story's,
    V_b = 1ᵀ(K_b x + C_b ẋ) [N] (the force the ground gives the building), over W = m_s·g.
    """
    drifts = np.diff(displacement, axis=1, prepend=0.0)
    shear = displacement @ building.stiffness_matrix.sum(axis=0) + velocity @ building.damping_matrix.sum(axis=0)
    story_drifts = np.max(np.abs(drifts), axis=0)
    floor_accelerations = np.max(np.abs(absolute_acceleration), axis=0)
    return {"peak_structure_displacement": float(np.max(np.abs(displacement))),
            "peak_drift": float(np.max(story_drifts)), "peak_story_drifts": story_drifts.tolist(),
            "peak_floor_acceleration": float(np.max(floor_accelerations)),
            "peak_floor_accelerations": floor_accelerations.tolist(),
            "base_shear_coefficient": float(np.max(np.abs(shear)) / (building.total_mass * g))}


def bare_history(case, acceleration: np.ndarray, dt: float) -> LinearHistory:
    """The bare building of ``case`` (a :class:`~stickslip.models.friction_tmd.case.DamperCase`) under
    ``acceleration`` [m/s²] sampled every ``dt`` [s]."""
    building = case.building
    return linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix,
                          np.ones(building.stories), acceleration, dt)


def attached_history(case, acceleration: np.ndarray, dt: float) -> LinearHistory:
    """The building of ``case`` with the damper's mass rigidly attached to its floor."""
    building = case.building
    return linear_history(case.attached_mass_matrix, building.damping_matrix, building.stiffness_matrix,
                          np.ones(building.stories), acceleration, dt)


def reference_answers(case, acceleration: np.ndarray, dt: float) -> dict[str, dict]:
    """``{"bare_structure": …, "attached_mass": …}``: :func:`structure_answers` of both references."""
    return {name: structure_answers(case.building, *history(case, acceleration, dt), case.g)
            for name, history in (("bare_structure", bare_history), ("attached_mass", attached_history))}


def reductions(answers: dict, references: dict[str, dict]) -> dict[str, float]:
    """1 − r/r_bare (``{r}_reduction``) and 1 − r/r_attached (``{r}_reduction_attached``) of each response r of
    :data:`RESPONSES`, from the damper's ``answers`` and the :func:`reference_answers` (NaN where the reference is 0:
    a ground at rest)."""
    found = {}
    for suffix, name in (("", "bare_structure"), ("_attached", "attached_mass")):
        for response in RESPONSES:
            reference = references[name][response]
            found[f"{response}_reduction{suffix}"] = 1.0 - answers[response] / reference if reference else math.nan
    return found
