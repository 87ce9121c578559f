"""The continuous μ_max is the global maximum of E_df(μ) over the grid's span, not a local one near the grid's best point.

E_df(μ) is continuous but has kinks and small bumps: a higher maximum can lie
a few grid cells away from the grid's best point.  :func:`refine_maximum`
resamples every cell that could reach above the best value found so far
(:func:`cells_within_reach`) until the cells are ``xatol`` wide.
"""

from __future__ import annotations


import numpy as np
import pytest
from scipy import optimize

from conftest import require_shared_records
from stickslip.analysis import CELL_SAMPLES, cell_steps, cells_within_reach, refine_maximum
from stickslip.models.rigid import RIGID
from stickslip.optimum import refine_mu_max
from stickslip.grids import Grid
from stickslip.records.readers import read_record

GRID = np.arange(1, 41) * 0.0025


def hidden_peak(x):
    """A broad maximum (1.0 at 0.055, on the grid) and, three cells lower, a higher, narrower one (1.01 at 0.0489)."""
    x = np.asarray(x, dtype=float)
    return np.maximum(1.0 - 5.0 * np.abs(x - 0.055), 1.01 - 20.0 * np.abs(x - 0.0489))


def test_the_grid_and_its_neighbours_see_only_the_lower_maximum():
    values = hidden_peak(GRID)
    best = int(np.argmax(values))
    assert GRID[best] == pytest.approx(0.055)
    local = optimize.minimize_scalar(lambda x: -hidden_peak(x), bounds=(GRID[best - 1], GRID[best + 1]),
                                     method="bounded")
    assert -local.fun < 1.0 + 1e-9  # a search between the best point's neighbours stays on the lower maximum


def test_refine_maximum_finds_the_higher_maximum_three_cells_away():
    found = refine_maximum(hidden_peak, GRID, xatol=1e-7)
    assert found.argument == pytest.approx(0.0489, abs=1e-7)
    assert found.value == pytest.approx(1.01, abs=20 * 1e-7)
    assert found.grid_argument == pytest.approx(0.055) and found.grid_value == pytest.approx(1.0)


def test_cells_within_reach_admit_the_hidden_peak_and_not_the_far_slopes():
    cells = cells_within_reach(GRID, hidden_peak(GRID))
    assert np.any((GRID[cells] <= 0.0489) & (GRID[cells + 1] >= 0.0489))
    assert GRID[cells].min() > 0.04 and GRID[cells + 1].max() < 0.065


def test_a_cell_a_few_tolerances_wide_is_resampled_in_one_round_at_the_tolerance():
    assert cell_steps(0.0025, 1e-4) == 25  # exactly 25 tolerances wide (round-off of 0.0025 / 1e-4 absorbed)
    assert cell_steps(0.0025 * (1 + 1e-6), 1e-4) == 26
    assert cell_steps(0.0025, 1e-6) == CELL_SAMPLES  # 2,500 tolerances: the first of several rounds
    assert cell_steps(5e-7, 1e-6) == 1


def test_refine_maximum_evaluates_each_point_once_and_reaches_its_tolerance():
    arguments = []

    def counted(points):
        arguments.extend(points)
        return hidden_peak(points)

    grid_values = hidden_peak(GRID)
    found = refine_maximum(hidden_peak, GRID, grid_values, xatol=1e-4, on_points=counted)
    assert len(arguments) == len(set(arguments))  # no point twice, the grid's points never again
    assert not set(arguments) & set(GRID)
    assert found.argument == pytest.approx(0.0489, abs=1e-4)
    # one round: each cell within reach, 25 tolerances wide, resampled at exactly the tolerance
    cells = cells_within_reach(GRID, grid_values)
    assert len(arguments) == 24 * cells.size


def test_refine_maximum_checks_its_tolerance():
    with pytest.raises(Exception, match="xatol must be positive"):
        refine_maximum(hidden_peak, GRID, xatol=0.0)


#: Records whose E_df(μ) has its continuous maximum away from the grid's best cell pair
#: (found by comparing with fine sweeps over 400 records of the SLAMMER library), and two that do not.
RECORDS = ["Kocaeli, Turkey 1999/ARK-090", "Nahanni, Canada 1985/NS3-360", "Chi-Chi, Taiwan 1999/TCU076-090",
           "Kobe, Japan 1995/TAK-000", "Landers 1992/LCN-260"]


@pytest.mark.parametrize("name", RECORDS)
def test_continuous_mu_max_is_not_below_a_fine_sweep(name):
    folder = require_shared_records() / "slammer" / "records"
    record = read_record(folder / name)
    grid = np.arange(1, 401) * 0.0025
    design = RIGID.design(Grid("mu", grid), mass=1.0, g=9.81)
    energy = design.curves([record])["energy_dissipated"][0]
    found = refine_mu_max(record, design, energy)
    fine = np.arange(max(found.grid_argument - 0.03, 1e-4), found.grid_argument + 0.03, 1e-5)
    fine_energy = design.with_values(fine).curves([record])["energy_dissipated"][0]
    assert found.value >= fine_energy.max() * (1 - 1e-9)
    assert found.value >= found.grid_value
