"""The response of a rigid block sliding in the plane on a flat surface, under both horizontal components.

:func:`solve_case` (the planar scheme's ``solve``) solves one
:class:`~stickslip.records.pair.RecordPair` for one friction ratio μ: one
friction force of magnitude μ·m·g opposite to the sliding velocity (the
friction circle), the equation and its integration in
:mod:`stickslip.solvers.plane`.  The result, a
:class:`PlanarResponse`, has the block's path in the plane, the energy ledger
(E_I, E_df, E_k and the balance residual), each component alone beside it
(:meth:`PlanarResponse.components_alone`) and ``to_xarray`` with a
``component`` dimension.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from stickslip.checks import checked_finite_results, checked_pair_axes, checked_positive, whole_count
from stickslip.constants import DEFAULT_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.models.result import Result
from stickslip.records.process import integrate_linear_acceleration
from stickslip.units import UNITS, energy_units, readable_units

#: What the plane is compared with each component alone on (:meth:`PlanarResponse.tables`).
COMPARED = ("energy_dissipated", "peak_displacement", "residual_displacement", "sliding_path")

#: The scalars of :meth:`PlanarResponse.scalars`: units (UDUNITS) and long names.
SCALAR_ATTRS = {name: (UNITS[name], long_name) for name, long_name in (
    ("energy_dissipated", "energy dissipated by friction E_df at the end of the record"),
    ("energy_input", "absolute input energy E_I at the end of the record"),
    ("kinetic_energy_final", "absolute kinetic energy E_k at the end of the record"),
    ("balance_residual", "largest |E_k - E_k(0) + E_df - E_I| over the samples"),
    ("residual_displacement", "distance from the start at the end, |x(end)|"),
    ("peak_displacement", "largest distance from the start, max |x|"),
    ("sliding_path", "length of the path slid"),
    ("slip_fraction", "fraction of the record duration spent sliding"),
    ("n_slip_episodes", "number of stick-to-slip transitions"),
)}

#: The histories of :meth:`PlanarResponse.to_xarray`: units (UDUNITS) and long names; the first four have two
#: components (shape (n, 2)).
HISTORY_ATTRS = {
    "ground_acceleration": ("m s-2", "base acceleration"),
    "ground_velocity": ("m s-1", "base velocity"),
    "relative_displacement": ("m", "block displacement relative to the base"),
    "relative_velocity": ("m s-1", "block velocity relative to the base"),
    "energy_dissipated": ("J", "energy dissipated by friction E_df"),
    "energy_input": ("J", "absolute input energy E_I"),
    "kinetic_energy": ("J", "absolute kinetic energy E_k"),
    "sliding_path": ("m", "length of the path slid"),
    "sliding": ("1", "1 where the block slides just after the sample"),
}


@dataclass(frozen=True)
class PlanarResponse(Result):
    """The response of a block sliding in the plane: histories on the record's samples, energies for its mass.

    Attributes
    ----------
    pair:
        The record pair solved.
    mu, g, mass:
        Friction ratio μ [1], gravity g [m/s²], block mass m [kg].
    time:
        Sample times [s].
    ground_acceleration, ground_velocity:
        Base motion on the pair's two orthogonal axes (:meth:`RecordPair.horizontal`), shape (n, 2) [m/s², m/s].
    relative_displacement, relative_velocity:
        The block relative to the base, shape (n, 2) [m, m/s].
    sliding:
        Whether the block slides just after each sample (bool, shape (n,)).
    energy_dissipated, energy_input:
        Cumulative E_df and E_I [J].
    sliding_path:
        Cumulative length of the path slid [m].
    peak_displacement:
        max |x| over the whole motion, stops and turns between samples included [m].
    slip_time:
        Time spent sliding [s].
    n_slip_episodes:
        Stick-to-slip transitions.
    rtol:
        The integration's relative tolerance per step.
    """

    model = "planar"
    method = "exact"
    scalar_table = SCALAR_ATTRS
    history_table = HISTORY_ATTRS
    # the residual is the ledger's only, not a history of the dataset
    ledger_terms = ("energy_input", "energy_dissipated", "kinetic_energy", "balance_residual")
    per_unit_mass = False  # the end results are the block's, energies for its mass
    response_figure = "path"

    pair: RecordPair
    mu: float
    g: float
    mass: float
    time: np.ndarray = field(repr=False)
    ground_acceleration: np.ndarray = field(repr=False)
    ground_velocity: np.ndarray = field(repr=False)
    relative_displacement: np.ndarray = field(repr=False)
    relative_velocity: np.ndarray = field(repr=False)
    sliding: np.ndarray = field(repr=False)
    energy_dissipated: np.ndarray = field(repr=False)
    energy_input: np.ndarray = field(repr=False)
    sliding_path: np.ndarray = field(repr=False)
    peak_displacement: float
    slip_time: float
    n_slip_episodes: int
    rtol: float

    @property
    def kinetic_energy(self) -> np.ndarray:
        """E_k = ½·m·|u̇_g + v|² [J] at the samples."""
        absolute = self.ground_velocity + self.relative_velocity
        return 0.5 * self.mass * np.einsum("ij,ij->i", absolute, absolute)

    @property
    def balance_residual(self) -> np.ndarray:
        """E_k − E_k(0) + E_df − E_I [J] at the samples: round-off and the integration's tolerance."""
        kinetic = self.kinetic_energy
        return kinetic - kinetic[0] + self.energy_dissipated - self.energy_input

    def end_values(self) -> dict[str, float]:
        """The end results of :data:`SCALAR_ATTRS` but the residual, for the block's mass (energies [J])."""
        return {"energy_dissipated": self.energy_dissipated[-1], "energy_input": self.energy_input[-1],
                "kinetic_energy_final": self.kinetic_energy[-1],
                "residual_displacement": np.hypot(*self.relative_displacement[-1]),
                "peak_displacement": self.peak_displacement, "sliding_path": self.sliding_path[-1],
                "slip_fraction": self.slip_time / (self.time[-1] if self.time[-1] > 0 else 1.0),
                "n_slip_episodes": self.n_slip_episodes}

    def histories(self) -> dict[str, np.ndarray]:
        """The histories of :data:`HISTORY_ATTRS` at the samples, and the ledger's ``balance_residual`` [J]."""
        return {**{name: getattr(self, name) for name in HISTORY_ATTRS if name != "sliding"},
                "sliding": self.sliding.astype(np.int8), "balance_residual": self.balance_residual}

    def describe(self) -> str:
        """``in the plane: mu = 0.05, mass = 5.1 kg, g = 9.81 m/s2, method = exact``."""
        return f"in the plane: mu = {self.mu:g}, mass = {self.mass:g} kg, g = {self.g:g} m/s2, method = {self.method}"

    def case(self) -> dict:
        """The model, the scheme, μ [1], the mass [kg] and g [m/s²]."""
        return {"model": self.model, "method": self.method, "mu": self.mu, "mass": self.mass, "g": self.g}

    def case_units(self) -> dict[str, str]:
        """The units of :meth:`case`'s numbers."""
        return {"mu": UNITS["mu"], "mass": UNITS["block_mass"], "g": UNITS["gravity"]}

    def extras(self) -> dict:
        """Each component alone at the same μ, keyed by its name: the quantities the plane is compared on."""
        alone = self.components_alone()
        return {"components_alone": {name: {quantity: alone[direction][quantity] for quantity in COMPARED}
                                     for name, direction in zip(self.component_names(), ("first", "second"))}}

    @property
    def never_slides(self) -> str | None:
        """Why the block never slid: the largest horizontal acceleration did not exceed μ·g; None when it slid."""
        if self.n_slip_episodes:
            return None
        peak = float(np.max(np.hypot(self.ground_acceleration[:, 0], self.ground_acceleration[:, 1])))
        return (f"its largest horizontal acceleration {peak:.4g} m/s2 ({peak / self.g:.4g} g) is at most "
                f"mu*g = {self.mu * self.g:.4g} m/s2 at mu = {self.mu:g}")

    def component_names(self) -> list[str]:
        """The components' names (their component, else their record id; a bare azimuth with its degree sign)."""
        from stickslip.records.components import component_label

        return [component_label(record.meta.component or record.meta.record_id) or default
                for record, default in ((self.pair.first, "1"), (self.pair.second, "2"))]

    def components_alone(self) -> dict[str, dict[str, float]]:
        """The 1-D block on each axis of the pair alone at the same μ: ``{"first": {...}, "second": {...}}``
        (:func:`stickslip.models.planar.sweep.components_alone`; energies [J], lengths [m])."""
        from stickslip.models.planar.sweep import components_alone

        return components_alone(self.pair, self.mu, mass=self.mass, g=self.g)

    def tables(self) -> list[str]:
        """The plane beside each component alone: E_df [J; J/kg for the default 1 kg block], peak and residual
        distance and path [m]."""
        from stickslip.models.planar.sweep import VARIABLES

        alone = {"plane": self.scalars(), **self.components_alone()}
        names = self.component_names()
        energy = readable_units(energy_units(self.mass))  # J/kg for the default 1 kg block
        labels = {quantity: f"{quantity} [{energy if VARIABLES[quantity][0] == 'J' else VARIABLES[quantity][0]}]"
                  for quantity in COMPARED}
        width = max(len(label) for label in labels.values()) + 6
        lines = [f"{'':<{width}}  {'plane':>14}  " + "  ".join(f"{name + ' alone':>16}" for name in names)]
        for quantity, label in labels.items():
            cells = [alone[direction][quantity] for direction in ("plane", "first", "second")]
            lines.append(f"{label:<{width}}  {cells[0]:>14.6g}  " + "  ".join(f"{cell:>16.6g}" for cell in cells[1:]))
        return ["\n".join(lines)]

    def coordinates(self) -> dict:
        """The components' names on ``component`` (:meth:`component_names`; the second says when it was resolved)."""
        components = self.component_names()
        if not self.pair.orthogonal:
            components[1] = f"{components[1]} (resolved normal to {components[0]})"
        return {"component": ("component", components)}

    def case_attrs(self) -> dict:
        """The model, μ [1], g [m/s²], mass [kg], the integration's tolerance, the pair and the angle between its
        components [degrees]."""
        return {"model": self.model, "mu": self.mu, "g": self.g, "mass": self.mass, "rtol": self.rtol,
                "record_pair": self.pair.name, "component_separation_degrees": self.pair.separation}


