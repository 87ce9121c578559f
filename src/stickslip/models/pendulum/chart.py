"""The friction pendulum's design chart: the demands of each record over the surface radius R and the friction μ.

An isolator designer chooses R (the period 2π√(R/g)) and μ together: a larger
μ or a smaller R keeps the slider nearer the middle (a smaller displacement
demand) at the price of a larger base shear V/W.  :func:`design_chart` sweeps
μ (:func:`stickslip.sweep` of the pendulum model) at each radius and stacks
the cubes along a ``radius`` dimension; :func:`chart_statistics` gives the
median and 84th percentile over the records of each demand, and their mean
over :data:`MEAN_RECORDS` or more (what design codes average), as every
model's chart does (:mod:`stickslip.models.design_chart`), which
:func:`stickslip.reports.isolator_plots.plot_design_chart` draws as contours.
"""

from __future__ import annotations

from collections.abc import Sequence

from stickslip.models.design_chart import MEAN_RECORDS, chart_statistics as _statistics, stacked_sweeps, statistic_label
from stickslip.optimum import PERCENTILES

#: The demands a design chart holds: name -> (units, what it is).
CHART_VARIABLES = {
    "peak_relative_displacement": ("m", "displacement demand: largest |slider displacement relative to the ground|"),
    "peak_base_shear": ("1", "peak base shear coefficient V/W"),
    "residual_displacement": ("m", "slider displacement relative to the ground at the end (re-centring)"),
    "energy_dissipated": ("J", "energy dissipated by friction E_df"),
}

#: The radii R [m] of a friction pendulum's design chart when none are given: periods 2π√(R/g) from 2.0 s to 4.0 s.
DEFAULT_CHART_RADII = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0)

__all__ = ["CHART_VARIABLES", "DEFAULT_CHART_RADII", "MEAN_RECORDS", "chart_statistics", "design_chart",
           "statistic_label"]


def design_chart(motions: Sequence, radius, mu, *, progress: bool = False, **parameters):
    """Every motion over the radii ``radius`` [m] and the friction ratios ``mu`` [1]: one cube, record × radius × mu.

    ``motions`` are records of one component or pairs of components
    (:class:`~stickslip.records.pair.RecordPair`: the pendulum in the plane),
    each with or without its vertical (:class:`~stickslip.records.vertical.WithVertical`);
    ``parameters`` the pendulum's others (``mass`` [kg], ``g`` [m/s²],
    ``method``).  The cube holds :data:`CHART_VARIABLES` and the records'
    coordinates of :func:`stickslip.sweep`; its attributes are the first
    radius's sweep's, without ``radius``.
    """
    chart = stacked_sweeps("pendulum", motions, "radius", radius, mu, CHART_VARIABLES, "surface radii R [m]",
                           progress=progress, **parameters)
    chart.attrs["title"] = "stickslip friction pendulum design chart"
    chart.attrs["motions"] = "stations" if all(_is_pair(motion) for motion in motions) else "records"
    chart["radius"].attrs.update(units="m", long_name="radius R of the spherical sliding surface")
    return chart


def _is_pair(motion) -> bool:
    """Whether ``motion`` holds a station's two horizontal components (with or without its vertical)."""
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    return isinstance(motion.horizontal if isinstance(motion, WithVertical) else motion, RecordPair)


def chart_statistics(chart, percentiles: Sequence[float] = PERCENTILES):
    """The ``percentiles`` [%] over the records of each demand of ``chart``, and their mean over
    :data:`MEAN_RECORDS` or more records: dims (statistic, radius, mu)
    (:func:`stickslip.models.design_chart.chart_statistics`), the residual displacement taken by its magnitude."""
    return _statistics(chart, percentiles, magnitudes=("residual_displacement",))
