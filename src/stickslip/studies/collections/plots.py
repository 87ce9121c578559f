"""Figures of a collection study (``notebooks/collection_study.ipynb``), from the files the workflow wrote.

Each function takes the study's tables (rows as read from CSV, or the
JSON documents) and returns a :class:`matplotlib.figure.Figure`; legends sit
outside the axes (beside or below them) so they never hide data.  Units on every axis.  Only the
records studied are drawn (:func:`stickslip.collections.members.studied`);
a figure with nothing to draw says why ("Not drawn: ...").
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from stickslip.analysis import near_optimal_set
from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn
from stickslip.collections.members import studied
from stickslip.units import readable_units

#: Axis labels of the checked measures (SLAMMER's units).
CHECK_LABELS = {"pga": "PGA [g]", "arias_intensity": "Arias intensity [m/s]",
                "dobry_duration": "5-95 % duration [s]", "mean_period": "mean period T_m [s]"}


def _legend_outside(ax) -> None:
    ax.legend(fontsize="small", **LEGEND_OUTSIDE)


def _legend_below(ax, ncols: int = 2) -> None:
    """The legend of ``ax`` under the axes, across the figure: long entries never squeeze the axes."""
    ax.figure.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncols=ncols, fontsize="small")


#: Most records drawn one by one, each named in the legend; more are drawn as thin grey lines and their median.
NAMED_CURVES = 12


def plot_energy_curves(cube: xr.Dataset) -> Figure:
    """Each record's E_df(μ) [J] and E_df/E_df,max [-] against μ, its continuous μ_max marked.

    ``cube`` holds the records studied (the study's cube, ``energy_dissipated``
    over ``record`` × ``mu`` and ``mu_max_continuous``).  Up to
    :data:`NAMED_CURVES` records are drawn in colour and named; more are thin
    grey lines with their median, so that the shape of the family shows.
    """
    title = "Energy dissipated by friction against μ, record by record"
    if cube.sizes["record"] == 0:
        return plot_not_drawn(title, "no record was studied")
    figure, (left, right) = new_figure(1, 2, figsize=(10.0, 4.8), sharex=True)
    mu = cube.mu.values
    energy = cube.energy_dissipated.values
    relative = energy / energy.max(axis=1, keepdims=True)
    mu_max = cube.mu_max_continuous.values
    named = cube.sizes["record"] <= NAMED_CURVES
    for k, record in enumerate(cube.record.values.astype(str)):
        style = {"color": f"C{k % 10}", "lw": 1.2, "label": record} if named else {"color": "0.6", "lw": 0.5,
                                                                                    "alpha": 0.4}
        left.plot(mu, energy[k], **style)
        right.plot(mu, relative[k], **{**style, "label": None})
        if named:
            right.plot(mu_max[k], np.interp(mu_max[k], mu, relative[k]), "o", color=style["color"], ms=4)
    if not named:
        right.plot(mu, np.median(relative, axis=0), color="k", lw=2, label=f"median of {len(mu_max)} records")
        right.legend(fontsize="small")
    slides = np.nonzero((energy > 0).any(axis=0))[0]
    x_max = mu[min(slides[-1] + 1, mu.size - 1)] if slides.size else mu[-1]
    left.set(xlabel="friction ratio μ [-]", ylabel="E_df [J]", xlim=(0, x_max), ylim=(0, None))
    right.set(xlabel="friction ratio μ [-]", ylabel="E_df / E_df,max [-]", ylim=(0, 1.05),
              title="dots: each record's continuous μ_max" if named else None)
    figure.suptitle(title)
    if named:
        _legend_below(left, ncols=min(4, cube.sizes["record"]))
    return figure


def plot_measures_check(check_rows: list[dict], summary: dict) -> Figure:
    """Our measures (SLAMMER's definitions) against the database's, one panel per measure, with pass rates."""
    if not check_rows:
        return plot_not_drawn("Intensity measures against the SLAMMER database",
                              "this collection publishes no intensity measures to check ours against")
    figure, axes = new_figure(2, 2, figsize=(9.0, 8.0))
    for ax, (name, label) in zip(axes.flat, CHECK_LABELS.items()):
        rows = [row for row in check_rows if row["measure"] == name]
        published = np.array([float(row["published"]) for row in rows])
        ours = np.array([float(row["ours_slammer_convention"]) for row in rows])
        beyond = np.array([row["status"] != "within tolerance" for row in rows], dtype=bool)
        ax.scatter(published[~beyond], ours[~beyond], s=8, color="C0", label="within the rounding")
        if beyond.any():
            ax.scatter(published[beyond], ours[beyond], s=30, marker="x", color="C3", label="beyond")
        if rows:
            span = [min(published.min(), ours.min()), max(published.max(), ours.max())]
            ax.plot(span, span, color="0.5", lw=0.8, zorder=0)
        stats = summary["measures"][name]
        rate = f"{stats['pass_rate']:.1%}" if stats["pass_rate"] is not None else "n/a"
        ax.set(xlabel=f"SLAMMER database: {label}", ylabel=f"stickslip: {label}",
               title=f"{stats['within']} of {stats['checked']} within ±{stats['tolerance']:g} ({rate})")
    figure.suptitle("Intensity measures against the SLAMMER database (grey: equality)")
    return figure


def plot_mu_max_vs_pga(rows: list[dict], design: dict, relations: list[dict]) -> Figure:
    """μ_max against PGA for every record, our line, the ratio band, and the paper's eight points and line."""
    figure, ax = new_figure(figsize=(9.0, 6.5))
    ok = studied(rows)
    pga = np.array([float(row["pga"]) for row in ok])
    mu_max = np.array([float(row["mu_max_continuous"]) for row in ok])
    ax.scatter(pga, mu_max, s=10, alpha=0.6, color="C0", label=f"records of the collection (n = {len(ok)})")
    x = np.linspace(0.0, max(pga.max(initial=0.0), 10.0), 50)
    ours = next(row for row in relations if row["predictor"] == "pga")
    if ours["status"] == "ok":
        ax.plot(x, ours["slope"] * x + ours["intercept"], color="C0",
                label=f"our line, r = {ours['pearson_r']:.2f}")
    else:
        ax.plot([], [], " ", label=f"our line: not drawn, {ours['status']}")
    quantiles = design.get("ratio_quantiles")
    if quantiles:
        g = design["g"]
        ax.fill_between(x, quantiles["0.1"] * x / g, quantiles["0.9"] * x / g, color="C0", alpha=0.12,
                        label="10-90 % of μ_max·g/PGA")
    else:
        ax.plot([], [], " ", label=f"ratio band: not drawn, {design['ratio_status']}")
    paper = design["paper_points"]
    ax.scatter([p["pga"] for p in paper], [p["mu_max"] for p in paper], marker="s", s=40, color="C1",
               edgecolor="k", label="the paper's 8 records (its Table 6)", zorder=3)
    paper_fit = design["paper_fit"]
    ax.plot(x, paper_fit["slope"] * x + paper_fit["intercept"], "--", color="C1",
            label=f"the paper's line, from its Table 6 (r = {paper_fit['r']:.2f})")
    ax.set(xlabel="PGA [m/s²]", ylabel="μ_max [-]", xlim=(0, x.max()), ylim=(0, None),
           title="Friction ratio of maximum dissipation against PGA")
    _legend_below(ax, ncols=1)
    return figure


def plot_relations(relations: list[dict]) -> Figure:
    """Spearman ρ of μ_max with each predictor (95 % interval), and the leave-one-event-out skill.

    A predictor without a fit is left out of the panels; the figure's foot
    names each one with its reason (with none fitted, the page does).
    """
    rows = [row for row in relations if row["status"] == "ok"]
    left_out = [f"{row['label']}: {row['status']}" for row in relations if row["status"] != "ok"]
    if not rows:  # the page lists each predictor's reason beneath
        return plot_not_drawn("What μ_max depends on", "no predictor has a fit")
    figure, (left, right) = new_figure(1, 2, figsize=(10.0, 4.5), sharey=True)
    y = np.arange(len(rows))
    rho = np.array([row["spearman_rho"] for row in rows])
    low = np.array([row["spearman_rho_low"] for row in rows])
    high = np.array([row["spearman_rho_high"] for row in rows])
    left.errorbar(rho, y, xerr=[rho - low, high - rho], fmt="o", color="C0", capsize=3)
    left.axvline(0, color="0.5", lw=0.8)
    left.set(yticks=y, yticklabels=[f"{row['label']} (n = {int(row['n'])})" for row in rows], xlim=(-1, 1),
             xlabel="Spearman ρ with μ_max [-], 95 % interval")
    skill = np.array([row["loeo_skill"] for row in rows], dtype=float)
    right.barh(y, np.nan_to_num(skill), color=np.where(skill > 0, "C2", "C3"))
    right.axvline(0, color="0.5", lw=0.8)
    right.set(xlabel="skill of a line, leave-one-event-out [-]")
    figure.suptitle("What μ_max depends on")
    if left_out:
        figure.supxlabel("Left out: " + "; ".join(left_out), fontsize="x-small", wrap=True)
    return figure


def plot_design_chart(design: dict, coverage: list[dict]) -> Figure:
    """μ_max against its best predictor with the 95 % prediction band, and the design μ per PGA band."""
    if design.get("status") != "ok":
        return plot_not_drawn("Design chart: μ_max against its best predictor", str(design.get("status")))
    figure, ax = new_figure(figsize=(9.0, 5.0))
    band = design["band"]
    x = np.array([p["x"] for p in design["points"]])
    y = np.array([p["y"] for p in design["points"]])
    ax.scatter(x, y, s=10, alpha=0.6, color="C0", label="records")
    ax.plot(band["x"], band["fitted"], color="k",
            label=f"μ_max = {band['slope']:.4g}·x {band['intercept']:+.3g}\n(leave-one-event-out RMSE "
                  f"{design['loeo_rmse']:.3f})")
    ax.fill_between(band["x"], band["low"], band["high"], color="0.6", alpha=0.3,
                    label=f"{band['level']:.0%} prediction band")
    units = readable_units(design["predictor_units"])
    ax.set(xlabel=f"x = {design['predictor_label']} [{units}]", ylabel="μ_max [-]", ylim=(0, None),
           title=f"Design chart: μ_max against its best predictor ({len(x)} records)")
    lines = [f"{row['pga_band']}: μ = {float(row['design_mu']):g} for {float(row['share_design_mu']):.0%} "
             f"of {int(float(row['n']))}" for row in coverage if row["status"] == "ok"]
    ax.text(1.02, 0.0, "μ reaching 90 % of E_max,\nby PGA band:\n" + "\n".join(lines), transform=ax.transAxes,
            va="bottom", fontsize="small")
    _legend_outside(ax)
    return figure


def plot_coverage(cube: xr.Dataset, pga_g: np.ndarray, bands_g: list[float], q: float,
                  reference_mu: float, min_records: int) -> Figure:
    """Share of records whose near-optimal range contains μ, against μ, for all records and each PGA band.

    ``cube`` holds the records studied, ``pga_g`` [g] their PGAs; a group of
    fewer than ``min_records`` records is not drawn, and the legend says so.
    """
    title = "Which single μ serves most records?"
    if pga_g.size < min_records:
        return plot_not_drawn(title, f"too few records studied: {pga_g.size}, a share needs at least {min_records}")
    figure, ax = new_figure(figsize=(9.0, 4.5))
    energy = cube.energy_dissipated.values
    inside = near_optimal_set(energy, q)
    mu = cube.mu.values
    ax.plot(mu, inside.mean(axis=0), color="k", lw=2, label=f"all records (n = {pga_g.size})")
    for k, (low, high) in enumerate(zip(bands_g, bands_g[1:])):
        members = (pga_g >= low) & (pga_g < high)
        if members.sum() >= min_records:
            ax.plot(mu, inside[members].mean(axis=0), color=f"C{k}", label=f"PGA {low:g}-{high:g} g (n = {members.sum()})")
        else:
            ax.plot([], [], " ",
                    label=f"PGA {low:g}-{high:g} g: {members.sum()} records (fewer than {min_records}), not drawn")
    ax.axvline(reference_mu, color="0.4", ls="--", lw=1, label=f"μ = {reference_mu:g}")
    ax.set(xlabel="friction ratio μ [-]", ylabel=f"share of records with E_df ≥ {q:g}·E_max [-]",
           xlim=(0, min(mu.max(), 0.5)), ylim=(0, 1), title=title)
    _legend_outside(ax)
    return figure


def plot_ratio_and_efficiency(rows: list[dict], reference_mu: float) -> Figure:
    """Histograms of μ_max·g/PGA and of the efficiency of the reference μ, over the records studied."""
    ok = studied(rows)
    if not ok:
        return plot_not_drawn("μ_max·g/PGA and the efficiency of the reference μ", "no record was studied")
    figure, (left, right) = new_figure(1, 2, figsize=(10.0, 4.0))
    ratio = np.array([float(row["mu_max_g_over_pga"]) for row in ok])
    efficiency = np.array([float(row["efficiency"]) for row in ok])
    left.hist(ratio, bins=30, color="C0")
    left.axvline(np.median(ratio), color="k", ls="--", lw=1)
    left.set(xlabel="μ_max·g/PGA [-]", ylabel="records", title=f"median {np.median(ratio):.3f}")
    right.hist(efficiency, bins=np.linspace(0, 1, 21), color="C2")
    right.axvline(np.median(efficiency), color="k", ls="--", lw=1)
    right.set(xlabel=f"E_df(μ = {reference_mu:g}) / E_df,max [-]", ylabel="records",
              title=f"median {np.median(efficiency):.2f}")
    for ax in (left, right):
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))  # counts of records
    return figure


def plot_scaling_law(law_rows: list[dict]) -> Figure:
    """μ_max of the scaled record against k·μ_max of the original: the scaling law's exact proportionality."""
    if not law_rows:
        return plot_not_drawn("Scaling law", "no record of the study's first chunk slides on the grid")
    figure, ax = new_figure(figsize=(6.5, 4.5))
    expected = np.array([float(row["factor"]) * float(row["mu_max"]) for row in law_rows])
    found = np.array([float(row["mu_max_scaled"]) for row in law_rows])
    ax.scatter(expected, found, color="C0", s=20)
    span = [0, max(expected.max(), found.max()) * 1.05]
    ax.plot(span, span, color="0.5", lw=0.8)
    worst = max(float(row["max_relative_energy_difference"]) for row in law_rows)
    ax.set(xlabel="k·μ_max(a) [-]", ylabel="μ_max(k·a) [-]",
           title=f"Scaling law: largest |E(kμ; ka) − k²E(μ; a)|/k²E = {worst:.1e}")
    return figure

