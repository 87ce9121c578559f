"""A cube swept over part of a grid, joined with the same records swept over the rest, is the cube of the whole grid
(what the record report does after refining its grid, instead of sweeping the whole refined grid again)."""

from __future__ import annotations

import numpy as np
import pytest

import stickslip
from stickslip.records.record import Record
from stickslip.sweeps import with_grid_values

pytest.importorskip("xarray")


@pytest.mark.parametrize("model, parameters", [("rigid", {}), ("pendulum", {"radius": 2.0})])
def test_values_added_to_a_swept_cube_give_the_cube_of_the_whole_grid(two_tone_record, model, parameters):
    record = Record(two_tone_record.acceleration[:400], two_tone_record.dt, two_tone_record.meta)  # its first 4 s
    grid = np.array([0.04, 0.08, 0.12, 0.2, 0.3])
    whole = stickslip.sweep([record], model=model, mu=grid, **parameters)
    given = stickslip.sweep([record], model=model, mu=grid[[0, 3, 4]], **parameters)
    added = stickslip.sweep([record], model=model, mu=grid[1:3], **parameters)  # between the others
    joined = with_grid_values(given, added)
    assert joined.identical(whole)
    assert list(joined.variables) == list(whole.variables)
    np.testing.assert_array_equal(joined["mu"].values, grid)
