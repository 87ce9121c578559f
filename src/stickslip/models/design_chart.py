"""A design chart: each record's responses over a grid of one of a model's parameters × μ, and statistics over them.

A designer chooses two things together: the friction ratio μ and one more
(the friction pendulum's or the isolated building's surface radius R [m],
the damper's mass ratio m_d/m_s [1]).  :func:`stacked_sweeps` sweeps μ
(:func:`stickslip.sweep`, batched over μ and the records) once at each value
of the other and stacks the cubes along it; :func:`chart_statistics` gives the
median and 84th percentile over the records of each response, and their mean
over :data:`MEAN_RECORDS` or more (what design codes average), which
:func:`stickslip.reports.isolator_plots.plot_design_chart` draws as contours.
A model declares the parameter (:attr:`~stickslip.models.entry.Model.chart_over`)
and what its chart holds (:meth:`~stickslip.models.entry.Model.design_chart`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from stickslip.errors import StickslipError
from stickslip.grids import positive_increasing
from stickslip.optimum import PERCENTILES

#: The fewest records (stations) over which a chart gives the mean of each response beside its percentiles: design
#: codes take the mean over seven or more ground motions (ASCE 7-22 Ch. 17 over seven pairs; EN 1998-1 4.3.3.4.3).
MEAN_RECORDS = 7


def stacked_sweeps(model: str, motions: Sequence, over: str, values, mu, variables: Mapping[str, tuple[str, str]],
                   described: str, *, progress: bool = False, **parameters):
    """Every motion over the ``values`` of the parameter ``over`` and the friction ratios ``mu`` [1]: one cube,
    record × ``over`` × mu, of the ``variables`` (name -> (units, long name)) of the ``model``'s sweep.

    ``described`` names the values in a message (``"surface radii R [m]"``);
    ``parameters`` are the model's others (and ``method``).  The cube's
    attributes are the first value's sweep's, without ``{over}_units``.
    """
    import xarray as xr

    from stickslip.models import sweep

    values = positive_increasing(values, described)
    if not len(motions):
        raise StickslipError("a design chart needs at least one record")
    cubes = []
    for value in values:
        cube = sweep(list(motions), model=model, mu=mu, progress=progress, **{over: float(value)}, **parameters)
        cubes.append(cube[list(variables)].expand_dims({over: [float(value)]}))
    chart = xr.concat(cubes, dim=over, combine_attrs="drop_conflicts")
    chart.attrs.pop(f"{over}_units", None)
    for name, (units, long_name) in variables.items():
        chart[name].attrs.update(units=units, long_name=long_name)
    return chart.transpose("record", over, "mu")


def statistic_label(percentile: float) -> str:
    """How a chart names a percentile [%] over its records: ``median``, ``84th percentile``."""
    return "median" if percentile == 50.0 else f"{percentile:g}th percentile"


def chart_statistics(chart, percentiles: Sequence[float] = PERCENTILES, magnitudes: Sequence[str] = ()):
    """The ``percentiles`` [%] over the records of each response of ``chart`` (record × chart value × mu), and
    their mean over :data:`MEAN_RECORDS` or more records: dims (statistic, chart value, mu).

    The ``statistic`` coordinate names each (:func:`statistic_label`:
    ``median``, ``84th percentile``; ``mean``).  The responses named in
    ``magnitudes`` are taken by their magnitude; records that could not be
    swept (NaN) are left out.  The attributes give the number of ``records``
    and what they are (``motions``: records, or stations for pairs of
    components), and keep the chart's friction law (``friction_law``; under
    the velocity law ``mu_slow_ratio`` [1] and ``rate`` [s/m], the grid's μ
    being μ_fast).
    """
    import xarray as xr

    _, over, friction = next(iter(chart.data_vars.values())).dims
    count = int(chart.sizes["record"])
    labels = [statistic_label(float(percentile)) for percentile in percentiles]
    labels += ["mean"] if count >= MEAN_RECORDS else []
    values = {}
    for name, variable in chart.data_vars.items():
        data = np.abs(variable.values) if name in magnitudes else variable.values
        found = np.nanpercentile(data, list(percentiles), axis=0)
        if count >= MEAN_RECORDS:
            found = np.concatenate([found, np.nanmean(data, axis=0)[None]])
        values[name] = (("statistic", over, friction), found,
                        {"units": variable.attrs["units"],
                         "long_name": variable.attrs["long_name"] + (" (magnitude)" if name in magnitudes else "")})
    return xr.Dataset(values, coords={"statistic": ("statistic", labels), over: chart[over], friction: chart[friction]},
                      attrs={"records": count, "motions": chart.attrs.get("motions", "records"),
                             **{name: chart.attrs[name] for name in ("friction_law", "mu_slow_ratio", "rate")
                                if name in chart.attrs}})
