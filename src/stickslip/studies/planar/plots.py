"""Figures of the planar study (``notebooks/planar_study.ipynb``), from the files the workflow wrote.

Each function takes the study's tables (rows of ``pair_results.csv`` and
``ratio_by_mu.csv`` as read from CSV, ``design.json``) or its cube and returns
a :class:`matplotlib.figure.Figure`, units on every axis, legends outside the
data.  Only the pairs that slide in the plane are drawn; a figure with
nothing to draw says why ("Not drawn: ...").
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn

#: How each direction is drawn: label and colour.
STYLE = {"plane": ("in the plane (2-D)", "k"), "first": ("first component alone (1-D)", "C0"),
         "second": ("second component alone (1-D)", "C1"),
         "rotd100": ("largest 1-D over the azimuths (RotD100)", "C3")}


def _number(value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        return np.nan


def studied(rows: list[dict]) -> list[dict]:
    """The rows of the pairs that slide in the plane, their numbers as floats."""
    out = []
    for row in rows:
        if row["status"] != "ok":
            continue
        out.append({key: (value if key in ("pair", "status", "event", "station", "first_component",
                                           "second_component", "near_fault") else _number(value))
                    for key, value in row.items()})
    return out


def typical_pairs(rows: list[dict], count: int) -> list[dict]:
    """``count`` pairs spread over the vector PGA: those nearest its quantiles 1/(count+1) … count/(count+1)."""
    ok = studied(rows)
    if not ok:
        return []
    pga = np.array([row["pga_plane"] for row in ok])
    chosen = []
    for q in np.arange(1, count + 1) / (count + 1):
        order = np.argsort(np.abs(pga - np.quantile(pga, q)))
        chosen.append(next(int(k) for k in order if int(k) not in chosen))
        if len(chosen) == len(ok):
            break
    return [ok[k] for k in sorted(chosen, key=lambda k: pga[k])]


def plot_energy_curves(cube: xr.Dataset, rows: list[dict], count: int, g: float) -> Figure:
    """E_df(μ) [J] of a few typical pairs: in the plane, each component alone, and the largest 1-D over the azimuths."""
    title = "Energy dissipated against μ: the block in the plane beside the 1-D block"
    chosen = typical_pairs(rows, count)
    if not chosen:
        return plot_not_drawn(title, "no station pair slides in the plane")
    ncols = min(2, len(chosen))
    nrows = -(-len(chosen) // ncols)
    figure, axes = new_figure(nrows, ncols, figsize=(5.2 * ncols, 3.6 * nrows + 0.8), squeeze=False)
    names = [str(name) for name in cube.pair_id.values]
    mu = cube.mu.values
    for ax, row in zip(axes.flat, chosen):
        k = names.index(row["pair"])
        curves = {"plane": cube.energy_dissipated.values[k, 0], "first": cube.energy_dissipated.values[k, 1],
                  "second": cube.energy_dissipated.values[k, 2], "rotd100": cube.energy_dissipated_rotd100.values[k]}
        for name, curve in curves.items():
            label, colour = STYLE[name]
            ax.plot(mu, curve, color=colour, lw=2.0 if name == "plane" else 1.2,
                    ls="--" if name == "rotd100" else "-", label=label)
        ax.axvline(row["mu_max_plane"], color="k", lw=0.8, ls=":")
        sliding = np.nonzero((cube.energy_dissipated.values[k, 0] > 0))[0]
        x_max = mu[min(sliding[-1] + 1, mu.size - 1)] if sliding.size else mu[-1]
        ax.set(xlim=(0, x_max), ylim=(0, None), xlabel="friction ratio μ [-]", ylabel="E_df [J]",
               title=f"{row['pair']} ({row['first_component']} + {row['second_component']})\n"
                     f"PGA of the vector {row['pga_plane'] / g:.2f} g; μ_max 2-D {row['mu_max_plane']:g}, "
                     f"worst azimuth {row['mu_max_worst_azimuth']:g}")
        ax.title.set_fontsize("small")
    for ax in list(axes.flat)[len(chosen):]:
        ax.set_axis_off()
    figure.suptitle(title + " (dotted: the plane's μ_max)")
    figure.legend(*axes.flat[0].get_legend_handles_labels(), loc="outside lower center", ncols=2, fontsize="small")
    return figure


def plot_ratio_distribution(rows: list[dict]) -> Figure:
    """Histogram and ECDF of R at the plane's μ_max: over the two components, and over every azimuth."""
    title = "R = peak displacement in the plane / largest 1-D peak, at the plane's μ_max"
    ok = studied(rows)
    if not ok:
        return plot_not_drawn(title, "no station pair slides in the plane")
    figure, (left, right) = new_figure(1, 2, figsize=(11.0, 4.4))
    for name, label, colour in (("ratio_components", "largest of the two components", "C0"),
                                ("ratio_azimuths", "largest over every azimuth", "C3")):
        values = np.array([row[name] for row in ok])
        values = values[np.isfinite(values)]
        q50, q90 = np.quantile(values, [0.5, 0.9])
        left.hist(values, bins=np.linspace(min(0.5, values.min()), max(2.5, values.max()), 41), color=colour,
                  alpha=0.45, label=f"{label}: median {q50:.2f}, 90 % {q90:.2f}")
        ordered = np.sort(values)
        right.step(ordered, np.arange(1, ordered.size + 1) / ordered.size, where="post", color=colour, label=label)
    for ax in (left, right):
        ax.axvline(1.0, color="k", lw=0.8, ls=":")
    left.set(xlabel="R [-]", ylabel="pairs", title=f"{len(ok)} station pairs")
    left.yaxis.set_major_locator(MaxNLocator(integer=True))  # counts of pairs
    right.set(xlabel="R [-]", ylabel="share of pairs with R ≤ x [-]", ylim=(0, 1.0),
              title="R > 1: the plane's stroke exceeds the 1-D one")
    right.axhline(0.9, color="0.5", lw=0.6)
    left.legend(fontsize="small", loc="upper right")
    right.legend(fontsize="small", loc="lower right")
    figure.suptitle(title)
    return figure


