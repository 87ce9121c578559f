"""Figures of the codes' equivalent-linear displacement against the exact one (``notebooks/code_vs_exact.ipynb``).

Each function takes rows of the tables :mod:`stickslip.studies.code_vs_exact.analysis`
wrote (as read from CSV: strings) and returns a :class:`matplotlib.figure.Figure`.
Displacements in m, D/R and ratios [1], R in m.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure

from stickslip.reports.plots import new_figure, plot_not_drawn

#: Each code's label and colour.
CODE_STYLE = {"asce7_22": ("ASCE 7-22 (B_M)", "C0"), "aashto": ("AASHTO (B_L)", "C1"),
              "en1998_2": ("EN 1998-2 (η)", "C2")}

#: The panels of one direction and the plane.
DIRECTION_PANELS = {"one direction": ("first", "second"), "plane (RotD100)": ("plane",)}


def _number(text) -> float:
    return math.nan if text in (None, "") else float(text)


def _logged(rows: Sequence[Mapping]) -> list[Mapping]:
    """The cases without a vertical that have a log ratio (the slider slid and the code found a D)."""
    return [row for row in rows if row["vertical"] == "none" and not math.isnan(_number(row["ln_ratio"]))]


def plot_ratio_vs_d_over_r(rows: Sequence[Mapping], factor: float) -> Figure:
    """ln(D_exact/D_code) against D_code/R (log axis), one colour per code; one direction and the plane apart.

    Above the line ln ``factor`` the code is unconservative by more than ``factor`` − 1.
    """
    rows = _logged(rows)
    if not rows:
        return plot_not_drawn("ln(D_exact/D_code) against D_code/R", "no case has both displacements")
    figure, axes = new_figure(1, 2, figsize=(12.0, 4.8), sharey=True, squeeze=False)
    for ax, (title, directions) in zip(axes[0], DIRECTION_PANELS.items()):
        for code, (label, colour) in CODE_STYLE.items():
            chosen = [row for row in rows if row["code"] == code and row["direction"] in directions]
            ax.plot([_number(row["d_code_over_r"]) for row in chosen], [_number(row["ln_ratio"]) for row in chosen],
                    ".", color=colour, alpha=0.35, markersize=3, label=f"{label} ({len(chosen)})")
        ax.axhline(0.0, color="0.3", linewidth=0.8)
        ax.axhline(math.log(factor), color="C3", linewidth=0.8, linestyle="--",
                   label=f"D_exact = {factor:g} D_code")
        ax.set_xscale("log")
        ax.set_xlabel("D_code / R [1]")
        ax.set_title(title, fontsize="medium", loc="left")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", markerscale=3)
    axes[0, 0].set_ylabel("ln(D_exact / D_code)")
    figure.suptitle("The exact peak displacement over the code's, from each record's own spectrum")
    return figure


def plot_ratio_cdf(rows: Sequence[Mapping], factor: float) -> Figure:
    """The cumulative distribution of D_exact/D_code per code (log axis), the line at ``factor`` marked."""
    rows = _logged(rows)
    if not rows:
        return plot_not_drawn("Distribution of D_exact/D_code", "no case has both displacements")
    figure, ax = new_figure(figsize=(8.0, 4.8))
    for code, (label, colour) in CODE_STYLE.items():
        ratios = np.sort(np.exp([_number(row["ln_ratio"]) for row in rows if row["code"] == code]))
        if ratios.size:
            share = np.mean(ratios > factor)
            ax.step(ratios, np.arange(1, ratios.size + 1) / ratios.size, where="post", color=colour,
                    label=f"{label}: {100 * share:.0f} % above {factor:g}")
    ax.axvline(factor, color="C3", linewidth=0.8, linestyle="--")
    ax.axvline(1.0, color="0.3", linewidth=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("D_exact / D_code [1]")
    ax.set_ylabel("share of cases ≤ x")
    ax.set_title("D_exact / D_code over every case without a vertical (one direction and the plane)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    return figure


def plot_bias_by_group(bias: Sequence[Mapping]) -> Figure:
    """Bias ± σ of ln(D_exact/D_code) per code against R, μ and D_code/R (one panel each)."""
    groupings = {"radius": "R [m]", "mu": "μ [1]", "d_code_over_r": "D_code / R [1]"}
    rows = [row for row in bias if row["grouping"] in groupings and int(row["n"]) > 1]
    if not rows:
        return plot_not_drawn("Bias and sigma per group", "no group has two cases")
    figure, axes = new_figure(1, len(groupings), figsize=(13.0, 4.4), sharey=True, squeeze=False)
    for ax, (grouping, xlabel) in zip(axes[0], groupings.items()):
        groups = list(dict.fromkeys(row["group"] for row in rows if row["grouping"] == grouping))
        for offset, (code, (label, colour)) in enumerate(CODE_STYLE.items()):
            chosen = {row["group"]: row for row in rows if row["grouping"] == grouping and row["code"] == code}
            x = [index + 0.15 * (offset - 1) for index, group in enumerate(groups) if group in chosen]
            ax.errorbar(x, [_number(chosen[group]["bias"]) for group in groups if group in chosen],
                        yerr=[_number(chosen[group]["sigma"]) for group in groups if group in chosen],
                        fmt="o", color=colour, capsize=3, label=label)
        ax.axhline(0.0, color="0.3", linewidth=0.8)
        ax.set_xticks(range(len(groups)), groups, fontsize="small")
        ax.set_xlabel(xlabel)
        ax.grid(True, axis="y", alpha=0.3)
    axes[0, 0].set_ylabel("bias ± σ of ln(D_exact / D_code)")
    axes[0, 0].legend(fontsize="small")
    figure.suptitle("Bias (mean) and σ of ln(D_exact/D_code) per code, cases without a vertical")
    return figure
