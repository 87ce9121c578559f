"""The rigid block over its swept coefficient, as the design answer reads it: curves, energies, where it sticks.

A :class:`RigidDesign` is one rigid block (mass, gravity, how it slides,
polarity), one scheme and a :class:`~stickslip.grids.Grid` of its friction
ratio μ or yield coefficient k_y.  :mod:`stickslip.optimum` asks it for the
response curves of records over the grid, E_df at any value of the
coefficient (the continuous maximum, the reference value) and, for a record
whose block never slides, at which grid value that starts and why.  The rigid
model's entry builds it (:meth:`stickslip.models.rigid.RigidModel.design`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from stickslip.grids import Grid
from stickslip.limits import check_memory
from stickslip.models.rigid.history import SCALAR_NAMES
from stickslip.records.record import Record


@dataclass(frozen=True)
class RigidDesign:
    """The rigid block ``case`` over ``grid``, solved by ``scheme`` with the ``options`` given.

    Attributes
    ----------
    grid:
        The swept coefficient and its values [1].
    case:
        The block at the grid's first value (:class:`~stickslip.models.rigid.case.RigidCase`).
    scheme:
        The :class:`~stickslip.models.rigid.scheme.RigidScheme` that solves it.
    options:
        The scheme's options, as given.
    """

    grid: Grid
    case: object
    scheme: object
    options: Mapping = field(default_factory=dict)

    @property
    def mass(self) -> float:
        """Block mass [kg]."""
        return self.case.mass

    @property
    def g(self) -> float:
        """Gravity [m/s²]."""
        return self.case.g

    def describe(self) -> str:
        """How the block slides, in words, where it is not flat friction on a record as given: ``one-way
        (downslope only)``, ``two-way, thrust angle 10 deg``, and the polarity ("" for a flat block as given)."""
        parameters = self.case.resistance.parameters
        if not self.case.resistance.on_slope:
            text = ""
        elif parameters["direction"] == "down":
            text = "one-way (downslope only)"
        else:
            text = f"two-way, thrust angle {parameters['thrust_angle']:g} deg"
        if self.case.inverse:
            text = (text + "; " if text else "flat surface; ") + "inverse polarity (record sign flipped)"
        return text

    def settings(self) -> dict:
        """What the block is, JSON-ready: its sliding direction and thrust angle on a slope, polarity, mass [kg],
        gravity [m/s²] and the scheme."""
        parameters = self.case.resistance.parameters
        return {**{key: parameters[key] for key in ("direction", "thrust_angle") if key in parameters and
                   (key != "thrust_angle" or parameters.get("direction") == "both")},
                "inverse": self.case.inverse, "mass": self.mass, "g": self.g, "method": self.scheme.name}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        from stickslip.units import UNITS

        return {"mass": UNITS["block_mass"], "g": UNITS["gravity"],
                **({"thrust_angle": UNITS["thrust_angle"]} if "thrust_angle" in self.settings() else {})}

    def with_values(self, values) -> RigidDesign:
        """The same block over other ``values`` [1] of its coefficient."""
        return RigidDesign(self.grid.with_values(values), self.case, self.scheme, self.options)

    def curves(self, versions: Sequence[Record]) -> dict[str, np.ndarray]:
        """E_df [J], the stroke (largest |x|) [m] and x at the end [m] of each record over the grid, (n, values) each."""
        from stickslip.models.rigid.sweep import end_results

        check_memory(len(versions) * self.grid.values.size * len(SCALAR_NAMES) * 8 * 2,
                     f"{len(versions)} record(s) x {self.grid.values.size:,} {self.grid.coefficient.plural}")
        values = end_results(list(versions), self.case, self.scheme, self.grid, dict(self.options))
        return {name: values[..., SCALAR_NAMES.index(name)]
                for name in ("energy_dissipated", "peak_relative_displacement", "residual_displacement")}

    def energy(self, version: Record, values) -> np.ndarray:
        """E_df [J] of ``version`` at each of ``values`` [1] of the coefficient (one value: one serial case)."""
        values = np.atleast_1d(np.asarray(values, dtype=float))
        if self.scheme.batched and values.size == 1:
            from stickslip.models.rigid.exact import record_scalars

            case = self.case.at(self.grid.name, values[0])
            scalars = record_scalars(case.solved(version.acceleration), version.dt, resistance=case.resistance)
            return np.array([scalars[SCALAR_NAMES.index("energy_dissipated")] * self.mass])
        return self.with_values(values).curves([version])["energy_dissipated"][0]

    def first_still(self, acceleration: np.ndarray) -> int:
        """Index of the first grid value from which on the block never slides on ``acceleration`` [m/s²] (size: none).

        Both levels of the stick band move away from zero as the coefficient
        grows, so the values without sliding are a tail of the grid.
        """
        low, high = 0, self.grid.values.size
        while low < high:  # bisection over the grid: slides, then still
            middle = (low + high) // 2
            if self.case.at(self.grid.name, self.grid.values[middle]).slides(acceleration):
                low = middle + 1
            else:
                high = middle
        return low

    def still_reason(self, version: Record, index: int = 0) -> str:
        """Why the block does not slide on ``version`` at ``grid.values[index]``: the record's extremes and the levels."""
        value = float(self.grid.values[index])
        name = self.grid.name
        smallest_of_several = index == 0 and self.grid.values.size > 1
        where = f"the grid's smallest {name}, {value:g}" if smallest_of_several else f"{name} = {value:g}"
        return self.case.at(name, value).still_reason(version.acceleration, where)
