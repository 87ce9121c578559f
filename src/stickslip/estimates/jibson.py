"""Jibson's regressions of Newmark's rigid-block displacement D_n, and his probability of failure: the one home of his formulas.

Units as Jibson's: D_n in cm (the estimates return m), the critical
(yield) acceleration a_c = k_y and the peak ground acceleration a_max in g,
Arias intensity I_a in m s-1, M the moment magnitude; logarithms base 10.
Every form is linear in its terms (:data:`FORM_TERMS`):

* Jibson (1993), Transportation Research Record 1411, 9-17:
  log D_n = 1.460 log I_a − 6.642 a_c + 1.546, σ 0.409;
* Jibson, Harp and Michael (2000), Engineering Geology 58, 271-289, eq. 3
  (SLAMMER's "Jibson and others (1998)"):
  log D_n = 1.521 log I_a − 1.993 log a_c − 1.546, σ 0.375;
* Jibson (2007), Engineering Geology 91, 209-218, with his printed
  coefficients and σ (``stickslip/reference/jibson2007.yaml``, read by
  :func:`jibson_reference`): eq. 6 in a_c/a_max, eq. 7 in a_c/a_max and M,
  eq. 9 in I_a and a_c, eq. 10 in I_a and a_c/a_max;
* the probability of failure of Jibson et al. (2000), eq. 5:
  P(f) = 0.335 [1 − exp(−0.048 D_n^1.565)], D_n in cm.

The refit of Jibson (2007) on our own displacements
(:mod:`stickslip.studies.jibson2007.fit`) and ``stickslip displacements``
(:mod:`stickslip.slope_displacements`) compute his equations with
:func:`predict` of this module.
"""

from __future__ import annotations

import math
from functools import cache
from importlib import resources

import numpy as np
import yaml

from stickslip.errors import StickslipError
from stickslip.estimates.estimate import Estimate, lognormal_estimate, no_sliding, yield_at_or_above

#: Each form's terms, in coefficient order: log10 D_n [cm] = Σ coefficient·term.
FORM_TERMS = {
    # Jibson (2007)
    "critical_acceleration_ratio": ("intercept", "log_one_minus_ratio", "log_ratio"),  # eq. 6
    "critical_acceleration_ratio_and_magnitude": ("intercept", "log_one_minus_ratio", "log_ratio", "magnitude"),  # 7
    "arias_intensity_and_critical_acceleration": ("intercept", "log_arias_intensity", "log_critical_acceleration"),  # 9
    "arias_intensity_and_ratio": ("intercept", "log_arias_intensity", "log_ratio"),  # eq. 10
    # Jibson (1993) and Jibson et al. (2000)
    "jibson_1993": ("intercept", "log_arias_intensity", "critical_acceleration"),
    "jibson_2000": ("intercept", "log_arias_intensity", "log_critical_acceleration"),
}

#: Jibson (1993) and Jibson et al. (2000) as printed: coefficients (by term) and σ [log10 units].
EARLIER_FORMS = {
    "jibson_1993": {"coefficients": {"intercept": 1.546, "log_arias_intensity": 1.460, "critical_acceleration": -6.642},
                    "sigma": 0.409},
    "jibson_2000": {"coefficients": {"intercept": -1.546, "log_arias_intensity": 1.521,
                                     "log_critical_acceleration": -1.993},
                    "sigma": 0.375},
}

#: Jibson et al.'s (2000) probability of failure P(f) = scale·[1 − exp(−rate·D_n^exponent)], D_n in cm.
FAILURE_PROBABILITY = {"scale": 0.335, "rate": 0.048, "exponent": 1.565}

#: Centimetres per metre.
CM_PER_M = 100.0


@cache
def jibson_reference() -> dict:
    """Jibson's (2007) printed values (``stickslip/reference/jibson2007.yaml``): his coefficients, sigmas and data."""
    text = resources.files("stickslip.reference").joinpath("jibson2007.yaml").read_text(encoding="utf-8")
    return yaml.safe_load(text)


