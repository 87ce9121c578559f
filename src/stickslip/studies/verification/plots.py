"""Figures of the verification against SLAMMER's own results (``notebooks/slammer_verification.ipynb``).

Each function takes the rows of the tables that
:mod:`stickslip.studies.verification.slammer` wrote (as read from CSV: strings)
and its summary (JSON), and returns a :class:`matplotlib.figure.Figure`.
Displacements are in cm, SLAMMER's unit.  On the logarithmic axes a
displacement of zero cannot be drawn: it is drawn on the axis floor
(:data:`FLOOR`), with an open marker, and the legend says how many.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure

from stickslip.models.parameters import POLARITIES
from stickslip.reference.acceptance import AcceptanceRules
from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn

#: Where a displacement of zero [cm] is drawn on a logarithmic axis (below every non-zero one of the data).
FLOOR = 1e-4

#: Colour of each polarity.
POLARITY_COLOURS = {"normal": "C0", "inverse": "C1"}


def _rows(rows: Sequence[Mapping], scheme: str, polarity: str | None = None) -> list[Mapping]:
    return [row for row in rows if row["scheme"] == scheme and (polarity is None or row["polarity"] == polarity)]


def _values(rows: Sequence[Mapping], column: str) -> np.ndarray:
    return np.array([float(row[column]) for row in rows])


def _passes(rows: Sequence[Mapping]) -> np.ndarray:
    return np.array([str(row["passes"]) == "True" for row in rows], dtype=bool)


def _on_floor(values: np.ndarray) -> np.ndarray:
    return np.where(values > FLOOR, values, FLOOR)


def _pass_band(ax, rules: AcceptanceRules, top: float) -> None:
    """Shade the band of computed values that pass, around the line computed = expected, from :data:`FLOOR` to ``top``."""
    expected = np.geomspace(FLOOR, top, 400)
    tolerance = rules.tolerance(expected)
    ax.fill_between(expected, np.maximum(expected - tolerance, FLOOR), expected + tolerance, color="0.85",
                    label="pass band (pySLAMMER's tolerance)", zorder=0)
    ax.plot(expected, expected, color="0.4", lw=0.8, zorder=1, label="computed = SLAMMER 1.1")


def plot_scatter(rows: Sequence[Mapping], summary: Mapping) -> Figure:
    """Ours against SLAMMER 1.1's displacement [cm], one panel per scheme and polarity, log axes, with the pass band."""
    schemes = list(summary["schemes"])
    rules = AcceptanceRules(**summary["rules"])
    figure, axes = new_figure(len(schemes), len(POLARITIES), figsize=(11.0, 4.6 * len(schemes)), squeeze=False)
    top = 2.0 * max(max(_values(rows, "reference_displacement")), max(_values(rows, "computed_displacement")))
    for ax_row, scheme in zip(axes, schemes):
        for ax, polarity in zip(ax_row, POLARITIES):
            group = _rows(rows, scheme, polarity)
            reference, computed = _values(group, "reference_displacement"), _values(group, "computed_displacement")
            passes = _passes(group)
            zero = (reference <= FLOOR) | (computed <= FLOOR)
            _pass_band(ax, rules, top)
            colour = POLARITY_COLOURS[polarity]
            ax.scatter(reference[passes & ~zero], computed[passes & ~zero], s=14, color=colour, zorder=2,
                       label=f"within tolerance ({np.count_nonzero(passes)})")
            if np.any(zero):
                ax.scatter(_on_floor(reference[zero]), _on_floor(computed[zero]), s=30, facecolor="none",
                           edgecolor=colour, zorder=2, label=f"zero, drawn at {FLOOR:g} cm ({np.count_nonzero(zero)})")
            if np.any(~passes):
                ax.scatter(_on_floor(reference[~passes]), _on_floor(computed[~passes]), s=50, marker="x",
                           color="C3", zorder=3, label=f"beyond tolerance ({np.count_nonzero(~passes)})")
            stats = summary["schemes"][scheme]["polarities"][polarity]
            ax.set(xscale="log", yscale="log", xlim=(FLOOR / 2, top), ylim=(FLOOR / 2, top),
                   xlabel="SLAMMER 1.1: permanent displacement [cm]",
                   ylabel=f"stickslip, {scheme} scheme [cm]",
                   title=f"{scheme}, {polarity} polarity: {stats['passed']} of {stats['analyses']} pass\n"
                         f"slope {stats['slope']:.5f}, intercept {stats['intercept']:+.4f} cm, "
                         f"R² {stats['r_squared']:.6f}")
            ax.set_aspect("equal")
            ax.grid(True, which="major", lw=0.3)
            ax.legend(fontsize="small", loc="upper left")
    figure.suptitle("Ours against SLAMMER 1.1's own results (90 rigid analyses per polarity)")
    return figure


def plot_normalized_differences(rows: Sequence[Mapping], summary: Mapping) -> Figure:
    """(ours − SLAMMER 1.1) / tolerance against SLAMMER's displacement [cm]: within ±1 passes; one panel per scheme."""
    schemes = list(summary["schemes"])
    figure, axes = new_figure(1, len(schemes), figsize=(5.5 * len(schemes) + 2.0, 4.5), squeeze=False, sharey=True)
    top = 2.0 * max(_values(rows, "reference_displacement"))
    for ax, scheme in zip(axes[0], schemes):
        ax.axhspan(-1.0, 1.0, color="0.85", zorder=0, label="within tolerance")
        ax.axhline(0.0, color="0.4", lw=0.8)
        for polarity in POLARITIES:
            group = _rows(rows, scheme, polarity)
            ax.scatter(_on_floor(_values(group, "reference_displacement")), _values(group, "normalized_difference"),
                       s=14, color=POLARITY_COLOURS[polarity], label=f"{polarity} polarity", zorder=2)
        result = summary["schemes"][scheme]
        ax.set(xscale="log", xlim=(FLOOR / 2, top), xlabel="SLAMMER 1.1: permanent displacement [cm]",
               title=f"{scheme}: {result['passed']} of {result['analyses']} within tolerance")
        ax.grid(True, lw=0.3)
    axes[0][0].set_ylabel("(ours − SLAMMER 1.1) / tolerance [1]")
    axes[0][-1].legend(fontsize="small", **LEGEND_OUTSIDE)
    figure.suptitle(f"Each analysis against its own tolerance (a zero displacement drawn at {FLOOR:g} cm)")
    return figure


