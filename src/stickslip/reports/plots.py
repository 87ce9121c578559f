"""Figures of a solved response.

Figures are built as :class:`matplotlib.figure.Figure` objects without pyplot, so
that no GUI backend is touched; saving renders PNG with the Agg canvas.
"""

from __future__ import annotations

import textwrap
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from stickslip.analysis import mu_max_on_grid, mu_max_on_grid_edge
from stickslip.plumbing.files import atomic_path
from stickslip.models.result import FLIGHT, STICK
from stickslip.records.components import component_label
from stickslip.reports.design_answer import format_number
from stickslip.units import energy_units, readable_units

if TYPE_CHECKING:  # annotations only
    import xarray as xr

#: Legend placement outside the axes, on the right, so that it never covers data.
LEGEND_OUTSIDE = {"loc": "upper left", "bbox_to_anchor": (1.02, 1.0), "borderaxespad": 0.0}

#: Label of the ring around a μ_max on the edge of its grid.
GRID_EDGE_LABEL = "μ_max on the grid edge (a bound)"


#: Panels of :func:`plot_response`: (block attribute, base attribute, label, units).
PANELS = (
    ("absolute_displacement", "ground_displacement", "displacement", "m"),
    ("absolute_velocity", "ground_velocity", "velocity", "m/s"),
    ("absolute_acceleration", "ground_acceleration", "acceleration", "m/s²"),
)


def slip_intervals(response) -> list[tuple[float, float]]:
    """(start, end) times [s] of the runs of samples where the block slides (phase ≠ 0)."""
    sliding = np.asarray(response.phase) != 0
    edges = np.flatnonzero(np.diff(np.concatenate([[False], sliding, [False]]).astype(np.int8)))
    time = response.time
    last = time.size - 1
    return [(float(time[start]), float(time[min(end, last)])) for start, end in zip(edges[::2], edges[1::2])]


def plot_response(response, ax: Sequence[Axes] | None = None, path: str | Path | None = None) -> Figure:
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
        f"{response.record_meta.record_id or 'record'}: {response.resistance.describe()}, {response.method} "
        f"(shaded: sliding, {response.n_slip_episodes} episodes)"
    )
    ax[-1].set_xlabel("time [s]")
    if path is not None:
        save_figure(figure, path)
    return figure


def axis_names(pair) -> tuple[str, str]:
    """What the two axes of a :class:`~stickslip.records.pair.RecordPair`'s plane are called.

    The first is the first component (its name: ``TAK-000``, ``0°``, else its
    record id: :func:`~stickslip.records.components.component_label`); the second is the second component, or, when the two are not a right
    angle apart and the second was resolved onto the axis a quarter turn from
    the first, "90° from LCN-260 towards LCN-345".
    """
    first, second = (component_label(record.meta.component or record.meta.record_id)
                     for record in (pair.first, pair.second))
    return first, second if pair.orthogonal else f"90° from {first} towards {second}"


def draw_path(ax, response, title: str) -> None:
    """On ``ax``: the path of a block (or a pendulum's slider) in the plane relative to the base [m] of a response
    in the plane (its ``relative_displacement`` (n, 2), ``peak_displacement`` and ``pair``), its start, end and
    farthest point."""
    path = response.relative_displacement
    distance = np.hypot(path[:, 0], path[:, 1])
    farthest = int(np.argmax(distance))
    ax.plot(path[:, 0], path[:, 1], color="k", lw=1.0)
    ax.plot(0.0, 0.0, "o", color="tab:green", label="start")
    ax.plot(*path[-1], "s", color="tab:red", label=f"end: {format_number(distance[-1])} m from the start")
    ax.plot(*path[farthest], "^", color="tab:purple",
            label=f"farthest at the samples: {format_number(distance[farthest])} m "
                  f"(peak {format_number(response.peak_displacement)} m)")
    reach = max(float(np.max(np.abs(path))), 1e-6) * 1.1
    first, second = axis_names(response.pair)
    ax.set(xlim=(-reach, reach), ylim=(-reach, reach), aspect="equal", title=title,
           xlabel=f"displacement along {first} [m]", ylabel=f"displacement along {second} [m]")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize="small", loc="upper left")