def solve_case(pair: RecordPair, mu: float, mass: float = DEFAULT_BLOCK_MASS, g: float = STANDARD_GRAVITY,
               rtol: float | None = None) -> PlanarResponse:
    """Solve a rigid block on a flat surface with friction ratio ``mu`` [1] under both components of ``pair``.

    Parameters
    ----------
    pair:
        The two horizontal components [m/s²], resolved onto orthogonal axes (:meth:`RecordPair.horizontal`).
    mu:
        Friction ratio μ [1], positive: the friction force is at most μ·m·g and opposes the sliding velocity.
    mass:
        Block mass m [kg] (energies scale with it; the motion does not depend on it).
    g:
        Gravitational acceleration [m/s²].
    rtol:
        Relative tolerance of the velocity per integration step (default
        :data:`~stickslip.solvers.plane.RTOL`, 1e-10).
    """
    from stickslip.models.planar.solver import solve_pair
    from stickslip.solvers import plane

    if not isinstance(pair, RecordPair):
        raise StickslipError(f"sliding in the plane needs a RecordPair of two components, got {type(pair).__name__}")
    mu = checked_positive(mu, "friction ratio mu")
    mass = checked_positive(mass, "block mass [kg]")
    g = checked_positive(g, "gravity g [m/s2]")
    rtol = plane.RTOL if rtol is None else checked_positive(rtol, "relative tolerance rtol")
    first, second = checked_pair_axes(pair)
    history = np.zeros((pair.npts, 8))
    out = np.zeros(len(plane.PLANAR_SCALAR_NAMES))
    stalled_at = solve_pair(first, second, pair.dt, mu * g, rtol, plane.LOCK_RATIO, history, out)
    plane.check_progress(stalled_at, lambda _: f"{pair.name}, mu = {mu:g}")
    velocity_1, _ = integrate_linear_acceleration(first, pair.dt)
    velocity_2, _ = integrate_linear_acceleration(second, pair.dt)
    response = PlanarResponse(
        pair=pair, mu=mu, g=g, mass=mass, time=np.arange(pair.npts) * pair.dt,
        ground_acceleration=np.column_stack([first, second]),
        ground_velocity=np.column_stack([velocity_1, velocity_2]),
        relative_displacement=history[:, 0:2].copy(), relative_velocity=history[:, 2:4].copy(),
        sliding=history[:, 4] > 0.5, energy_dissipated=mass * history[:, 5], energy_input=mass * history[:, 6],
        sliding_path=history[:, 7].copy(), peak_displacement=float(out[5]), slip_time=float(out[7]) * (pair.npts - 1)
        * pair.dt, n_slip_episodes=whole_count(out[8]), rtol=rtol,
    )
    with np.errstate(over="ignore", invalid="ignore"):
        checked_finite_results(response.scalars(), f"{pair.name}, mu = {mu:g}")
    return response