def plot_convergence(convergence: Sequence[Mapping], summary: Mapping) -> Figure:
    """|slammer scheme − exact| / tolerance against the time step [s], for every miss of the exact solver.

    Filled markers: the ``slammer`` scheme on the record resampled to dt/k;
    open markers at the record's own step: SLAMMER 1.1's own difference from
    the exact answer.  The grey line has slope 2 (second order).
    """
    cases = summary["convergence"]["cases"]
    if not cases:
        return plot_not_drawn("Convergence of SLAMMER's scheme to the exact answer",
                              "the exact solver is within tolerance of SLAMMER 1.1 on every analysis: "
                              "no miss to explain")
    figure, ax = new_figure(figsize=(11.0, 5.5))
    steps = []
    for index, case in enumerate(cases):
        mine = [row for row in convergence
                if row["analysis_id"] == case["analysis_id"] and row["polarity"] == case["polarity"]]
        step = _values(mine, "time_step")
        ratio = np.abs(_values(mine, "difference_from_exact")) / case["tolerance"]
        colour = f"C{index % 10}"
        row = mine[0]
        ax.plot(step, ratio, "o-", color=colour, lw=1.0,
                label=f"{row['earthquake']} {row['station']}, {float(row['slammer_target_pga']):g} g, "
                      f"k_y = {float(row['ky']):g}, {case['polarity']}")
        ax.plot(step[0], abs(case["reference_difference_from_exact"]) / case["tolerance"], "o", color=colour,
                markerfacecolor="none", markersize=10)
        steps.extend(step)
    span = np.array([min(steps), max(steps)])
    ax.plot(span, 0.3 * (span / span[1]) ** 2, color="0.5", lw=2.0, alpha=0.6, label="slope 2 (second order)")
    ax.plot([], [], "o", color="0.3", markerfacecolor="none", markersize=10,
            label="SLAMMER 1.1 (at the record's time step)")
    ax.axhline(1.0, color="C3", lw=1.0, ls="--", label="pySLAMMER's tolerance")
    ax.set(xscale="log", yscale="log", xlabel="time step of the resampled record [s]",
           ylabel="|slammer scheme − exact| / tolerance [1]")
    figure.suptitle(f"The exact solver's {len(cases)} miss{'es' if len(cases) != 1 else ''} beyond tolerance: "
                    "SLAMMER's scheme on finer resampled records converges to the exact answer")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize="small", **LEGEND_OUTSIDE)
    return figure


def plot_flexible_scatter(rows: Sequence[Mapping], summary: Mapping, scheme: str) -> Figure:
    """Ours (one scheme) against SLAMMER 1.1's flexible displacements [cm], one panel per group, log axes."""
    rules = AcceptanceRules(**summary["rules"])
    rows = [row for row in rows if row["scheme"] == scheme]
    groups = list(summary["schemes"][scheme])
    figure, axes = new_figure(2, 2, figsize=(11.0, 10.0), squeeze=False)
    top = 2.0 * max(max(_values(rows, "reference_displacement")), max(_values(rows, "computed_displacement")))
    for ax, group in zip(axes.flat, groups):
        model_name, soil_model = group.split(" ")
        mine = [row for row in rows if row["model"] == model_name and row["soil_model"] == soil_model]
        _pass_band(ax, rules, top)
        for polarity in POLARITIES:
            chosen = [row for row in mine if row["polarity"] == polarity]
            reference, computed = _values(chosen, "reference_displacement"), _values(chosen, "computed_displacement")
            passes = _passes(chosen)
            ax.scatter(_on_floor(reference[passes]), _on_floor(computed[passes]), s=6, color=POLARITY_COLOURS[polarity],
                       zorder=2, label=f"{polarity} polarity, within tolerance ({np.count_nonzero(passes)})")
            if np.any(~passes):
                ax.scatter(_on_floor(reference[~passes]), _on_floor(computed[~passes]), s=50, marker="x", color="C3",
                           zorder=3, label=f"{polarity}, beyond tolerance ({np.count_nonzero(~passes)})")
        stats = summary["schemes"][scheme][group]
        theirs = stats.get("pyslammer")
        versus = f"\n(pySLAMMER 0.2.3 on the same values: {theirs['passed']} pass)" if theirs else ""
        ax.set(xscale="log", yscale="log", xlim=(FLOOR / 2, top), ylim=(FLOOR / 2, top),
               xlabel="SLAMMER 1.1: permanent displacement [cm]", ylabel=f"stickslip, {scheme} scheme [cm]",
               title=f"{model_name}, {soil_model}: {stats['passed']} of {stats['analyses']} pass{versus}")
        ax.set_aspect("equal")
        ax.grid(True, which="major", lw=0.3)
        ax.legend(fontsize="x-small", loc="upper left")
    figure.suptitle(f"Flexible sliding block, {scheme} scheme: ours against SLAMMER 1.1's own results "
                    f"({len(rows):,} values; zero drawn at {FLOOR:g} cm)")
    return figure
