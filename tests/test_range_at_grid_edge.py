"""A near-optimal range that the grid's edge cuts: ``optimum`` and the record report extend the grid beyond the edge
(down towards 0 and up) until the range ends inside it, say so, and mark the range's quantities as bounds where it
cannot (``mu_low_at_grid_edge``, ``mu_high_at_grid_edge``, ``stickslip.optimum.range_bounds``)."""

from __future__ import annotations

import json

import numpy as np
import pytest
from test_optimum import pulse, write_at2

import stickslip.optimum
from stickslip.grids import Grid, grid_values, range_values
from stickslip.models.rigid import RIGID
from stickslip.optimum import DEFAULT_MU, extend_for_ranges, grid_for_ranges, optimum, range_bounds, solve_curves
from stickslip.reports.design_answer import answer_rows

G = 9.81


def answer(record, values, name="mu", rounds=None, **parameters):
    """The record's results (name -> value) on the grid ``values`` after :func:`extend_for_ranges` (``rounds``),
    the extensions, and the results on the grid as given."""
    design = RIGID.design(Grid(name, values), mass=5.1, g=G, **parameters)
    given = solve_curves([record], design)
    extended, extensions = extend_for_ranges([record], given, design, rounds=rounds)
    found, _ = optimum([record], extended, design.with_values(extended.grid.values))
    before, _ = optimum([record], given, design)
    return ({key: float(value[0]) for key, value in found.items()}, extensions,
            {key: float(value[0]) for key, value in before.items()}, extended)


def test_a_range_cut_at_the_grid_s_first_value_is_found_below_it():
    weakish = pulse("weakish", 0.6, 4)  # μ_max about 0.021
    found, (extension,), before, curves = answer(weakish, range_values(0.02, 0.3, 0.01))
    assert before["mu_low"] == 0.02 and before["mu_low_at_grid_edge"] == 1.0  # cut, as the user's grid had it
    assert (extension.side, extension.start, extension.added, extension.inside) == ("below", 0.01, 1, True)
    assert found["mu_low"] == 0.02  # 0.01 falls below q E_df,max: the range now starts inside the grid
    assert found["mu_low_at_grid_edge"] == 0.0 and found["mu_high_at_grid_edge"] == 0.0
    assert range_bounds(found) == {}
    assert extension.describe("mu") == "1 value of mu added below the grid, 0.01: its near-optimal range now starts " \
                                       "inside the grid"
    refined, _, _ = grid_for_ranges([weakish], curves, RIGID.design(curves.grid, mass=5.1, g=G))
    low = optimum([weakish], refined, RIGID.design(refined.grid, mass=5.1, g=G))[0]["mu_low"][0]
    assert 0.01 < low < 0.02  # refined between the value added and the grid as given


def test_a_range_cut_at_the_grid_s_last_value_is_found_above_it():
    strong = pulse("strong", 4.0)  # μ_max about 0.14
    found, (extension,), before, curves = answer(strong, range_values(0.02, 0.1, 0.02))
    assert before["mu_high"] == 0.1 and before["mu_high_at_grid_edge"] == 1.0 and before["mu_max_at_grid_edge"] == 1.0
    assert (extension.side, extension.start, extension.step, extension.inside) == ("above", 0.12, 0.02, True)
    assert found["mu_high"] > 0.1 and found["mu_high"] < curves.grid.values[-1]
    assert found["mu_high_at_grid_edge"] == 0.0 and found["mu_max_at_grid_edge"] == 0.0
    assert found["energy_dissipated_max"] > before["energy_dissipated_max"]  # the maximum lay beyond the edge


def test_below_the_grid_s_spacing_the_extension_halves_towards_zero():
    faint = pulse("faint", 0.03, 5)  # μ_max below the default grid's first value, 0.0025
    found, (extension,), before, curves = answer(faint, grid_values(DEFAULT_MU))
    assert before["mu_low"] == 0.0025 and before["mu_low_at_grid_edge"] == 1.0
    assert extension.side == "below" and extension.inside
    assert (extension.start, extension.stop) == (0.000625, 0.00125)  # 0.0025 / 4 and / 2
    assert np.all(curves.grid.values > 0.0)
    assert found["mu_low"] < 0.0025 and found["mu_low_at_grid_edge"] == 0.0


def test_a_yield_grid_is_extended_as_a_friction_grid_is():
    found, (extension,), before, _ = answer(pulse("weakish", 0.6, 4), range_values(0.02, 0.3, 0.01), "ky",
                                            direction="both")
    assert before["ky_low_at_grid_edge"] == 1.0 and extension.side == "below" and extension.inside
    assert found["ky_low"] == 0.02 and found["ky_low_at_grid_edge"] == 0.0


def test_where_the_grid_cannot_be_extended_far_enough_the_range_s_quantities_are_bounds():
    found, (extension,), _, _ = answer(pulse("strong", 4.0), range_values(0.02, 0.1, 0.02), rounds=1)
    assert extension.added == 1 and not extension.inside
    assert extension.describe("mu") == ("1 value of mu added above the grid, 0.12: its near-optimal range still "
                                        "reaches the grid's last value, 0.12, where it is cut: a bound")
    assert found["mu_high_at_grid_edge"] == 1.0 and found["mu_low_at_grid_edge"] == 0.0
    residual = "≤" if found["largest_residual_displacement"] < 0 else "≥"
    assert range_bounds(found) == {"mu_high": "≥", "largest_stroke": "≥", "mu_at_largest_stroke": "≥",
                                   "largest_residual_displacement": residual,
                                   "mu_at_largest_residual_displacement": "≥"}
    both = {**found, "mu_low_at_grid_edge": 1.0, "largest_residual_displacement": -0.2, "grid_values_in_range": 3}
    assert range_bounds(both) == {"mu_low": "≤", "mu_high": "≥", "largest_stroke": "≥", "mu_at_largest_stroke": "?",
                                  "largest_residual_displacement": "≤", "mu_at_largest_residual_displacement": "?",
                                  "grid_values_in_range": "≥"}
    page = {variable: value for _, variable, value, _ in answer_rows(found, "mu", 0.95, 0.1)}
    assert page["mu_high"].startswith("≥") and page["largest_stroke"].startswith("≥")
    assert not page["mu_low"].startswith(("≤", "≥")) and not page["mu_max"].startswith(("≤", "≥"))


