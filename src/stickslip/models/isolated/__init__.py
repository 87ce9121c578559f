"""The isolated building: a linear shear building on a base mass that slides on a friction pendulum or a flat slider.

A superstructure of n stories (n = 1: the standard two-degree-of-freedom
design model, Naeim and Kelly 1999) on a base mass m_b; the base slides on a
spherical surface of radius R [m] (R = inf: a flat slider) under the whole
weight W = (m_b + m_s)·g with Coulomb friction μ or the velocity law μ(v).
It is the friction-linked structure of :mod:`stickslip.solvers.structure.friction_linked`
with the base as its interface: on one component with Coulomb friction solved
exactly (closed forms per sample step, the events located to round-off); on a
pair of components, with the vertical (N = W·(1 + a_v/g), lift-off where it
vanishes) or with μ(v), integrated in the plane to a tolerance
(:mod:`~stickslip.models.isolated.plane`; :mod:`stickslip.models.structure_scheme`,
docs/structures.md).  Its answers are the
designer's: the isolator's peak and residual displacement, each story's peak
drift and each floor's peak absolute acceleration, the base shear V_b/W and
the superstructure's V_s/W_s, beside E_df, with its energy ledger.

Damping is classical on the fixed-base modes by default (``modal``: every
mode of the superstructure has the ratio named, as the design model and the
codes' response-history rules assume); ``rayleigh`` gives the modes between
the first and the last less (and those above more).
"""

from __future__ import annotations

import math

from stickslip.errors import StickslipError
from stickslip.models.entry import Parameter
from stickslip.models.parameters import (DAMPING_MODEL, GRAVITY, MU, MU_FAST, MU_SLOW, MU_SLOW_RATIO, RATE, STORIES,
                                         between, friction_attrs, friction_law, friction_parameters, positive)
from stickslip.models.registry import register
from stickslip.models.structure_scheme import plane_variables, structure_schemes
from stickslip.models.swept import SweptModel


def _radius(value) -> float:
    """The isolator's radius R [m]: positive, inf for a flat slider."""
    try:
        radius = float(value)
    except (TypeError, ValueError):
        radius = math.nan
    if not radius > 0.0:
        raise StickslipError(f"radius of the isolator's surface [m] (--radius) must be positive (inf for a flat "
                             f"slider), got {value!r}")
    return radius


SUPERSTRUCTURE_PERIOD = Parameter(
    "superstructure_period", "s", "fundamental fixed-base period [s] of the superstructure (a shear building of "
    "equal floors and stories)", check=positive("superstructure period [s] (--superstructure-period)"),
    usual=(0.05, 5.0, "the fixed-base periods of buildings"))
SUPERSTRUCTURE_DAMPING = Parameter(
    "superstructure_damping", "1", "damping ratio [-] of the superstructure's fixed-base modes (default 0.02)",
    default=0.02, check=between("superstructure damping ratio (--superstructure-damping)", 0.0, 0.99, "[-]"))
MASS_RATIO = Parameter("mass_ratio", "1", "superstructure mass over base mass m_s/m_b [-] (default 4)", default=4.0,
                       check=positive("mass ratio m_s/m_b (--mass-ratio)"))
RADIUS = Parameter("radius", "m", "radius R [m] of the isolator's spherical surface (default inf: a flat slider)",
                   default=math.inf, check=_radius, usual=(0.2, 20.0, "the surfaces of friction pendulums"))
TOTAL_MASS = Parameter("mass", "kg", "total mass m_b + m_s [kg] of the isolated building (default 1: energies per "
                       "kg of the building)", default=1.0, check=positive("total mass [kg] (--mass)"))


