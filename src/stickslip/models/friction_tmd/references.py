"""The building's answers, with the damper and without: peaks of displacement, drift, floor acceleration, base shear.

The damper is judged against two linear buildings: the **bare** building (no
damper), solved by the first-order hold of
:func:`~stickslip.solvers.structure.linear_response.linear_history` at the
samples and the damper's solver's search points, and the building with the
damper's mass **attached** rigidly to its floor, solved by the damper's own
exact solver (:mod:`stickslip.solvers.structure.friction_linked`) at μ =
:data:`~stickslip.models.parameters.HELD`, which no record overcomes; so that every peak is taken at the
same points as the damper's (the samples, the search points and, for the
damper, its events).
For each response r of :data:`RESPONSES`, the reduction is 1 − r/r_bare
(``{r}_reduction``) and 1 − r/r_attached (``{r}_reduction_attached``):
positive where the damper does better.
"""

from __future__ import annotations

import numpy as np

from stickslip.models.parameters import HELD

#: The building's answers: name -> (unit, long name); with the lists per story and floor of
#: :func:`structure_answers`, story (floor) 1 first.
RESPONSES = {
    "peak_structure_displacement": ("m", "largest |floor displacement relative to the ground| over the floors"),
    "peak_drift": ("m", "largest |story drift| over the stories"),
    "peak_floor_acceleration": ("m s-2", "largest |absolute floor acceleration| over the floors"),
    "base_shear_coefficient": ("1", "peak base shear of the building over its weight, V_b/W (W = m_s g)"),
}


def structure_answers(case, peaks: np.ndarray) -> dict:
    """The building's answers from the peaks of ``case.tracked``'s rows (trailing axis; any leading shape): each of
    :data:`RESPONSES`, ``peak_story_drifts`` [m] and ``peak_floor_accelerations`` [m/s²]."""
    n = case.stories
    displacements, drifts, accelerations = peaks[..., :n], peaks[..., n:2 * n], peaks[..., 2 * n:3 * n]
    return {"peak_structure_displacement": displacements.max(axis=-1), "peak_drift": drifts.max(axis=-1),
            "peak_floor_acceleration": accelerations.max(axis=-1),
            "base_shear_coefficient": peaks[..., 3 * n] / (case.mass * case.g),
            "peak_story_drifts": drifts, "peak_floor_accelerations": accelerations}


def bare_answers(case, acceleration: np.ndarray, dt: float) -> dict:
    """The answers of the bare building of ``case`` (a :class:`~stickslip.models.friction_tmd.case.DamperCase`)
    under ``acceleration`` [m/s²] sampled every ``dt`` [s], at the samples and the damper's solver's search points:
    the first-order hold of :func:`~stickslip.solvers.structure.linear_response.linear_history` on the record
    resampled at them (exactly: the record is linear between samples)."""
    from stickslip.solvers.structure.friction_linked import search_points
    from stickslip.solvers.structure.linear_response import linear_history

    building = case.building
    points = search_points(np.stack(case.system.phase_matrices()), dt)
    fine = np.interp(np.arange((acceleration.size - 1) * points + 1) / points, np.arange(acceleration.size),
                     acceleration)
    history = linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix,
                             np.ones(building.stories), fine, dt / points)
    return structure_answers(case, _linear_peaks(building, *(value[..., None] for value in history)))


def _linear_peaks(building, displacement, velocity, absolute_acceleration) -> np.ndarray:
    """The peaks of :func:`structure_answers` (floor displacements, story drifts, floor accelerations, base shear)
    of a linear building's history, arrays (samples, n, directions): the largest magnitude over the samples."""
    shear = (np.einsum("knd,n->kd", displacement, building.stiffness_matrix.sum(axis=0))
             + np.einsum("knd,n->kd", velocity, building.damping_matrix.sum(axis=0)))
    drifts = np.diff(displacement, axis=1, prepend=0.0)
    return np.concatenate([np.max(np.linalg.norm(values, axis=-1), axis=0)
                           for values in (displacement, drifts, absolute_acceleration)]
                          + [[np.max(np.linalg.norm(shear, axis=-1))]])


def attached_history(case, acceleration: np.ndarray, dt: float):
    """The building of ``case`` with the damper's mass rigidly attached to its floor (the damper held)."""
    from stickslip.solvers.structure.friction_linked import friction_linked_history

    return friction_linked_history(case.system, acceleration, dt, HELD, case.tracked)


def _json_ready(answers: dict) -> dict:
    return {name: np.asarray(value).tolist() for name, value in answers.items()}


def reference_answers(case, acceleration: np.ndarray, dt: float) -> dict[str, dict]:
    """``{"bare_structure": …, "attached_mass": …}``: :func:`structure_answers` of both references, JSON-ready."""
    attached = structure_answers(case, attached_history(case, acceleration, dt).peaks)
    return {"bare_structure": _json_ready(bare_answers(case, acceleration, dt)), "attached_mass": _json_ready(attached)}


def plane_reference_answers(case, ground_acceleration: np.ndarray, dt: float) -> dict[str, dict]:
    """:func:`reference_answers` in the plane, ``ground_acceleration`` [m/s²] (samples, 2) on two orthogonal axes:
    both references are linear, solved in each direction by the first-order hold of
    :func:`~stickslip.solvers.structure.linear_response.linear_history`, their peaks the largest magnitudes of the
    vectors at the samples (where the plane's damper's are taken)."""
    from stickslip.solvers.structure.linear_response import linear_history

    building = case.building
    found = {}
    for name, mass in (("bare_structure", building.mass_matrix), ("attached_mass", case.attached_mass_matrix)):
        axes = [linear_history(mass, building.damping_matrix, building.stiffness_matrix, np.ones(case.stories), axis,
                               dt) for axis in ground_acceleration.T]
        history = [np.stack([getattr(axis, field) for axis in axes], axis=-1)
                   for field in ("displacement", "velocity", "absolute_acceleration")]
        found[name] = _json_ready(structure_answers(case, _linear_peaks(building, *history)))
    return found


def reductions(answers: dict, references: dict[str, dict]) -> dict[str, np.ndarray]:
    """1 − r/r_bare (``{r}_reduction``) and 1 − r/r_attached (``{r}_reduction_attached``) of each response r of
    :data:`RESPONSES`, from the damper's ``answers`` (numbers or arrays) and the :func:`reference_answers` (NaN
    where the reference is 0: a ground at rest)."""
    found = {}
    for suffix, name in (("", "bare_structure"), ("_attached", "attached_mass")):
        for response in RESPONSES:
            reference = references[name][response]
            with np.errstate(divide="ignore", invalid="ignore"):
                found[f"{response}_reduction{suffix}"] = np.where(
                    reference != 0, 1.0 - np.asarray(answers[response]) / reference, np.nan)
    return found