def plot_ratio_vs_mu(ratios: list[dict], pairs: int) -> Figure:
    """Median and 10-90 % band of R across the pairs against μ, and how many pairs slide in the plane."""
    title = "R against μ, across the station pairs"
    rows = [{key: _number(value) for key, value in row.items()} for row in ratios]
    if not rows or not any(np.isfinite(row.get("ratio_components_q50", np.nan)) for row in rows):
        return plot_not_drawn(title, "no μ has enough pairs sliding in the plane")
    figure, (top, bottom) = new_figure(2, 1, figsize=(9.0, 6.4), sharex=True, height_ratios=(3, 1))
    mu = np.array([row["mu"] for row in rows])
    for name, label, colour in (("ratio_components", "over the two components", "C0"),
                                ("ratio_azimuths", "over every azimuth", "C3")):
        q10, q50, q90 = (np.array([row[f"{name}_q{q}"] for row in rows]) for q in ("10", "50", "90"))
        top.plot(mu, q50, color=colour, lw=1.8, label=f"median, {label}")
        top.plot(mu, q90, color=colour, lw=1.0, ls="--", label=f"90th percentile, {label}")
        top.fill_between(mu, q10, q90, color=colour, alpha=0.12)
    top.axhline(1.0, color="k", lw=0.8, ls=":")
    sliding = np.array([row["pairs_sliding_in_plane"] for row in rows])
    # the μ range where at least a tenth of the pairs slide: beyond it the quantiles rest on a few pairs
    enough = sliding >= max(0.1 * pairs, 1)
    x_max = mu[enough][-1] if enough.any() else mu[-1]
    q90_shown = np.array([max(row["ratio_components_q90"], row["ratio_azimuths_q90"]) for row in rows])[mu <= x_max]
    y_max = min(4.0, 1.1 * np.nanmax(q90_shown)) if np.isfinite(q90_shown).any() else 4.0
    top.set(ylabel="R [-]", xlim=(0, x_max), ylim=(0, y_max),
            title=f"shaded: 10th to 90th percentile\nμ up to where 10 % of the {pairs} pairs still slide"
                  + ("; R axis cut at 4" if y_max == 4.0 else ""))
    top.legend(fontsize="small", **LEGEND_OUTSIDE)
    bottom.plot(mu, sliding, color="k", lw=1.2, label="slide in the plane")
    bottom.plot(mu, [row["pairs_only_plane_slides"] for row in rows], color="C2", lw=1.2,
                label="only the plane slides (R infinite)")
    bottom.set(xlabel="friction ratio μ [-]", ylabel="pairs", ylim=(0, pairs * 1.05))
    bottom.legend(fontsize="small", **LEGEND_OUTSIDE)
    figure.suptitle(title)
    return figure