class IsolatedModel(SweptModel):
    """The entry of the isolated building."""

    name = "isolated"
    summary = ("a shear building on a base mass that slides on a friction pendulum of radius R (inf: a flat "
               "slider): isolator displacement, story drift, floor acceleration")
    motions = ("component", "pair")
    vertical = True
    parameters = (MU, MU_SLOW, MU_FAST, MU_SLOW_RATIO, RATE, SUPERSTRUCTURE_PERIOD, STORIES, SUPERSTRUCTURE_DAMPING,
                  DAMPING_MODEL, MASS_RATIO, RADIUS, TOTAL_MASS, GRAVITY)
    schemes = structure_schemes("stickslip.models.isolated.response", "stickslip.models.isolated.plane")
    objectives = ("energy", "drift", "floor-acceleration", "base-shear", "displacement")
    #: The design answer's stroke and residual displacement, which the displacement objective reads: the isolator's.
    strokes = ("peak_isolator_displacement", "residual_isolator_displacement")
    demands = {
        "peak_drift": ("m", "largest peak story drift over the stories", "drift"),
        "peak_floor_acceleration": ("m s-2", "largest peak absolute floor acceleration", "floor acc."),
        "base_shear_coefficient": ("1", "peak isolator force over the weight V_b/W", "V_b/W"),
    }
    examples = ({"mu": 0.06, "superstructure_period": 0.5, "radius": 2.0},)
    #: Its design chart: the objective's quantity and the isolator's displacement over R × μ, by default over the
    #: radii of isolation periods 2π√(R/g) from 2.0 s to 4.0 s.
    chart_over = "radius"
    chart_values = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0)
    chart_long_name = "radius R of the isolator's spherical surface"
    chart_title = "Isolated building design chart"
    mass_of = "building (m_b + m_s)"
    #: Every motion, however short, reaches both schemes' compiled kernels: 0.05 s of the warm-up's motion do.
    warm_up_samples = 50

    @property
    def result(self) -> type:
        from stickslip.models.isolated.response import IsolatedResponse

        return IsolatedResponse

    def case(self, parameters):
        from stickslip.models.isolated.case import IsolatedCase

        given = [parameters[name] for name in ("mu", "mu_slow", "mu_fast")]
        if all(value is None for value in given) or parameters["superstructure_period"] is None:
            raise StickslipError("the isolated model needs a friction ratio mu= and the superstructure's "
                                 "fixed-base period superstructure_period= [s]")
        law = friction_law(parameters)
        return IsolatedCase(law.mu_fast, parameters["superstructure_period"], parameters["stories"],
                            parameters["superstructure_damping"], parameters["damping_model"],
                            parameters["mass_ratio"], parameters["radius"], parameters["mass"], parameters["g"],
                            None if law.is_coulomb else law.mu_slow, law.rate)

    def variables(self, case) -> dict[str, dict[str, str]]:
        from stickslip.models.isolated.response import SCALARS

        found = {name: {"units": units, "long_name": long_name} for name, (units, long_name) in SCALARS.items()
                 if name != "balance_residual"}
        return found

    def cube_variables(self, case, motions) -> dict[str, dict[str, str]]:
        """:meth:`variables` on records of one component; on pairs or motions with their vertical, the answers in
        the plane with W_v and, with a vertical, the lift-off time
        (:func:`~stickslip.models.structure_scheme.plane_variables`)."""
        from stickslip.models.isolated.plane import PLANE_SCALARS

        return plane_variables(self.variables(case), PLANE_SCALARS, motions)

    def cube_attrs(self, case, scheme, run_options) -> dict:
        return {**{f"solver_{name}": value for name, value in run_options.items()}, **friction_attrs(case.friction),
                "superstructure_period": case.superstructure_period, "superstructure_period_units": "s",
                "stories": case.stories, "superstructure_damping": case.superstructure_damping,
                "damping_model": case.damping_model, "mass_ratio": case.mass_ratio, "radius": case.radius,
                "radius_units": "m", "block_mass": case.mass, "block_mass_units": "kg", "gravity": case.g,
                "gravity_units": "m s-2", "sliding": case.describe_sliding()}

    def parameters_of(self, cube) -> tuple[str, dict, dict]:
        attrs = cube.attrs
        options = {key.removeprefix("solver_"): value for key, value in attrs.items() if key.startswith("solver_")}
        return attrs["solver"], options, {**friction_parameters(attrs),
            "superstructure_period": float(attrs["superstructure_period"]), "stories": int(attrs["stories"]),
            "superstructure_damping": float(attrs["superstructure_damping"]),
            "damping_model": str(attrs["damping_model"]), "mass_ratio": float(attrs["mass_ratio"]),
            "radius": float(attrs["radius"]), "mass": float(attrs["block_mass"]), "g": float(attrs["gravity"])}


#: The isolated building's entry.
ISOLATED = register(IsolatedModel())
