"""A block on a linear spring with Coulomb friction: the smallest model with a restoring force.

A block of mass m [kg] is tied to the moving base by a linear spring of
stiffness k = m·ω² (natural period T = 2π/ω [s]) and slides on the base
with Coulomb friction μ·m·g.  Per unit mass, relative to the base:

    ü = −a_g − ω²·u − μ·g·sign(u̇)   while sliding,

stuck while |a_g + ω²·u| ≤ μ·g; it starts from u = 0 with the velocity
``initial_velocity`` [m/s] relative to the base, which is at rest.  Coulomb
friction with a restoring stiffness ω² is a resistance the event engine
composes (:mod:`stickslip.solvers.restoring`: its phase functions on
:mod:`stickslip.solvers.events`), so the block is solved exactly, phase by
phase, with its own stiffness ω² = k/m (the friction pendulum composes the
same resistance with ω² = g/R).  In free vibration each half cycle ends a
distance 2μg/ω² nearer the middle than the last, and the block stays where a
turn ends within μg/ω² of it.

The module is the whole model: its parameters, its case, its scheme, its
result and its entry, registered by the one line naming it in
:data:`stickslip.models.registry.MODEL_MODULES` (docs/adding_a_model.md
builds it step by step).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from stickslip.errors import StickslipError
from stickslip.models.entry import Parameter, Scheme
from stickslip.models.parameters import GRAVITY, MASS, MU, positive
from stickslip.models.registry import register
from stickslip.models.result import Result
from stickslip.models.swept import SweptModel


def _finite(value) -> float:
    """The initial velocity [m/s] as a finite number."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = math.nan
    if not math.isfinite(number):
        raise StickslipError(f"initial velocity [m/s] must be a finite number, got {value!r}")
    return number


PERIOD = Parameter("period", "s", "natural period T = 2 pi sqrt(m/k) [s] of the block on its spring",
                   check=positive("natural period T [s]"), usual=(0.02, 20.0, "the natural periods of structures"))
INITIAL_VELOCITY = Parameter("initial_velocity", "m s-1", "the block's velocity relative to the base at t = 0 [m/s] "
                             "(the base starts at rest)", default=0.0, check=_finite)

#: The end results: name -> (unit, long name); energies for the block's mass.
SCALARS = {
    "energy_dissipated": ("J", "energy dissipated by friction E_df at the end of the record"),
    "energy_input": ("J", "absolute input energy E_I at the end of the record"),
    "kinetic_energy_final": ("J", "absolute kinetic energy E_k at the end of the record"),
    "restoring_work": ("J", "energy stored in the spring at the end, k (u^2 - u0^2)/2"),
    "balance_residual": ("J", "largest |E_k - E_k(0) + E_r + E_df - E_I| over the record"),
    "residual_displacement": ("m", "block displacement relative to the base at the end"),
    "peak_relative_displacement": ("m", "largest |block displacement relative to the base|"),
    "sliding_path": ("m", "total distance slid relative to the base"),
    "slip_fraction": ("1", "fraction of the record duration spent sliding"),
    "n_slip_episodes": ("1", "number of stick-to-slip transitions"),
}

#: Histories of :meth:`SpringResponse.to_xarray`: name -> (unit, long name); energies for the block's mass.
HISTORIES = {
    "relative_displacement": ("m", "block displacement relative to the base"),
    "relative_velocity": ("m s-1", "block velocity relative to the base"),
    "energy_dissipated": ("J", "cumulative energy dissipated by friction E_df"),
    "energy_input": ("J", "cumulative absolute input energy E_I"),
    "restoring_work": ("J", "energy stored in the spring E_r"),
    "kinetic_energy": ("J", "absolute kinetic energy E_k"),
    "balance_residual": ("J", "energy balance residual E_k - E_k(0) + E_r + E_df - E_I"),
}

#: The terms of :meth:`SpringResponse.energy_ledger`: E_k − E_k(0) + E_r + E_df − E_I = residual.
LEDGER = ("energy_input", "energy_dissipated", "restoring_work", "kinetic_energy", "balance_residual")


@dataclass(frozen=True)
class SpringCase:
    """One block on its spring: friction ratio μ [1], period T [s], initial velocity [m/s], mass [kg], g [m/s²]."""

    mu: float
    period: float
    initial_velocity: float
    mass: float
    g: float

    #: The records are solved as given (no inverse polarity).
    inverse = False

    @property
    def omega2(self) -> float:
        """ω² = k/m = (2π/T)² [1/s²]."""
        return (2.0 * math.pi / self.period) ** 2

    @property
    def stick_distance(self) -> float:
        """μg/ω² [m]: the spring holds the block at rest within this distance of its middle."""
        return self.mu * self.g / self.omega2

    def at(self, coefficient: str, value: float) -> SpringCase:
        """The same block with its friction ratio μ at ``value`` [1]."""
        return SpringCase(float(value), self.period, self.initial_velocity, self.mass, self.g)

    def solved(self, acceleration: np.ndarray) -> np.ndarray:
        """The base acceleration [m/s²] as the kernel takes it (as given)."""
        return acceleration

    def slides(self, motion) -> bool:
        """Whether the block leaves rest: it starts moving, or the base's |a| exceeds μg somewhere."""
        return self.initial_velocity != 0.0 or bool(np.any(np.abs(motion.acceleration) > self.mu * self.g))

    def still_reason(self, motion, where: str | None = None) -> str:
        """Why the block never leaves rest: it starts at rest and the PGA is at most μg."""
        pga = float(np.max(np.abs(motion.acceleration)))
        return (f"it starts at rest and the PGA {pga:.4g} m/s2 is at most mu*g = {self.mu * self.g:.4g} m/s2 at "
                f"{where or f'mu = {self.mu:g}'}")

    def describe_sliding(self) -> str:
        """``on a spring T = 1 s, from 0.3 m/s``."""
        start = f", from {self.initial_velocity:g} m/s" if self.initial_velocity else ""
        return f"on a spring T = {self.period:g} s{start}"

    def settings(self) -> dict:
        """The block but its friction ratio, JSON-ready."""
        return {"period": self.period, "initial_velocity": self.initial_velocity, "mass": self.mass, "g": self.g}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {"period": "s", "initial_velocity": "m s-1", "mass": "kg", "g": "m s-2"}


