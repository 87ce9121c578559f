"""The design chart of the isolated building (over R × μ) and of the friction damper (over m_d/m_s × μ): the
statistics over the records of the objective's quantity and of the stroke, each at a chart point the same as solving
each record there, the objective choosing what is coloured, the best μ at each value marked, ``optimum --chart``
writing it for both models, and the chart's levels (``--chart-levels``, the record report's ``chart_levels``) refused in
one line naming the quantities of each model's chart."""

from __future__ import annotations

import numpy as np
import pytest

import stickslip
from stickslip.models import MODELS
from stickslip.records.record import Record, RecordMeta
from stickslip.reports.isolator_plots import ChartLevels, plot_design_chart, round_levels

BUILDING = {"superstructure_period": 0.5}
DAMPED = {"structure_period": 1.0}
MU = [0.03, 0.06, 0.1, 0.15]


@pytest.fixture(scope="module")
def records():
    """Three short motions [m/s²] of different frequency and strength (3 s at 0.01 s)."""
    time = np.arange(0.0, 3.0, 0.01)
    shapes = (4.0 * np.sin(2 * np.pi * 0.7 * time) * np.exp(-0.3 * time),
              6.0 * np.exp(-((time - 1.5) / 0.4) ** 2) * np.sin(2 * np.pi * 1.1 * time),
              3.0 * np.sin(2 * np.pi * 1.6 * time))
    return [Record(shape, 0.01, RecordMeta(record_id=f"motion_{k}")) for k, shape in enumerate(shapes)]


@pytest.fixture(scope="module")
def building_chart(records):
    return MODELS["isolated"].design_chart(records, [1.0, 2.5], MU, objective="drift", **BUILDING)


def test_the_building_s_chart_is_over_the_radii_and_mu_with_the_drift_and_the_isolator_displacement(building_chart):
    assert building_chart.peak_drift.dims == ("statistic", "radius", "mu")
    assert building_chart.radius.values.tolist() == [1.0, 2.5] and building_chart.mu.values.tolist() == MU
    assert building_chart.statistic.values.tolist() == ["median", "84th percentile"]
    assert building_chart.radius.attrs["units"] == "m" and building_chart.peak_drift.attrs["units"] == "m"
    assert building_chart.attrs["filled"] == "peak_drift"
    assert building_chart.attrs["lines"] == "peak_isolator_displacement"
    assert building_chart.attrs["objective"] == "drift" and building_chart.attrs["records"] == 3


@pytest.mark.parametrize(("radius", "mu"), [(1.0, 0.06), (2.5, 0.15)])
def test_the_building_s_median_at_a_point_is_the_median_of_each_record_solved_there(records, building_chart, radius,
                                                                                       mu):
    solved = [stickslip.solve(record, model="isolated", mu=mu, radius=radius, **BUILDING).scalars()
              for record in records]
    for name in ("peak_drift", "peak_isolator_displacement"):
        found = building_chart[name].sel(statistic="median", radius=radius, mu=mu).item()
        assert found == pytest.approx(np.median([scalars[name] for scalars in solved]), rel=1e-9), name
        upper = building_chart[name].sel(statistic="84th percentile", radius=radius, mu=mu).item()
        assert upper == pytest.approx(np.percentile([scalars[name] for scalars in solved], 84), rel=1e-9), name


def test_the_objective_chooses_the_quantity_coloured(records, building_chart):
    accelerations = MODELS["isolated"].design_chart(records, [1.0, 2.5], MU, objective="floor-acceleration",
                                                    **BUILDING)
    assert accelerations.attrs["filled"] == "peak_floor_acceleration"
    assert accelerations.peak_floor_acceleration.attrs["units"] == "m s-2"
    np.testing.assert_allclose(accelerations.peak_isolator_displacement, building_chart.peak_isolator_displacement,
                               rtol=1e-12)
    stroke = MODELS["isolated"].design_chart(records, [1.0, 2.5], MU, objective="displacement", **BUILDING)
    assert list(stroke.data_vars) == ["peak_isolator_displacement"] and stroke.attrs["lines"] == ""


