"""The response-history check of a friction pendulum on a scaled suite of station pairs, beside the ELF design.

Each pair of the suite (with its vertical where given), multiplied by its
scale factor (:mod:`stickslip.codes.suite_scaling`), is solved exactly in the
plane by the ``pendulum`` model (:func:`stickslip.solve`; docs/solvers.md, "The
friction pendulum in the plane") at the upper- and lower-bound friction
λ_max μ and λ_min μ.  Of each run it keeps

- ``peak_displacement`` [m]: the largest distance of the slider from the
  surface's centre, max |u| in the plane (the model's
  ``peak_relative_displacement``);
- ``base_shear_coefficient`` [1]: the largest V_b/W (the model's
  ``peak_base_shear``).

The suite's statistic of each (:func:`~stickslip.codes.suite_scaling.suite_statistic`:
the mean over seven or more pairs, else the maximum) is set beside the ELF
values of the same bound (:func:`stickslip.codes.friction_pendulum.design`)
with the lower limits we code from ASCE 7-22 §17.6 as we know it: the
response history's displacement not less than :data:`DISPLACEMENT_FLOOR` of
the ELF displacement and its base shear not less than :data:`BASE_SHEAR_FLOOR`
of the ELF base shear; a design value is the greater of the statistic and the
limit.  The runs have no torsion, so the displacement is compared with D_M
(ASCE's limit is on D_TM, D_M with the torsion factor).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, replace

import numpy as np

from stickslip.codes.suite_scaling import statistic_of

#: The bounds of friction the suite is run at, in output order (keys of :func:`~stickslip.codes.friction_pendulum.design`).
RUN_BOUNDS = ("upper_bound", "lower_bound")

#: The responses kept of each run: our name -> the pendulum model's end result.
RESPONSES = {"peak_displacement": "peak_relative_displacement", "base_shear_coefficient": "peak_base_shear"}

#: The ELF value each response is compared with (:class:`~stickslip.codes.friction_pendulum.BoundDesign`'s field).
ELF_FIELDS = {"peak_displacement": "design_displacement", "base_shear_coefficient": "base_shear_coefficient"}

#: ASCE 7-22 §17.6 (as we code it): the response history's displacement is not taken as less than this fraction of
#: the ELF displacement [1].
DISPLACEMENT_FLOOR = 0.80
#: ASCE 7-22 §17.6 (as we code it): the base shear is not taken as less than this fraction of the ELF V_b [1].
BASE_SHEAR_FLOOR = 0.90
#: Each response's lower limit as a fraction of its ELF value [1].
FLOORS = {"peak_displacement": DISPLACEMENT_FLOOR, "base_shear_coefficient": BASE_SHEAR_FLOOR}

#: Units of the responses (UDUNITS spelling).
UNITS = {"peak_displacement": "m", "base_shear_coefficient": "1"}


def scaled_motion(motion, factor: float):
    """``motion`` (a :class:`~stickslip.records.pair.RecordPair`, or one with its vertical,
    :class:`~stickslip.records.vertical.WithVertical`) with every component multiplied by ``factor`` [1]."""
    from stickslip.records.process import scale
    from stickslip.records.vertical import WithVertical

    if isinstance(motion, WithVertical):
        return replace(motion, horizontal=motion.horizontal.scaled(factor), vertical=scale(motion.vertical, factor))
    return motion.scaled(factor)


def peak_responses(motions, factors, radius: float, frictions: dict[str, float], g: float,
                   progress: bool = False) -> dict[str, dict[str, np.ndarray]]:
    """Per bound of ``frictions`` (bound -> μ [1]), each response of :data:`RESPONSES` of every motion scaled by its
    factor [1], on a friction pendulum of radius ``radius`` [m] at gravity ``g`` [m/s²]; a progress bar on stderr
    with ``progress`` (when stderr is a terminal)."""
    from tqdm import tqdm

    from stickslip.models import solve

    found = {bound: {name: np.empty(len(motions)) for name in RESPONSES} for bound in frictions}
    show = progress and sys.stderr.isatty()
    with tqdm(total=len(motions) * len(frictions), desc="isolation suite", unit="run", disable=not show,
              file=sys.stderr) as bar:
        for index, (motion, factor) in enumerate(zip(motions, factors)):
            scaled = scaled_motion(motion, float(factor))
            for bound, mu in frictions.items():
                scalars = solve(scaled, model="pendulum", radius=radius, mu=mu, g=g).scalars()
                for name, result in RESPONSES.items():
                    found[bound][name][index] = scalars[result]
                bar.update()
    return found


@dataclass(frozen=True)
class Comparison:
    """One response's statistic over the suite at one bound, beside the ELF value (units of :data:`UNITS`)."""

    statistic: float
    elf: float
    ratio: float
    floor: float
    passed: bool
    design_value: float


def compared_with_elf(peaks: dict[str, dict[str, np.ndarray]], statistic: str,
                      designs: dict) -> dict[str, dict[str, Comparison]]:
    """Per bound and response, the suite's ``statistic`` (``"mean"`` or ``"max"``) of ``peaks`` beside the ELF
    value of ``designs`` (bound -> :class:`~stickslip.codes.friction_pendulum.BoundDesign`) and its lower limit."""
    found = {}
    for bound, responses in peaks.items():
        found[bound] = {}
        for name, values in responses.items():
            value, elf = statistic_of(values, statistic), getattr(designs[bound], ELF_FIELDS[name])
            found[bound][name] = Comparison(value, elf, value / elf, FLOORS[name], value >= FLOORS[name] * elf,
                                            max(value, FLOORS[name] * elf))
    return found