def design_matrix(form: str, ratio, arias_intensity, magnitude=None, critical_acceleration=None) -> np.ndarray:
    """The terms (n, p) of ``form`` (:data:`FORM_TERMS`) at the given regressors, broadcast to one length n.

    ``ratio`` a_c/a_max [1] in (0, 1), ``arias_intensity`` I_a [m s-1],
    ``magnitude`` M [1], ``critical_acceleration`` a_c [g]; a regressor the
    form does not use may be None.
    """
    if form not in FORM_TERMS:
        raise StickslipError(f"unknown Jibson form {form!r}; known: {', '.join(FORM_TERMS)}")
    given = {"ratio": ratio, "arias_intensity": arias_intensity, "magnitude": magnitude,
             "critical_acceleration": critical_acceleration}
    values = dict(zip(given, np.broadcast_arrays(*(np.atleast_1d(np.asarray(1.0 if value is None else value,
                                                                                    dtype=float))
                                                   for value in given.values()))))
    terms = {
        "intercept": lambda: np.ones_like(values["ratio"]),
        "log_one_minus_ratio": lambda: np.log10(1.0 - values["ratio"]),
        "log_ratio": lambda: np.log10(values["ratio"]),
        "log_arias_intensity": lambda: np.log10(values["arias_intensity"]),
        "magnitude": lambda: values["magnitude"],
        "log_critical_acceleration": lambda: np.log10(values["critical_acceleration"]),
        "critical_acceleration": lambda: values["critical_acceleration"],
    }
    return np.column_stack([terms[term]() for term in FORM_TERMS[form]])


def predict(form: str, coefficients, ratio, arias_intensity=None, magnitude=None,
            critical_acceleration=None) -> np.ndarray:
    """log10 D_n [log10 cm] of ``form`` with ``coefficients`` (term name -> value) at the regressors given.

    Regressors as :func:`design_matrix`; an ``arias_intensity`` the form does not use may be left out.
    """
    values = np.array([coefficients[term] for term in FORM_TERMS[form]], dtype=float)
    return design_matrix(form, ratio, arias_intensity, magnitude, critical_acceleration) @ values


def form_reference(form: str) -> dict:
    """The printed ``coefficients`` and ``sigma`` [log10 units] of ``form``: Jibson (2007)'s, or an earlier paper's."""
    return EARLIER_FORMS.get(form) or jibson_reference()["forms"][form]


def _estimate(form: str, ky: float, pga: float | None = None, **regressors) -> Estimate:
    """The estimate of ``form`` for a yield coefficient ``ky`` [g]; zero with the reason when ``ky`` ≥ ``pga`` [g]."""
    if pga is not None:
        reason = yield_at_or_above(ky, pga)
        if reason:
            return no_sliding("10", reason)
        regressors["ratio"] = ky / pga
    reference = form_reference(form)
    log_median = float(predict(form, reference["coefficients"], regressors.pop("ratio", None),
                               critical_acceleration=ky, **regressors)[0])
    return lognormal_estimate(log_median, reference["sigma"], "10")


def jibson_1993(ky: float, arias_intensity: float) -> Estimate:
    """Jibson (1993): D_n from the yield coefficient ``ky`` [g] and the Arias intensity [m s-1]."""
    return _estimate("jibson_1993", ky, arias_intensity=arias_intensity)


def jibson_2000(ky: float, arias_intensity: float) -> Estimate:
    """Jibson et al. (2000), eq. 3: D_n from ``ky`` [g] and the Arias intensity [m s-1]."""
    return _estimate("jibson_2000", ky, arias_intensity=arias_intensity)


def jibson_2007_pga(ky: float, pga: float) -> Estimate:
    """Jibson (2007), eq. 6: D_n from ``ky`` and ``pga`` [g] (a_c/a_max)."""
    return _estimate("critical_acceleration_ratio", ky, pga)


def jibson_2007_pga_m(ky: float, pga: float, magnitude: float) -> Estimate:
    """Jibson (2007), eq. 7: D_n from ``ky`` and ``pga`` [g] and the moment magnitude."""
    return _estimate("critical_acceleration_ratio_and_magnitude", ky, pga, magnitude=magnitude)


def jibson_2007_ia(ky: float, arias_intensity: float) -> Estimate:
    """Jibson (2007), eq. 9: D_n from ``ky`` [g] and the Arias intensity [m s-1]."""
    return _estimate("arias_intensity_and_critical_acceleration", ky, arias_intensity=arias_intensity)


def jibson_2007_ia_pga(ky: float, pga: float, arias_intensity: float) -> Estimate:
    """Jibson (2007), eq. 10: D_n from ``ky`` and ``pga`` [g] (a_c/a_max) and the Arias intensity [m s-1]."""
    return _estimate("arias_intensity_and_ratio", ky, pga, arias_intensity=arias_intensity)


def failure_probability(displacement: float) -> float:
    """Jibson et al.'s (2000) probability of failure P(f) [1] of a slope of Newmark displacement ``displacement`` [m].

    P(f) = 0.335 [1 − exp(−0.048 D_n^1.565)] with D_n in cm: 0 at D_n = 0,
    rising to 0.335 (the share of the Northridge cells that failed at large D_n).
    """
    if not displacement >= 0.0:
        raise StickslipError(f"Newmark displacement {displacement!r} m: expected a number >= 0")
    constants = FAILURE_PROBABILITY
    exponent = constants["rate"] * (CM_PER_M * displacement) ** constants["exponent"]
    return constants["scale"] * (1.0 - math.exp(-exponent))
