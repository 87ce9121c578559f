"""The equivalent-lateral-force design of a friction pendulum by ASCE 7-22, AASHTO and EN 1998-2.

A friction pendulum of radius R [m] and friction coefficient μ [1] under a
weight W, at a displacement D [m], has (Zayas et al. 1990; ASCE 7-22
§17.8.5.1's definitions of K_eff and β_eff):

    K_eff = W/R + μW/D                     the secant (effective) stiffness,
    T_eff = 2π sqrt(W/(K_eff g))           = 2π / sqrt(g (1/R + μ/D)),
    β_eff = E_loop/(2π K_eff D²)           = (2/π) μ/(μ + D/R),

the loop's energy being E_loop = 4μWD.  Each code's design displacement is
the spectral displacement of its spectrum at (T_eff, β_eff):

    D = g S_a(T_eff, β_eff) T_eff²/(4π²),

which in the velocity branch S_a = S_1/(B T) is ASCE 7-22 Eq. 17.5-1,
D_M = g S_M1 T_M/(4π² B_M) (B_M of Table 17.5-1), and AASHTO's Guide
Specifications for Seismic Isolation Design Eq. 7.1-4, d = g S_D1 T_eff/(4π² B_L)
(= 9.79 S_D1 T_eff/B_L in., B_L of Eq. 7.1-3), and for EN 1998-2 §7.5.4,
Table 7.1, d_cd = (0.625/π²) a_g S η_eff T_C T_eff (T_C ≤ T_eff ≤ T_D), η_eff
by Eq. 7.9.  T_eff and β_eff depend on D: D is the fixed point of
D ← D(T_eff(D), β_eff(D)), iterated from the displacement at the pendulum
period 2π sqrt(R/g) and 5 % damping until two steps agree to
:data:`TOLERANCE`; an iteration that has not settled in
:data:`MAX_ITERATIONS` steps is reported as having no fixed point.

The base shear is V_b = K_eff D (ASCE 7-22 Eq. 17.5-5; AASHTO's F = K_eff d,
Eq. 7.1-1; EN's V_d = K_eff d_cd), here as the coefficient V_b/W = D/R + μ.
ASCE's superstructure shear is V_st = V_b (W_s/W)^(1 − 3.5 β_M) (Eq. 17.5-7 with
the exponent it prescribes for a system whose hysteresis changes abruptly from
pre-slip to post-slip, as a slider's does, in place of 1 − 2.5 β_M),
V_s = V_st/R_I (Eq. 17.5-8), and not less than V_st of Eq. 17.5-7 with V_b the
force that activates the isolation system, the slider's breakaway friction
at the greater of the upper-bound μ and 1.5 times the nominal μ
(§17.5.4.3, item 3).  Total displacement with torsion (bearings
spread evenly over a b × d plan, e the actual eccentricity plus 5 % of the
longer plan dimension, y the bearing's distance from the centre of
rigidity): ASCE 7-22 Eq. 17.5-3, D_TM = D_M (1 + (y/P_T²) 12e/(b² + d²)) ≥
1.15 D_M, P_T the ratio of the translational to the torsional period; EN
1998-1 §10.9.3 (buildings), d (1 + e y/r²) with r² = (b² + d²)/12; AASHTO's
uniform load method has no such factor.  The restoring-force checks:
ASCE 7-22 §17.2.4.4, F(D_TM) − F(D_TM/2) ≥ 0.025 W, for the pendulum
D_TM/(2R) ≥ 0.025; AASHTO Guide Specifications §12.2, F(d) − F(d/2) ≥ W/80,
d/(2R) ≥ 1/80, and the period of the restoring stiffness alone,
2π sqrt(R/g), below 6 s; EN 1998-2 §7.7.1(2), d_cd/d_r ≥ δ_w = 0.5 with
d_r = μR the displacement at which the restoring force equals friction.

Upper- and lower-bound properties (ASCE 7-22 §17.2.8.4; AASHTO §8.2; EN
1998-2 §7.5.2.4) multiply μ by λ_max and λ_min; the design is repeated at
each.  docs/isolation_design.md gives the clauses, a worked example and the
editions read.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from stickslip.codes.damping import aashto_damping_coefficient, asce_damping_coefficient, eurocode_damping_correction
from stickslip.errors import StickslipError

#: The fixed point is reached when two steps of D agree to this relative difference [1].
TOLERANCE = 1e-10
#: The steps after which an iteration that has not settled is reported as having no fixed point.
MAX_ITERATIONS = 500

#: The bounds of the design, in output order (μ, λ_max μ, λ_min μ).
BOUNDS = ("nominal", "upper_bound", "lower_bound")

#: Our defaults for λ_max and λ_min where none are given [1] (docs/isolation_design.md says why these).
DEFAULT_LAMBDA_MAX, DEFAULT_LAMBDA_MIN = 1.8, 0.6


@dataclass(frozen=True)
class Plan:
    """The plan of the isolated structure for the torsion amplification: b × d [m], the actual eccentricity e [m]
    between the centres of mass and rigidity, the bearing's distance y [m] from the centre of rigidity
    perpendicular to the direction considered, and ASCE's period ratio P_T [1]."""

    width: float
    depth: float
    offset: float
    eccentricity: float = 0.0
    period_ratio: float = 1.0

    def __post_init__(self) -> None:
        for name, value, smallest in (("plan dimension b [m]", self.width, 0.0), ("plan dimension d [m]", self.depth, 0.0),
                                      ("torsional period ratio P_T", self.period_ratio, 0.0)):
            if not (math.isfinite(value) and value > smallest):
                raise StickslipError(f"{name} {value!r}: expected a positive number")
        for name, value in (("bearing offset y [m]", self.offset), ("eccentricity e [m]", self.eccentricity)):
            if not (math.isfinite(value) and value >= 0.0):
                raise StickslipError(f"{name} {value!r}: expected a number >= 0")

    @property
    def total_eccentricity(self) -> float:
        """e [m]: the actual eccentricity plus the accidental 5 % of the longer plan dimension."""
        return self.eccentricity + 0.05 * max(self.width, self.depth)

    def amplification(self, period_ratio: float = 1.0) -> float:
        """1 + (y/P_T²)·12 e/(b² + d²) [1]."""
        return 1.0 + self.offset / period_ratio**2 * 12.0 * self.total_eccentricity / (self.width**2 + self.depth**2)


