"""The parameters that several sliding-block models share, declared once, and the friction law they give.

Each is a :class:`~stickslip.models.entry.Parameter`: its keyword of
:func:`stickslip.solve` (and option of the command line), unit, default,
check and help.  A model lists the ones it takes in its entry; a parameter
of one model only is declared in that model's module.
"""

from __future__ import annotations

import math
from functools import partial

from stickslip.checks import checked_positive
from stickslip.constants import DEFAULT_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.models.entry import Parameter
from stickslip.solvers.structure.shear_building import DAMPING_MODELS


#: A friction ratio [1] no record overcomes: the friction-linked models' interface held (the isolated building on its
#: isolator, the damper on its floor).
HELD = 1e9


def positive(name: str):
    """A check that the value is a positive finite number; ``name`` (with its unit) names it in the message."""
    return partial(checked_positive, name=name)


def between(name: str, low: float, high: float, unit: str):
    """A check that the value is a number from ``low`` to ``high`` [``unit``]."""

    def check(value):
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise StickslipError(f"{name} [{unit}] must be a number, got {value!r}") from None
        if not low <= number <= high:
            raise StickslipError(f"{name} must be from {low:g} to {high:g} {unit}, got {value!r}")
        return number

    return check


def positive_or_table(name: str):
    """A check that the value is a positive finite number, or a table of values (a
    :class:`~stickslip.models.yield_table.YieldTable`, checked when it was built)."""
    number = positive(name)

    def check(value):
        return value if hasattr(value, "thresholds") else number(value)

    return check


def one_of(name: str, choices: tuple[str, ...]):
    """A check that the value is one of ``choices``."""

    def check(value):
        if value not in choices:
            raise StickslipError(f"{name} must be one of {', '.join(choices)}, got {value!r}")
        return value

    return check


def flag(value) -> bool:
    """A switch, as a bool."""
    return bool(value)


MU = Parameter("mu", "1", "friction ratio mu [-] of a flat surface: the friction force is at most mu*m*g",
               check=positive("friction ratio mu"), swept=True, excludes=("ky",), plural="friction ratios mu",
               example="0.05:0.2:0.025", plausible=1.0)
KY = Parameter("ky", "1", "yield coefficient k_y [-] (yield acceleration / g; 0.15, the same as 0.15g, or an "
               "acceleration with its unit, 1.47m/s2): the block slides downslope when the driving acceleration "
               "exceeds k_y*g", check=positive_or_table("yield coefficient ky"), kind="acceleration", swept=True, tables=True,
               excludes=("mu",), plural="yield coefficients k_y",
               example="0.02:0.4:0.02", plausible=1.0)
DIRECTION = Parameter("direction", "1", "with ky: down (default: slides downslope only) or both (also upslope, past "
                      "k_y*g + 2 g sin(thrust angle))", kind="choice", choices=("down", "both"),
                      check=one_of("direction", ("down", "both")), requires=("ky", None))
THRUST_ANGLE = Parameter("thrust_angle", "degree", "with direction both: SLAMMER's thrust angle [degrees, 0 to 90] "
                         "(default 0)", check=between("thrust angle", 0.0, 90.0, "degrees"), requires=("direction", "both"))
INVERSE = Parameter("inverse", "1", "solve the record with its sign flipped (SLAMMER's inverse polarity)",
                    default=False, check=flag, kind="flag")
#: SLAMMER's two polarities, as tables and figures name them: the record as given, and its sign flipped (INVERSE).
POLARITIES = ("normal", "inverse")
MASS = Parameter("mass", "kg", f"block mass [kg] (default {DEFAULT_BLOCK_MASS:g}: energies per kg of the block, J/kg; "
                 "they scale with the mass; the paper's block is 5.1)", default=DEFAULT_BLOCK_MASS,
                 check=positive("block mass [kg]"))
#: The velocity law μ(v) of a sliding surface (:class:`~stickslip.solvers.friction_law.FrictionLaw`), instead of
#: Coulomb's ``mu``: its three numbers, or ``mu`` as its μ_fast with ``mu_slow_ratio`` and ``rate``
#: (:func:`friction_law`).
MU_SLOW = Parameter("mu_slow", "1", "friction ratio at rest and at low speed of the velocity law mu(v) = mu_fast - "
                    "(mu_fast - mu_slow) exp(-rate |v|) (Constantinou, Mokha & Reinhorn 1990); instead of mu (solve "
                    "only: a sweep holds mu_slow/mu_fast, --mu-slow-ratio)",
                    check=positive("friction ratio at low speed mu_slow"), excludes=("mu",),
                    in_sweeps="a sweep's friction grid --mu is the velocity law's mu_fast: hold the law's shape with "
                              "--mu-slow-ratio (mu_slow/mu_fast) and --rate")
