"""The friction pendulum's design chart as a figure: displacement demand and base shear over R × μ.

:func:`plot_design_chart` draws, from :func:`stickslip.models.pendulum.chart.chart_statistics`,
filled contours of the displacement demand [m] and labelled contour lines of
the peak base shear coefficient V/W [1] over the surface radius R [m] (with
its period 2π√(R/g) [s] on a second axis) and the friction ratio μ [1]: for
one record, its own; over several, one panel each for the median and the 84th
percentile, and the mean over seven or more (what design codes average).  A
designer reads off the (R, μ) pairs that keep the displacement within the
isolator's capacity and V/W within what the structure above takes.

The levels are round numbers, the same for every chart unless given
(:class:`ChartLevels`): two charts a user compares, with and without the
vertical or of two stations, draw the same values in the same colours.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from matplotlib.colors import BoundaryNorm
from matplotlib.figure import Figure
from matplotlib.ticker import FuncFormatter

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.models.pendulum import MEAN_RECORDS
from stickslip.reports.plots import plot_not_drawn


#: The design chart shows μ up to where the displacement demand falls below this share of its largest value.
DEMAND_SHOWN = 0.02

#: The displacement demand's levels [m] by default, where the chart's colours change: round, and one colour per band
#: whatever the chart (past the last, the last band's colour).
DISPLACEMENT_LEVELS = (0.0, 0.025, 0.05, 0.075, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.25, 1.5, 2.0,
                       2.5, 3.0, 4.0, 5.0)

#: The peak base shear coefficient V/W's levels [1] by default, drawn as labelled lines where the chart reaches them.
SHEAR_LEVELS = (0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.25, 1.5, 1.75, 2.0,
                2.5, 3.0, 4.0, 5.0)


@dataclass(frozen=True)
class ChartLevels:
    """The levels of a design chart: the displacement demand's bands [m] and the V/W lines [1], each increasing.

    :meth:`every` makes them from two steps (``--chart-levels 0.1,0.05``);
    the default is :data:`DISPLACEMENT_LEVELS` and :data:`SHEAR_LEVELS`.
    """

    displacement: tuple[float, ...] = DISPLACEMENT_LEVELS
    shear: tuple[float, ...] = SHEAR_LEVELS
    steps: tuple[float, float] | None = None

    @classmethod
    def every(cls, displacement_step: float, shear_step: float) -> ChartLevels:
        """Levels at every multiple of ``displacement_step`` [m] and of ``shear_step`` [1], from zero; a step that is
        not a positive number raises :class:`~stickslip.errors.StickslipError`."""
        for step, what in ((displacement_step, "displacement demand step [m]"), (shear_step, "V/W step")):
            if not (math.isfinite(step) and step > 0):
                raise StickslipError(f"the design chart's {what} must be a positive number, not {step!r}")
        return cls((), (), (float(displacement_step), float(shear_step)))

    def bands(self, largest: float) -> tuple[np.ndarray, np.ndarray, bool]:
        """The displacement levels [m] that cover 0 to ``largest`` [m], the levels that fix the colours, and whether
        ``largest`` lies past the last level (its band is then the last band's colour)."""
        if self.steps is not None:
            levels = _multiples(self.steps[0], 0.0, max(largest, self.steps[0]), cover=True)
            return levels, levels, False
        ladder = np.asarray(self.displacement, dtype=float)
        past = largest > ladder[-1]
        covered = int(np.searchsorted(ladder, largest, side="left")) + 1
        return ladder[:max(min(covered, ladder.size), 2)], ladder, past

    def lines(self, lowest: float, largest: float) -> np.ndarray:
        """The V/W levels [1] between ``lowest`` and ``largest``: those the chart draws."""
        if self.steps is not None:
            return _multiples(self.steps[1], lowest, largest)
        ladder = np.asarray(self.shear, dtype=float)
        return ladder[(ladder >= lowest) & (ladder <= largest)]


def _multiples(step: float, lowest: float, largest: float, cover: bool = False) -> np.ndarray:
    """The multiples of ``step`` from ``lowest`` to ``largest`` (with ``cover``, up to the first at or past it),
    rounded to the step's own digits."""
    first, last = math.ceil(lowest / step - 1e-9), (math.ceil if cover else math.floor)(largest / step + (
        -1e-9 if cover else 1e-9))
    digits = max(0, 10 - int(math.floor(math.log10(step))))
    return np.round(np.arange(first, last + 1) * step, digits)


def focused_mu_limit(mu: np.ndarray, displacement: np.ndarray) -> float:
    """The largest μ [1] the design chart shows: the grid's next μ after the last one where, at some radius, the
    displacement demand (``displacement`` [m], shape (μ, radius)) is at least :data:`DEMAND_SHOWN` of its largest.

    Past it the block hardly slides and the chart would be one flat colour; a grid without such a μ shows whole.
    """
    shown = np.nonzero((displacement >= DEMAND_SHOWN * np.nanmax(displacement)).any(axis=1))[0]
    if shown.size == 0 or not np.nanmax(displacement) > 0.0:
        return float(mu[-1])
    return float(mu[min(shown[-1] + 1, mu.size - 1)])


def friction_axis_label(attrs) -> str:
    """The friction axis of a chart with the attributes ``attrs``: μ, or the velocity law's μ_fast with its shape."""
    if attrs.get("friction_law") != "velocity_dependent":
        return "friction ratio μ [-]"
    ratio, rate = float(attrs["mu_slow_ratio"]), float(attrs["rate"])
    return f"friction ratio μ_fast [-] (μ_slow = {ratio:g} μ_fast, a = {rate:g} s/m)"


def plot_design_chart(statistics, g: float = STANDARD_GRAVITY, title: str | None = None,
                      levels: ChartLevels | None = None, shown: tuple[str, ...] | None = None) -> Figure:
    """Displacement demand [m] (filled contours) and V/W [1] (labelled lines) over R [m] × μ [1], one panel per
    statistic over the records.

    ``statistics`` is :func:`~stickslip.models.pendulum.chart.chart_statistics` of a design chart: one record gets
    one panel (its own demands); several, one panel for each of its statistics (the median, the 84th percentile and,
    over :data:`~stickslip.models.pendulum.chart.MEAN_RECORDS` or more, the mean), or those named in ``shown``.
    The panels share ``levels`` (default :class:`ChartLevels`: round, the same for every chart), one colour bar and
    the μ range, up to where the displacement demand fades (:func:`focused_mu_limit`; the figure says so below the
    panels).  ``g`` [m/s²] converts R to the period on the top axis.  A chart with fewer than two radii or two
    friction ratios cannot be contoured and says so.
    """
    records = int(statistics.attrs.get("records", 0))
    motions = statistics.attrs.get("motions", "records")
    title = title or "Friction pendulum design chart"
    radius, mu = statistics.radius.values, statistics.mu.values
    if radius.size < 2 or mu.size < 2:
        return plot_not_drawn(title, f"{radius.size} radius and {mu.size} friction ratio(s): contours need at least "
                                     "two of each")
    levels = levels or ChartLevels()
    names = [str(name) for name in statistics.statistic.values]
    names = names[:1] if records == 1 else [name for name in names if shown is None or name in shown]
    displacement = statistics.peak_relative_displacement.sel(statistic=names).values.transpose(0, 2, 1)  # (s, mu, R)
    shear = statistics.peak_base_shear.sel(statistic=names).values.transpose(0, 2, 1)
    top = focused_mu_limit(mu, np.nanmax(displacement, axis=0))
    inside = mu <= top
    mu, displacement, shear = mu[inside], displacement[:, inside], shear[:, inside]
    bands, ladder, past = levels.bands(float(np.nanmax(displacement)))
    norm = BoundaryNorm(ladder, ncolors=256, extend="max" if past else "neither")
    lines = levels.lines(float(np.nanmin(shear)), float(np.nanmax(shear)))
    figure = Figure(figsize=(1.6 + 5.2 * len(names), 5.6), layout="constrained")
    axes = np.atleast_1d(figure.subplots(1, len(names), sharey=True, squeeze=False)[0])
    for index, (ax, name) in enumerate(zip(axes, names)):
        filled = ax.contourf(radius, mu, displacement[index], levels=bands, cmap="viridis", norm=norm,
                             extend="max" if past else "neither")
        if lines.size:
            contour = ax.contour(radius, mu, shear[index], levels=lines, colors="white", linewidths=1.0)
            _label_every_level(ax, contour)
        ax.set_xlabel("radius R of the sliding surface [m]")
        ax.set_title(f"{name} over {records} {motions}" if records != 1 else "", fontsize="medium")
        period = ax.secondary_xaxis("top", functions=(lambda r: 2 * np.pi * np.sqrt(np.maximum(r, 0.0) / g),
                                                      lambda t: g * (np.asarray(t) / (2 * math.pi)) ** 2))
        period.set_xlabel("period 2π√(R/g) [s]")
    axes[0].set_ylabel(friction_axis_label(statistics.attrs))
    which = "" if records == 1 else f", {names[0]}" if len(names) == 1 else ""
    bar = figure.colorbar(filled, ax=list(axes), label=f"displacement demand{which} [m]", ticks=bands,
                          format=FuncFormatter(lambda value, _: f"{value:g}"))
    bar.ax.tick_params(labelsize="small")
    notes = [] if records == 1 or records >= MEAN_RECORDS else [
        f"no mean: {records} {motions}, design codes average over {MEAN_RECORDS} or more"]
    if not inside.all():
        notes.insert(0, f"μ > {top:.3g} not shown: displacement demand below {DEMAND_SHOWN:.0%} of its largest")
    if notes:
        figure.supxlabel("; ".join(notes), fontsize="small")
    figure.suptitle(f"{title}\nfilled: displacement demand; white lines, labelled: peak base shear coefficient V/W",
                    fontsize="medium")
    _labels_inside(figure, axes)
    return figure


def _labels_inside(figure: Figure, axes) -> None:
    """Move each V/W label that the contouring placed across an edge of its panel (a line along the top of the μ
    range) inside the panel, so that no value is cut."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(figure).get_renderer()
    figure.draw(renderer)
    for ax in axes:
        box = ax.get_window_extent(renderer)
        for text in ax.texts:
            extent = text.get_window_extent(renderer)
            dx = max(box.x0 - extent.x0, 0.0) - max(extent.x1 - box.x1, 0.0)
            dy = max(box.y0 - extent.y0, 0.0) - max(extent.y1 - box.y1, 0.0)
            if dx or dy:
                x, y = ax.transData.transform(text.get_position())
                text.set_position(ax.transData.inverted().transform((x + dx, y + dy)))


def _label_every_level(ax, contour) -> None:
    """Label the lines of ``contour`` with their values (two decimals); a level that the automatic placement leaves
    without a label (its lines too short for one inline) gets one at the middle of its longest line."""
    texts = ax.clabel(contour, fmt=lambda value: f"{value:.2f}", fontsize="x-small", inline_spacing=2)
    labelled = {text.get_text() for text in texts}
    for level, path in zip(contour.levels, contour.get_paths()):
        if f"{level:.2f}" in labelled or not len(path.vertices):
            continue
        pieces = [piece for piece in path.to_polygons(closed_only=False) if len(piece)]
        longest = max(pieces, key=len)
        middle = longest[len(longest) // 2]
        ax.text(middle[0], middle[1], f"{level:.2f}", color="white", fontsize="x-small", ha="center", va="center",
                bbox={"facecolor": "black", "alpha": 0.35, "edgecolor": "none", "pad": 1})