#: The energy ledger's terms as :func:`plot_case_response` draws them: name -> (label, colour).
LEDGER_LINES = {"energy_input": ("E_I, input", "0.3"), "energy_dissipated": ("E_df, dissipated by friction", "C3"),
                "kinetic_energy": ("E_k, kinetic", "C0"), "potential_energy": ("E_p, potential", "C2"),
                "energy_input_vertical": ("E_I,v, vertical motion's work", "C4"),
                "restoring_work": ("E_r, restoring force", "C2"),
                "body_force_work": ("W_b, body force", "C1"),
                "viscous_energy": ("E_zeta, the structure's damping", "C5"),
                "strain_energy": ("E_s, the structure's strain", "C1")}


def plot_case_response(result, title: str | None = None) -> Figure:
    """The response of one solved case of any model against time, as the result declares
    (:attr:`~stickslip.models.result.Result.response_figure`, :attr:`~stickslip.models.result.Result.response_panels`).

    ``"absolute"`` (the rigid block's) is drawn as :func:`plot_response` draws
    it (the paper's Fig. 3); declared panels by :func:`plot_declared_response`;
    ``"relative"`` and ``"path"`` as the displacement relative to the base [m]
    (in the plane, along each component), sliding and lift-off (a pendulum's
    flight) shaded where its history has a ``phase``, over its energy ledger
    [J] (each term of :meth:`~stickslip.models.result.Result.energy_ledger`;
    none drawn where the scheme keeps none); ``"path"`` with the path in the
    plane beside them (:func:`draw_path`).
    """
    if result.response_panels:
        return plot_declared_response(result, result.to_xarray(), title)
    if result.response_figure == "absolute":
        return plot_response(result)
    dataset = result.to_xarray()
    ledger = result.energy_ledger()
    time = dataset["time"].values
    displacement = dataset["relative_displacement"]
    in_plane = result.response_figure == "path"
    if in_plane:  # the path beside the histories
        figure = Figure(figsize=(13.0, 6.0), layout="constrained")
        panels = figure.subplot_mosaic([["displacement", "path"], ["energy", "path"]], width_ratios=[3, 2])
        axes = [panels["displacement"], panels["energy"]]
        axes[1].sharex(axes[0])
        axes[0].tick_params(labelbottom=False)
        draw_path(panels["path"], result, "path of the slider in the plane")
    else:
        figure, axes = new_figure(2 if ledger else 1, 1, figsize=(8.0, 6.0 if ledger else 3.5), sharex=True,
                                  squeeze=False)
        axes = axes[:, 0]
    if in_plane:  # one line along each component
        for index, (component, colour) in enumerate(zip(dataset["component"].values, ("C3", "C2"))):
            axes[0].plot(time, displacement.values[:, index], color=colour, linewidth=0.9,
                         label=f"along {component_label(str(component))}")
        axes[0].legend(fontsize="small", **LEGEND_OUTSIDE)
    else:
        axes[0].plot(time, displacement.values, color="C3", linewidth=0.9)
    shaded = []
    if "phase" in dataset:
        phase = dataset["phase"].values
        for label, where, colour in (("sliding", (phase != STICK) & (phase != FLIGHT), "C0"),
                                     ("lifted off", phase == FLIGHT, "C1")):
            edges = np.flatnonzero(np.diff(np.concatenate([[False], where, [False]]).astype(np.int8)))
            for start, end in zip(edges[::2], edges[1::2]):
                axes[0].axvspan(time[start], time[min(end, time.size - 1)], color=colour,
                                alpha=0.15 if colour == "C0" else 0.35, linewidth=0)
            shaded += [f"{label} ({'blue' if colour == 'C0' else 'orange'})"] if where.any() else []
    axes[0].set_ylabel("displacement relative\nto the base [m]")
    axes[0].grid(True, linewidth=0.3)
    title = title or result.describe() + (f"; shaded: {', '.join(shaded)}" if shaded else "")
    axes[0].set_title(title, fontsize="small")  # wrapped to the axes when saved (wrap_titles)
    if ledger:
        for name, (label, colour) in LEDGER_LINES.items():
            if name in ledger:
                axes[1].plot(time, ledger[name], color=colour, linewidth=0.9, label=label)
        mass = result.case().get("mass")  # None where the ledger is per kg already (a layer's)
        axes[1].set_ylabel(f"energy [{readable_units(energy_units(mass)) if mass is not None else 'J/kg'}]")
        axes[1].grid(True, linewidth=0.3)
        axes[1].legend(fontsize="small", **LEGEND_OUTSIDE)
    axes[-1].set_xlabel("time [s]")
    return figure