@dataclass(frozen=True)
class Procedure:
    """One code's procedure, its rules as data.

    Attributes
    ----------
    key, title:
        The code's name in outputs (``asce7_22``) and for people.
    spectrum:
        ``spectrum(periods, damping)``: S_a [g] at periods [s] (:mod:`stickslip.codes.target_spectra`).
    damping_factor_name, damping_factor:
        The name (``B_M``) and rule (β [1] -> factor [1]) of the code's damping factor.
    torsion:
        ``torsion(plan)``: the factor [1] on D for the total displacement, or None where the code has none.
    checks:
        ``checks(radius [m], friction [1], displacement [m], g [m/s²])``: the restoring-force checks.
    superstructure_shear:
        Whether the code gives the superstructure's shear V_s of Eqs. 17.5-7 and 17.5-8.
    """

    key: str
    title: str
    spectrum: Callable[..., np.ndarray]
    damping_factor_name: str
    damping_factor: Callable[[float], float]
    torsion: Callable[[Plan], float] | None
    checks: Callable[[float, float, float, float], dict]
    superstructure_shear: bool = False


#: ASCE 7-22 Eq. 17.5-3: D_TM is not less than this multiple of D_M.
SMALLEST_TORSION_FACTOR = 1.15


def asce7_22(spectrum) -> Procedure:
    """ASCE 7-22 Chapter 17 on an MCE_R spectrum (:class:`~stickslip.codes.target_spectra.AsceTwoPeriod` or a
    multi-period table)."""
    return Procedure("asce7_22", "ASCE 7-22 Ch. 17", spectrum, "B_M", asce_damping_coefficient,
                     lambda plan: max(plan.amplification(plan.period_ratio), SMALLEST_TORSION_FACTOR), _asce_checks,
                     superstructure_shear=True)


def aashto(spectrum) -> Procedure:
    """AASHTO's Guide Specifications for Seismic Isolation Design on its spectrum
    (:class:`~stickslip.codes.target_spectra.AashtoThreePoint`)."""
    return Procedure("aashto", "AASHTO GSID", spectrum, "B_L", aashto_damping_coefficient, None, _aashto_checks)


