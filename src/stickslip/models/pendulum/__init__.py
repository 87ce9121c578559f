"""The friction pendulum: a slider on a concave spherical surface, under the horizontal motion and its vertical.

Per unit mass, relative to the ground, in small-angle geometry (Zayas, Low
and Mahin 1987; docs/solvers.md, "The friction pendulum and the vertical
motion"):

    ü = −a_g − (N/mR)·u − μ(u̇)·(N/m)·sign(u̇)   while sliding,

stuck while the force needed to hold it, |a_g + (N/mR)·u|, stays within
μ(0)·N/m; N/m = g + a_v with the vertical ground acceleration a_v (positive
up, zero without one), and where g + a_v ≤ 0 the slider lifts off (no
friction, no restoring force).  R = ∞ is the flat surface, and then the
flat block under a vertical motion.  The friction is Coulomb's (``mu``) or
Constantinou, Mokha and Reinhorn's velocity law (``mu_slow``, ``mu_fast``,
``rate`` [s/m]; or ``mu`` as μ_fast with ``mu_slow_ratio`` = μ_slow/μ_fast
and ``rate``, the form a sweep's grid of ``mu`` takes: it sweeps μ_fast with
the law's shape held).

Two schemes: ``exact`` solves in closed form where one exists (Coulomb
friction and a constant normal force, :mod:`~stickslip.models.pendulum.exact`;
a flat surface under a vertical motion, :mod:`~stickslip.models.pendulum.vertical_exact`)
and otherwise integrates to a relative tolerance of 1e-10 with the events
located (:mod:`~stickslip.models.pendulum.integrated`); ``integrated`` always
integrates.  The result is a :class:`~stickslip.models.pendulum.response.PendulumResponse`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from stickslip.models.entry import Parameter, Scheme
from stickslip.models.parameters import GRAVITY, MASS, MU, MU_FAST, MU_SLOW, MU_SLOW_RATIO, RATE, friction_law
from stickslip.models.pendulum.chart import DEFAULT_CHART_RADII
from stickslip.models.pendulum.surface import checked_radius
from stickslip.models.registry import public_names, register
from stickslip.models.swept import SweptModel


RADIUS = Parameter("radius", "m", "radius R [m] of the friction pendulum's spherical surface (inf: flat); the free "
                   "swing's period is 2 pi sqrt(R/g)", default=math.inf, check=checked_radius,
                   usual=(0.2, 20.0, "the surfaces of friction pendulums (T = 0.9 to 9 s)"))
@dataclass(frozen=True)
class PendulumScheme(Scheme):
    """A scheme of the pendulum: closed forms where they exist (``exact``), or always integration (``integrated``)."""

    name: str
    summary: str
    integrates_always: bool = False
    batched: bool = True

    @property
    def options(self) -> dict:
        """``rtol``, the integration's relative tolerance per step (default 1e-10)."""
        return {"rtol": None}

    def solve(self, motion, case, rtol=None):
        """The :class:`~stickslip.models.pendulum.response.PendulumResponse` of the slider ``case`` on ``motion``."""
        from stickslip.models.pendulum.solve import solve_motion

        return solve_motion(self, motion, case, rtol)

    def sweep(self, motions, case, coefficient: str, values, rtol=None) -> dict:
        """The end results of every motion at every friction ratio of ``values`` [1], by name, energies in J."""
        from stickslip.models.pendulum.solve import sweep_motions

        return sweep_motions(self, motions, case, values, rtol)


SCHEMES = (
    PendulumScheme("exact", "closed forms per sample step, events located, where they exist (Coulomb friction and a "
                   "constant normal force; a flat surface under a vertical motion); else integrated to 1e-10"),
    PendulumScheme("integrated", "embedded Runge-Kutta (DOP853) to a relative tolerance of 1e-10, events located",
                   integrates_always=True),
)