def plot_ratio_vs_pga(rows: list[dict], near_fault_km: float, g: float) -> Figure:
    """R (over the components) at the plane's μ_max against the vector PGA and against rupture distance."""
    title = "R at the plane's μ_max against PGA and distance"
    ok = studied(rows)
    if not ok:
        return plot_not_drawn(title, "no station pair slides in the plane")
    figure, (left, right) = new_figure(1, 2, figsize=(11.0, 4.4), sharey=True)
    groups = (("True", f"near fault (≤ {near_fault_km:g} km)", "C3"), ("False", f"farther (> {near_fault_km:g} km)",
                                                                      "C0"), ("", "distance unknown", "0.5"))
    for key, label, colour in groups:
        members = [row for row in ok if str(row["near_fault"]) == key]
        if not members:
            continue
        ratio = [row["ratio_components"] for row in members]
        left.scatter([row["pga_plane"] / g for row in members], ratio, s=12, alpha=0.6, color=colour,
                     label=f"{label}: {len(members)}")
        right.scatter([row["rupture_distance"] for row in members], ratio, s=12, alpha=0.6, color=colour)
    for ax in (left, right):
        ax.axhline(1.0, color="k", lw=0.8, ls=":")
    left.set(xlabel="PGA of the vector, max |a(t)| [g]", ylabel="R over the two components [-]")
    right.set(xlabel="rupture distance [km]")
    left.legend(fontsize="small", loc="upper right")
    figure.suptitle(title)
    return figure


def plot_mu_max_2d_vs_1d(rows: list[dict]) -> Figure:
    """μ_max in the plane against μ_max of each component alone, and of the worst azimuth."""
    title = "μ_max in the plane against μ_max in 1-D"
    ok = studied(rows)
    if not ok:
        return plot_not_drawn(title, "no station pair slides in the plane")
    figure, (left, right) = new_figure(1, 2, figsize=(11.0, 4.8), sharey=True)
    plane = np.array([row["mu_max_plane"] for row in ok])
    top = np.nanmax([plane.max(), *[row["mu_max_worst_azimuth"] for row in ok]]) * 1.05
    larger = np.array([max(row["mu_max_first"], row["mu_max_second"]) for row in ok])
    smaller = np.array([min(row["mu_max_first"], row["mu_max_second"]) for row in ok])
    left.vlines(plane, smaller, larger, color="0.7", lw=0.6)
    left.scatter(plane, larger, s=10, color="C0", label="the component with the larger μ_max")
    left.scatter(plane, smaller, s=10, color="C1", label="the other component")
    right.scatter(plane, [row["mu_max_worst_azimuth"] for row in ok], s=10, color="C3",
                  label="worst azimuth (largest 1-D E_df,max)")
    right.scatter(plane, [row["mu_max_rotd50"] for row in ok], s=10, color="C2", marker="x",
                  label="median over the azimuths (RotD50)")
    for ax in (left, right):
        ax.plot([0, top], [0, top], color="k", lw=0.8, ls=":")
        ax.set(xlim=(0, top), ylim=(0, top), xlabel="μ_max in the plane [-]", aspect="equal")
        ax.legend(fontsize="small", loc="upper left")
    left.set(ylabel="μ_max in 1-D [-]", title="each component alone")
    right.set(title="the pair turned through every azimuth")
    figure.suptitle(title + f" ({len(ok)} station pairs; dotted: equal)")
    return figure


