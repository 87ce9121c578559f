"""What "optimal" means in a design answer over a grid: the objectives a model declares and a user chooses among.

An :class:`Objective` turns one of a model's response curves over the grid
of its swept coefficient c into a merit, the larger the better, so that
:mod:`stickslip.optimum` answers every objective alike: the optimum
``{c}_max`` is the grid value of the largest merit (then found
continuously between its neighbours), the near-optimal range the values
whose merit is at least q times the best, and the efficiency the merit at
the reference value over the best.

``energy``
    the most energy dissipated by friction, merit E_df [J]: the paper's
    objective, every model's default;
``displacement``
    the smallest stroke (peak |x|, x the block's displacement relative to the
    base), merit 1/stroke [1/m]: the near-optimal range holds the values whose
    stroke is at most stroke_min / q, and the efficiency is stroke_min over the
    stroke at the reference value.
``drift``, ``floor-acceleration``, ``base-shear``
    the structure's smallest largest story drift [m], largest absolute floor
    acceleration [m/s²] or base shear coefficient V_b/W [1] (the models with
    a structure above or below the slider: merit the reciprocal, as for the
    stroke).

A model lists the ones it offers in its entry
(:attr:`stickslip.models.swept.SweptModel.objectives`, its default first);
``stickslip optimum --objective NAME`` chooses among them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from stickslip.errors import StickslipError


@dataclass(frozen=True)
class Objective:
    """One meaning of "optimal": the response curve it reads and which way is better.

    Attributes
    ----------
    name:
        The name users give (``--objective displacement``).
    summary:
        What is optimal, in words.
    curve:
        The response curve it reads (a variable of the model's cube:
        ``energy_dissipated`` [J], ``peak_relative_displacement`` [m]).
    larger:
        Whether a larger value of the curve is better (the merit is the curve);
        else a smaller one is (the merit is its reciprocal).
    note:
        What the design answer's results mean under it, one line under the
        terminal's tables ("" for the paper's, which the tables already say).
    long_names:
        The per-record results whose long names it changes, template ->
        long name (``{c}``: the coefficient's name, ``{noun}``: what it is called).
    """

    name: str
    summary: str
    curve: str
    larger: bool = True
    note: str = ""
    long_names: dict[str, str] = field(default_factory=dict)

    @property
    def quantity(self) -> str:
        """What its curve is, in words: :attr:`summary` without "the most" or "the smallest" and its remark in
        brackets (``peak story drift``)."""
        return self.summary.split(" ", 2)[2].split(" (")[0]

    def merit(self, values) -> np.ndarray:
        """The merit of the curve's ``values`` (any shape): the values where larger is better, else 1/values
        (+inf where a value is 0: a block that never slides has the smallest stroke)."""
        values = np.asarray(values, dtype=float)
        if self.larger:
            return values
        with np.errstate(divide="ignore"):
            return 1.0 / values


#: The paper's objective: the most energy dissipated by friction.
ENERGY = Objective("energy", "the most energy dissipated by friction E_df (the paper's)", "energy_dissipated")

#: The smallest stroke.
DISPLACEMENT = Objective(
    "displacement", "the smallest stroke (peak |x|, x the block's displacement relative to the base)",
    "peak_relative_displacement", larger=False,
    note="objective: the smallest stroke; {c}_max is the {c} of the smallest stroke, E_df,max the E_df there, the "
         "near-optimal range the {c} whose stroke is at most stroke_min / q, the efficiency stroke_min over the "
         "stroke at the reference {c}",
    long_names={"{c}_max": "{noun} of the smallest stroke, on the grid",
                "energy_dissipated_max": "energy dissipated at {c}_max",
                "{c}_max_continuous": "{noun} of the smallest stroke, found continuously",
                "energy_dissipated_max_continuous": "energy dissipated at {c}_max_continuous",
                "{c}_low": "smallest grid {c} whose stroke is at most the smallest stroke over q",
                "{c}_high": "largest grid {c} whose stroke is at most the smallest stroke over q",
                "efficiency": "the smallest stroke over the stroke at the reference {noun}"})



def _smallest(name: str, curve: str, quantity: str, symbol: str) -> Objective:
    """The objective of the smallest ``quantity`` (the cube's ``curve``, written ``symbol`` in the notes)."""
    return Objective(
        name, f"the smallest {quantity}", curve, larger=False,
        note=f"objective: the smallest {quantity}; {{c}}_max is the {{c}} of the smallest {symbol}, E_df,max the E_df "
             f"there, the near-optimal range the {{c}} whose {symbol} is at most {symbol}_min / q, the efficiency "
             f"{symbol}_min over the {symbol} at the reference {{c}}",
        long_names={"{c}_max": f"{{noun}} of the smallest {quantity}, on the grid",
                    "energy_dissipated_max": "energy dissipated at {c}_max",
                    "{c}_max_continuous": f"{{noun}} of the smallest {quantity}, found continuously",
                    "energy_dissipated_max_continuous": "energy dissipated at {c}_max_continuous",
                    "{c}_low": f"smallest grid {{c}} whose {symbol} is at most the smallest over q",
                    "{c}_high": f"largest grid {{c}} whose {symbol} is at most the smallest over q",
                    "efficiency": f"the smallest {symbol} over the {symbol} at the reference {{noun}}"})


#: The smallest largest story drift of the structure.
DRIFT = _smallest("drift", "peak_drift", "peak story drift (the largest over the stories)", "drift")

#: The smallest largest absolute floor acceleration of the structure.
FLOOR_ACCELERATION = _smallest("floor-acceleration", "peak_floor_acceleration",
                               "peak absolute floor acceleration (the largest over the floors)", "floor acceleration")

#: The smallest base shear coefficient V_b/W.
BASE_SHEAR = _smallest("base-shear", "base_shear_coefficient", "base shear coefficient V_b/W", "V_b/W")

#: Every objective, by name.
OBJECTIVES = {objective.name: objective for objective in (ENERGY, DISPLACEMENT, DRIFT, FLOOR_ACCELERATION, BASE_SHEAR)}


def objective_named(name: str, offered: tuple[str, ...], model: str, option: str = "objective") -> Objective:
    """The objective ``name`` among the ``offered`` ones of ``model`` (its name); else one line naming ``option``."""
    if name not in OBJECTIVES:
        raise StickslipError(f"{option} {name!r}: expected one of {', '.join(OBJECTIVES)}")
    if name not in offered:
        raise StickslipError(f"{option} {name}: the {model} model's optimum is {' or '.join(offered)} "
                             f"({'; '.join(OBJECTIVES[other].summary for other in offered)}), not "
                             f"{OBJECTIVES[name].summary}")
    return OBJECTIVES[name]
