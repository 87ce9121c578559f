"""Figures of the isolation study (``notebooks/isolation_study.ipynb``).

Each function takes rows of ``isolation_summary.csv`` (:mod:`stickslip.studies.isolation.tables`, as read from
CSV: strings) and returns a :class:`matplotlib.figure.Figure`: one panel per fixed-base period T [s], μ [1] on
the x axis, one colour per radius R [m], the median over the records as a line and the 16th and 84th percentiles
as thin dashed lines of the same colour (the radii's bands overlap: shaded, they would hide one another).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure

from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn


def _chosen(summary: Sequence[Mapping], library: str, quantity: str) -> list[Mapping]:
    return [row for row in summary if row["library"] == library and row["quantity"] == quantity
            and row["median"] not in ("", "nan")]


def plot_quantity_vs_mu(summary: Sequence[Mapping], library: str, quantity: str, ylabel: str, title: str,
                        unity: bool = True) -> Figure:
    """``quantity`` of the summary against μ, one panel per T, one line per R with its 16-84 % band; with ``unity``
    a line at 1 (the fixed-base building)."""
    rows = _chosen(summary, library, quantity)
    if not rows:
        return plot_not_drawn(title, "no record was available")
    periods = sorted({float(row["period"]) for row in rows})
    radii = sorted({float(row["radius"]) for row in rows})
    figure, axes = new_figure(1, len(periods), figsize=(3.6 * len(periods) + 1.8, 4.2), sharey=True, squeeze=False)
    for ax, period in zip(axes[0], periods):
        for colour, radius in enumerate(radii):
            cell = sorted((row for row in rows if float(row["period"]) == period and float(row["radius"]) == radius),
                          key=lambda row: float(row["mu"]))
            mu = np.array([float(row["mu"]) for row in cell])
            for bound in ("p16", "p84"):
                ax.plot(mu, [float(row[bound]) for row in cell], "--", color=f"C{colour}", linewidth=0.8)
            ax.plot(mu, [float(row["median"]) for row in cell], "o-", color=f"C{colour}", markersize=3.5,
                    label=f"R = {radius:g} m")
        if unity:
            ax.axhline(1.0, color="0.3", linewidth=0.8, linestyle="--")
        ax.set_title(f"fixed-base period T = {period:g} s", fontsize="medium")
        ax.set_xlabel("friction coefficient μ [1]")
        ax.grid(True, alpha=0.3)
    axes[0, 0].set_ylabel(ylabel)
    axes[0, -1].legend(**LEGEND_OUTSIDE, fontsize="small", title="median (dashed: 16th, 84th)")
    figure.suptitle(title)
    return figure