def test_the_figure_marks_the_mu_of_the_smallest_drift_at_each_radius(building_chart):
    figure = plot_design_chart(building_chart)
    median = figure.axes[0]
    (best,) = [line for line in median.get_lines() if line.get_label().startswith("best μ")]
    drift = building_chart.peak_drift.sel(statistic="median")
    expected = [float(drift.mu[int(np.argmin(row))]) for row in drift.values]
    assert best.get_ydata().tolist() == expected and best.get_xdata().tolist() == [1.0, 2.5]
    assert "objective: drift" in figure.get_suptitle() and median.get_xlabel().endswith("[m]")
    bar = figure.axes[-1].get_yticks()  # the 84th percentile's own colours, on round levels over its values
    upper = building_chart.peak_drift.sel(statistic="84th percentile").values
    assert bar[0] <= upper.min() < bar[1] and bar[-2] < upper.max() <= bar[-1]
    # the record report's default levels (the pendulum's round ladder) leave an objective's levels its own
    default = plot_design_chart(building_chart, levels=ChartLevels())
    assert default.axes[-1].get_yticks().tolist() == bar.tolist()


def test_the_levels_are_round_steps_that_cover_the_values():
    np.testing.assert_allclose(round_levels(0.0043, 0.026, 10), np.arange(0.0025, 0.0276, 0.0025), atol=1e-15)
    np.testing.assert_allclose(round_levels(0.0, 0.93, 6), [0.0, 0.2, 0.4, 0.6, 0.8, 1.0])


def test_the_damper_s_chart_is_over_its_mass_ratios_with_its_stroke(records):
    entry = MODELS["friction-tmd"]
    chart = entry.design_chart(records, [0.02, 0.1], MU, **DAMPED)
    assert chart.energy_dissipated.dims == ("statistic", "mass_ratio", "mu")
    assert chart.mass_ratio.attrs["units"] == "1" and chart.attrs["lines"] == "peak_damper_stroke"
    solved = [stickslip.solve(record, model="friction-tmd", mu=0.1, mass_ratio=0.02, **DAMPED).scalars()
              for record in records]
    for name in ("energy_dissipated", "peak_damper_stroke"):
        found = chart[name].sel(statistic="median", mass_ratio=0.02, mu=0.1).item()
        assert found == pytest.approx(np.median([scalars[name] for scalars in solved]), rel=1e-9), name
    assert entry.design_chart(records[:1], None, MU[:1], **DAMPED).mass_ratio.values.tolist() == list(
        entry.chart_values)


@pytest.fixture()
def motion_file(records, tmp_path):
    path = tmp_path / "motion.txt"
    np.savetxt(path, np.column_stack([np.arange(records[0].npts) * 0.01, records[0].acceleration / 9.81]))
    return path


@pytest.mark.parametrize("arguments", [
    ("--model", "isolated", "--superstructure-period", "0.5", "--objective", "base-shear", "--chart-radii", "1,2"),
    ("--model", "friction-tmd", "--structure-period", "1", "--chart-values", "2%,5%,10%"),
])
def test_optimum_writes_the_chart_of_a_structure(run_cli, motion_file, tmp_path, arguments):
    chart = tmp_path / "chart.png"
    code, out, err = run_cli("optimum", motion_file, "--units", "g", "--mu", "0.02:0.2:0.03", "--range-points", "0",
                             *arguments, "--chart", chart)
    assert code == 0, err
    assert f"written: {chart}" in out and " (m_" in out.splitlines()[0] and "block" not in out.splitlines()[0]
    assert chart.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and chart.stat().st_size > 20_000


def test_the_damper_s_chart_takes_no_radii(run_cli, motion_file, tmp_path):
    from conftest import assert_one_error_line

    code, out, err = run_cli("optimum", motion_file, "--units", "g", "--model", "friction-tmd", "--structure-period",
                             "1", "--chart", tmp_path / "c.png", "--chart-radii", "1,2")
    assert_one_error_line(code, out, err, "--chart-radii", "runs over the damper-to-building mass ratio")
    assert not (tmp_path / "c.png").exists()


#: Each model that draws a chart, its options for ``optimum``, and the quantities its chart's levels step.
CHARTING = [
    (("--radius", "2"), "displacement demand [m]", "peak base shear coefficient V/W [-]"),
    (("--model", "isolated", "--superstructure-period", "0.5"), "energy dissipated by friction E_df [J]",
     "peak isolator displacement [m]"),
    (("--model", "isolated", "--superstructure-period", "0.5", "--objective", "drift"), "peak story drift [m]",
     "peak isolator displacement [m]"),
    (("--model", "friction-tmd", "--structure-period", "1"), "energy dissipated by friction E_df [J]",
     "peak damper stroke [m]"),
    (("--model", "friction-tmd", "--structure-period", "1", "--objective", "floor-acceleration"),
     "peak absolute floor acceleration [m/s2]", "peak damper stroke [m]"),
]