def _draw_ledger(axes, result, ledger, time) -> None:
    """The energy ledger's terms against time on ``axes`` (each of :data:`LEDGER_LINES` the ledger has, then the
    rest in the ledger's order)."""
    drawn = set()
    for name, (label, colour) in LEDGER_LINES.items():
        if name in ledger:
            axes.plot(time, ledger[name], color=colour, linewidth=0.9, label=label)
            drawn.add(name)
    for name in ledger:
        if name not in drawn and name != "balance_residual":
            axes.plot(time, ledger[name], linewidth=0.9, label=result.history_table[name][1])
    mass = result.case().get("mass")
    axes.set_ylabel(f"energy [{readable_units(energy_units(mass)) if mass is not None else 'J/kg'}]")
    axes.grid(True, linewidth=0.3)
    axes.legend(fontsize="small", **LEGEND_OUTSIDE)


def plot_declared_response(result, dataset: xr.Dataset, title: str | None = None) -> Figure:
    """The response a result declares (:attr:`~stickslip.models.result.Result.response_panels`): each panel's
    histories against time (one line per ``component``), its energy ledger below them, and its
    :attr:`~stickslip.models.result.Result.hysteresis` loop beside them."""
    panels = list(result.response_panels)
    ledger = result.energy_ledger()
    rows = len(panels) + (1 if ledger else 0)
    figure = Figure(figsize=(13.0 if result.hysteresis else 8.0, 2.2 * rows + 1.0), layout="constrained")
    layout = [[f"panel{row}", "loop"] if result.hysteresis else [f"panel{row}"] for row in range(rows)]
    axes_by_name = figure.subplot_mosaic(layout, width_ratios=[3, 2] if result.hysteresis else None)
    axes = [axes_by_name[f"panel{row}"] for row in range(rows)]
    time = dataset["time"].values
    for row, (label, names) in enumerate(panels):
        for name in names:
            values = dataset[name]
            if "component" in values.dims:
                for index, component in enumerate(dataset["component"].values):
                    axes[row].plot(time, values.values[:, index], linewidth=0.8, label=f"{component}")
                axes[row].legend(fontsize="small", title=dataset["component"].attrs.get("long_name"),
                                 title_fontsize="small", **LEGEND_OUTSIDE)
            else:
                axes[row].plot(time, values.values, color="C3", linewidth=0.9)
        axes[row].set_ylabel(label)
        axes[row].grid(True, linewidth=0.3)
        if row:
            axes[row].sharex(axes[0])
    if ledger:
        _draw_ledger(axes[-1], result, ledger, time)
    for row in range(rows - 1):
        axes[row].tick_params(labelbottom=False)
    axes[-1].set_xlabel("time [s]")
    axes[0].set_title(title or result.describe(), fontsize="small")
    if result.hysteresis:
        x_name, y_name, loop_title = result.hysteresis
        loop = axes_by_name["loop"]
        loop.plot(dataset[x_name].values, dataset[y_name].values, color="C0", linewidth=0.7)
        loop.set_xlabel(f"{x_name.replace('_', ' ')} [{result.history_table[x_name][0]}]")
        loop.set_ylabel(f"{y_name.replace('_', ' ')} [{result.history_table[y_name][0]}]")
        loop.set_title(loop_title, fontsize="small")
        loop.grid(True, linewidth=0.3)
    return figure


# ---------------------------------------------------------------------------
# Report figures (the notebooks under notebooks/ call these; no physics here,
# only drawing of values the library or the workflow computed).
# ---------------------------------------------------------------------------

#: Colour of the significant duration [t5, t95] (the paper's Fig. 17 draws it in red).
SIGNIFICANT_COLOR = "C3"


def new_figure(nrows: int = 1, ncols: int = 1, figsize: tuple[float, float] = (7.0, 4.5), **kwargs):
    """A pyplot-free :class:`Figure` with constrained layout and its axes (as ``Figure.subplots``)."""
    figure = Figure(figsize=figsize, layout="constrained")
    return figure, figure.subplots(nrows, ncols, **kwargs)


