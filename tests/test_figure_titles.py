"""Figure titles wrap to the width of their axes, as drawn, and are never clipped at the figure's edges."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

from stickslip.reports import design_plots, plots
from stickslip.reports.plots import new_figure, save_figure, wrap_titles

#: A record page's title: the record id, then what the figure shows.
LONG_TITLE = "RSN181_IMPVALL.H_H-E06230: energy dissipated by friction, m = 5.1 kg, beside the reference friction ratio"

ANSWER = {"mu_low": 0.065, "mu_high": 0.0875, "contiguous": True, "mu_max_continuous": 0.0778,
          "energy_dissipated_max_continuous": 5.6, "energy_dissipated_reference": 4.7, "efficiency": 0.84}


def _extents(figure):
    """Each title's drawn box and its axes' box, in pixels, after the layout."""
    renderer = figure.canvas.get_renderer()
    figure.draw(renderer)
    return [(axes.title.get_window_extent(renderer), axes.bbox) for axes in figure.axes if axes.title.get_text()]


def test_a_title_wider_than_its_axes_wraps_to_fit_them():
    mu = np.linspace(0.0025, 0.5, 200)
    figure = design_plots.plot_design_energy(mu, 5.0 * np.exp(-((mu - 0.08) / 0.05) ** 2), ANSWER, 0.95, 0.1,
                                             LONG_TITLE)  # the legend outside narrows the axes
    FigureCanvasAgg(figure)
    ((before, axes),) = _extents(figure)
    assert before.width > axes.width  # as the user saw it: wider than its axes, clipped at the figure's edges
    wrap_titles(figure)
    ((title, axes),) = _extents(figure)
    assert axes.x0 - 1 <= title.x0 and title.x1 <= axes.x1 + 1
    assert 0 <= title.x0 and title.x1 <= figure.bbox.width
    text = figure.axes[0].get_title()
    assert "\n" in text and " ".join(text.split()) == LONG_TITLE  # wrapped at spaces, no word lost


def test_save_figure_wraps_the_titles_of_every_panel_and_keeps_a_title_that_fits(tmp_path):
    figure, (wide, narrow) = new_figure(1, 2, figsize=(6.0, 3.0))
    wide.set_title(LONG_TITLE)
    narrow.set_title("fits")
    figure.suptitle("A figure title " * 12)
    save_figure(figure, tmp_path / "panels.png")
    for title, axes in _extents(figure):
        assert axes.x0 - 1 <= title.x0 and title.x1 <= axes.x1 + 1
    assert narrow.get_title() == "fits"
    suptitle = figure.get_suptitle()
    assert "\n" in suptitle and figure._suptitle.get_window_extent().width <= figure.bbox.width


@pytest.mark.parametrize("word", ["RSN181_IMPVALL.H_H-E06230_RSN181_IMPVALL.H_H-E06140_with_a_long_suffix"])
def test_a_word_longer_than_the_axes_is_broken_rather_than_clipped(word):
    figure, ax = new_figure(figsize=(3.0, 2.5))
    ax.set_title(word)
    wrap_titles(figure)
    ((title, axes),) = _extents(figure)
    assert title.x1 <= axes.x1 + 1 and ax.get_title().replace("\n", "") == word


def test_a_figure_that_could_not_be_drawn_keeps_its_title_inside(tmp_path):
    figure = plots.plot_not_drawn(LONG_TITLE + LONG_TITLE, "nothing to draw")
    save_figure(figure, tmp_path / "not_drawn.png")
    ((title, axes),) = _extents(figure)
    assert title.x1 <= axes.x1 + 1 and title.x0 >= axes.x0 - 1
