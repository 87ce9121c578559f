"""Figures of one record's friction design answer (``notebooks/record_report.ipynb``).

The answer is a mapping with the names of the sweep cube's per-record
results: ``mu_max`` and ``mu_max_continuous`` [1],
``energy_dissipated_max_continuous`` [J], the near-optimal range ``mu_low``,
``mu_high`` [1] and ``contiguous``, ``energy_dissipated_reference`` [J] and
``efficiency`` [1] at the reference μ, and the stroke (peak |x|) and residual
displacement [m] at the grid's μ_max (``peak_relative_displacement_at_mu_max``,
``residual_displacement_at_mu_max``): the results of :mod:`stickslip.optimum`.
Curves over μ come from a sweep cube.
Legends sit outside the axes, and give each number in the unit of its axis
and of the report's table (J, m), written as the table writes it
(:func:`~stickslip.reports.design_answer.format_number`).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from stickslip.reports.design_answer import format_number
from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure

RANGE_COLOR = "C2"
MAXIMUM_COLOR = "C3"
REFERENCE_COLOR = "0.35"


def _right_edge(mu: np.ndarray, sliding: np.ndarray) -> float:
    """The right end of the μ axis: a little beyond the largest μ of the grid where the block still slides.

    Beyond it the curves are zero (μ·g reaches the PGA), so a wide grid does not squeeze them to the left.
    """
    last = mu[sliding].max() if sliding.any() else mu.max()
    return float(min(mu.max(), 1.1 * last))


def _mark_range_and_maximum(ax, answer: dict) -> None:
    """The near-optimal range shaded and μ_max (continuous) as a dashed line."""
    ax.axvspan(answer["mu_low"], answer["mu_high"], color=RANGE_COLOR, alpha=0.15, lw=0,
               label=f"near-optimal range on the grid, {format_number(answer['mu_low'])} to "
                     f"{format_number(answer['mu_high'])}" + ("" if answer["contiguous"] else " (with gaps)"))
    ax.axvline(answer["mu_max_continuous"], color=MAXIMUM_COLOR, ls="--", lw=1,
               label=f"μ_max = {format_number(answer['mu_max_continuous'], 5)} (continuous)")


def plot_design_energy(mu: np.ndarray, energy: np.ndarray, answer: dict, q: float, reference_mu: float,
                       title: str, energy_units: str = "J") -> Figure:
    """E_df [J] against μ [-] with μ_max, the near-optimal range (E_df ≥ q·E_df,max) and the reference μ; energies
    labelled in ``energy_units`` (``J/kg`` for the default 1 kg block: :func:`stickslip.units.energy_units`)."""
    figure, ax = new_figure(figsize=(9.0, 4.5))
    ax.plot(mu, energy, color="k", lw=1.2, label="E_df on the grid")
    _mark_range_and_maximum(ax, answer)
    ax.plot([answer["mu_max_continuous"]], [answer["energy_dissipated_max_continuous"]], "*", color=MAXIMUM_COLOR,
            ms=11, label=f"E_df,max = {format_number(answer['energy_dissipated_max_continuous'])} {energy_units} at μ_max")
    ax.axhline(q * np.max(energy), color=RANGE_COLOR, ls=":", lw=1, label=f"{q:g}·E_df,max on the grid")
    ax.plot([reference_mu], [answer["energy_dissipated_reference"]], "o", mfc="none", color=REFERENCE_COLOR,
            label=f"μ = {reference_mu:g}: E_df = {format_number(answer['energy_dissipated_reference'])} {energy_units}, "
                  f"{answer['efficiency']:.0%} of the maximum")
    ax.axvline(reference_mu, color=REFERENCE_COLOR, ls=":", lw=1)
    ax.set(xlabel="friction ratio μ [-]", ylabel=f"energy dissipated by friction E_df [{energy_units}]",
           xlim=(0, _right_edge(mu, energy > 0)), ylim=(0, None), title=title)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize="small", **LEGEND_OUTSIDE)
    return figure


def plot_displacements_vs_mu(mu: np.ndarray, peak: np.ndarray, residual: np.ndarray, answer: dict,
                             title: str) -> Figure:
    """The stroke (peak |x|) and the residual displacement x_end [m] of the block against μ [-].

    The residual displacement keeps its sign (relative to the base).
    """
    figure, (top, bottom) = new_figure(2, 1, figsize=(9.0, 6.0), sharex=True)
    sliding = peak > 0
    top.plot(mu[sliding], peak[sliding], color="k", lw=1.2, label="stroke on the grid")
    bottom.plot(mu, residual, color="k", lw=1.2, label="residual displacement on the grid")
    bottom.axhline(0.0, color="0.6", lw=0.6)
    for ax, key, name in ((top, "peak_relative_displacement_at_mu_max", "stroke"),
                          (bottom, "residual_displacement_at_mu_max", "residual")):
        _mark_range_and_maximum(ax, answer)
        ax.plot([answer["mu_max"]], [answer[key]], "*", color=MAXIMUM_COLOR, ms=11,
                label=f"{name} at the grid's μ_max, {format_number(answer['mu_max'])}: {format_number(answer[key])} m")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize="small", **LEGEND_OUTSIDE)
    top.set(ylabel="stroke: peak |x| [m]", ylim=(0, None), title=title)
    bottom.set(xlabel="friction ratio μ [-]", ylabel="residual displacement x_end [m]",
               xlim=(0, _right_edge(mu, sliding)))
    return figure