@pytest.mark.parametrize(("model", "filled", "lines"), CHARTING)
@pytest.mark.parametrize(("levels", "says"), [("0.1", "expected two steps, COLOURS,LINES"),
                                              ("0.1,a", "expected two steps, COLOURS,LINES"),
                                              ("0,0.05", "must be a positive number"),
                                              ("0.1,-1", "must be a positive number")])
def test_bad_chart_levels_are_one_line_naming_the_model_s_quantities(run_cli, motion_file, tmp_path, model, filled,
                                                                     lines, levels, says):
    from conftest import assert_one_error_line

    code, out, err = run_cli("optimum", motion_file, "--units", "g", "--mu", "0.02:0.2:0.03", *model,
                             "--chart", tmp_path / "c.png", "--chart-levels", levels)
    assert_one_error_line(code, out, err, f"--chart-levels {levels!r}", says)
    named = {"0,0.05": [filled], "0.1,-1": [lines]}.get(levels, [filled, lines])
    assert all(quantity in err for quantity in named), err
    assert "D,VW" not in err and not (tmp_path / "c.png").exists()


def test_the_chart_levels_of_the_displacement_objective_have_no_lines_to_step(run_cli, motion_file, tmp_path):
    from conftest import assert_one_error_line

    code, out, err = run_cli("optimum", motion_file, "--units", "g", "--model", "isolated", "--superstructure-period",
                             "0.5", "--objective", "displacement", "--chart", tmp_path / "c.png", "--chart-levels", "1")
    assert_one_error_line(code, out, err, "--chart-levels", "COLOURS the stroke [m], LINES unused: no lines drawn")


@pytest.mark.parametrize(("model", "quantities"), [
    ("pendulum", ("displacement demand [m]", "peak base shear coefficient V/W [-]")),
    ("isolated", ("energy dissipated by friction E_df [J]", "peak isolator displacement [m]")),
    ("friction-tmd", ("energy dissipated by friction E_df [J]", "peak damper stroke [m]")),
])
def test_the_record_report_names_the_model_s_chart_quantities_for_bad_levels(model, quantities):
    from stickslip.reports.record_report import ParameterError, report_settings

    def settings(levels):
        return report_settings("x.AT2", None, None, None, None, None, None, 1.0, 9.81, chart_levels=levels, model=model)

    assert settings([0.1, 0.05])["chart_levels"] == ChartLevels.every(0.1, 0.05)
    with pytest.raises(ParameterError, match="expected two steps") as short:
        settings([0.1])
    assert all(quantity in str(short.value) for quantity in quantities)
    with pytest.raises(ParameterError) as negative:
        settings([0.1, -1.0])
    assert f"step of the {quantities[1]} must be a positive number" in str(negative.value)


@pytest.mark.parametrize("command", ["optimum", "report"])
def test_the_help_names_each_model_s_chart_quantities(capsys, command):
    from stickslip.cli import main

    with pytest.raises(SystemExit):
        main([command, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "--chart-levels COLOURS,LINES" in text and "D,VW" not in text
    for entry in MODELS.values():
        if entry.chart_over:
            assert all(" ".join(quantity.split()) in text for quantity in entry.chart_quantities() if quantity)


@pytest.mark.parametrize("name", ["isolated", "friction-tmd"])
def test_the_chart_s_quantities_carry_the_units_of_the_model_s_cube(name):
    from stickslip.optimum import STROKES
    from stickslip.units import readable_units

    entry = MODELS[name]
    cube = entry.variables(entry.case(entry.checked(dict(entry.examples[0]))))
    for objective in entry.objectives:
        curve = entry.objective(objective).curve
        filled = dict(zip(STROKES, entry.strokes)).get(curve, curve)
        colours, lines = entry.chart_quantities(objective)
        assert colours.endswith(f"[{readable_units(cube[filled]['units'])}]"), (objective, colours)
        assert lines == ("" if filled == entry.strokes[0] else
                         f"{entry.strokes[0].replace('_', ' ')} [{readable_units(cube[entry.strokes[0]]['units'])}]")
