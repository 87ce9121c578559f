"""The design stroke and residual displacement are the largest over the whole near-optimal range, with where they occur.

A device chosen anywhere in the range {μ : E_df ≥ q·E_df,max} must
accommodate the largest stroke of the range, which its ends and its optimum
can understate.
"""

from __future__ import annotations

import json
from importlib.resources import files

import numpy as np
import pytest

from conftest import require_shared_records
from stickslip.grids import Grid
from stickslip.models.rigid import RIGID
from stickslip.optimum import Curves, grid_results, solve_curves
from stickslip.records.readers import read_record

MU = np.array([0.05, 0.1, 0.15, 0.2, 0.25, 0.3])


def curves(energy, stroke, residual) -> Curves:
    return Curves(Grid("mu", MU), np.array([energy], dtype=float), np.array([stroke], dtype=float),
                  np.array([residual], dtype=float))


def test_the_largest_stroke_inside_the_range_is_reported_where_it_occurs():
    # Near-optimal (q = 0.95): mu = 0.1 to 0.25; the stroke peaks inside, at 0.2, not at an end or the optimum 0.15.
    found = grid_results(curves([1.0, 9.6, 10.0, 9.7, 9.5, 2.0], [9.0, 0.3, 0.4, 0.7, 0.5, 8.0],
                                [9.0, 0.1, -0.2, 0.3, -0.6, 8.0]), q=0.95)
    assert (found["mu_low"][0], found["mu_max"][0], found["mu_high"][0]) == (0.1, 0.15, 0.25)
    assert found["largest_stroke"][0] == 0.7 and found["mu_at_largest_stroke"][0] == 0.2
    assert max(found[f"peak_relative_displacement_at_mu_{at}"][0] for at in ("low", "max", "high")) == 0.5
    # Outside the range (mu = 0.05, 0.3) larger strokes do not count; the residual keeps its sign.
    assert found["largest_residual_displacement"][0] == -0.6 and found["mu_at_largest_residual_displacement"][0] == 0.25


def test_a_range_with_a_gap_still_covers_the_gap():
    found = grid_results(curves([9.7, 5.0, 10.0, 0.0, 0.0, 0.0], [0.1, 0.9, 0.2, 0.0, 0.0, 0.0],
                                [0.1, 0.9, 0.2, 0.0, 0.0, 0.0]), q=0.95)
    assert found["contiguous"][0] == 0.0
    assert found["largest_stroke"][0] == 0.9 and found["mu_at_largest_stroke"][0] == 0.1


def test_a_block_that_never_slides_has_no_design_quantities():
    found = grid_results(curves([0.0] * 6, [0.0] * 6, [0.0] * 6))
    assert np.isnan(found["largest_stroke"][0]) and np.isnan(found["mu_at_largest_stroke"][0])


def test_optimum_reports_the_largest_stroke_of_the_range(run_cli):
    path = files("pyslammer") / "sample_ground_motions" / "Northridge_1994_PAC-175.csv"
    code, out, err = run_cli("optimum", path, "--json")
    assert code == 0, err
    row = json.loads(out)["records"][0]
    record = read_record(path)
    grid = np.arange(1, 401) * 0.0025
    swept = solve_curves([record], RIGID.design(Grid("mu", grid), mass=5.1, g=9.81))
    inside = (grid >= row["mu_low"] - 1e-12) & (grid <= row["mu_high"] + 1e-12)
    strokes = swept.peak_relative_displacement[0][inside]
    assert row["largest_stroke"] == pytest.approx(strokes.max(), rel=1e-12)
    assert row["mu_at_largest_stroke"] == pytest.approx(grid[inside][np.argmax(strokes)], rel=1e-12)
    assert row["largest_stroke"] >= max(row[f"peak_relative_displacement_at_mu_{at}"] for at in ("low", "max", "high"))
    assert json.loads(out)["units"]["largest_stroke"] == "m"


def test_kobe_takatori_stroke_is_larger_inside_the_range_than_at_its_ends(run_cli):
    path = require_shared_records() / "slammer" / "records" / "Kobe, Japan 1995" / "TAK-000"
    code, out, err = run_cli("optimum", path, "--json")
    assert code == 0, err
    row = json.loads(out)["records"][0]
    ends = max(row[f"peak_relative_displacement_at_mu_{at}"] for at in ("low", "max", "high"))
    assert row["largest_stroke"] > ends * 1.004  # 0.5805 m against 0.5775 m at mu_high
    assert row["mu_low"] < row["mu_at_largest_stroke"] < row["mu_high"]
