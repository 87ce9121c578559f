"""Figures of the isolation study (``notebooks/isolation_study.ipynb``).

:func:`plot_quantity_vs_mu` takes rows of ``isolation_summary.csv`` (:mod:`stickslip.studies.isolation.tables`,
as read from CSV: strings) and returns a :class:`matplotlib.figure.Figure`: one panel per fixed-base period T [s],
μ [1] on the x axis, one colour per radius R [m], the median over the records as a line and the 16th and 84th
percentiles as thin dashed lines of the same colour (the radii's bands overlap: shaded, they would hide one
another).  :func:`plot_vertical_ratios` draws the in-plane part's ratios with / without the vertical, and
:func:`plot_near_far` the near-fault against the far-field components against their rupture distance.
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


#: The panels of :func:`plot_vertical_ratios`: column of ``isolation_vertical_ratios.csv`` -> its label.
VERTICAL_PANELS = {"peak_isolator_displacement_ratio": "isolator displacement |u_b|",
                   "peak_drift_ratio": "story drift", "peak_floor_acceleration_ratio": "floor acceleration",
                   "base_shear_coefficient_ratio": "base shear V_b/W", "energy_dissipated_ratio": "E_df"}


def plot_vertical_ratios(rows: Sequence[Mapping]) -> Figure:
    """Each peak with the vertical over without it against μ [1] (rows of ``isolation_vertical_ratios.csv``, from
    :mod:`stickslip.studies.isolation.with_vertical`): one panel per answer, one thin line per station, and per
    T [s] and R [m] the median over the stations as a thick line with its 16-84 % band shaded."""
    title = "In the plane: with the vertical over without it"
    if not rows:
        return plot_not_drawn(title, "the three-component records were not available")
    cells = sorted({(float(row["period"]), float(row["radius"])) for row in rows})
    figure, axes = new_figure(1, len(VERTICAL_PANELS), figsize=(3.1 * len(VERTICAL_PANELS) + 1.8, 3.8), sharey=True,
                              squeeze=False)
    for ax, (column, label) in zip(axes[0], VERTICAL_PANELS.items()):
        for colour, (period, radius) in enumerate(cells):
            cell = [row for row in rows if (float(row["period"]), float(row["radius"])) == (period, radius)]
            mu = np.array(sorted({float(row["mu"]) for row in cell}))
            by_station: dict[str, dict[float, float]] = {}
            for row in cell:
                by_station.setdefault(row["station"], {})[float(row["mu"])] = float(row[column])
            ratios = np.array([[values.get(value, np.nan) for value in mu] for values in by_station.values()])
            for line in ratios:
                ax.plot(mu, line, color=f"C{colour}", linewidth=0.6, alpha=0.35)
            low, median, high = np.nanpercentile(ratios, (16, 50, 84), axis=0)
            ax.fill_between(mu, low, high, color=f"C{colour}", alpha=0.2, linewidth=0)
            ax.plot(mu, median, "o-", color=f"C{colour}", linewidth=2.0, markersize=4,
                    label=f"T = {period:g} s, R = {radius:g} m ({len(by_station)} stations)")
        ax.axhline(1.0, color="0.3", linewidth=0.8, linestyle="--")
        ax.set_title(label, fontsize="medium")
        ax.set_xlabel("friction coefficient μ [1]")
        ax.grid(True, alpha=0.3)
    axes[0, 0].set_ylabel("with the vertical / without [1]")
    axes[0, -1].legend(**LEGEND_OUTSIDE, fontsize="small", title="median, 16-84 % shaded;\nthin: each station")
    figure.suptitle(title)
    return figure


#: The panels of :func:`plot_near_far`: column of ``isolation_cases.csv`` -> its axis label, its scale and whether a
#: line at 1 (the fixed-base building) belongs on it.
NEAR_FAR_PANELS = {"drift_ratio": ("peak drift isolated / fixed base [1]", "linear", True),
                   "peak_isolator_displacement": ("peak isolator displacement [m] (0 not drawn)", "log", False)}


def plot_near_far(cases: Sequence[Mapping], period: float, radius: float, near_fault_km: float) -> Figure:
    """The drift ratio and the isolator displacement against the rupture distance [km] (log scale) at one T [s] and
    R [m] (rows of ``isolation_cases.csv``): one colour per μ, each component a dot, and per μ the median of the
    near-fault components (within ``near_fault_km``) and of the far-field ones as a line over their distances.  The
    displacement on a log scale (a bearing that never slid, 0, is off it)."""
    title = f"Near-fault against far-field at T = {period:g} s, R = {radius:g} m"
    rows = [row for row in cases if float(row["period"]) == period and float(row["radius"]) == radius
            and np.isfinite(float(row["rupture_distance"]))]
    if not rows:
        return plot_not_drawn(title, "no component of known rupture distance was available")
    mus = sorted({float(row["mu"]) for row in rows})
    figure, axes = new_figure(1, len(NEAR_FAR_PANELS), figsize=(5.2 * len(NEAR_FAR_PANELS) + 1.8, 4.4),
                              squeeze=False)
    for ax, (column, (label, scale, unity)) in zip(axes[0], NEAR_FAR_PANELS.items()):
        for colour, mu in enumerate(mus):
            chosen = [row for row in rows if float(row["mu"]) == mu]
            distance = np.array([float(row["rupture_distance"]) for row in chosen])
            value = np.array([float(row[column]) for row in chosen])
            ax.plot(distance, value, ".", color=f"C{colour}", markersize=2.5, alpha=0.35)
            for group in (distance <= near_fault_km, distance > near_fault_km):
                if group.any():
                    ax.plot([distance[group].min(), distance[group].max()], [np.median(value[group])] * 2, "-",
                            color=f"C{colour}", linewidth=2.2)
            ax.plot([], [], "o-", color=f"C{colour}", label=f"μ = {mu:g}")
        ax.axvline(near_fault_km, color="0.3", linewidth=0.8, linestyle=":")
        if unity:
            ax.axhline(1.0, color="0.3", linewidth=0.8, linestyle="--")
        ax.set_xscale("log")
        ax.set_yscale(scale)
        ax.set_xlabel("rupture distance [km]")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0, -1].legend(**LEGEND_OUTSIDE, fontsize="small",
                       title=f"dots: components;\nlines: median ≤ and > {near_fault_km:g} km")
    figure.suptitle(title)
    return figure
