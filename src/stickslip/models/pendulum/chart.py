"""The friction pendulum's design chart: the demands of each record over the surface radius R and the friction μ.

An isolator designer chooses R (the period 2π√(R/g)) and μ together: a larger
μ or a smaller R keeps the slider nearer the middle (a smaller displacement
demand) at the price of a larger base shear V/W.  :func:`design_chart` sweeps
μ (:func:`stickslip.sweep` of the pendulum model) at each radius and stacks
the cubes along a ``radius`` dimension; :func:`chart_statistics` gives the
median and 84th percentile over the records of each demand, and their mean
over :data:`MEAN_RECORDS` or more (what design codes average), which
:func:`stickslip.reports.isolator_plots.plot_design_chart` draws as contours.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from stickslip.errors import StickslipError
from stickslip.grids import positive_increasing
from stickslip.optimum import PERCENTILES

#: The demands a design chart holds: name -> (units, what it is).
CHART_VARIABLES = {
    "peak_relative_displacement": ("m", "displacement demand: largest |slider displacement relative to the ground|"),
    "peak_base_shear": ("1", "peak base shear coefficient V/W"),
    "residual_displacement": ("m", "slider displacement relative to the ground at the end (re-centring)"),
    "energy_dissipated": ("J", "energy dissipated by friction E_df"),
}


#: The fewest records (stations) over which a chart gives the mean of each demand beside its percentiles: design
#: codes take the mean over seven or more ground motions (ASCE 7-22 Ch. 17 over seven pairs; EN 1998-1 4.3.3.4.3).
MEAN_RECORDS = 7


#: The radii R [m] of a friction pendulum's design chart when none are given: periods 2π√(R/g) from 2.0 s to 4.0 s.
DEFAULT_CHART_RADII = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0)


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
    import xarray as xr

    from stickslip.models import sweep

    radii = positive_increasing(radius, "surface radii R [m]")
    if not len(motions):
        raise StickslipError("a design chart needs at least one record")
    cubes = []
    for value in radii:
        cube = sweep(list(motions), model="pendulum", mu=mu, radius=float(value), progress=progress, **parameters)
        cubes.append(cube[list(CHART_VARIABLES)].expand_dims(radius=[float(value)]))
    chart = xr.concat(cubes, dim="radius", combine_attrs="drop_conflicts")
    chart.attrs.pop("radius_units", None)
    chart.attrs["title"] = "stickslip friction pendulum design chart"
    chart.attrs["motions"] = "stations" if all(_is_pair(motion) for motion in motions) else "records"
    chart["radius"].attrs.update(units="m", long_name="radius R of the spherical sliding surface")
    for name, (units, long_name) in CHART_VARIABLES.items():
        chart[name].attrs.update(units=units, long_name=long_name)
    return chart.transpose("record", "radius", "mu")


def _is_pair(motion) -> bool:
    """Whether ``motion`` holds a station's two horizontal components (with or without its vertical)."""
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    return isinstance(motion.horizontal if isinstance(motion, WithVertical) else motion, RecordPair)


def statistic_label(percentile: float) -> str:
    """How a chart names a percentile [%] over its records: ``median``, ``84th percentile``."""
    return "median" if percentile == 50.0 else f"{percentile:g}th percentile"


def chart_statistics(chart, percentiles: Sequence[float] = PERCENTILES):
    """The ``percentiles`` [%] over the records of each demand of ``chart``, and their mean over
    :data:`MEAN_RECORDS` or more records: dims (statistic, radius, mu).

    The ``statistic`` coordinate names each (:func:`statistic_label`:
    ``median``, ``84th percentile``; ``mean``).  The residual displacement is
    taken by its magnitude; records that could not be swept (NaN) are left
    out.  The attributes give the number of ``records`` and what they are
    (``motions``: records, or stations for pairs of components).
    """
    import xarray as xr

    count = int(chart.sizes["record"])
    labels = [statistic_label(float(percentile)) for percentile in percentiles]
    labels += ["mean"] if count >= MEAN_RECORDS else []
    values = {}
    for name, (units, long_name) in CHART_VARIABLES.items():
        data = chart[name].values
        data = np.abs(data) if name == "residual_displacement" else data
        found = np.nanpercentile(data, list(percentiles), axis=0)
        if count >= MEAN_RECORDS:
            found = np.concatenate([found, np.nanmean(data, axis=0)[None]])
        values[name] = (("statistic", "radius", "mu"), found,
                        {"units": units, "long_name": long_name + (" (magnitude)" if name == "residual_displacement"
                                                                     else "")})
    return xr.Dataset(values, coords={"statistic": ("statistic", labels), "radius": chart.radius, "mu": chart.mu},
                      attrs={"records": count, "motions": chart.attrs.get("motions", "records")})