def save_figure(figure: Figure, path: str | Path, dpi: int = 120) -> Path:
    """Save ``figure`` as PNG to ``path`` atomically (the Agg canvas; folders created), its titles wrapped to fit
    (:func:`wrap_titles`); return the path."""
    path = Path(path)
    wrap_titles(figure)
    with atomic_path(path) as tmp:
        figure.savefig(tmp, format="png", dpi=dpi)
    return path


def wrap_titles(figure: Figure, attempts: int = 6) -> Figure:
    """Wrap each axes title to the width of its axes, and the figure's title to the figure's, as drawn.

    A title wider than its axes (a record id before a long description, beside
    a legend outside the axes) would be clipped at both ends of the figure.
    Widths are measured with the Agg renderer after the layout; each line too
    wide is wrapped at spaces, and the layout is redone until every title
    fits (a word longer than the width is broken).  Returns ``figure``.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    if not isinstance(figure.canvas, FigureCanvasAgg):
        FigureCanvasAgg(figure)
    for _ in range(attempts):
        renderer = figure.canvas.get_renderer()
        figure.draw(renderer)  # lays the figure out, so that axes and titles have their drawn widths
        changed = False
        for text, width in _titles_and_widths(figure):
            if text.get_window_extent(renderer).width <= width:
                continue
            lines = text.get_text().splitlines()
            per_char = text.get_window_extent(renderer).width / max(len(line) for line in lines)
            characters = max(int(width / per_char * 0.97) - 1, 8)
            text.set_text("\n".join(textwrap.fill(line, characters, break_on_hyphens=False) for line in lines))
            changed = True
        if not changed:
            break
    return figure


def _titles_and_widths(figure: Figure) -> list[tuple]:
    """Every non-empty title of ``figure``, with the width [pixels] it must fit in: its axes', or the figure's."""
    titles = [(title, axes.bbox.width) for axes in figure.axes if axes.get_visible()
              for title in (axes.title, axes._left_title, axes._right_title) if title.get_text()]
    if figure._suptitle is not None and figure._suptitle.get_text():
        titles.append((figure._suptitle, figure.bbox.width))
    return titles


def plot_significant_acceleration(
    ax: Axes, time: np.ndarray, acceleration: np.ndarray, t5: float, t95: float, title: str | None = None
) -> Axes:
    """Ground acceleration [m/s²] against time [s], the part inside [t5, t95] [s] in red (the paper's Fig. 17)."""
    time = np.asarray(time)
    acceleration = np.asarray(acceleration)
    inside = (time >= t5) & (time <= t95)
    ax.plot(time, acceleration, color="0.45", linewidth=0.6, label="record")
    ax.plot(
        np.where(inside, time, np.nan),
        np.where(inside, acceleration, np.nan),
        color=SIGNIFICANT_COLOR,
        linewidth=0.6,
        label=f"significant duration {t5:.2f}–{t95:.2f} s",
    )
    ax.axhline(0.0, color="0.2", linewidth=0.4)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("acceleration [m/s²]")
    ax.grid(True, linewidth=0.3)
    if title:
        ax.set_title(title, fontsize="medium")
    return ax


def plot_husid(ax: Axes, time: np.ndarray, husid: np.ndarray, t5: float, t95: float) -> Axes:
    """Husid curve H(t) (cumulative Arias intensity / Arias intensity, dimensionless) against time [s], t5 and t95 marked."""
    ax.plot(time, husid, color="C0", linewidth=1.0, label="H(t)")
    ax.axvspan(t5, t95, color=SIGNIFICANT_COLOR, alpha=0.12, linewidth=0, label="[t5, t95]")
    for level in (0.05, 0.95):
        ax.axhline(level, color="0.5", linewidth=0.5, linestyle=":")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("Husid curve H [-]")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(True, linewidth=0.3)
    ax.legend(loc="lower right", fontsize="small")
    return ax


def plot_record_overview(time: np.ndarray, acceleration: np.ndarray, husid: np.ndarray, t5: float, t95: float,
                         title: str = "") -> Figure:
    """Two panels: acceleration [m/s²] with [t5, t95] in red, and the Husid curve (for one record's report)."""
    figure, (top, bottom) = new_figure(2, 1, figsize=(8.0, 6.0), sharex=True)
    plot_significant_acceleration(top, time, acceleration, t5, t95, title=title)
    top.set_xlabel("")
    top.legend(loc="upper right", fontsize="small")
    plot_husid(bottom, time, husid, t5, t95)
    return figure


class NotDrawn(Figure):
    """A figure that could not be drawn, and why: what a report shows as one sentence instead of an empty box.

    The workflow declares every figure of a page as a file, so the figure
    itself is saved too (the index's thumbnails show it); a report page shows
    :attr:`sentence` in its place (:meth:`stickslip.reports.notebook_helpers.FigureFolder.show`).
    """

    def __init__(self, title: str, reason: str, **kwargs):
        super().__init__(**kwargs)
        self.title, self.reason = title, reason

    @property
    def sentence(self) -> str:
        """``Not drawn: <reason>.``, on one line."""
        reason = "; ".join(line.strip() for line in self.reason.splitlines() if line.strip())
        return f"Not drawn: {reason}".rstrip(".") + "."


def plot_not_drawn(title: str, reason: str) -> NotDrawn:
    """A figure that says why it could not be drawn (for example: its records are missing); see :class:`NotDrawn`.

    The reason is wrapped to the figure's width, a long address broken where it must be.
    """
    lines = textwrap.wrap(f"Not drawn: {reason}", width=95, break_long_words=True, break_on_hyphens=False)
    figure = NotDrawn(title, reason, figsize=(7.0, 1.0 + 0.2 * len(lines)), layout="constrained")
    ax = figure.subplots()
    ax.set_axis_off()
    ax.set_title(title)
    ax.text(0.5, 0.5, "\n".join(lines), transform=ax.transAxes, ha="center", va="center", fontsize="small")
    return figure


def plot_records_grid(records: Sequence[dict], ncols: int = 2) -> Figure:
    """The paper's Fig. 17: one panel per record, acceleration [m/s²] with [t5, t95] [s] in red.

    ``records`` holds dicts with keys ``time`` [s], ``acceleration`` [m/s²],
    ``t5``, ``t95`` [s] and ``title``.
    """
    nrows = max(1, -(-len(records) // ncols))
    figure, axes = new_figure(nrows, ncols, figsize=(5.0 * ncols, 2.3 * nrows), squeeze=False)
    flat = axes.ravel()
    for ax, item in zip(flat, records):
        plot_significant_acceleration(ax, item["time"], item["acceleration"], item["t5"], item["t95"], item["title"])
        ax.legend(loc="upper right", fontsize="x-small")
    for ax in flat[len(records):]:
        ax.set_visible(False)
    return figure


def plot_energy_vs_mu(
    ax: Axes,
    mu: np.ndarray,
    energy: np.ndarray,
    label: str = "",
    color: str | None = None,
    points_mu: np.ndarray | None = None,
    points_energy: np.ndarray | None = None,
    mu_max: float | None = None,
) -> Axes:
    """E_df [J] against the friction ratio μ [-] (the paper's Fig. 21).

    ``mu``/``energy`` are drawn as a line (a fine grid), ``points_mu``/``points_energy``
    as markers (the paper's grid), and ``mu_max`` as a vertical dashed line.
    """
    (line,) = ax.plot(mu, energy, linewidth=1.1, color=color, label=label)
    color = line.get_color()
    if points_mu is not None and points_energy is not None:
        ax.plot(points_mu, points_energy, "o", color=color, markersize=4)
    if mu_max is not None:
        ax.axvline(mu_max, color=color, linewidth=0.8, linestyle="--")
    ax.set_xlabel("friction ratio μ [-]")
    ax.set_ylabel("energy dissipated by friction E_df [J]")
    ax.grid(True, linewidth=0.3)
    return ax


def plot_energy_sweeps(grid: xr.Dataset, fine: xr.Dataset | None = None) -> Figure:
    """The paper's Fig. 21 from sweep cubes: E_df [J] vs μ [-] per record.

    Markers: the cube ``grid`` (the paper's μ grid), with its μ_max (largest E_df on that
    grid) dashed; line: ``fine`` (a fine μ grid) when given, else the grid itself.  A μ_max
    on the first or last μ of the grid is ringed and marked "grid edge" in the legend, which
    stands outside the axes, clear of the curves.
    """
    figure, ax = new_figure(figsize=(10.5, 5.5))
    for k, record in enumerate(grid["record"].values):
        points = grid["energy_dissipated"].sel(record=record)
        curve = fine["energy_dissipated"].sel(record=record) if fine is not None else points
        mu_max = float(mu_max_on_grid(points))
        edge = mu_max_on_grid_edge(points)
        label = f"{record} (μ_max = {mu_max:.3f}{', grid edge' if edge else ''})"
        plot_energy_vs_mu(
            ax, curve["mu"].values, curve.values, label=label, color=f"C{k % 10}",
            points_mu=points["mu"].values, points_energy=points.values, mu_max=mu_max,
        )
        if edge:
            _ring_grid_edge(ax, [mu_max], [float(points.max())])
    ax.legend(fontsize="small", title="markers: paper grid; line: fine grid; dashed: μ_max", title_fontsize="small",
              **LEGEND_OUTSIDE)
    ax.set_title("E_df against μ (the paper's Fig. 21)")
    return figure


def _ring_grid_edge(ax: Axes, x, y, label: str | None = None) -> None:
    """Ring the points (x, y) whose μ_max is on the edge of the μ grid (open red circles)."""
    ax.plot(x, y, "o", markersize=13, markerfacecolor="none", markeredgecolor="red", markeredgewidth=1.3,
            label=label, zorder=5)


def plot_mu_max_fit(ax: Axes, relation: dict, label: str, color: str = "C0", marker: str = "o",
                    show_fit: bool = True) -> Axes:
    """Points of μ_max [-] against an intensity measure, with the linear fit and its bootstrap band.

    ``relation`` is one block of ``results/fits.json`` (``points`` with ``x``, ``y``, ``label``;
    ``linear_fit`` with ``slope``, ``intercept``, ``r``, ``band_x``, ``band_low``, ``band_high``).
    """
    points = relation["points"]
    x = np.array([p["x"] for p in points], dtype=float)
    y = np.array([p["y"] for p in points], dtype=float)
    ax.plot(x, y, marker, color=color, label=label, markersize=6, markerfacecolor="none" if marker != "o" else color)
    fit = relation.get("linear_fit")
    if show_fit and fit:
        line_x = np.array([x.min(), x.max()])
        ax.plot(line_x, fit["intercept"] + fit["slope"] * line_x, "--", color=color, linewidth=1.0,
                label=f"fit: μ = {fit['intercept']:.4f} {fit['slope']:+.4f}·x (r = {fit['r']:.2f})")
        if fit.get("band_x"):
            ax.fill_between(fit["band_x"], fit["band_low"], fit["band_high"], color=color, alpha=0.15, linewidth=0,
                            label="bootstrap band")
    ax.grid(True, linewidth=0.3)
    ax.set_ylabel("μ_max [-]")
    return ax


def annotate_points(ax: Axes, relation: dict, fontsize: str = "x-small") -> None:
    """Write each point's label (the record id) beside it, alternately above and below (in order of x).

    Labels of the points in the right fifth of the range go to their left, so they stay inside the axes.
    """
    points = sorted(relation["points"], key=lambda p: p["x"])
    if not points:
        return
    low, high = points[0]["x"], points[-1]["x"]
    for k, p in enumerate(points):
        leftward = high > low and p["x"] > high - 0.2 * (high - low)
        ax.annotate(p["label"], (p["x"], p["y"]), textcoords="offset points",
                    xytext=(-4 if leftward else 4, 5 if k % 2 == 0 else -11), ha="right" if leftward else "left",
                    fontsize=fontsize)


def plot_mu_max_relation(fits: dict, grid_key: str, continuous_key: str | None, xlabel: str, title: str) -> Figure:
    """The paper's Fig. 22 / 23 from ``fits.json``: grid μ_max (filled) and continuous μ_max (open), with fits.

    The legend stands outside the axes, clear of the points and bands.
    """
    figure, ax = new_figure(figsize=(10.0, 5.0))
    plot_mu_max_fit(ax, fits[grid_key], "μ_max on the paper grid", color="C0", marker="o")
    if continuous_key and continuous_key in fits:
        plot_mu_max_fit(ax, fits[continuous_key], "μ_max continuous", color="C1", marker="s")
    annotate_points(ax, fits[grid_key])
    status = fits[grid_key].get("status", "ok")
    if status != "ok":  # too few records for a fit: say so where the line would be
        ax.text(0.5, 0.5, f"no fit: {status}", transform=ax.transAxes, ha="center", va="center", wrap=True)
    ax.set_xlabel(xlabel)
    ax.legend(fontsize="small", **LEGEND_OUTSIDE)
    figure.suptitle(title)  # over the whole figure: the axes are narrower than the title
    return figure


def plot_scaling(rows: Sequence[dict], x: str, xlabel: str, title: str) -> Figure:
    """The paper's Figs. 24–25 from ``table8_results.csv`` rows: μ_max [-] against ``x`` for each record.

    Rows need ``record``, ``status``, ``mu_max`` and the column ``x`` (as strings or numbers);
    rows whose status is not ``ok`` or whose values are empty are skipped.  A row whose
    ``mu_max_on_grid_edge`` is true (``"True"`` in the CSV) is ringed in red.  The legend
    stands outside the axes, clear of the data.
    """
    figure, ax = new_figure(figsize=(10.0, 5.0))
    by_record: dict[str, list[tuple[float, float]]] = {}
    edge_points: list[tuple[float, float]] = []
    for row in rows:
        if row.get("status", "ok") != "ok" or row.get(x) in ("", None) or row.get("mu_max") in ("", None):
            continue
        point = (float(row[x]), float(row["mu_max"]))
        by_record.setdefault(row["record"], []).append(point)
        if str(row.get("mu_max_on_grid_edge", "")).lower() == "true":
            edge_points.append(point)
    for k, (record, values) in enumerate(by_record.items()):
        values.sort()
        ax.plot(*zip(*values), "-", marker="osD^vP"[k % 6], color=f"C{k % 10}", label=record, markersize=5,
                linewidth=1.0, markerfacecolor="none" if k % 2 else f"C{k % 10}")
    if edge_points:
        _ring_grid_edge(ax, *zip(*edge_points), label=GRID_EDGE_LABEL)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("μ_max [-]")
    ax.grid(True, linewidth=0.3)
    ax.legend(fontsize="small", **LEGEND_OUTSIDE)
    figure.suptitle(title)  # over the whole figure: the axes are narrower than the title
    return figure


#: Legend labels of the time-step study's solvers.
SOLVER_LABELS = {
    "exact": "exact (event-driven)",
    "newmark": "Newmark, default reading of Algorithm 1",
    "newmark_literal": "Newmark, literal Algorithm 1",
}


def plot_timestep(cube: xr.Dataset, mu: float, t_start: float, t_end: float,
                  solvers: Sequence[str] = ("newmark_literal", "newmark", "exact")) -> Figure:
    """The paper's Figs. 18–20: block absolute acceleration [m/s²] at Δt = each ``time_step`` of ``cube``.

    One panel per integration step (the paper's (a) 1 ms, (b) 5 ms); each panel draws
    ``solvers`` (both readings of Newmark under the exact solution, dashed) over [t_start, t_end] [s]
    at friction ratio ``mu`` (the nearest in the cube).  The cube is ``results/sweeps/timestep_{id}.nc``.
    """
    window = cube.sel(mu=mu, method="nearest").sel(time=slice(t_start, t_end))
    steps = window["time_step"].values
    figure, axes = new_figure(len(steps), 1, figsize=(8.0, 2.8 * len(steps)), sharex=True, squeeze=False)
    styles = {"exact": dict(color="0.1", linewidth=0.8, linestyle="--"), "newmark": dict(color="C0", linewidth=0.9),
              "newmark_literal": dict(color="C2", linewidth=0.8)}
    for ax, step in zip(axes[:, 0], steps):
        panel = window.sel(time_step=step)
        for solver in solvers:
            if solver not in panel["solver"].values:
                continue
            acc = panel["block_acceleration"].sel(solver=solver)
            # A solver run at Δt has values only on its own samples; the rest are NaN.
            keep = np.isfinite(acc.values)
            ax.plot(panel["time"].values[keep], acc.values[keep], label=SOLVER_LABELS.get(solver, solver),
                    **styles.get(solver, {}))
        ax.set_ylabel("block acceleration [m/s²]")
        ax.set_title(f"{cube.attrs.get('record_id', '')}: Δt = {step * 1000:g} ms, μ = {float(window['mu']):.3f}",
                     fontsize="medium")
        ax.grid(True, linewidth=0.3)
        ax.legend(loc="upper right", fontsize="x-small")
    axes[-1, 0].set_xlabel("time [s]")
    return figure