def plot_mu_max_vs_pga_rms(rows: list[dict], relations: list[dict]) -> Figure:
    """μ_max against PGA and against RMS acceleration, with the least-squares lines: plane beside components."""
    title = "μ_max against PGA and RMS acceleration, in the plane and in 1-D"
    ok = studied(rows)
    if not ok:
        return plot_not_drawn(title, "no station pair slides in the plane")
    fits = {(row["response"], row["predictor"]): row for row in relations}
    figure, axes = new_figure(1, 2, figsize=(11.0, 4.6), sharey=True)
    for ax, (measure, plane_x, label) in zip(axes, (("pga", "pga_plane", "PGA"), ("rms", "rms_plane", "RMS"))):
        x1 = [row[f"{measure}_{side}"] for row in ok for side in ("first", "second")]
        y1 = [row[f"mu_max_{side}"] for row in ok for side in ("first", "second")]
        ax.scatter(x1, y1, s=6, alpha=0.35, color="C0", label="1-D: each component against its own")
        ax.scatter([row[plane_x] for row in ok], [row["mu_max_plane"] for row in ok], s=10, alpha=0.7, color="k",
                   label="2-D: the plane against the vector's")
        for key, colour in ((("mu_max_components", measure), "C0"), (("mu_max_plane", plane_x), "k")):
            fit = fits.get(key)
            if fit and fit["status"] == "ok":
                slope, intercept = (float(fit[name]) for name in ("slope", "intercept"))
                xs = np.linspace(0, max(max(x1), max(row[plane_x] for row in ok)), 50)
                ax.plot(xs, slope * xs + intercept, color=colour, lw=1.5,
                        label=f"μ_max = {slope:.4f}·x {intercept:+.3f} [{float(fit['slope_low']):.4f}, "
                              f"{float(fit['slope_high']):.4f}], r = {float(fit['pearson_r']):.2f}")
        ax.set(xlabel=f"{label} [m/s²]", ylim=(0, None), xlim=(0, None))
        ax.legend(fontsize="x-small", loc="upper left")
    axes[0].set(ylabel="μ_max [-]")
    figure.suptitle(title + " (slope's 95 % bootstrap interval in brackets)")
    return figure


def plot_design_chart(design: dict, g: float) -> Figure:
    """The design chart in 2-D: μ_max of the plane against the vector PGA, band, ratio lines; design μ by PGA band."""
    title = "Design chart in 2-D"
    plane = design.get("plane", {})
    if plane.get("status") != "ok":
        return plot_not_drawn(title, plane.get("status") or design.get("status", "no pair"))
    figure, (left, right) = new_figure(1, 2, figsize=(12.0, 5.0), width_ratios=(3, 2))
    for side, colour, label in (("components", "C0", "1-D, each component (its own PGA)"),
                                ("plane", "k", "2-D, in the plane (PGA of the vector)")):
        data = design[side]
        if data.get("status") != "ok":
            continue
        x = np.array([p["x"] for p in data["points"]]) / g
        y = np.array([p["y"] for p in data["points"]])
        band = data["band"]
        bx = np.array(band["x"]) / g
        left.scatter(x, y, s=6 if side == "components" else 10, alpha=0.3 if side == "components" else 0.6,
                     color=colour)
        left.plot(bx, band["fitted"], color=colour, lw=1.6,
                  label=f"{label}: μ_max = {band['slope'] * g:.3f}·PGA/g {band['intercept']:+.3f}")
        left.fill_between(bx, band["low"], band["high"], color=colour, alpha=0.12)
        ratio = data["ratio_quantiles"]
        left.plot(bx, float(ratio["0.5"]) * bx, color=colour, lw=1.0, ls="--",
                  label=f"{label}: median μ_max·g/PGA = {float(ratio['0.5']):.3f}")
    left.set(xlabel="PGA [g]", ylabel="μ_max [-]", ylim=(0, None), xlim=(0, None),
             title=f"{design['plane']['n']} station pairs; shaded: 95 % prediction bands")
    left.legend(fontsize="x-small", loc="upper left")
    labels, plane_mu, line_mu = [], [], []
    bands = {row["pga_band"]: row for row in design["components"].get("coverage", [])}
    for row in design["plane"]["coverage"]:
        if row["status"] != "ok":
            continue
        labels.append(f"{'all pairs' if row['pga_band'] == 'all records' else row['pga_band']}\n({row['n']} pairs)")
        plane_mu.append(row["design_mu"])
        other = bands.get(row["pga_band"])
        line_mu.append(other["design_mu"] if other and other["status"] == "ok" else np.nan)
    if labels:
        position = np.arange(len(labels))
        right.bar(position - 0.2, plane_mu, 0.4, color="k", label="2-D (bands of the vector PGA)")
        right.bar(position + 0.2, line_mu, 0.4, color="C0", label="1-D (bands of each component's PGA)")
        right.set_xticks(position, labels, fontsize="small")
        right.set(ylabel="design μ [-]", title="μ reaching 90 % of E_df,max for the most pairs, by PGA band")
        right.title.set_fontsize("small")
        right.legend(fontsize="x-small", loc="upper left")
    else:
        right.set_axis_off()
    figure.suptitle(title)
    return figure
