"""Figures of the damper study (``notebooks/damper_study.ipynb``).

Each function takes rows of the tables :mod:`stickslip.studies.damper.tables` wrote (as read from CSV: strings)
and returns a :class:`matplotlib.figure.Figure`.  μ [1], periods T [s], drift reductions [1].
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib import colormaps
from matplotlib.colors import LogNorm
from matplotlib.figure import Figure

from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn

#: Marker of each mass ratio, in the order of the ratios.
MARKERS = "os^Dv<>p"


def _number(text) -> float:
    return math.nan if text in (None, "") else float(text)


def plot_mu_scatter(cases: Sequence[Mapping]) -> Figure:
    """μ_Edf (the paper's μ_max) against μ_drift, per record, mass ratio and T: colour the period (log scale), marker
    the mass ratio, the diagonal where they agree."""
    title = "The μ of most E_df against the μ of least drift"
    rows = [row for row in cases if math.isfinite(_number(row["mu_energy"]))]
    if not rows:
        return plot_not_drawn(title, "no record was available, or the damper never slides")
    figure, ax = new_figure(figsize=(8.4, 6.0))
    ratios = sorted({float(row["mass_ratio"]) for row in rows})
    periods = [float(row["period"]) for row in rows]
    norm = LogNorm(min(periods), max(periods)) if min(periods) < max(periods) else None
    cmap = colormaps["viridis"]
    for index, ratio in enumerate(ratios):
        chosen = [row for row in rows if float(row["mass_ratio"]) == ratio]
        points = ax.scatter([float(row["mu_drift"]) for row in chosen], [float(row["mu_energy"]) for row in chosen],
                            c=[float(row["period"]) for row in chosen], cmap=cmap, norm=norm,
                            marker=MARKERS[index % len(MARKERS)], s=16, alpha=0.6, edgecolors="none",
                            label=f"m_d/m_s = {ratio:g}")
    low = min(min(float(row["mu_drift"]) for row in rows), min(float(row["mu_energy"]) for row in rows))
    high = max(max(float(row["mu_drift"]) for row in rows), max(float(row["mu_energy"]) for row in rows))
    ax.plot([low, high], [low, high], color="0.3", linewidth=0.8, linestyle="--", label="μ_Edf = μ_drift")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("μ_drift, the μ of the smallest peak drift [1]")
    ax.set_ylabel("μ_Edf, the μ of the most E_df (the paper's μ_max) [1]")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    figure.colorbar(points, ax=ax, label="structure period T [s]")
    ax.legend(fontsize="small", loc="upper left")
    return figure


def plot_given_up(summary: Sequence[Mapping], library: str) -> Figure:
    """The drift reduction the paper's μ gives up against the drift's optimum, and μ_Edf/μ_drift, against T: median
    (solid) and 84th percentile (dashed) over the records, one colour per mass ratio."""
    title = "What the μ of most E_df gives up against the μ of least drift"
    rows = [row for row in summary if row["library"] == library and row["median"] not in ("", "nan")]
    if not rows:
        return plot_not_drawn(title, "no record was available")
    ratios = sorted({float(row["mass_ratio"]) for row in rows})
    figure, axes = new_figure(1, 2, figsize=(12.0, 4.4), squeeze=False)
    for ax, quantity, label in ((axes[0, 0], "reduction_given_up", "drift reduction given up [1]"),
                                (axes[0, 1], "mu_ratio", "μ_Edf / μ_drift [1]")):
        for colour, ratio in enumerate(ratios):
            cell = sorted((row for row in rows if row["quantity"] == quantity and float(row["mass_ratio"]) == ratio),
                          key=lambda row: float(row["period"]))
            periods = [float(row["period"]) for row in cell]
            ax.plot(periods, [float(row["median"]) for row in cell], "o-", color=f"C{colour}",
                    label=f"m_d/m_s = {ratio:g}, median")
            ax.plot(periods, [float(row["p84"]) for row in cell], "s--", color=f"C{colour}", markersize=4,
                    label=f"m_d/m_s = {ratio:g}, 84th percentile")
        ax.set_xscale("log")
        ax.set_xlabel("structure period T [s]")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[0, 1].axhline(1.0, color="0.3", linewidth=0.8, linestyle=":")
    axes[0, 1].set_yscale("log")
    axes[0, 1].legend(**LEGEND_OUTSIDE, fontsize="small")
    figure.suptitle(title)
    return figure


def plot_drift_reduction(curves: Sequence[Mapping], library: str, mass_ratio: float) -> Figure:
    """The drift reduction 1 − drift/drift_bare against the friction level η = μg/PFA_bare at ``mass_ratio``, one
    line per T: median over the records with its 16-84 % band."""
    title = f"Drift reduction by the damper against the friction level, m_d/m_s = {mass_ratio:g}"
    rows = [row for row in curves if row["library"] == library and float(row["mass_ratio"]) == mass_ratio
            and row["median"] not in ("", "nan")]
    if not rows:
        return plot_not_drawn(title, "no record was available")
    periods = sorted({float(row["period"]) for row in rows})
    figure, ax = new_figure(figsize=(9.0, 5.0))
    for colour, period in enumerate(periods):
        cell = sorted((row for row in rows if float(row["period"]) == period), key=lambda row: float(row["level"]))
        levels = np.array([float(row["level"]) for row in cell])
        ax.fill_between(levels, [float(row["p16"]) for row in cell], [float(row["p84"]) for row in cell],
                        color=f"C{colour}", alpha=0.12, linewidth=0)
        ax.plot(levels, [float(row["median"]) for row in cell], "o-", color=f"C{colour}", markersize=3.5,
                label=f"T = {period:g} s")
    ax.axhline(0.0, color="0.3", linewidth=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("friction level η = μg / PFA_bare (the bare floor's peak acceleration) [1]")
    ax.set_ylabel("drift reduction 1 − drift/drift_bare [1]")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(**LEGEND_OUTSIDE, fontsize="small", title="median, 16-84 % band")
    return figure
