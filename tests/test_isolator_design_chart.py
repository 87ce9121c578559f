"""The friction pendulum's design chart: each record's demands over R × μ are its solves, the statistics their
percentiles over the records, and the figure contours them (or says why it cannot)."""

from __future__ import annotations

import numpy as np
import pytest

import stickslip
from stickslip.models.pendulum.chart import chart_statistics, design_chart
from stickslip.records.record import Record, RecordMeta
from stickslip.reports.isolator_plots import DEMAND_SHOWN, focused_mu_limit, plot_design_chart


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


def test_the_statistics_are_the_median_and_84th_percentile_over_the_records(chart):
    statistics = chart_statistics(chart)
    assert statistics.attrs["records"] == 3
    np.testing.assert_allclose(statistics.peak_base_shear.values,
                               np.percentile(chart.peak_base_shear.values, [50, 84], axis=0), rtol=1e-15)
    np.testing.assert_allclose(statistics.residual_displacement.sel(percentile=84).values,
                               np.percentile(np.abs(chart.residual_displacement.values), 84, axis=0), rtol=1e-15)


def test_the_figure_contours_the_demands_or_says_why_it_cannot(chart):
    figure = plot_design_chart(chart_statistics(chart), percentile=84.0)
    ax = figure.axes[0]
    assert ax.get_xlabel() == "radius R of the sliding surface [m]" and ax.get_ylabel() == "friction ratio μ [-]"
    assert "84th percentile over 3 records" in ax.get_title()
    assert figure.axes[1].get_ylabel() == "displacement demand, 84th percentile [m]"
    one = plot_design_chart(chart_statistics(chart.isel(record=[0])))
    assert one.axes[1].get_ylabel() == "displacement demand [m]"
    single = plot_design_chart(chart_statistics(chart.isel(radius=[0])))
    assert "Not drawn: 1 radius and 3 friction ratio(s)" in single.axes[0].texts[0].get_text()


def test_the_chart_shows_mu_up_to_where_the_displacement_demand_fades(records):
    wide = design_chart(records, [1.0, 2.5], [0.04, 0.08, 0.12, 0.3, 0.6, 1.0])
    statistics = chart_statistics(wide)
    demand = statistics.peak_relative_displacement.sel(percentile=50.0).values.T  # (mu, radius)
    last = np.nonzero((demand >= DEMAND_SHOWN * demand.max()).any(axis=1))[0][-1]
    assert last < 5  # at mu = 1 these motions hardly slide the block
    top = float(wide.mu.values[last + 1])
    assert focused_mu_limit(wide.mu.values, demand) == top
    ax = plot_design_chart(statistics).axes[0]
    assert ax.get_ylim() == pytest.approx((0.04, top))
    assert f"μ > {top:.3g} not shown: displacement demand below 2% of its largest" in [text.get_text()
                                                                                      for text in ax.texts]
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
    (("--mu", "0.1", "--chart", "c.png"), "--chart draws a friction pendulum's design chart over its surface radius: "
                                          "the rigid model has none (give --radius R)"),
    (("--radius", "2", "--chart-radii", "1,2"), "--chart-radii: give --chart PNG"),
    (("--radius", "2", "--chart-radii", "2,1", "--chart", "c.png"), "values must be strictly increasing"),
])
def test_a_design_chart_that_cannot_be_drawn_is_one_line(run_cli, tmp_path, records, arguments, message):
    from conftest import assert_one_error_line

    path = tmp_path / "motion.txt"
    np.savetxt(path, np.column_stack([np.arange(records[0].npts) * 0.01, records[0].acceleration / 9.81]))
    code, out, err = run_cli("optimum", path, *[tmp_path / value if value.endswith(".png") else value
                                                 for value in arguments])
    assert_one_error_line(code, out, err, "--chart", message)
    assert not (tmp_path / "c.png").exists()
