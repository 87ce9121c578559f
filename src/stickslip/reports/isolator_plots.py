"""The friction pendulum's design chart as a figure: displacement demand and base shear over R × μ.

:func:`plot_design_chart` draws, from :func:`stickslip.models.pendulum.chart.chart_statistics`,
filled contours of the displacement demand [m] and labelled contour lines of
the peak base shear coefficient V/W [1] over the surface radius R [m] (with
its period 2π√(R/g) [s] on a second axis) and the friction ratio μ [1], for
one percentile over the records (the median, or the 84th).  A designer reads
off the (R, μ) pairs that keep the displacement within the isolator's
capacity and V/W within what the structure above takes.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure

from stickslip.constants import STANDARD_GRAVITY
from stickslip.reports.plots import new_figure, plot_not_drawn


#: The design chart shows μ up to where the displacement demand falls below this share of its largest value.
DEMAND_SHOWN = 0.02


def focused_mu_limit(mu: np.ndarray, displacement: np.ndarray) -> float:
    """The largest μ [1] the design chart shows: the grid's next μ after the last one where, at some radius, the
    displacement demand (``displacement`` [m], shape (μ, radius)) is at least :data:`DEMAND_SHOWN` of its largest.

    Past it the block hardly slides and the chart would be one flat colour; a grid without such a μ shows whole.
    """
    shown = np.nonzero((displacement >= DEMAND_SHOWN * np.nanmax(displacement)).any(axis=1))[0]
    if shown.size == 0 or not np.nanmax(displacement) > 0.0:
        return float(mu[-1])
    return float(mu[min(shown[-1] + 1, mu.size - 1)])


def friction_axis_label(attrs) -> str:
    """The friction axis of a chart with the attributes ``attrs``: μ, or the velocity law's μ_fast with its shape."""
    if attrs.get("friction_law") != "velocity_dependent":
        return "friction ratio μ [-]"
    ratio, rate = float(attrs["mu_slow_ratio"]), float(attrs["rate"])
    return f"friction ratio μ_fast [-] (μ_slow = {ratio:g} μ_fast, a = {rate:g} s/m)"


def plot_design_chart(statistics, percentile: float = 50.0, g: float = STANDARD_GRAVITY, title: str | None = None
                      ) -> Figure:
    """Displacement demand [m] (filled contours) and V/W [1] (lines) over R [m] × μ [1] at one ``percentile`` [%].

    ``statistics`` is :func:`~stickslip.models.pendulum.chart.chart_statistics` of a design chart;
    ``g`` [m/s²] converts R to the period on the top axis.  A chart with
    fewer than two radii or two friction ratios cannot be contoured and says so.
    """
    records = int(statistics.attrs.get("records", 0))
    which = ("" if records == 1 else "median" if percentile == 50.0 else f"{percentile:g}th percentile")
    title = title or (f"Friction pendulum design chart: {which} over {records} records" if records != 1 else
                      "Friction pendulum design chart")
    radius, mu = statistics.radius.values, statistics.mu.values
    if radius.size < 2 or mu.size < 2:
        return plot_not_drawn(title, f"{radius.size} radius and {mu.size} friction ratio(s): contours need at least "
                                     "two of each")
    chosen = statistics.sel(percentile=percentile)
    displacement = chosen.peak_relative_displacement.values.T  # (mu, radius)
    shear = chosen.peak_base_shear.values.T
    top = focused_mu_limit(mu, displacement)
    shown = mu <= top
    mu, displacement, shear = mu[shown], displacement[shown], shear[shown]
    figure, ax = new_figure(figsize=(7.5, 5.2))
    filled = ax.contourf(radius, mu, displacement, levels=12, cmap="viridis")
    figure.colorbar(filled, ax=ax, label=f"displacement demand{', ' + which if which else ''} [m]")
    lines = ax.contour(radius, mu, shear, levels=8, colors="white", linewidths=1.0)
    # the values alone (the title names them): where the lines crowd, at small μ and R, long labels overlap
    ax.clabel(lines, fmt=lambda value: f"{value:.2f}", fontsize="x-small", inline_spacing=2)
    if not shown.all():
        ax.text(0.99, 0.98, f"μ > {top:.3g} not shown: displacement demand below {DEMAND_SHOWN:.0%} of its largest",
                transform=ax.transAxes, ha="right", va="top", color="white", fontsize="x-small",
                bbox={"facecolor": "black", "alpha": 0.5, "edgecolor": "none", "pad": 2})
    ax.set_xlabel("radius R of the sliding surface [m]")
    ax.set_ylabel(friction_axis_label(statistics.attrs))
    ax.set_title(f"{title}\nfilled: displacement demand; white lines, labelled: peak base shear coefficient V/W",
                 fontsize="medium")
    period = ax.secondary_xaxis("top", functions=(lambda r: 2 * np.pi * np.sqrt(np.maximum(r, 0.0) / g),
                                                  lambda t: g * (np.asarray(t) / (2 * math.pi)) ** 2))
    period.set_xlabel("period 2π√(R/g) [s]")
    return figure
