"""Every simplified estimate, declared once: its name, reference, inputs with their units, and its function.

The command ``stickslip estimate`` and the library study take from
:data:`METHODS` the methods that apply to the measures they have: a method
applies when every input it needs is given.  Inputs, in the papers' units
(:data:`INPUTS`): the yield coefficient ``ky`` [g], ``pga`` [g], ``pgv``
[cm s-1], ``arias_intensity`` [m s-1], ``magnitude`` (moment magnitude),
``mean_period`` T_m [s], ``site_period`` T_s [s],
``spectral_acceleration`` Sa(1.5 T_s) and ``spectral_acceleration_13``
Sa(1.3 T_s) at 5 % damping [g].

A rigid block whose k_y·g is at least the PGA never slides: where the PGA is
given, every rigid method returns zero with the reason there, also those
that do not use the PGA (Jibson 1993, Jibson et al. 2000, Jibson 2007 eq. 9).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from stickslip.errors import StickslipError
from stickslip.estimates import (ambraseys_menu, bray_macedo, bray_travasarou, jibson, rathje_antonakos,
                                 saygili_rathje)
from stickslip.estimates.estimate import Estimate, no_sliding, yield_at_or_above

#: The inputs: name -> (unit, what it is).
INPUTS = {
    "ky": ("g", "yield coefficient k_y (the yield acceleration in g)"),
    "pga": ("g", "peak ground acceleration"),
    "pgv": ("cm s-1", "peak ground velocity"),
    "arias_intensity": ("m s-1", "Arias intensity"),
    "magnitude": ("1", "moment magnitude M"),
    "mean_period": ("s", "mean period T_m (Rathje et al. 1998)"),
    "site_period": ("s", "fundamental period T_s of the sliding mass"),
    "spectral_acceleration": ("g", "5 %-damped pseudo-spectral acceleration Sa(1.5 T_s)"),
    "spectral_acceleration_13": ("g", "5 %-damped pseudo-spectral acceleration Sa(1.3 T_s)"),
}


@dataclass(frozen=True)
class Method:
    """One simplified estimate.

    Attributes
    ----------
    name:
        Its name (the keys of ``stickslip estimate --json``).
    label:
        How a table names it.
    reference:
        The paper, and the form.
    kind:
        ``"rigid"`` (a rigid block's D_n) or ``"flexible"`` (a sliding mass of period T_s).
    log_base:
        The base of its logarithms, ``"10"`` or ``"e"``.
    inputs:
        The names of :data:`INPUTS` it takes, in the order of its function's arguments.
    function:
        ``function(**inputs) -> Estimate``.
    needs:
        The inputs it needs given the values at hand (by default all of ``inputs``).
    """

    name: str
    label: str
    reference: str
    kind: str
    log_base: str
    inputs: tuple[str, ...]
    function: Callable[..., Estimate]
    needs: Callable[[Mapping[str, float]], tuple[str, ...]] | None = field(default=None, compare=False)

    def missing(self, values: Mapping[str, float]) -> tuple[str, ...]:
        """The inputs it needs that ``values`` lacks."""
        needed = self.needs(values) if self.needs else self.inputs
        return tuple(name for name in needed if values.get(name) is None)

    def estimate(self, values: Mapping[str, float]) -> Estimate:
        """Its estimate from ``values`` (input name -> value in :data:`INPUTS`' units), which must hold what it needs."""
        if self.kind == "rigid" and "pga" not in self.inputs and values.get("pga") is not None:
            reason = yield_at_or_above(values["ky"], values["pga"])
            if reason:
                return no_sliding(self.log_base, reason)
        return self.function(**_arguments(self, values))


def _arguments(method: Method, values: Mapping[str, float]) -> dict[str, float | None]:
    return {name: values.get(name) for name in method.inputs}


def _needs_spectral(spectral: str, rigid: Callable[[float], bool], *others: str):
    """What a method of Bray's family needs: T_s first; then the PGA for a mass ``rigid`` at its T_s, else the
    spectral acceleration ``spectral``; and ``others``."""
    def needs(values: Mapping[str, float]) -> tuple[str, ...]:
        period = values.get("site_period")
        if period is None:
            return ("ky", "site_period", *others)
        return ("ky", "site_period", "pga" if rigid(period) else spectral, *others)

    return needs


#: The methods, in the order tables show them.
METHODS: dict[str, Method] = {method.name: method for method in (
    Method("jibson_1993", "Jibson (1993)", "Jibson (1993), TRR 1411: log D_n in I_a and a_c",
           "rigid", "10", ("ky", "arias_intensity"), jibson.jibson_1993),
    Method("jibson_2000", "Jibson et al. (2000)", "Jibson, Harp and Michael (2000), Eng. Geol. 58, eq. 3: "
           "log D_n in I_a and a_c", "rigid", "10", ("ky", "arias_intensity"), jibson.jibson_2000),
    Method("jibson_2007_pga", "Jibson (2007) eq. 6", "Jibson (2007), Eng. Geol. 91, eq. 6: a_c/a_max",
           "rigid", "10", ("ky", "pga"), jibson.jibson_2007_pga),
    Method("jibson_2007_pga_m", "Jibson (2007) eq. 7", "Jibson (2007), eq. 7: a_c/a_max and M",
           "rigid", "10", ("ky", "pga", "magnitude"), jibson.jibson_2007_pga_m),
    Method("jibson_2007_ia", "Jibson (2007) eq. 9", "Jibson (2007), eq. 9: I_a and a_c",
           "rigid", "10", ("ky", "arias_intensity"), jibson.jibson_2007_ia),
    Method("jibson_2007_ia_pga", "Jibson (2007) eq. 10", "Jibson (2007), eq. 10: I_a and a_c/a_max",
           "rigid", "10", ("ky", "pga", "arias_intensity"), jibson.jibson_2007_ia_pga),
    Method("ambraseys_menu_1988", "Ambraseys & Menu (1988)", "Ambraseys and Menu (1988), EESD 16: a_c/a_max",
           "rigid", "10", ("ky", "pga"), ambraseys_menu.ambraseys_menu_1988),
    Method("saygili_rathje_2008_pga", "Saygili & Rathje (2008) PGA",
           "Saygili and Rathje (2008), JGGE 134: a_c/a_max and PGA",
           "rigid", "e", ("ky", "pga"), saygili_rathje.saygili_rathje_2008_pga),
    Method("saygili_rathje_2008_pga_pgv", "Saygili & Rathje (2008) PGA, PGV",
           "Saygili and Rathje (2008): a_c/a_max, PGA and PGV",
           "rigid", "e", ("ky", "pga", "pgv"), saygili_rathje.saygili_rathje_2008_pga_pgv),
    Method("saygili_rathje_2008_pga_pgv_ia", "Saygili & Rathje (2008) PGA, PGV, I_a",
           "Saygili and Rathje (2008): a_c/a_max, PGA, PGV and I_a",
           "rigid", "e", ("ky", "pga", "pgv", "arias_intensity"), saygili_rathje.saygili_rathje_2008_pga_pgv_ia),
    Method("rathje_saygili_2009_pga_m", "Rathje & Saygili (2009) PGA, M",
           "Rathje and Saygili (2009), BNZSEE 42: a_c/a_max, PGA and M",
           "rigid", "e", ("ky", "pga", "magnitude"), saygili_rathje.rathje_saygili_2009_pga_m),
    Method("bray_travasarou_2007", "Bray & Travasarou (2007)",
           "Bray and Travasarou (2007), JGGE 133: k_y, T_s, Sa(1.5 T_s) and M, with P(D = 0)",
           "flexible", "e", ("ky", "site_period", "spectral_acceleration", "magnitude", "pga"),
           bray_travasarou.bray_travasarou_2007,
           needs=_needs_spectral("spectral_acceleration", lambda period: period < bray_travasarou.RIGID_PERIOD,
                                 "magnitude")),
    Method("bray_macedo_2019", "Bray & Macedo (2019) crustal",
           "Bray and Macedo (2019), JGGE 145(12): shallow crustal earthquakes; k_y, T_s, Sa(1.3 T_s), M and PGV, "
           "with P(D = 0)",
           "flexible", "e", ("ky", "site_period", "spectral_acceleration_13", "magnitude", "pgv", "pga"),
           bray_macedo.bray_macedo_2019,
           needs=_needs_spectral("spectral_acceleration_13", lambda period: period == 0.0, "magnitude", "pgv")),
    Method("bray_macedo_travasarou_2018", "Bray et al. (2018) subduction",
           "Bray, Macedo and Travasarou (2018), JGGE 144(3): subduction-zone earthquakes; k_y, T_s, Sa(1.5 T_s) "
           "and M, with P(D = 0)",
           "flexible", "e", ("ky", "site_period", "spectral_acceleration", "magnitude", "pga"),
           bray_macedo.bray_macedo_travasarou_2018,
           needs=_needs_spectral("spectral_acceleration", lambda period: period == 0.0, "magnitude")),
    Method("rathje_antonakos_2011_pgv", "Rathje & Antonakos (2011) PGV",
           "Rathje and Antonakos (2011), Eng. Geol. 122: k_y/k_max, k_max, k-vel_max and T_s",
           "flexible", "e", ("ky", "pga", "pgv", "site_period", "mean_period"),
           rathje_antonakos.rathje_antonakos_2011_pgv),
    Method("rathje_antonakos_2011_m", "Rathje & Antonakos (2011) M",
           "Rathje and Antonakos (2011): k_y/k_max, k_max, M and T_s",
           "flexible", "e", ("ky", "pga", "magnitude", "site_period", "mean_period"),
           rathje_antonakos.rathje_antonakos_2011_m),
)}


#: The methods of current practice that came after SLAMMER 1.1 (the others are SLAMMER's fourteen): the command
#: offers them, the library study (:mod:`stickslip.studies.estimates.simplified`) does not measure them yet.
AFTER_SLAMMER = ("bray_macedo_2019", "bray_macedo_travasarou_2018")


def checked_inputs(values: Mapping[str, float | None]) -> dict[str, float | None]:
    """``values`` with every given input a finite number in its range; one StickslipError naming the input otherwise.

    Positive: every input but ``magnitude`` (any finite number) and
    ``site_period`` (T_s ≥ 0; 0 is a rigid mass).  Unknown names are refused.
    """
    checked = {}
    for name, value in values.items():
        if name not in INPUTS:
            raise StickslipError(f"unknown input {name!r} of the simplified estimates; known: {', '.join(INPUTS)}")
        if value is None:
            checked[name] = None
            continue
        unit, description = INPUTS[name]
        number = float(value)
        lowest_ok = {"magnitude": -math.inf, "site_period": 0.0}.get(name)
        valid = math.isfinite(number) and (number >= lowest_ok if lowest_ok is not None else number > 0.0)
        if not valid:
            expected = ("a finite number" if name == "magnitude" else "a number >= 0" if name == "site_period"
                        else "a positive number")
            raise StickslipError(f"{description} {value!r} [{unit}]: expected {expected}")
        checked[name] = number
    return checked


def estimates(values: Mapping[str, float | None]) -> tuple[dict[str, Estimate], dict[str, tuple[str, ...]]]:
    """Every applicable method's estimate, and the inputs each other method lacks, from ``values`` (:data:`INPUTS`).

    ``values`` must hold ``ky``; returns (name -> :class:`Estimate`, name -> the missing inputs), in the order
    of :data:`METHODS`.
    """
    values = checked_inputs(values)
    if values.get("ky") is None:
        raise StickslipError("the simplified estimates need the yield coefficient k_y [g]")
    found, lacking = {}, {}
    for name, method in METHODS.items():
        missing = method.missing(values)
        if missing:
            lacking[name] = missing
        else:
            found[name] = method.estimate(values)
    return found, lacking
