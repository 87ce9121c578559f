"""Figures of the simplified estimates against the rigorous answers (``notebooks/estimates.ipynb``).

Each function takes rows of the tables :mod:`stickslip.studies.estimates.simplified`
wrote (as read from CSV: strings) and returns a :class:`matplotlib.figure.Figure`.
Displacements in cm; residuals ln(D / D_est) in natural-log units.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import matplotlib
import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import NullFormatter

from stickslip.estimates.registry import METHODS
from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn

#: Marker of each sliding-mass period T_s [s] (0: against the rigid D_n).
PERIOD_MARKERS = ("o", "s", "^", "D", "v")


def _colour(method: str):
    """One colour per method (20 distinct ones)."""
    return matplotlib.colormaps["tab20"](list(METHODS).index(method) % 20)


def _label(row: Mapping) -> str:
    period = float(row["site_period"])
    label = METHODS[row["method"]].label
    return label if period == 0.0 else f"{label}, T_s {period:g} s"


def _number(text) -> float:
    return math.nan if text in (None, "") else float(text)


def plot_bias(summary: Sequence[Mapping]) -> Figure:
    """The bias (mean of ln(D / D_est), points) and ±σ of the residual (bars) against k_y, per method.

    Left: against the rigid D_n; right: against the coupled D.  Above zero the
    method underestimates.
    """
    groups: dict[tuple[str, float], list[Mapping]] = {}
    for row in summary:
        if not math.isnan(_number(row["bias_ln"])):
            groups.setdefault((row["method"], float(row["site_period"])), []).append(row)
    if not groups:
        return plot_not_drawn("Bias of the simplified estimates", "too few rows with D at or above the floor")
    figure, axes = new_figure(1, 2, figsize=(13.0, 5.5), sharey=True)
    names = list(METHODS)
    periods = sorted({period for _, period in groups if period > 0.0})
    for (method, period), rows in sorted(groups.items(), key=lambda item: (names.index(item[0][0]), item[0][1])):
        ax = axes[0] if period == 0.0 else axes[1]
        ky = np.array([float(row["ky"]) for row in rows])
        bias = np.array([_number(row["bias_ln"]) for row in rows])
        sigma = np.array([_number(row["sigma_ln"]) for row in rows])
        shift = 1.0 + 0.02 * (names.index(method) - len(names) / 2)
        marker = "o" if period == 0.0 else PERIOD_MARKERS[1 + periods.index(period) % (len(PERIOD_MARKERS) - 1)]
        ax.errorbar(ky * shift, bias, yerr=sigma, marker=marker, ms=4, capsize=2, lw=1.0,
                    color=_colour(method), label=_label(rows[0]))
    for ax, title in zip(axes, ("against the exact rigid D_n", "against the exact coupled D")):
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set_xscale("log")
        kys = sorted({float(row["ky"]) for row in summary})
        ax.set_xticks(kys, [f"{value:g}" for value in kys])
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("k_y [g]")
        ax.set_title(title)
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, **LEGEND_OUTSIDE)
    axes[0].set_ylabel("ln(D / D_est): mean ± standard deviation")
    return figure


def plot_scatter(rows: Sequence[Mapping], floor_cm: float) -> Figure:
    """Estimated against exact D [cm], log-log, one panel per method (rows with D ≥ ``floor_cm`` and D_est > 0)."""
    panels: dict[tuple[str, bool], list[tuple[float, float]]] = {}
    for row in rows:
        observed, estimated = float(row["observed_displacement"]), float(row["estimated_displacement"])
        if observed >= floor_cm and estimated > 0.0:
            panels.setdefault((row["method"], float(row["site_period"]) > 0.0), []).append((observed, estimated))
    if not panels:
        return plot_not_drawn("Estimated against exact displacement", "no row with D at or above the floor")
    names = list(METHODS)
    keys = sorted(panels, key=lambda key: (key[1], names.index(key[0])))
    ncols = 4
    nrows = -(-len(keys) // ncols)
    figure, axes = new_figure(nrows, ncols, figsize=(13.0, 3.2 * nrows), squeeze=False)
    for ax, key in zip(axes.flat, keys):
        values = np.array(panels[key])
        ax.scatter(values[:, 0], values[:, 1], s=3, alpha=0.25, linewidths=0, rasterized=True)
        low, high = floor_cm, max(values.max(), floor_cm * 10)
        ax.plot([low, high], [low, high], color="k", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        against = " (coupled D)" if key[1] else " (T_s = 0, rigid D_n)" if METHODS[key[0]].kind == "flexible" else ""
        ax.set_title(f"{METHODS[key[0]].label}{against}", fontsize=8)
        ax.set_xlabel("exact D [cm]", fontsize=8)
        ax.set_ylabel("estimated median [cm]", fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(keys):]:
        ax.set_visible(False)
    return figure


def plot_zeros(summary: Sequence[Mapping], floor_cm: float) -> Figure:
    """Predicted against observed share of zero displacements (D = 0, left) and of D < ``floor_cm`` (right)."""
    if not summary:
        return plot_not_drawn("Zero displacements", "no rows")
    figure, axes = new_figure(1, 2, figsize=(12.0, 5.0))
    for method in dict.fromkeys(row["method"] for row in summary):
        rows = [row for row in summary if row["method"] == method]
        colour = _colour(method)
        for ax, (observed, estimated) in zip(axes, (("observed_zero_share", "estimated_zero_share"),
                                                    ("observed_below_floor_share", "estimated_below_floor_share"))):
            ax.scatter([float(row[observed]) for row in rows], [float(row[estimated]) for row in rows], s=18,
                       color=colour, label=METHODS[method].label if ax is axes[1] else None)
    for ax, title in zip(axes, ("D = 0 (the block never slides)", f"D < {floor_cm:g} cm")):
        ax.plot([0, 1], [0, 1], color="k", lw=0.8)
        ax.set_xlim(-0.02, 1.02)
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel("observed share of rows")
        ax.set_ylabel("predicted share (mean probability)")
        ax.set_title(title)
        ax.grid(alpha=0.3)
    axes[1].legend(fontsize=7, **LEGEND_OUTSIDE)
    return figure


def plot_exceedance(exceedance: Sequence[Mapping]) -> Figure:
    """The mean predicted P(D > d) against the observed share with D > d, per method (one point per k_y, T_s, d)."""
    if not exceedance:
        return plot_not_drawn("Probability of exceedance", "no rows")
    figure, ax = new_figure(figsize=(8.5, 6.0))
    thresholds = sorted({float(row["displacement"]) for row in exceedance})
    for method in dict.fromkeys(row["method"] for row in exceedance):
        for k, threshold in enumerate(thresholds):
            rows = [row for row in exceedance if row["method"] == method and float(row["displacement"]) == threshold]
            ax.scatter([float(row["observed_share"]) for row in rows],
                       [float(row["estimated_probability"]) for row in rows], s=14,
                       marker=PERIOD_MARKERS[k % len(PERIOD_MARKERS)], color=_colour(method),
                       label=METHODS[method].label if k == 0 else None)
    ax.plot([0, 1], [0, 1], color="k", lw=0.8)
    ax.set_xlabel("observed share of rows with D > d")
    ax.set_ylabel("mean predicted P(D > d)")
    ax.set_title("d = " + ", ".join(f"{value:g} cm ({PERIOD_MARKERS[k % len(PERIOD_MARKERS)]})"
                                    for k, value in enumerate(thresholds)))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, **LEGEND_OUTSIDE)
    return figure
