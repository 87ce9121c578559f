"""The friction pendulum's design chart: each record's demands over R × μ are its solves, the statistics their
percentiles over the records (and their mean over seven or more), and the figure contours them on round levels, the
same for every chart unless given (or says why it cannot)."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

import stickslip
from stickslip.models.pendulum.chart import MEAN_RECORDS, chart_statistics, design_chart
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical
from stickslip.reports.isolator_plots import (
    DEMAND_SHOWN,
    DISPLACEMENT_LEVELS,
    SHEAR_LEVELS,
    ChartLevels,
    focused_mu_limit,
    plot_design_chart,
)


@pytest.fixture(scope="module")
def records():
    time = np.arange(0.0, 10.0, 0.01)
    shapes = (4.0 * np.sin(2 * np.pi * 0.7 * time) * np.exp(-0.3 * time),
              6.0 * np.exp(-((time - 3.0) / 0.5) ** 2) * np.sin(2 * np.pi * 0.6 * time),
              3.0 * np.sin(2 * np.pi * 1.3 * time) * np.exp(-0.2 * time))
    return [Record(shape, 0.01, RecordMeta(record_id=f"motion_{k}")) for k, shape in enumerate(shapes)]


@pytest.fixture(scope="module")
def chart(records):
    return design_chart(records, [1.0, 2.5], [0.04, 0.08, 0.12])


def test_each_record_s_demands_are_its_solves(records, chart):
    assert chart.energy_dissipated.dims == ("record", "radius", "mu")
    assert chart.radius.attrs["units"] == "m" and chart.peak_base_shear.attrs["units"] == "1"
    for k, record in enumerate(records):
        for i, radius in enumerate(chart.radius.values):
            for j, mu in enumerate(chart.mu.values):
                solved = stickslip.solve(record, mu=float(mu), radius=float(radius)).scalars()
                for name in ("peak_relative_displacement", "peak_base_shear", "residual_displacement",
                             "energy_dissipated"):
                    assert float(chart[name].values[k, i, j]) == pytest.approx(solved[name], rel=1e-12), name


def test_the_statistics_are_the_median_and_84th_percentile_over_the_records_and_no_mean_below_seven(chart):
    statistics = chart_statistics(chart)
    assert statistics.attrs["records"] == 3 and statistics.attrs["motions"] == "records"
    assert statistics.statistic.values.tolist() == ["median", "84th percentile"]
    np.testing.assert_allclose(statistics.peak_base_shear.values,
                               np.percentile(chart.peak_base_shear.values, [50, 84], axis=0), rtol=1e-15)
    np.testing.assert_allclose(statistics.residual_displacement.sel(statistic="84th percentile").values,
                               np.percentile(np.abs(chart.residual_displacement.values), 84, axis=0), rtol=1e-15)


def test_over_seven_or_more_records_the_chart_adds_the_mean_beside_the_median_and_84th_percentile(records):
    seven = [Record(record.acceleration * factor, record.dt, RecordMeta(record_id=f"{record.meta.record_id}_{factor}"))
             for record in records for factor in (1.0, 1.3, 0.8)][:MEAN_RECORDS]
    chart = design_chart(seven, [1.0, 2.5], [0.04, 0.08, 0.12])
    statistics = chart_statistics(chart)
    assert statistics.statistic.values.tolist() == ["median", "84th percentile", "mean"]
    np.testing.assert_allclose(statistics.peak_relative_displacement.sel(statistic="mean").values,
                               chart.peak_relative_displacement.values.mean(axis=0), rtol=1e-14)
    figure = plot_design_chart(statistics)
    titles = [ax.get_title() for ax in figure.axes if ax.get_ylabel() != "displacement demand [m]"]
    assert titles == ["median over 7 records", "84th percentile over 7 records", "mean over 7 records"]
    assert "no mean" not in figure.get_supxlabel()


def test_the_figure_contours_the_demands_or_says_why_it_cannot(chart):
    figure = plot_design_chart(chart_statistics(chart))
    median, percentile = (ax for ax in figure.axes if ax.get_xlabel())
    assert median.get_xlabel() == "radius R of the sliding surface [m]" and median.get_ylabel() == "friction ratio μ [-]"
    assert (median.get_title(), percentile.get_title()) == ("median over 3 records", "84th percentile over 3 records")
    assert "no mean: 3 records, design codes average over 7 or more" in figure.get_supxlabel()
    assert figure.axes[-1].get_ylabel() == "displacement demand [m]"
    alone = plot_design_chart(chart_statistics(chart), shown=("84th percentile",))
    assert alone.axes[-1].get_ylabel() == "displacement demand, 84th percentile [m]"
    one = plot_design_chart(chart_statistics(chart.isel(record=[0])))
    assert one.axes[-1].get_ylabel() == "displacement demand [m]" and one.axes[0].get_title() == ""
    single = plot_design_chart(chart_statistics(chart.isel(radius=[0])))
    assert "Not drawn: 1 radius and 3 friction ratio(s)" in single.axes[0].texts[0].get_text()


def _drawn_levels(figure):
    """The filled levels, their colour boundaries and the V/W lines of a one-panel chart, and the V/W labels shown."""
    ax = figure.axes[0]
    filled, lines = ax.collections[0], ax.collections[1]
    labels = {text.get_text() for text in ax.texts}
    return list(filled.levels), list(filled.norm.boundaries), list(lines.levels), labels


def test_two_charts_of_one_station_with_and_without_its_vertical_share_round_labelled_levels(records):
    horizontal = records[1]
    vertical = Record(0.4 * horizontal.acceleration[::-1], horizontal.dt, RecordMeta(record_id="motion_up"))
    charts = [design_chart([motion], [1.0, 2.0, 3.0], [0.02, 0.05, 0.08, 0.12, 0.16])
              for motion in (horizontal, WithVertical.of(horizontal, vertical, "up", any_vertical=True))]
    statistics = [chart_statistics(chart) for chart in charts]
    assert not np.allclose(statistics[0].energy_dissipated.values, statistics[1].energy_dissipated.values)
    for found in statistics:
        filled, boundaries, lines, labels = _drawn_levels(plot_design_chart(found))
        assert filled == list(DISPLACEMENT_LEVELS[:len(filled)])  # round, from the one ladder
        assert boundaries == list(DISPLACEMENT_LEVELS)  # one colour per band, whatever the chart
        shear = found.peak_base_shear.values
        # the V/W lines are the ladder's values in the chart's range: the two charts draw the same values where
        # their ranges meet, whatever else differs
        assert lines == [level for level in SHEAR_LEVELS if shear.min() <= level <= shear.max()] and lines
        assert {f"{level:.2f}" for level in lines} <= labels  # every line drawn has its value written on it


def test_chart_levels_every_step_are_multiples_of_the_steps(chart):
    levels = ChartLevels.every(0.1, 0.05)
    figure = plot_design_chart(chart_statistics(chart.isel(record=[0])), levels=levels)
    filled, boundaries, lines, _ = _drawn_levels(figure)
    assert filled == boundaries and filled[0] == 0.0
    assert np.allclose(np.diff(filled), 0.1) and filled[-1] >= float(chart.peak_relative_displacement[0].max())
    assert np.allclose(np.array(lines) / 0.05, np.round(np.array(lines) / 0.05))
    with pytest.raises(stickslip.StickslipError, match="step of the lines' quantity must be a positive number"):
        ChartLevels.every(0.1, 0.0)
    with pytest.raises(stickslip.StickslipError, match=r"step of the V/W \[-\] must be a positive number"):
        ChartLevels.every(0.1, 0.0, quantities=("displacement demand [m]", "V/W [-]"))


def test_the_chart_shows_mu_up_to_where_the_displacement_demand_fades(records):
    wide = design_chart(records, [1.0, 2.5], [0.04, 0.08, 0.12, 0.3, 0.6, 1.0])
    statistics = chart_statistics(wide)
    demand = statistics.peak_relative_displacement.values.max(axis=0).T  # (mu, radius), over the panels
    last = np.nonzero((demand >= DEMAND_SHOWN * demand.max()).any(axis=1))[0][-1]
    assert last < 5  # at mu = 1 these motions hardly slide the block
    top = float(wide.mu.values[last + 1])
    assert focused_mu_limit(wide.mu.values, demand) == top
    figure = plot_design_chart(statistics)
    ax = figure.axes[0]
    assert ax.get_ylim() == pytest.approx((0.04, top))
    note = figure._supxlabel
    assert note.get_text().startswith(f"μ > {top:.3g} not shown: displacement demand below 2% of its largest")
    renderer = FigureCanvasAgg(figure).get_renderer()
    figure.draw(renderer)
    box = note.get_window_extent(renderer)
    for axes in figure.axes:  # below the panels, clear of every label the chart writes
        assert not box.overlaps(axes.get_tightbbox(renderer)), axes.get_title()
    assert focused_mu_limit(wide.mu.values, np.zeros_like(demand)) == 1.0  # nothing slides: the whole grid


def test_a_chart_without_records_or_radii_is_refused():
    with pytest.raises(stickslip.StickslipError, match="at least one record"):
        design_chart([], [1.0], [0.1])
    with pytest.raises(stickslip.StickslipError, match="surface radii R"):
        design_chart([Record(np.ones(10), 0.01, RecordMeta(record_id="x"))], [2.0, 1.0], [0.1])


def test_optimum_draws_a_stations_design_chart_with_its_two_components_and_vertical(run_cli, tmp_path):
    """``optimum A B --pair --vertical V --radius R --chart PNG``: the chart of the pendulum in the plane."""
    from conftest import require_shared_records

    station = require_shared_records() / "three_component" / "Gazli_Karakyr"
    first, second, vertical = (station / f"RSN126_GAZLI_GAZ{name}.AT2" for name in ("000", "090", "-UP"))
    chart_path = tmp_path / "chart.png"
    code, out, err = run_cli("optimum", first, second, "--pair", "--pad", "--radius", "2", "--vertical", vertical,
                             "--mu", "0.04:0.16:0.04", "--chart", chart_path, "--chart-radii", "1,2,3")
    assert code == 0, err
    assert f"written: {chart_path}" in out and "with its vertical" in out and "0 + 90" in out
    assert chart_path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and chart_path.stat().st_size > 20_000


@pytest.mark.parametrize(("arguments", "message"), [
    (("--mu", "0.1", "--chart", "c.png"), "--chart: the rigid model draws no design chart; friction-tmd (over its "
                                          "damper-to-building mass ratio m_d/m_s), isolated"),
    (("--radius", "2", "--chart-radii", "1,2"), "--chart-radii: give --chart PNG"),
    (("--radius", "2", "--chart-radii", "2,1", "--chart", "c.png"), "values must be strictly increasing"),
    (("--radius", "2", "--chart-levels", "0.1,0.05"), "--chart-levels: give --chart PNG"),
    (("--mu", "0.1", "--chart-levels", "0.1,0.05"), "--chart-levels: the rigid model draws no design chart"),
])
def test_a_design_chart_that_cannot_be_drawn_is_one_line(run_cli, tmp_path, records, arguments, message):
    from conftest import assert_one_error_line

    path = tmp_path / "motion.txt"
    np.savetxt(path, np.column_stack([np.arange(records[0].npts) * 0.01, records[0].acceleration / 9.81]))
    code, out, err = run_cli("optimum", path, *[tmp_path / value if value.endswith(".png") else value
                                                 for value in arguments])
    assert_one_error_line(code, out, err, "--chart", message)
    assert not (tmp_path / "c.png").exists()


def test_the_record_report_takes_the_chart_levels_as_two_steps_and_names_its_parameter():
    from stickslip.reports.record_report import ParameterError, report_settings

    def settings(levels):
        return report_settings("x.AT2", None, None, None, None, None, None, 1.0, 9.81, chart_levels=levels)

    assert settings(None)["chart_levels"] == ChartLevels()
    assert settings([0.1, 0.05])["chart_levels"] == ChartLevels.every(0.1, 0.05)
    for bad, message in (([0.1], "expected two steps"), ([0.1, 0.0], "lines' quantity must be a positive number")):
        with pytest.raises(ParameterError, match=f"-p chart_levels .*{message}"):
            settings(bad)
