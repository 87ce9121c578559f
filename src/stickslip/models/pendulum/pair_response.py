"""The response of a friction pendulum (or a flat slider) in the plane, under two horizontal components and the vertical.

A :class:`PairPendulumResponse` holds the plane solver's per-unit-mass
history (:data:`stickslip.solvers.plane.HISTORY_NAMES`) and gives it
for the slider's mass: the energy ledger

    E_k − E_k(0) + E_p − E_p(0) + E_df = E_I,h + E_I,v   [J],

(E_k = ½·m·|u̇_g + v|² the absolute kinetic energy, E_p = m·g·|u|²/(2R) the
potential energy, E_df the friction's work, E_I,h = ∫m·ü·u̇_g dt the horizontal
ground motion's, E_I,v = W_v = −∫m·(n − g)·u·u̇/R dt the vertical motion's
through the normal force on the curved surface; docs/solvers.md, "The friction
pendulum in the plane"), the displacement
demand (the largest distance from the surface's centre), the residual
displacement (the distance at the end), the peak base shear coefficient V/W
and the intervals where the slider lifted off.  Its end results have the
names of the one-direction pendulum's (:data:`~stickslip.models.pendulum.response.SCALARS`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from stickslip.models.pendulum.case import PendulumCase
from stickslip.models.pendulum.response import LEDGER, LEDGER_NOTE, SCALARS, SliderResult
from stickslip.solvers.ledger import potential_energy
from stickslip.models.result import Result
from stickslip.records.pair import RecordPair
from stickslip.units import UNITS

#: What the plane's end results mean where they differ from one direction's (:data:`SCALARS`).
PLANE_SCALARS = {**SCALARS, **{name: (UNITS[name], long_name) for name, long_name in {
    "residual_displacement": "distance of the slider from the surface's centre at the end, |u(end)| (re-centring)",
    "peak_relative_displacement": "largest distance of the slider from the surface's centre, max |u| "
                                  "(displacement demand)",
    "sliding_path": "length of the path slid relative to the ground"}.items()}}

#: Histories, in order: name -> (unit, long name), units from :data:`stickslip.units.UNITS`; the first four
#: on ``time`` and ``component``, the others on ``time``.
HISTORIES = {name: (UNITS[name], long_name) for name, long_name in {
    "ground_acceleration": "horizontal ground acceleration",
    "ground_velocity": "horizontal ground velocity",
    "relative_displacement": "slider displacement relative to the ground",
    "relative_velocity": "slider velocity relative to the ground",
    "phase": "0 stuck, 1 sliding, 2 lifted off (just after the time)",
    "energy_dissipated": "cumulative energy dissipated by friction E_df",
    "energy_input": "cumulative absolute input energy of the horizontal ground motion E_I,h",
    "energy_input_vertical": "cumulative work of the vertical ground motion through the normal force on the curved "
                             "surface E_I,v = W_v",
    "kinetic_energy": "absolute kinetic energy E_k",
    "potential_energy": "potential energy E_p = m g |u|^2 / (2R)",
    "balance_residual": "energy balance residual E_k - E_k(0) + E_p - E_p(0) + E_df - E_I,h - E_I,v",
    "sliding_path": "cumulative length of the path slid",
    "vertical_acceleration": "vertical ground acceleration a_v, positive up",
}.items()}


#: The end results of the plane as the pendulum's (:data:`stickslip.models.pendulum.response.SCALARS`), from the
#: kernel's columns (:data:`stickslip.solvers.plane.SURFACE_SCALAR_NAMES`): residual and peak are distances
#: from the surface's centre [m], the base shear is the largest |ü| over g, the potential energy is the residual's.
KERNEL_COLUMNS = {
    "energy_dissipated": "energy_dissipated", "energy_input": "energy_input",
    "energy_input_vertical": "energy_input_vertical", "kinetic_energy_final": "kinetic_energy_final",
    "peak_relative_displacement": "peak_displacement", "sliding_path": "sliding_path",
    "slip_fraction": "slip_fraction", "n_slip_episodes": "n_slip_episodes", "liftoff_time": "flight_time",
}


def kernel_case(case) -> tuple[float, float, float, float]:
    """(μ_slow, μ_fast [1], rate [s/m], 1/R [1/m]) of a :class:`~stickslip.models.pendulum.case.PendulumCase`."""
    law = case.friction
    return law.mu_slow, law.mu_fast, law.rate, 0.0 if math.isinf(case.radius) else 1.0 / case.radius


def end_results(out: np.ndarray, g: float, curvature: float) -> dict[str, np.ndarray]:
    """The pendulum's end results (per unit mass) from the kernel's scalars ``out`` (..., columns), by name; ``g``
    [m/s²] and the surface's ``curvature`` 1/R [1/m] give the base shear over the weight and the potential energy."""
    from stickslip.solvers.plane import SURFACE_SCALAR_NAMES

    column = {name: index for index, name in enumerate(SURFACE_SCALAR_NAMES)}
    found = {name: out[..., column[kernel]] for name, kernel in KERNEL_COLUMNS.items()}
    found["residual_displacement"] = np.hypot(out[..., column["residual_displacement_1"]],
                                              out[..., column["residual_displacement_2"]])
    found["peak_base_shear"] = out[..., column["peak_absolute_acceleration"]] / g
    found["potential_energy_final"] = potential_energy(found["residual_displacement"], g * curvature)
    return found