def en1998_2(spectrum) -> Procedure:
    """EN 1998-2 §7.5 on an EN 1998-1 spectrum (:class:`~stickslip.codes.target_spectra.Eurocode8`)."""
    return Procedure("en1998_2", "EN 1998-2", spectrum, "eta", eurocode_damping_correction,
                     lambda plan: plan.amplification(), _eurocode_checks)


def effective_period(radius: float, mu: float, displacement: float, g: float) -> float:
    """T_eff = 2π / sqrt(g (1/R + μ/D)) [s]."""
    return 2.0 * math.pi / math.sqrt(g * (1.0 / radius + mu / displacement))


def effective_damping(radius: float, mu: float, displacement: float) -> float:
    """β_eff = (2/π) μ/(μ + D/R) [1]."""
    return 2.0 / math.pi * mu / (mu + displacement / radius)


def spectral_displacement(procedure: Procedure, period: float, damping: float, g: float) -> float:
    """g S_a(T, β) T²/(4π²) [m] of ``procedure``'s spectrum."""
    return g * float(procedure.spectrum([period], damping)[0]) * period**2 / (4.0 * math.pi**2)


@dataclass(frozen=True)
class BoundDesign:
    """One code's design at one bound of the friction coefficient; quantities as their names, units in
    :data:`UNITS`."""

    friction: float
    property_factor: float
    design_displacement: float
    effective_period: float
    effective_stiffness: float
    effective_damping: float
    damping_factor: float
    base_shear_coefficient: float
    superstructure_shear_coefficient: float | None
    superstructure_shear_exponent: float | None
    total_displacement: float | None
    iterations: int
    checks: dict = field(default_factory=dict)


#: Units of :class:`BoundDesign`'s numbers (UDUNITS spelling; the stiffness is per unit weight).
UNITS = {"friction": "1", "property_factor": "1", "design_displacement": "m", "effective_period": "s",
         "effective_stiffness": "m-1", "effective_damping": "1", "damping_factor": "1",
         "base_shear_coefficient": "1", "superstructure_shear_coefficient": "1",
         "superstructure_shear_exponent": "1", "total_displacement": "m", "iterations": "1"}


def fixed_point(procedure: Procedure, radius: float, mu: float, g: float,
                max_iterations: int = MAX_ITERATIONS) -> tuple[float, int]:
    """D [m] with D = g S_a(T_eff(D), β_eff(D)) T_eff(D)²/(4π²), and the steps taken; an error naming the code
    when the iteration does not settle."""
    displacement = spectral_displacement(procedure, 2.0 * math.pi * math.sqrt(radius / g), 0.05, g)
    previous = math.nan
    for step in range(1, max_iterations + 1):
        updated = spectral_displacement(procedure, effective_period(radius, mu, displacement, g),
                                        effective_damping(radius, mu, displacement), g)
        if not (math.isfinite(updated) and updated > 0.0):
            raise StickslipError(f"{procedure.title}, mu = {mu:g}: the iteration in D left the positive numbers "
                                 f"(D = {updated!r} m): no fixed point")
        if abs(updated - displacement) <= TOLERANCE * updated:
            return updated, step
        previous, displacement = displacement, updated
    raise StickslipError(f"{procedure.title}, R = {radius:g} m, mu = {mu:g}: the iteration in D has no fixed point: "
                         f"not settled after {max_iterations} steps (its last two values {previous:.6g} m and "
                         f"{displacement:.6g} m)")


#: ASCE 7-22 Eq. 17.5-7's exponent 1 − SLIDER_EXPONENT·β_M for a system with an abrupt pre-slip to post-slip
#: transition (a slider), in place of 2.5.
SLIDER_EXPONENT = 3.5
#: ASCE 7-22 §17.5.4.3: the activation force at no less than this multiple of the nominal properties.
ACTIVATION_FACTOR = 1.5