@dataclass(frozen=True)
class SpringResponse(Result):
    """One solved block on its spring: the kernel's history per unit mass (``history``) and the case."""

    model = "spring"
    scalar_table = SCALARS
    history_table = HISTORIES
    ledger_terms = LEDGER

    block: SpringCase
    method: str
    history: dict = field(repr=False)

    @property
    def mass(self) -> float:
        """Block mass [kg]."""
        return self.block.mass

    @property
    def time(self) -> np.ndarray:
        """Sample times [s]."""
        return self.history["time"]

    def histories(self) -> dict[str, np.ndarray]:
        """The histories of :data:`HISTORIES`, energies for the block's mass [J]."""
        return {name: self.history[name] * (self.mass if unit == "J" else 1.0)
                for name, (unit, _) in HISTORIES.items()}

    def end_values(self) -> dict[str, float]:
        """The kernel's end results per unit mass, with the energy stored in the spring."""
        return self.history["scalars"]

    def describe(self) -> str:
        return (f"block {self.block.describe_sliding()}, mu = {self.block.mu:g}, mass = {self.block.mass:g} kg, "
                f"g = {self.block.g:g} m/s2, method = {self.method}")

    def case(self) -> dict:
        return {"model": self.model, "method": self.method, "mu": self.block.mu, **self.block.settings()}

    def case_units(self) -> dict[str, str]:
        return {"mu": "1", **self.block.settings_units()}

    @property
    def never_slides(self) -> str | None:
        if self.history["scalars"]["sliding_path"] > 0.0:
            return None
        from stickslip.records.record import Record

        time = self.history["time"]
        return self.block.still_reason(Record(self.history["ground_acceleration"], float(time[1] - time[0])))

    def notes(self) -> list[str]:
        return ["energies [J]: E_k - E_k(0) + E_r + E_df = E_I; restoring_work E_r is the energy stored in the spring"]


class SpringScheme(Scheme):
    """The closed-form solution, phase by phase: Coulomb friction with the restoring stiffness ω² on the event engine."""

    name = "exact"
    summary = "closed form per sample step, the events located (friction with a restoring stiffness)"

    def solve(self, motion, case: SpringCase) -> SpringResponse:
        from stickslip.solvers.restoring import restoring_history

        history = restoring_history(motion.acceleration, motion.dt, case.mu * case.g, case.omega2, case.g,
                                    initial_velocity=case.initial_velocity)
        # the energy stored in the spring, k·u²/2 from u = 0, is the ledger's potential energy ½·ω²·u²
        scalars = {**history["scalars"], "restoring_work": history["scalars"]["potential_energy_final"]}
        return SpringResponse(case, self.name, {**history, "restoring_work": history["potential_energy"],
                                                "scalars": scalars, "ground_acceleration": motion.acceleration})


class SpringModel(SweptModel):
    """The entry of the block on a spring."""

    name = "spring"
    summary = "a block on a linear spring with Coulomb friction (a restoring force k u)"
    motions = ("component",)
    parameters = (MU, PERIOD, INITIAL_VELOCITY, MASS, GRAVITY)
    schemes = (SpringScheme(),)
    result = SpringResponse
    examples = ({"mu": 0.1, "period": 1.0, "initial_velocity": 0.2},)

    def case(self, parameters) -> SpringCase:
        if parameters["mu"] is None or parameters["period"] is None:
            raise StickslipError("the spring model needs a friction ratio mu= and a natural period period= [s]")
        return SpringCase(parameters["mu"], parameters["period"], parameters["initial_velocity"],
                          parameters["mass"], parameters["g"])

    def variables(self, case) -> dict[str, dict[str, str]]:
        return {name: {"units": unit, "long_name": long_name} for name, (unit, long_name) in SCALARS.items()}

    def cube_attrs(self, case, scheme, run_options) -> dict:
        return {"period": case.period, "period_units": "s", "initial_velocity": case.initial_velocity,
                "initial_velocity_units": "m s-1", "block_mass": case.mass, "block_mass_units": "kg",
                "gravity": case.g, "gravity_units": "m s-2", "sliding": case.describe_sliding()}

    def parameters_of(self, cube) -> tuple[str, dict, dict]:
        attrs = cube.attrs
        return attrs["solver"], {}, {"period": float(attrs["period"]), "initial_velocity": float(attrs["initial_velocity"]),
                                     "mass": float(attrs["block_mass"]), "g": float(attrs["gravity"])}


#: The spring's entry.
SPRING = register(SpringModel())
