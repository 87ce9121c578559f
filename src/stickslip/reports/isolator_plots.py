"""Design charts as figures: the friction pendulum's displacement demand and base shear over R × μ, and a
structure's objective and stroke over R or m_d/m_s × μ.

:func:`plot_design_chart` draws, from the statistics of a model's design chart
(:meth:`~stickslip.models.entry.Model.design_chart`), one quantity in filled
contours and another in labelled contour lines over the chart's other
coordinate and the friction ratio μ [1]: for one record, its own; over
several, one panel each for the median and the 84th percentile, and the mean
over seven or more (what design codes average).  The friction pendulum's
(:func:`stickslip.models.pendulum.chart.chart_statistics`): the displacement
demand [m] filled and the peak base shear coefficient V/W [1] in lines over
the surface radius R [m] (with its period 2π√(R/g) [s] on a second axis); a
designer reads off the (R, μ) pairs that keep the displacement within the
isolator's capacity and V/W within what the structure above takes.  The
isolated building's (over R) and the friction damper's (over m_d/m_s): the
quantity of the design answer's objective filled, the stroke in lines, and the
best μ at each value of the other coordinate marked.

The pendulum's levels are round numbers, the same for every chart unless given
(:class:`ChartLevels`): two charts a user compares, with and without the
vertical or of two stations, draw the same values in the same colours.  An
objective's quantity (a drift [m], an acceleration [m/s²], an energy [J]) has
no such common scale: its chart takes round steps over its own values
(:func:`round_levels`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from matplotlib.colors import BoundaryNorm
from matplotlib.figure import Figure
from matplotlib.ticker import FuncFormatter

from stickslip.constants import DEFAULT_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.models.design_chart import MEAN_RECORDS
from stickslip.reports.plots import plot_not_drawn
from stickslip.units import energy_units, readable_units


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
    """The levels of a design chart: the bands of its colours and its lines, each increasing.

    :meth:`every` makes them from two steps, each in its quantity's units
    (``--chart-levels 0.1,0.05``: the friction pendulum's displacement demand
    every 0.1 m and V/W every 0.05; a model's
    :meth:`~stickslip.models.entry.Model.chart_quantities` names its own); the
    default is the pendulum's round :data:`DISPLACEMENT_LEVELS` [m] and
    :data:`SHEAR_LEVELS` [1].
    """

    displacement: tuple[float, ...] = DISPLACEMENT_LEVELS
    shear: tuple[float, ...] = SHEAR_LEVELS
    steps: tuple[float, float] | None = None

    @classmethod
    def every(cls, filled_step: float, lines_step: float,
              quantities: tuple[str, str] = ("colours' quantity", "lines' quantity")) -> ChartLevels:
        """Levels at every multiple of ``filled_step`` (of the colours) and of ``lines_step`` (of the lines), from
        zero, each in the units of its quantity; a step that is not a positive number raises
        :class:`~stickslip.errors.StickslipError` naming the step by its quantity (``quantities``: the colours' and
        the lines', as :meth:`~stickslip.models.entry.Model.chart_quantities` gives them)."""
        for step, what in zip((filled_step, lines_step), quantities):
            if not (math.isfinite(step) and step > 0):
                raise StickslipError(f"the design chart's step of the {what or 'lines'} must be a positive number, "
                                     f"not {step!r}")
        return cls((), (), (float(filled_step), float(lines_step)))

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


#: What a chart contours when its statistics do not say (:func:`plot_design_chart`): the friction pendulum's
#: displacement demand in colour and its V/W in lines.
PENDULUM_CHART = {"filled": "peak_relative_displacement", "lines": "peak_base_shear",
                  "stroke": "peak_relative_displacement", "title": "Friction pendulum design chart"}

#: About how many colour bands, and how many lines, a chart without given levels draws of an objective's quantity.
OBJECTIVE_BANDS, STROKE_LINES = 10, 6


def round_levels(lowest: float, largest: float, count: int) -> np.ndarray:
    """About ``count`` levels at the multiples of a round step (1, 2, 2.5 or 5 times a power of ten) that cover
    ``lowest`` to ``largest``: from the last multiple at or below ``lowest`` to the first at or above ``largest``."""
    span = largest - lowest if largest > lowest else abs(largest) or 1.0
    power = 10.0 ** math.floor(math.log10(span / count))
    step = next(power * factor for factor in (1.0, 2.0, 2.5, 5.0, 10.0) if span / (power * factor) <= count)
    return _multiples(step, math.floor(lowest / step + 1e-9) * step, largest, cover=True)


def plot_design_chart(statistics, g: float = STANDARD_GRAVITY, title: str | None = None,
                      levels: ChartLevels | None = None, shown: tuple[str, ...] | None = None) -> Figure:
    """One quantity in filled contours and another in labelled lines over a chart value (R [m], m_d/m_s [1]) × μ
    [1], one panel per statistic over the records.

    ``statistics`` is the statistics of a design chart (:meth:`~stickslip.models.entry.Model.design_chart`,
    :func:`~stickslip.models.design_chart.chart_statistics`); its attributes say what it contours
    (``filled``, ``lines``, the ``stroke`` whose fading ends the μ range, the ``title``), by default the
    friction pendulum's (:data:`PENDULUM_CHART`): the displacement demand [m] in colour and V/W [1] in lines on
    round levels, the same for every chart (:class:`ChartLevels`).  A chart of an ``objective`` colours its
    quantity on round levels between its smallest and largest (:func:`round_levels`), draws the stroke in lines
    and marks the best μ at each chart value (``objective_larger``: the largest, else the smallest); ``levels``
    given as steps (:meth:`ChartLevels.every`) are those of the filled quantity and of the lines, from zero.  The
    pendulum's panels (and those of given steps) share their levels and one colour bar; an objective's panel has
    its own, since the median and the 84th percentile of a structure's response may lie far apart.  One
    record gets one panel (its own); several, one for each of its statistics (the median, the 84th percentile and, over
    :data:`~stickslip.models.design_chart.MEAN_RECORDS` or more, the mean), or those named in ``shown``.  The
    panels share the μ range, up to where the stroke fades
    (:func:`focused_mu_limit`; the figure says so below the panels).  On a chart over the surface ``radius``, ``g``
    [m/s²] converts R to the period on the top axis.  A chart with fewer than two chart values or two friction
    ratios cannot be contoured and says so.
    """
    drawn = {**PENDULUM_CHART, **{key: statistics.attrs[key] for key in PENDULUM_CHART if key in statistics.attrs}}
    objective = statistics.attrs.get("objective")
    records = int(statistics.attrs.get("records", 0))
    motions = statistics.attrs.get("motions", "records")
    title = title or drawn["title"]
    over = statistics[drawn["filled"]].dims[1]
    values, mu = statistics[over].values, statistics.mu.values
    if values.size < 2 or mu.size < 2:
        what = "radius" if over == "radius" else f"value(s) of {over.replace('_', ' ')}"
        return plot_not_drawn(title, f"{values.size} {what} and {mu.size} friction ratio(s): contours need at least "
                                     "two of each")
    names = [str(name) for name in statistics.statistic.values]
    names = names[:1] if records == 1 else [name for name in names if shown is None or name in shown]

    def panels(name: str) -> np.ndarray:  # (statistic, mu, chart value)
        return statistics[name].sel(statistic=names).values.transpose(0, 2, 1)

    filled, stroke = panels(drawn["filled"]), panels(drawn["stroke"])
    lined = panels(drawn["lines"]) if drawn["lines"] else None
    best = None
    if objective is not None:
        pick = np.nanargmax if statistics.attrs.get("objective_larger") else np.nanargmin
        best = np.array([[mu[pick(column)] if np.isfinite(column).any() else np.nan for column in panel.T]
                         for panel in filled])
    top = max(focused_mu_limit(mu, np.nanmax(stroke, axis=0)), float(np.nanmax(best)) if best is not None else 0.0)
    inside = mu <= top
    mu, filled = mu[inside], filled[:, inside]
    lined = None if lined is None else lined[:, inside]
    shared = objective is None or (levels is not None and levels.steps is not None)
    scales, lines = _scales(filled, lined, levels or ChartLevels(), shared)
    figure = Figure(figsize=(1.6 + 5.2 * len(names) + (0.0 if shared else 1.0 * (len(names) - 1)), 5.6),
                    layout="constrained")
    axes = np.atleast_1d(figure.subplots(1, len(names), sharey=True, squeeze=False)[0])
    quantity = _quantity(statistics, drawn["filled"]) if objective is not None else ("displacement demand", "m")
    for index, (ax, name) in enumerate(zip(axes, names)):
        bands, norm, past = scales[index]
        contoured = ax.contourf(values, mu, filled[index], levels=bands, cmap="viridis", norm=norm,
                                extend="max" if past else "neither")
        if lines.size:
            contour = ax.contour(values, mu, lined[index], levels=lines, colors="white", linewidths=1.0)
            _label_every_level(ax, contour, ".2f" if objective is None else "g")  # a round step's own digits
        if best is not None:
            ax.plot(values, best[index], color="tab:red", marker="o", markersize=4, linewidth=1.2, clip_on=False,
                    zorder=3, label=f"best μ at each {_symbol(statistics[over])}")
            ax.legend(loc="best", fontsize="x-small", framealpha=0.8)
        ax.set_xlabel("radius R of the sliding surface [m]" if objective is None else _axis_label(statistics[over]))
        ax.set_title(f"{name} over {records} {motions}" if records != 1 else "", fontsize="medium")
        if over == "radius":
            period = ax.secondary_xaxis("top", functions=(lambda r: 2 * np.pi * np.sqrt(np.maximum(r, 0.0) / g),
                                                          lambda t: g * (np.asarray(t) / (2 * math.pi)) ** 2))
            period.set_xlabel("period 2π√(R/g) [s]")
        if not shared:  # each panel its own colours: the median and the 84th percentile may lie far apart
            _colour_bar(figure, contoured, [ax], f"{quantity[0]}, {name} [{quantity[1]}]" if records != 1 else
                        f"{quantity[0]} [{quantity[1]}]", bands)
    axes[0].set_ylabel(friction_axis_label(statistics.attrs))
    if shared:
        which = "" if records == 1 else f", {names[0]}" if len(names) == 1 else ""
        _colour_bar(figure, contoured, list(axes), f"{quantity[0]}{which} [{quantity[1]}]", scales[0][0])
    notes = [] if records == 1 or records >= MEAN_RECORDS else [
        f"no mean: {records} {motions}, design codes average over {MEAN_RECORDS} or more"]
    if not inside.all():
        notes.insert(0, f"μ > {top:.3g} not shown: " + ("displacement demand" if objective is None else "stroke")
                     + f" below {DEMAND_SHOWN:.0%} of its largest")
    if notes:
        figure.supxlabel("; ".join(notes), fontsize="small")
    if objective is None:
        legend = "filled: displacement demand; white lines, labelled: peak base shear coefficient V/W"
    else:
        legend = f"objective: {objective}, {statistics.attrs['objective_summary']}\nfilled: {quantity[0]}" + (
            "; white lines, labelled: {} [{}]".format(*_quantity(statistics, drawn["lines"])) if lined is not None
            else "")
    figure.suptitle(f"{title}\n{legend}", fontsize="medium")
    _labels_inside(figure, axes)
    return figure


def _scales(filled: np.ndarray, lined: np.ndarray | None, levels: ChartLevels, shared: bool):
    """Each panel's colour bands, their norm and whether the largest value lies past the last band, and the levels
    of the lines: with ``shared``, the ``levels`` over every panel (the pendulum's round ladder, or given steps);
    else each panel's own round levels (:func:`round_levels`) and round lines within the lined values."""
    if shared:
        bands, ladder, past = levels.bands(float(np.nanmax(filled)))
        norm = BoundaryNorm(ladder, ncolors=256, extend="max" if past else "neither")
        lines = (levels.lines(float(np.nanmin(lined)), float(np.nanmax(lined))) if lined is not None
                 else np.array([]))
        return [(bands, norm, past)] * len(filled), lines
    scales = []
    for panel in filled:
        bands = round_levels(float(np.nanmin(panel)), float(np.nanmax(panel)), OBJECTIVE_BANDS)
        scales.append((bands, BoundaryNorm(bands, ncolors=256), False))
    if lined is None:
        return scales, np.array([])
    lowest, largest = float(np.nanmin(lined)), float(np.nanmax(lined))
    lines = round_levels(0.0, largest, STROKE_LINES)
    return scales, lines[(lines >= lowest) & (lines <= largest) & (lines > 0.0)]


def _colour_bar(figure: Figure, contoured, axes: list, label: str, bands: np.ndarray) -> None:
    """The colour bar of ``contoured`` beside ``axes``, ticked at each band's edge."""
    bar = figure.colorbar(contoured, ax=axes, label=label, ticks=bands,
                          format=FuncFormatter(lambda value, _: f"{value:g}"))
    bar.ax.tick_params(labelsize="small")


def _quantity(statistics, name: str) -> tuple[str, str]:
    """What the statistics' variable ``name`` is, without its trailing remark, and its units as people read them
    (an energy in J/kg for the default 1 kg, :func:`~stickslip.units.energy_units`)."""
    variable = statistics[name]
    units = variable.attrs["units"]
    if units == "J":
        units = energy_units(float(statistics.attrs.get("mass", DEFAULT_BLOCK_MASS)))
    return variable.attrs["long_name"].split(" (")[0], readable_units(units)


def _axis_label(coordinate) -> str:
    """A chart value's axis: its long name and units (``[-]`` for a ratio)."""
    return f"{coordinate.attrs['long_name']} [{readable_units(coordinate.attrs['units'])}]"


def _symbol(coordinate) -> str:
    """A chart value's symbol, the last word of its long name before the units (``R``, ``m_d/m_s``)."""
    words = [word for word in coordinate.attrs["long_name"].split() if word[:1].isupper() or "/" in word]
    return words[0] if words else coordinate.name.replace("_", " ")


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


def _label_every_level(ax, contour, written: str = ".2f") -> None:
    """Label the lines of ``contour`` with their values (in the format ``written``: two decimals by default); a level
    that the automatic placement leaves without a label (its lines too short for one inline) gets one at the middle
    of its longest line."""
    texts = ax.clabel(contour, fmt=lambda value: f"{value:{written}}", fontsize="x-small", inline_spacing=2)
    labelled = {text.get_text() for text in texts}
    for level, path in zip(contour.levels, contour.get_paths()):
        if f"{level:{written}}" in labelled or not len(path.vertices):
            continue
        pieces = [piece for piece in path.to_polygons(closed_only=False) if len(piece)]
        longest = max(pieces, key=len)
        middle = longest[len(longest) // 2]
        ax.text(middle[0], middle[1], f"{level:{written}}", color="white", fontsize="x-small", ha="center", va="center",
                bbox={"facecolor": "black", "alpha": 0.35, "edgecolor": "none", "pad": 1})