@dataclass(frozen=True)
class PairPendulumResponse(SliderResult, Result):
    """One solved case of the pendulum model in the plane.

    Attributes
    ----------
    slider:
        The slider (:class:`~stickslip.models.pendulum.case.PendulumCase`).
    method:
        The scheme asked for (``"exact"`` or ``"integrated"``: both integrate in the plane).
    solved_by:
        How, in words (``"integration to a relative tolerance of 1e-10, events located"``).
    pair:
        The two horizontal components.
    vertical, vertical_sense:
        The vertical component's file and how its sense was read, or None.
    ground_acceleration, ground_velocity:
        The ground motion on the pair's orthogonal axes, shape (n, 2) [m/s², m/s].
    vertical_acceleration:
        a_v [m/s², positive up] at the samples, or None.
    history:
        The kernel's history, per unit mass (columns :data:`stickslip.solvers.plane.HISTORY_NAMES`).
    kernel_scalars:
        The kernel's end results, per unit mass (:data:`stickslip.solvers.plane.SURFACE_SCALAR_NAMES`).
    liftoff:
        The intervals of lift-off, (k, 2) start and end times [s].
    """

    model = "pendulum"
    scalar_table = PLANE_SCALARS
    history_table = HISTORIES
    where = "in the plane: "
    response_figure = "path"
    case_extra = {"motion": "pair"}

    slider: PendulumCase
    method: str
    solved_by: str
    pair: RecordPair
    vertical: str | None
    vertical_sense: str | None
    ground_acceleration: np.ndarray = field(repr=False)
    ground_velocity: np.ndarray = field(repr=False)
    vertical_acceleration: np.ndarray | None = field(repr=False)
    history: np.ndarray = field(repr=False)
    kernel_scalars: dict = field(repr=False)
    liftoff: np.ndarray = field(repr=False)

    @property
    def time(self) -> np.ndarray:
        """Sample times [s]."""
        return np.arange(self.history.shape[0]) * self.pair.dt

    @property
    def relative_displacement(self) -> np.ndarray:
        """u [m], shape (n, 2), relative to the ground on the pair's orthogonal axes."""
        return self.history[:, 0:2]

    @property
    def relative_velocity(self) -> np.ndarray:
        """v [m/s], shape (n, 2)."""
        return self.history[:, 2:4]

    @property
    def peak_displacement(self) -> float:
        """The displacement demand [m]: the largest distance of the slider from the surface's centre (at the samples,
        step ends and events)."""
        return self.kernel_scalars["peak_displacement"]

    @property
    def kinetic_energy(self) -> np.ndarray:
        """E_k = ½·m·|u̇_g + v|² [J] at the samples."""
        absolute = self.ground_velocity + self.relative_velocity
        return 0.5 * self.mass * np.einsum("ij,ij->i", absolute, absolute)

    @property
    def potential_energy(self) -> np.ndarray:
        """E_p = m·g·|u|²/(2R) [J] at the samples (0 on a flat surface)."""
        distance = np.hypot(self.relative_displacement[:, 0], self.relative_displacement[:, 1])
        return self.mass * potential_energy(distance, self.slider.g * kernel_case(self.slider)[3])

    def histories(self) -> dict[str, np.ndarray]:
        """Every history of :data:`HISTORIES`: the ground's and the slider's vectors on the pair's axes, the phase,
        the ledger for the slider's mass [J] and the path slid [m]; a_v [m/s²] with a vertical."""
        kinetic, potential = self.kinetic_energy, self.potential_energy
        ledger = {"energy_input": self.mass * self.history[:, 6],
                  "energy_input_vertical": self.mass * self.history[:, 8],
                  "energy_dissipated": self.mass * self.history[:, 5], "kinetic_energy": kinetic,
                  "potential_energy": potential}
        ledger["balance_residual"] = (kinetic - kinetic[0] + potential - potential[0] + ledger["energy_dissipated"]
                                      - ledger["energy_input"] - ledger["energy_input_vertical"])
        moving, flying = self.history[:, 4], self.history[:, 9]
        values = {"ground_acceleration": self.ground_acceleration, "ground_velocity": self.ground_velocity,
                  "relative_displacement": self.relative_displacement, "relative_velocity": self.relative_velocity,
                  "phase": np.where(flying > 0.5, 2, np.where(moving > 0.5, 1, 0)).astype(np.int8),
                  **{name: ledger[name] for name in LEDGER}, "sliding_path": self.history[:, 7]}
        if self.vertical_acceleration is not None:
            values["vertical_acceleration"] = self.vertical_acceleration
        return values

    def end_values(self) -> dict[str, float]:
        """The kernel's end results per unit mass, distances from the surface's centre (:func:`end_results`)."""
        from stickslip.solvers.plane import SURFACE_SCALAR_NAMES

        kernel = np.array([self.kernel_scalars[name] for name in SURFACE_SCALAR_NAMES])
        return end_results(kernel, self.slider.g, kernel_case(self.slider)[3])

    def extras(self) -> dict:
        """The residual displacement's two components [m] on the pair's axes, and the lift-off intervals [s]."""
        return {"residual_displacement_components": [float(value) for value in self.relative_displacement[-1]],
                "liftoff_intervals": self.liftoff.tolist()}

    @property
    def never_slides(self) -> str | None:
        """Why the slider never left rest (its largest |a| beside μ(0)·(g + a_v)); None when it slid or flew."""
        if self.kernel_scalars["n_slip_episodes"] or self.kernel_scalars["flight_time"]:
            return None
        from stickslip.records.vertical import WithVertical

        motion = self.pair if self.vertical_acceleration is None else WithVertical(
            self.pair, self.pair.first.derive(self.vertical_acceleration, step="the vertical"), "")
        return self.slider.still_reason(motion)

    def notes(self) -> list[str]:
        """What the energies and distances are, and when the slider lifted off."""
        return [LEDGER_NOTE + "; distances from the surface's centre; peak_base_shear is V/W = max |u''|/g",
                *self.liftoff_notes()]

    def component_names(self) -> list[str]:
        """The components' names (their component, else their record id); the second says when it was resolved."""
        names = [self.pair.first.meta.component or self.pair.first.meta.record_id or "1",
                 self.pair.second.meta.component or self.pair.second.meta.record_id or "2"]
        if not self.pair.orthogonal:
            names[1] = f"{names[1]} (resolved normal to {names[0]})"
        return names

    def coordinates(self) -> dict:
        """The components' names (:meth:`component_names`) on ``component``."""
        return {"component": ("component", self.component_names())}

    def dataset_attrs(self) -> dict:
        """The pair's name and the angle between its components [degrees]."""
        return {"record_pair": self.pair.name, "component_separation_degrees": self.pair.separation}