MU_FAST = Parameter("mu_fast", "1", "friction ratio at high speed of the velocity law (solve only: a sweep's grid "
                    "--mu is mu_fast)",
                    check=positive("friction ratio at high speed mu_fast"),
                    in_sweeps="a sweep's friction grid --mu is the velocity law's mu_fast: give the grid as --mu, "
                              "with --mu-slow-ratio (mu_slow/mu_fast) and --rate")
MU_SLOW_RATIO = Parameter("mu_slow_ratio", "1", "mu_slow/mu_fast of the velocity law, with rate; mu is then mu_fast "
                          "(a sweep's grid of mu sweeps mu_fast with this ratio and the rate held)",
                          check=positive("ratio mu_slow/mu_fast of the velocity law"), requires=("rate", None))
RATE = Parameter("rate", "s m-1", "rate a [s/m] of the velocity law (tests report 10 to 100 s/m)",
                 check=positive("rate of the velocity law [s/m]"))
GRAVITY = Parameter("g", "m s-2", f"gravity [m/s2] (default {STANDARD_GRAVITY:g}; SLAMMER's is 9.80665)",
                    default=STANDARD_GRAVITY, check=positive("gravity g [m/s2]"))


def _whole_stories(value) -> int:
    """The number of stories of a shear building, a whole number of at least 1."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = math.nan
    if not (number.is_integer() and number >= 1):
        raise StickslipError(f"number of stories (--stories) must be a whole number of at least 1, got {value!r}")
    return int(number)


STORIES = Parameter("stories", "1", "number of stories of the shear building (equal floors and stories; default 1: "
                    "the two-degree-of-freedom design model of an isolated building)", default=1,
                    check=_whole_stories)
DAMPING_MODEL = Parameter(
    "damping_model", "1", "the shear building's damping: modal (default: every fixed-base mode the ratio given) or "
    "rayleigh (mass and stiffness proportional, the ratio on the first and last mode)", default="modal",
    kind="choice", choices=DAMPING_MODELS, check=one_of("damping model (--damping-model)", DAMPING_MODELS))


def friction_law(parameters):
    """The :class:`~stickslip.solvers.friction_law.FrictionLaw` of a model's checked ``parameters``: Coulomb's
    ``mu``, the velocity law's ``mu_slow``, ``mu_fast`` and ``rate``, or ``mu`` (its μ_fast) with ``mu_slow_ratio``
    and ``rate``; any other combination is one line, and an unusual law a warning
    (:func:`~stickslip.solvers.friction_law.unusual_law_warnings`)."""
    import warnings

    from stickslip.errors import StickslipWarning
    from stickslip.solvers.friction_law import FrictionLaw, unusual_law_warnings

    mu, ratio, rate = parameters["mu"], parameters["mu_slow_ratio"], parameters["rate"]
    law = [parameters[name] for name in ("mu_slow", "mu_fast", "rate")]
    slow = "mu_slow="
    if mu is not None and (parameters["mu_slow"] is not None or parameters["mu_fast"] is not None):
        raise StickslipError("mu= and mu_slow=/mu_fast= are two friction laws: give mu= (with mu_slow_ratio= "
                             "and rate=, mu is mu_fast), or mu_slow=, mu_fast= and rate=")
    if mu is not None and ratio is not None and rate is not None:
        friction, slow = FrictionLaw.velocity_dependent(ratio * mu, mu, rate), "mu_slow_ratio="
    elif mu is not None and ratio is None and rate is None:
        friction = FrictionLaw.coulomb(mu)
    elif mu is None and ratio is None and all(value is not None for value in law):
        friction = FrictionLaw.velocity_dependent(*law)
    elif mu is not None and rate is not None:
        raise StickslipError("rate= applies to the velocity law: give mu_slow_ratio= with mu= (mu is then its "
                             "mu_fast), or mu_slow= and mu_fast= instead of mu=")
    else:
        raise StickslipError("give a friction ratio mu= (with mu_slow_ratio= and rate=, the velocity law: mu is "
                             "its mu_fast), or the velocity law's mu_slow=, mu_fast= and rate=")
    for warning in unusual_law_warnings(friction, slow):  # attributed here, so that a sweep says it once
        warnings.warn(warning, StickslipWarning)
    return friction


def friction_attrs(law) -> dict:
    """A cube's attributes of the friction law ``law`` (:meth:`~stickslip.solvers.friction_law.FrictionLaw.settings`,
    and under the velocity law its shape in words and the rate's unit), read back by :func:`friction_parameters`."""
    if law.is_coulomb:
        return law.settings()
    return {**law.settings(), "friction_law_description": law.describe_shape(), "rate_units": "s m-1"}


def friction_parameters(attrs) -> dict:
    """The parameters of the friction law a cube was swept with, from its attributes (:func:`friction_attrs`): under
    the velocity law ``mu_slow_ratio`` and ``rate`` (its grid of ``mu`` is μ_fast); none for Coulomb friction."""
    if attrs.get("friction_law") != "velocity_dependent":
        return {}
    return {"mu_slow_ratio": float(attrs["mu_slow_ratio"]), "rate": float(attrs["rate"])}
