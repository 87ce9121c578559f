"""Figures of the vertical-motion study (``notebooks/vertical_study.ipynb``).

Each function takes rows of the tables :mod:`stickslip.studies.vertical.effect`
wrote (as read from CSV: strings) and returns a :class:`matplotlib.figure.Figure`.
Radii R in m (``inf``: the flat slider); accelerations in g; times in s; ratios [1].
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure

from stickslip.reports.plots import LEGEND_OUTSIDE, new_figure, plot_not_drawn

#: How each vertical variant is drawn: (label, filled marker?).
VARIANT_STYLE = {"recorded": ("vertical as recorded", True), "reversed": ("vertical reversed", False)}

#: Marker of each direction.
DIRECTION_MARKERS = {"H1": "o", "H2": "s", "plane": "D"}


def _number(text) -> float:
    return math.nan if text in (None, "") else float(text)


def radius_label(radius) -> str:
    """``flat (R = inf)`` or ``R = 2 m``."""
    value = float(radius)
    return "flat slider (R = ∞)" if math.isinf(value) else f"pendulum, R = {value:g} m"


def _radii(rows: Sequence[Mapping]) -> list[float]:
    return sorted({float(row["radius"]) for row in rows}, key=lambda value: (not math.isinf(value), value))


def _station_order(rows: Sequence[Mapping], liftoff: Sequence[Mapping]) -> list[str]:
    """The stations in the order of their vertical's largest downward acceleration (as recorded), weakest first."""
    down = {row["record"]: _number(row["vertical_down_peak"]) for row in liftoff if row["vertical"] == "recorded"}
    return sorted({row["record"] for row in rows}, key=lambda name: down.get(name, math.nan))


def plot_change_by_station(changes: Sequence[Mapping], liftoff: Sequence[Mapping], column: str, ylabel: str,
                           title: str) -> Figure:
    """``column`` of the change table per station (x, ordered by the vertical's downward peak), one panel per radius.

    Filled markers: the vertical as recorded; open: reversed; one marker per direction; the line at 1 (no change).
    """
    rows = [row for row in changes if not math.isnan(_number(row[column]))]
    if not rows:
        return plot_not_drawn(title, "no case slides both with and without the vertical")
    radii = _radii(rows)
    stations = _station_order(rows, liftoff)
    figure, axes = new_figure(len(radii), 1, figsize=(11.0, 2.4 + 2.1 * len(radii)), sharex=True, squeeze=False)
    position = {name: index for index, name in enumerate(stations)}
    directions = sorted({row["direction"] for row in rows}, key=list(DIRECTION_MARKERS).index)
    for ax, radius in zip(axes[:, 0], radii):
        for variant, (label, filled) in VARIANT_STYLE.items():
            for offset, direction in enumerate(directions):
                chosen = [row for row in rows if float(row["radius"]) == radius and row["vertical"] == variant
                          and row["direction"] == direction]
                if not chosen:
                    continue
                x = np.array([position[row["record"]] for row in chosen]) + 0.12 * (offset - (len(directions) - 1) / 2)
                colour = "C0" if variant == "recorded" else "C3"
                ax.plot(x, [_number(row[column]) for row in chosen], DIRECTION_MARKERS[direction], color=colour,
                        markerfacecolor=colour if filled else "none", linestyle="none",
                        label=f"{label}, {direction}")
        ax.axhline(1.0, color="0.4", linewidth=0.8)
        ax.set_title(radius_label(radius), fontsize="medium", loc="left")
        ax.set_ylabel(ylabel)
        ax.grid(True, axis="y", alpha=0.3)
    axes[0, 0].legend(**LEGEND_OUTSIDE, fontsize="small")
    axes[-1, 0].set_xticks(range(len(stations)), stations, rotation=40, ha="right", fontsize="small")
    axes[-1, 0].set_xlabel("station (ordered by the vertical's largest downward acceleration, as recorded)")
    figure.suptitle(title)
    return figure


def plot_liftoff(liftoff: Sequence[Mapping]) -> Figure:
    """Time lifted off [s] against the vertical's largest downward acceleration [g], each station and sense.

    The slider lifts off where g + a_v ≤ 0, that is where the ground's downward acceleration passes 1 g (the line).
    """
    if not liftoff:
        return plot_not_drawn("Lift-off time", "no station with its vertical")
    figure, ax = new_figure(figsize=(9.0, 5.0))
    for variant, (label, filled) in VARIANT_STYLE.items():
        chosen = [row for row in liftoff if row["vertical"] == variant]
        colour = "C0" if variant == "recorded" else "C3"
        ax.plot([_number(row["vertical_down_peak"]) for row in chosen], [_number(row["liftoff_time"]) for row in chosen],
                "o", color=colour, markerfacecolor=colour if filled else "none", linestyle="none", label=label)
        for row in chosen:
            if _number(row["liftoff_time"]) > 0.0:
                ax.annotate(row["record"], (_number(row["vertical_down_peak"]), _number(row["liftoff_time"])),
                            textcoords="offset points", xytext=(6, 4 if filled else -10), fontsize="x-small")
    ax.axvline(1.0, color="0.4", linewidth=0.8, linestyle="--", label="1 g: g + a_v = 0")
    ax.set_xlabel("largest downward vertical ground acceleration, −min a_v [g]")
    ax.set_ylabel("time lifted off (g + a_v ≤ 0) [s]")
    ax.set_title("Lift-off time per station against its vertical's downward peak")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    return figure


def plot_mu_max(cases: Sequence[Mapping]) -> Figure:
    """μ_max with the vertical against μ_max without it, one panel per radius: on the diagonal, no change."""
    without = {(row["direction"], row["radius"], row["record"]): _number(row["mu_max"]) for row in cases
               if row["vertical"] == "none"}
    rows = [row for row in cases if row["vertical"] != "none" and not math.isnan(_number(row["mu_max"]))]
    if not rows:
        return plot_not_drawn("mu_max with and without the vertical", "no case has a mu_max")
    radii = _radii(rows)
    figure, axes = new_figure(1, len(radii), figsize=(3.4 * len(radii) + 1.5, 4.0), squeeze=False)
    for ax, radius in zip(axes[0], radii):
        chosen = [row for row in rows if float(row["radius"]) == radius]
        x = [without[(row["direction"], row["radius"], row["record"])] for row in chosen]
        top = max(max(x), max(_number(row["mu_max"]) for row in chosen)) * 1.1
        ax.plot([0.0, top], [0.0, top], color="0.4", linewidth=0.8)
        for variant, (label, filled) in VARIANT_STYLE.items():
            colour = "C0" if variant == "recorded" else "C3"
            for direction, marker in DIRECTION_MARKERS.items():
                pick = [(xv, _number(row["mu_max"])) for xv, row in zip(x, chosen)
                        if row["vertical"] == variant and row["direction"] == direction]
                if pick:
                    ax.plot(*zip(*pick), marker, color=colour, markerfacecolor=colour if filled else "none",
                            linestyle="none", label=f"{label}, {direction}")
        ax.set_title(radius_label(radius), fontsize="medium")
        ax.set_xlabel("μ_max without the vertical [1]")
        ax.grid(True, alpha=0.3)
    axes[0, 0].set_ylabel("μ_max with the vertical [1]")
    axes[0, -1].legend(**LEGEND_OUTSIDE, fontsize="small")
    return figure
