"""Figures of a solved response.

Figures are built as :class:`matplotlib.figure.Figure` objects without pyplot, so
that no GUI backend is touched; saving renders PNG with the Agg canvas.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from stickslip.io import atomic_path
from stickslip.response import Response

#: Panels of :func:`plot_response`: (block attribute, base attribute, label, units).
PANELS = (
    ("absolute_displacement", "ground_displacement", "displacement", "m"),
    ("absolute_velocity", "ground_velocity", "velocity", "m/s"),
    ("absolute_acceleration", "ground_acceleration", "acceleration", "m/s²"),
)


def slip_intervals(response: Response) -> list[tuple[float, float]]:
    """(start, end) times [s] of the runs of samples where the block slides (phase ≠ 0)."""
    sliding = np.asarray(response.phase) != 0
    edges = np.flatnonzero(np.diff(np.concatenate([[False], sliding, [False]]).astype(np.int8)))
    time = response.time
    last = time.size - 1
    return [(float(time[start]), float(time[min(end, last)])) for start, end in zip(edges[::2], edges[1::2])]


def plot_response(response: Response, ax: Sequence[Axes] | None = None, path: str | Path | None = None) -> Figure:
    """Absolute displacement, velocity and acceleration of block and base (the paper's Fig. 3).

    Parameters
    ----------
    response:
        The solved case.
    ax:
        Three axes to draw into (displacement [m], velocity [m/s], acceleration [m/s²]);
        a new figure when ``None``.
    path:
        Where to save the figure as PNG (written atomically); not saved when ``None``.

    Returns
    -------
    matplotlib.figure.Figure
        The figure holding the axes.  Sliding intervals are shaded.
    """
    if ax is None:
        figure = Figure(figsize=(8.0, 7.5), layout="constrained")
        ax = figure.subplots(len(PANELS), 1, sharex=True)
    else:
        if len(ax) != len(PANELS):
            raise ValueError(f"plot_response needs {len(PANELS)} axes, got {len(ax)}")
        figure = ax[0].figure
    intervals = slip_intervals(response)
    for axes, (block, base, label, units) in zip(ax, PANELS):
        axes.plot(response.time, getattr(response, base), color="0.55", linewidth=0.8, label="base")
        axes.plot(response.time, getattr(response, block), color="C3", linewidth=0.9, label="block")
        for start, end in intervals:
            axes.axvspan(start, end, color="C0", alpha=0.15, linewidth=0)
        axes.set_ylabel(f"{label} [{units}]")
        axes.grid(True, linewidth=0.3)
    ax[0].legend(loc="upper right", fontsize="small")
    ax[0].set_title(
        f"{response.record_meta.record_id or 'record'}: mu = {response.mu:g}, {response.method} "
        f"(shaded: sliding, {response.n_slip_episodes} episodes)"
    )
    ax[-1].set_xlabel("time [s]")
    if path is not None:
        with atomic_path(path) as tmp:
            figure.savefig(tmp, format="png", dpi=120)
    return figure