@pytest.fixture
def weakish_file(tmp_path):
    path = tmp_path / "weakish.AT2"
    write_at2(path, pulse("weakish", 0.6, 4))
    return path


def test_optimum_extends_a_user_s_grid_and_says_so(run_cli, weakish_file):
    code, out, err = run_cli("optimum", weakish_file, "--mu", "0.02:0.3:0.01", "--json")
    assert code == 0, err
    document = json.loads(out)
    (extension,) = document["settings"]["grid_extensions"]
    assert extension == {"record": "weakish", "side": "below", "start": 0.01, "stop": 0.01, "step": 0.01,
                         "values_added": 1, "grid_edge": 0.01, "range_inside": True}
    (row,) = document["records"]
    assert 0.01 < row["mu_low"] < 0.02 and row["mu_low_at_grid_edge"] == 0.0 and row["bounds"] == {}
    assert document["settings"]["given_mu"][0] == 0.02 and document["settings"]["mu"][0] == 0.01
    code, out, err = run_cli("optimum", weakish_file, "--mu", "0.02:0.3:0.01")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[1] == "extended where a near-optimal range reached the grid's edge, for every record:"
    assert lines[2] == "  weakish: 1 value of mu added below the grid, 0.01: its near-optimal range now starts inside " \
                       "the grid"
    assert "≤" not in out and "≥" not in out


def test_optimum_marks_the_range_s_quantities_as_bounds_where_it_cannot_extend(run_cli, weakish_file, monkeypatch):
    monkeypatch.setattr(stickslip.optimum, "MAX_EXTENSIONS", 0)
    code, out, err = run_cli("optimum", weakish_file, "--mu", "0.02:0.3:0.01", "--range-points", "0", "--json")
    assert code == 0, err
    (row,) = json.loads(out)["records"]
    assert row["mu_low"] == 0.02 and row["mu_low_at_grid_edge"] == 1.0
    assert row["bounds"]["mu_low"] == "≤" and row["bounds"]["largest_stroke"] == "≥"
    assert row["bounds"]["grid_values_in_range"] == "≥" and "mu_high" not in row["bounds"]
    code, out, err = run_cli("optimum", weakish_file, "--mu", "0.02:0.3:0.01", "--range-points", "0")
    assert code == 0, err
    cells = [cell.strip() for cell in next(line for line in out.splitlines() if line.startswith("weakish ")).split("  ")
             if cell.strip()]
    assert cells[5] == "≤0.02 to 0.02" and cells[6] == "≥1"
    assert any(line.startswith("≤ ≥: the near-optimal range reaches the grid's edge, which could not be extended")
               for line in out.splitlines())


def test_the_record_report_extends_the_grid_as_optimum_does(run_cli, weakish_file, tmp_path):
    page = tmp_path / "weakish.html"
    code, out, err = run_cli("report", weakish_file, "--mu", "0.02:0.3:0.01", "--out", page)
    assert code == 0, err
    text = page.read_text()
    assert ("extended where the near-optimal range reached its edge (1 value of μ added below the grid, 0.01: its "
            "near-optimal range now starts inside the grid)") in text
    assert "could not be extended far enough" not in text


def test_a_range_that_reaches_where_the_damper_no_longer_slides_is_not_extended_above():
    """By the drift, the damper held to its floor (E_df = 0 at every larger μ) can stay near-optimal: no extension
    above could end that range (each larger μ gives the same answer), so none is made and μ_high is a bound; on a
    grid that ends where the damper still slides, the same range is extended above as before."""
    from stickslip.models.registry import MODELS

    record, damper = pulse("moderate", 1.0), MODELS["friction-tmd"]
    parameters = damper.checked({"structure_period": 1.0, "mu": 0.1})
    design = damper.design(Grid("mu", range_values(0.01, 0.5, 0.01)), "exact", {}, "drift", **parameters)
    given = solve_curves([record], design)
    assert given.energy_dissipated[0, -1] == 0.0  # held at μ = 0.5
    extended, extensions = extend_for_ranges([record], given, design)
    assert [extension.side for extension in extensions] == ["below"]
    assert extended.grid.values[-1] == pytest.approx(0.5)
    found, _ = optimum([record], extended, design.with_values(extended.grid.values))
    assert found["mu_high"][0] == pytest.approx(0.5) and found["mu_high_at_grid_edge"][0] == 1.0  # a bound: ≥ 0.5
    sliding = damper.design(Grid("mu", range_values(0.001, 0.005, 0.001)), "exact", {}, "drift", **parameters)
    short = solve_curves([record], sliding)
    assert short.energy_dissipated[0, -1] > 0.0
    _, extensions = extend_for_ranges([record], short, sliding, rounds=1)
    assert "above" in [extension.side for extension in extensions]