def design_bound(procedure: Procedure, radius: float, mu: float, g: float, *, property_factor: float = 1.0,
                 lambda_max: float = DEFAULT_LAMBDA_MAX, plan: Plan | None = None, weight_ratio: float = 1.0,
                 response_modification: float = 1.0, max_iterations: int = MAX_ITERATIONS) -> BoundDesign:
    """``procedure``'s design of the pendulum (R [m], nominal μ times ``property_factor``) at gravity ``g`` [m/s²]
    (module docstring); ``weight_ratio`` W_s/W, ``response_modification`` R_I and ``lambda_max`` (the activation
    force) enter ASCE's V_s, ``plan`` the torsion."""
    friction = mu * property_factor
    displacement, steps = fixed_point(procedure, radius, friction, g, max_iterations)
    period = effective_period(radius, friction, displacement, g)
    damping = effective_damping(radius, friction, displacement)
    base_shear = displacement / radius + friction
    superstructure = exponent = None
    if procedure.superstructure_shear:
        exponent = 1.0 - SLIDER_EXPONENT * damping
        activation = max(lambda_max, ACTIVATION_FACTOR) * mu
        superstructure = max(base_shear / response_modification, activation) * weight_ratio**exponent
    total = None if plan is None or procedure.torsion is None else displacement * procedure.torsion(plan)
    return BoundDesign(friction, property_factor, displacement, period, 1.0 / radius + friction / displacement, damping,
                       procedure.damping_factor(damping), base_shear, superstructure, exponent, total, steps,
                       procedure.checks(radius, friction, displacement if total is None else total, g))


def _asce_checks(radius: float, friction: float, displacement: float, g: float) -> dict:
    """ASCE 7-22 §17.2.4.4 at ``displacement`` [m] (D_TM where the plan is given, else D_M)."""
    return {"restoring_force": _check(displacement / (2.0 * radius), ">=", 0.025, "ASCE 7-22 §17.2.4.4",
                                      "[F(D) - F(D/2)]/W = D/(2R) at D_TM (D_M without a plan) >= 0.025")}


def _aashto_checks(radius: float, friction: float, displacement: float, g: float) -> dict:
    """AASHTO GSID §12.2: the restoring force between d/2 and d, and the period of the restoring stiffness."""
    return {"restoring_force": _check(displacement / (2.0 * radius), ">=", 1.0 / 80.0, "AASHTO GSID §12.2",
                                      "[F(d) - F(d/2)]/W = d/(2R) >= 1/80"),
            "restoring_period": _check(2.0 * math.pi * math.sqrt(radius / g), "<", 6.0, "AASHTO GSID §12.2",
                                       "period of the restoring stiffness alone 2 pi sqrt(R/g) < 6 s")}


def _eurocode_checks(radius: float, friction: float, displacement: float, g: float) -> dict:
    """EN 1998-2 §7.7.1(2): d_cd/d_r ≥ δ_w = 0.5, d_r = μR."""
    return {"restoring_capability": _check(displacement / (friction * radius), ">=", 0.5, "EN 1998-2 §7.7.1(2)",
                                           "d_cd/d_r >= delta_w = 0.5, d_r = mu R")}


def _check(value: float, relation: str, limit: float, clause: str, what: str) -> dict:
    passed = value >= limit if relation == ">=" else value < limit
    return {"value": value, "limit": limit, "passed": bool(passed), "clause": clause, "what": what}


def design(procedure: Procedure, radius: float, mu: float, g: float, *, lambda_max: float = DEFAULT_LAMBDA_MAX,
           lambda_min: float = DEFAULT_LAMBDA_MIN, **options) -> dict[str, BoundDesign]:
    """``procedure``'s design at nominal μ, λ_max μ (upper bound) and λ_min μ (lower bound), by :data:`BOUNDS`;
    ``options`` as :func:`design_bound`'s."""
    for name, value in (("radius R [m]", radius), ("friction coefficient mu", mu), ("g [m/s2]", g),
                        ("lambda_max", lambda_max), ("lambda_min", lambda_min)):
        if not (math.isfinite(value) and value > 0.0):
            raise StickslipError(f"{name} {value!r}: expected a positive number")
    if not lambda_min <= 1.0 <= lambda_max:
        raise StickslipError(f"lambda_min {lambda_min:g} and lambda_max {lambda_max:g}: expected lambda_min <= 1 <= "
                             "lambda_max")
    factors = dict(zip(BOUNDS, (1.0, lambda_max, lambda_min)))
    return {bound: design_bound(procedure, radius, mu, g, property_factor=factor, lambda_max=lambda_max, **options)
            for bound, factor in factors.items()}
