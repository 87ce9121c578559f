"""The friction tuned mass damper: a mass sliding with friction on a floor of a shear building on a fixed base.

A uniform shear building of n stories (fundamental period T [s], modal or
Rayleigh damping ζ, mass m_s [kg] in equal floors) carries on floor j (the
top by default) a mass m_d = (mass ratio)·m_s [kg] that slides with Coulomb
friction μ on a flat surface or on a concave one of radius R_d [m], which
tunes it (its swing's period 2π√(R_d/g)).  In one direction, with the normal
force N = m_d·g constant and Coulomb friction, every phase (the damper held,
sliding one way) is a linear structure under a linear force, solved in closed
form per sample step with the events located (:mod:`stickslip.solvers.structure`);
a pair of components, the vertical (N = m_d·(g + a_v)) or the velocity law
μ(v) are integrated in the plane (:mod:`~stickslip.models.friction_tmd.plane`).  Its answers are
the designer's: the building's peak displacement, story drifts, floor
accelerations and base shear, each beside the same building without the
damper and with the damper's mass attached (the reductions), the damper's
stroke, and E_df.  The design answer's objectives: the most E_df (the
paper's, default), the smallest drift, floor acceleration, base shear or
stroke (docs/structures.md).
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


def _whole(name: str):
    """A check that the value is a whole number of at least 1 (``name`` names it in the message)."""

    def check(value) -> int:
        try:
            number = float(value)
        except (TypeError, ValueError):
            number = math.nan
        if not (math.isfinite(number) and number >= 1 and number == int(number)):
            raise StickslipError(f"{name} must be a whole number of at least 1, got {value!r}")
        return int(number)

    return check


def _radius(value) -> float:
    """R_d [m]: positive, ``math.inf`` for a flat surface."""
    try:
        radius = float(value)
    except (TypeError, ValueError):
        radius = math.nan
    if not radius > 0.0:
        raise StickslipError(f"radius of the damper's surface R_d [m] must be positive (inf for a flat surface), "
                             f"got {value!r}")
    return radius


STRUCTURE_PERIOD = Parameter("structure_period", "s", "fundamental fixed-base period T [s] of the shear building "
                             "that carries the damper", check=positive("structure period T [s]"),
                             usual=(0.05, 10.0, "the fundamental periods of buildings"))
STRUCTURE_DAMPING = Parameter("structure_damping", "1", "damping ratio zeta [-] of the building's fixed-base modes "
                              "(default 0.02)", default=0.02, check=between("structure damping ratio", 0.0, 0.99, "-"))
MASS_RATIO = Parameter("mass_ratio", "1", "damper-to-building mass ratio m_d/m_s [-] (default 0.05)", default=0.05,
                       check=positive("mass ratio m_d/m_s"))
RADIUS = Parameter("radius", "m", "radius R_d [m] of the damper's concave surface (default inf: flat); its free "
                   "swing's period is 2 pi sqrt(R_d/g)", default=math.inf, check=_radius,
                   usual=(0.05, 50.0, "the surfaces of sliding mass dampers"))
DAMPER_STORY = Parameter("damper_story", "1", "the floor j the damper sits on (1 the lowest; default the top)",
                         check=_whole("damper story"))
MASS = Parameter("mass", "kg", "the building's mass m_s [kg] (default 1: energies per kg of the building)",
                 default=1.0, check=positive("building mass m_s [kg]"))

#: The building's answers the design answer reports beside E_df and the stroke: name -> (units, long name, label).
DEMANDS = {
    "peak_drift": ("m", "largest |story drift| over the stories", "drift"),
    "peak_floor_acceleration": ("m s-2", "largest |absolute floor acceleration| over the floors", "floor acc."),
    "base_shear_coefficient": ("1", "peak base shear of the building over its weight, V_b/W", "V_b/W"),
    "peak_structure_displacement": ("m", "largest |floor displacement relative to the ground|", "displacement"),
}


class FrictionTmdModel(SweptModel):
    """The friction tuned mass damper's entry."""

    name = "friction-tmd"
    summary = ("a mass sliding with friction (flat, or on a concave surface of radius R_d) on a floor of a shear "
               "building on a fixed base: a friction tuned mass damper")
    motions = ("component", "pair")
    vertical = True
    parameters = (MU, MU_SLOW, MU_FAST, MU_SLOW_RATIO, RATE, STRUCTURE_PERIOD, STORIES, STRUCTURE_DAMPING,
                  DAMPING_MODEL, MASS_RATIO, RADIUS, DAMPER_STORY, MASS, GRAVITY)
    schemes = structure_schemes("stickslip.models.friction_tmd.solve", "stickslip.models.friction_tmd.plane")
    objectives = ("energy", "drift", "floor-acceleration", "base-shear", "displacement")
    demands = DEMANDS
    strokes = ("peak_damper_stroke", "residual_damper_stroke")
    #: A damper on a flat surface on one story, and on a curved one on the middle floor of three.
    examples = ({"mu": 0.1, "structure_period": 1.0},
                {"mu": 0.1, "structure_period": 1.0, "stories": 3, "radius": 2.0, "damper_story": 2})
    #: Its design chart: the objective's quantity and the damper's stroke over m_d/m_s × μ, by default over mass
    #: ratios from 1 % to 10 % (what tuned mass dampers carry).
    chart_over = "mass_ratio"
    chart_values = (0.01, 0.02, 0.03, 0.05, 0.075, 0.1)
    chart_long_name = "damper-to-building mass ratio m_d/m_s"
    chart_title = "Friction tuned mass damper design chart"
    mass_of = "building (m_s)"
    #: Every motion, however short, reaches both schemes' compiled kernels: 0.05 s of the warm-up's motion do.
    warm_up_samples = 50

    @property
    def result(self) -> type:
        from stickslip.models.friction_tmd.response import DamperResponse

        return DamperResponse

    def case(self, parameters):
        """The :class:`~stickslip.models.friction_tmd.case.DamperCase`; the damper on a floor the building has."""
        from stickslip.models.friction_tmd.case import DamperCase

        friction = [parameters[name] for name in ("mu", "mu_slow", "mu_fast")]
        if all(value is None for value in friction) or parameters["structure_period"] is None:
            raise StickslipError("the friction-tmd model needs a friction ratio mu= and the building's period "
                                 "structure_period= [s]")
        stories = parameters["stories"]
        story = stories if parameters["damper_story"] is None else parameters["damper_story"]
        if story > stories:
            floors = f"{stories} stor{'y' if stories == 1 else 'ies'}"
            raise StickslipError(f"damper story {story}: the building has {floors} (floors 1 to {stories})")
        law = friction_law(parameters)
        return DamperCase(law.mu_fast, parameters["structure_period"], stories, parameters["structure_damping"],
                          parameters["damping_model"], parameters["mass_ratio"], parameters["radius"], story,
                          parameters["mass"], parameters["g"], None if law.is_coulomb else law.mu_slow, law.rate)

    def variables(self, case) -> dict[str, dict[str, str]]:
        from stickslip.models.friction_tmd.response import SCALARS

        return {name: {"units": unit, "long_name": long_name} for name, (unit, long_name) in SCALARS.items()
                if name != "balance_residual"}

    def cube_variables(self, case, motions) -> dict[str, dict[str, str]]:
        """:meth:`variables` on records of one component; on pairs or motions with their vertical, the answers in
        the plane with W_v and, with a vertical, the lift-off time
        (:func:`~stickslip.models.structure_scheme.plane_variables`)."""
        from stickslip.models.friction_tmd.plane import PLANE_SCALARS

        return plane_variables(self.variables(case), PLANE_SCALARS, motions)

    def cube_attrs(self, case, scheme, run_options) -> dict:
        return {**{f"solver_{name}": value for name, value in run_options.items()}, **friction_attrs(case.friction),
                "structure_period": case.structure_period, "structure_period_units": "s", "stories": case.stories,
                "structure_damping": case.structure_damping, "damping_model": case.damping_model,
                "mass_ratio": case.mass_ratio, "radius": case.radius, "radius_units": "m",
                "damper_story": case.damper_story, "structure_mass": case.mass, "structure_mass_units": "kg",
                "gravity": case.g, "gravity_units": "m s-2", "sliding": case.describe_sliding()}

    def parameters_of(self, cube) -> tuple[str, dict, dict]:
        attrs = cube.attrs
        options = {key.removeprefix("solver_"): value for key, value in attrs.items() if key.startswith("solver_")}
        return attrs["solver"], options, {**friction_parameters(attrs),
            "structure_period": float(attrs["structure_period"]), "stories": int(attrs["stories"]),
            "structure_damping": float(attrs["structure_damping"]), "damping_model": str(attrs["damping_model"]),
            "mass_ratio": float(attrs["mass_ratio"]), "radius": float(attrs["radius"]),
            "damper_story": int(attrs["damper_story"]), "mass": float(attrs["structure_mass"]),
            "g": float(attrs["gravity"])}


#: The friction tuned mass damper's entry.
FRICTION_TMD = register(FrictionTmdModel())
