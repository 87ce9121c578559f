"""Figures of Jibson (2007), recomputed (``notebooks/jibson2007.ipynb``).

Each function takes the displacement table's rows that enter a fit (as read
from CSV: strings; :func:`stickslip.studies.jibson2007.fit.select`) and the
fit document (JSON) of :mod:`stickslip.studies.jibson2007.fit`, and returns a
:class:`matplotlib.figure.Figure`.  Units are Jibson's: D_n [cm], a_c and
a_max [g], I_a [m s-1]; his curves are drawn from the reference values the
document carries.  A fit that could not be made gives a figure that says why.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from stickslip.estimates.jibson import design_matrix, predict
from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn

#: Colour of each polarity's points.
POLARITY_COLOURS = {"normal": "C0", "inverse": "C1"}


def _values(rows: Sequence[Mapping], column: str) -> np.ndarray:
    return np.array([float(row[column]) for row in rows])


def _coefficients(fit: Mapping) -> dict[str, float]:
    return {term: value["value"] for term, value in fit["coefficients"].items()}


def _points(ax, rows: Sequence[Mapping], x: np.ndarray, y: np.ndarray) -> None:
    polarity = np.array([row["polarity"] for row in rows])
    for name, colour in POLARITY_COLOURS.items():
        chosen = polarity == name
        ax.scatter(x[chosen], y[chosen], s=6, alpha=0.35, color=colour, linewidths=0,
                   label=f"ours, {name} polarity ({int(chosen.sum())} rows)")


def plot_form1(rows: Sequence[Mapping], document: Mapping) -> Figure:
    """log10 D_n against a_c/a_max with Jibson's curve and both of ours (form ``critical_acceleration_ratio``).

    ``rows``: the rows of the selection without a floor (every D_n > 0); those
    below the floor, which only that fit uses, are drawn in grey.
    """
    fits = {name: selection["forms"]["critical_acceleration_ratio"]
            for name, selection in document["selections"].items()}
    title = "log10 D_n against a_c/a_max, with Jibson's (2007) curve and ours"
    if all(fit["status"] != "ok" for fit in fits.values()):
        return plot_not_drawn(title, fits["without_floor"]["status"])
    floor = document["settings"]["displacement_floor_cm"]
    figure, ax = new_figure(figsize=(10.0, 5.2))
    ratio, displacement = _values(rows, "critical_acceleration_ratio"), _values(rows, "newmark_displacement")
    below = displacement < floor
    ax.scatter(ratio[below], np.log10(displacement[below]), s=6, alpha=0.35, color="0.6", linewidths=0,
               label=f"ours, D_n < {floor:g} cm ({int(below.sum())} rows)")
    above = [row for row, low in zip(rows, below) if not low]
    _points(ax, above, ratio[~below], np.log10(displacement[~below]))
    grid = np.geomspace(max(ratio.min(), 1e-3) * 0.9, min(ratio.max() * 1.02, 0.999), 300)
    reference = document["reference"]["forms"]["critical_acceleration_ratio"]
    ax.plot(grid, predict("critical_acceleration_ratio", reference["coefficients"], grid), color="k", lw=2.0,
            label=f"Jibson (2007), σ = {reference['sigma']:.3f}")
    for (name, fit), style in zip(fits.items(), (("C3", "--"), ("C2", "-."))):
        if fit["status"] == "ok":
            what = f"D_n ≥ {floor:g} cm" if name == "with_floor" else "every D_n > 0"
            ax.plot(grid, predict("critical_acceleration_ratio", _coefficients(fit), grid), color=style[0], lw=2.0,
                    ls=style[1], label=f"ours, fitted on {what}, σ = {fit['sigma']['value']:.3f}")
    ax.set_xscale("log")
    ax.set_xlabel("critical acceleration ratio a_c / a_max [1]")
    ax.set_ylabel("log10 D_n [log10 cm]")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(**LEGEND_OUTSIDE, fontsize="small")
    return figure


def plot_form2(rows: Sequence[Mapping], document: Mapping, selection: str) -> Figure:
    """Predicted against observed log10 D_n of form ``arias_intensity_and_ratio``: Jibson's coefficients and ours."""
    fit = document["selections"][selection]["forms"]["arias_intensity_and_ratio"]
    title = "log10 D_n predicted by the form in I_a and a_c/a_max, against ours"
    if fit["status"] != "ok":
        return plot_not_drawn(title, fit["status"])
    reference = document["reference"]["forms"]["arias_intensity_and_ratio"]
    ratio, arias = _values(rows, "critical_acceleration_ratio"), _values(rows, "arias_intensity")
    observed = np.log10(_values(rows, "newmark_displacement"))
    figure, axes = new_figure(1, 2, figsize=(11.0, 5.0), sharex=True, sharey=True)
    for ax, (name, coefficients, sigma) in zip(axes, (
            ("Jibson's (2007) coefficients", reference["coefficients"], reference["sigma"]),
            ("our coefficients", _coefficients(fit), fit["sigma"]["value"]))):
        predicted = predict("arias_intensity_and_ratio", coefficients, ratio, arias)
        _points(ax, rows, observed, predicted)
        bounds = np.array([min(observed.min(), predicted.min()), max(observed.max(), predicted.max())])
        ax.plot(bounds, bounds, color="0.3", lw=1.0, label="predicted = observed")
        rms = float(np.sqrt(np.mean((predicted - observed) ** 2)))
        ax.set_title(f"{name}: RMS error {rms:.3f} (σ {sigma:.3f})", fontsize="medium")
        ax.set_xlabel("observed log10 D_n (ours) [log10 cm]")
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("predicted log10 D_n [log10 cm]")
    axes[1].legend(**LEGEND_OUTSIDE, fontsize="small")
    return figure


def plot_residuals(rows: Sequence[Mapping], document: Mapping, selection: str) -> Figure:
    """Histograms of the residuals (observed − our fit) of both forms [log10 cm], with ± σ marked."""
    forms = document["selections"][selection]["forms"]
    title = "Residuals of our fits"
    failed = [fit["status"] for fit in forms.values() if fit["status"] != "ok"]
    if failed:
        return plot_not_drawn(title, failed[0])
    ratio, arias = _values(rows, "critical_acceleration_ratio"), _values(rows, "arias_intensity")
    observed = np.log10(_values(rows, "newmark_displacement"))
    figure, axes = new_figure(1, len(forms), figsize=(11.0, 4.2), sharey=True)
    for ax, (form, fit) in zip(np.atleast_1d(axes), forms.items()):
        values = np.array([fit["coefficients"][term]["value"] for term in fit["coefficients"]])
        residuals = observed - design_matrix(form, ratio, arias) @ values
        sigma = fit["sigma"]["value"]
        ax.hist(residuals, bins=min(60, max(10, residuals.size // 20)), color="C0", alpha=0.8)
        for sign in (-1, 1):
            ax.axvline(sign * sigma, color="C3", ls="--", lw=1.2)
        ax.set_title(f"{form.replace('_', ' ')}: σ = {sigma:.3f}", fontsize="medium")
        ax.set_xlabel("residual log10 D_n, observed − fitted [log10 cm]")
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))  # counts of rows
        ax.grid(True, alpha=0.3)
    np.atleast_1d(axes)[0].set_ylabel("rows")
    return figure