class PendulumModel(SweptModel):
    """The pendulum's entry: one component with or without its vertical, the surface's radius, the friction law."""

    name = "pendulum"
    summary = ("a slider on a concave spherical surface of radius R (friction pendulum; R = inf is flat), with the "
               "vertical ground motion in the normal force")
    motions = ("component", "pair")
    vertical = True
    parameters = (MU, MU_SLOW, MU_FAST, MU_SLOW_RATIO, RATE, RADIUS, MASS, GRAVITY)
    schemes = SCHEMES
    counts = ("n_slip_episodes",)
    demands = {"peak_base_shear": ("1", "peak base shear coefficient V/W = max over time of |mu N z + N u/R| / W", "V/W")}
    #: Coulomb friction on a flat and on a curved surface (closed forms; integrated under a vertical on the curved
    #: one) and the velocity law (integrated).
    examples = ({"mu": 0.1}, {"mu": 0.1, "radius": 2.0}, {"mu_slow": 0.05, "mu_fast": 0.1, "rate": 20.0,
                                                          "radius": 2.0})

    @property
    def result(self) -> type:
        from stickslip.models.pendulum.response import PendulumResponse

        return PendulumResponse

    def case(self, parameters):
        """The :class:`~stickslip.models.pendulum.case.PendulumCase`: Coulomb's ``mu``, the velocity law's three, or
        ``mu`` (μ_fast) with ``mu_slow_ratio`` and ``rate``; a warning for an unusual law
        (:func:`~stickslip.solvers.friction_law.unusual_law_warnings`)."""
        from stickslip.models.pendulum.case import PendulumCase

        friction = friction_law(parameters)
        return PendulumCase(friction, parameters["radius"], parameters["mass"], parameters["g"])

    def sweep(self, motions, method=None, *, angles=None, **keywords):
        """As every swept model sweeps (:meth:`stickslip.models.swept.SweptModel.sweep`: a pair of components or a
        motion with its vertical as given); ``angles`` is the flat planar block's, refused in one line."""
        from stickslip.errors import StickslipError

        if angles is not None:
            raise StickslipError("angles= (the 1-D block on turned axes) is the flat planar block's sweep "
                                 "(model planar), not the pendulum's")
        return super().sweep(motions, method, **keywords)

    chart_over = "radius"
    chart_values = DEFAULT_CHART_RADII
    chart_long_name = "radius R of the spherical sliding surface"
    chart_title = "Friction pendulum design chart"

    def design_chart(self, motions, values, mu, progress: bool = False, objective: str | None = None, **parameters):
        """The median, 84th percentile and (over :data:`~stickslip.models.pendulum.chart.MEAN_RECORDS` or more) mean
        over ``motions`` of the displacement demand and V/W over the radii ``values`` [m] (None:
        :data:`~stickslip.models.pendulum.chart.DEFAULT_CHART_RADII`) and the friction ratios ``mu`` [1]
        (:func:`~stickslip.models.pendulum.chart.chart_statistics`): the same chart for its one ``objective``."""
        from stickslip.models.pendulum.chart import chart_statistics, design_chart

        self.objective(objective)  # refuses an objective it does not declare
        chart = design_chart(motions, self.chart_values if values is None else values, mu, progress=progress,
                             **parameters)
        statistics = chart_statistics(chart)
        statistics.attrs["title"] = self.chart_title
        return statistics

    def chart_quantities(self, objective: str | None = None) -> tuple[str, str]:
        """Its chart's displacement demand [m] in colours and peak base shear coefficient V/W [-] in lines, whatever
        its one ``objective``."""
        from stickslip.models.pendulum.chart import CHART_VARIABLES
        from stickslip.units import readable_units

        self.objective(objective)  # refuses an objective it does not declare
        return tuple(f"{CHART_VARIABLES[name][1].split(':')[0]} [{readable_units(CHART_VARIABLES[name][0])}]"
                     for name in ("peak_relative_displacement", "peak_base_shear"))

        self.objective(objective)  # refuses an objective it does not declare
        return tuple(f"{CHART_VARIABLES[PENDULUM_CHART[drawn]][1].split(':')[0]} "
                     f"[{readable_units(CHART_VARIABLES[PENDULUM_CHART[drawn]][0])}]" for drawn in ("filled", "lines"))

    motion_note_columns = {"liftoff_time": ("lift-off", "time [s]"), "liftoff_intervals": ("lift-off", "intervals")}
    motion_note_text = ("lift-off: the slider off its surface where g + a_v <= 0, the total time and how many times; "
                        "the vertical's alone, the same at every {c}")

    def motion_notes(self, motion, g: float) -> dict:
        """For a motion with its vertical: ``liftoff_time``, the total time [s] the slider spends lifted off (g + a_v
        ≤ 0, ``g`` [m/s²]), and ``liftoff_intervals``, how many times it lifts off; nothing without a vertical.

        Both are the vertical's alone, the same at every friction ratio (the sweep's ``liftoff_time`` over μ)."""
        import numpy as np

        from stickslip.models.pendulum.normal_force import liftoff_intervals
        from stickslip.records.vertical import WithVertical

        if not isinstance(motion, WithVertical):
            return {}
        intervals = liftoff_intervals(motion.vertical.acceleration, motion.vertical.dt, g)
        return {"liftoff_time": float(np.sum(intervals[:, 1] - intervals[:, 0])), "liftoff_intervals": len(intervals)}

    def variables(self, case):
        from stickslip.models.pendulum.response import SCALARS

        return {name: {"units": units, "long_name": long_name} for name, (units, long_name) in SCALARS.items()
                if name != "balance_residual"}

    def grid_coords(self, grid, case) -> dict:
        """Under the velocity law, ``mu_slow`` = μ_slow/μ_fast · μ_fast [1] along the grid of μ (its μ_fast)."""
        from stickslip.units import UNITS

        law = case.friction
        if law.is_coulomb:
            return {}
        return {"mu_slow": (law.slow_ratio * grid.values,
                            {"units": UNITS["mu_slow"], "long_name": "friction ratio at rest and at low speed "
                                                                     "mu_slow of the velocity law, the grid's mu its "
                                                                     "mu_fast"})}

    def cube_attrs(self, case, scheme, run_options):
        from stickslip.units import UNITS

        law = case.friction
        friction = ({"friction_law": "coulomb"} if law.is_coulomb else
                    {"friction_law": "velocity_dependent", "friction_law_description": law.describe_shape(),
                     "mu_slow_ratio": law.slow_ratio, "rate": law.rate, "rate_units": UNITS["rate"]})
        return {**{f"solver_{name}": value for name, value in run_options.items()},
                "block_mass": case.mass, "block_mass_units": UNITS["block_mass"], "gravity": case.g,
                "gravity_units": UNITS["gravity"], "radius": case.radius, "radius_units": UNITS["radius"],
                **friction, "sliding": case.describe_sliding()}

    def parameters_of(self, cube):
        attrs = cube.attrs
        options = {key.removeprefix("solver_"): value for key, value in attrs.items() if key.startswith("solver_")}
        law = ({"mu_slow_ratio": float(attrs["mu_slow_ratio"]), "rate": float(attrs["rate"])}
               if attrs.get("friction_law") == "velocity_dependent" else {})
        return attrs["solver"], options, {"mass": float(attrs["block_mass"]), "g": float(attrs["gravity"]),
                                          "radius": float(attrs["radius"]), **law}


#: The pendulum's entry.
PENDULUM = register(PendulumModel())

#: The friction pendulum's public names beside its entry (:func:`~stickslip.models.registry.public_names`).
PUBLIC = {"DEFAULT_CHART_RADII": "chart", "MEAN_RECORDS": "chart", "SliderResult": "response"}
__getattr__ = public_names(__name__, PUBLIC)
