"""``optimum`` over several records prints its percentile table over the friction ratios where the block slides,
not rows of zeros past them."""

from __future__ import annotations

import json

import numpy as np
import pytest


@pytest.fixture(scope="module")
def record_files(tmp_path_factory):
    """Three pulses in g whose blocks stop sliding below μ = 0.3 (PGA 0.1 to 0.25 g)."""
    folder = tmp_path_factory.mktemp("statistics")
    time = np.arange(0.0, 6.0, 0.01)
    paths = []
    for number, peak in enumerate((0.1, 0.18, 0.25)):
        path = folder / f"pulse{number}.txt"
        np.savetxt(path, np.column_stack([time, peak * np.sin(2 * np.pi * 1.2 * time) * np.exp(-((time - 2.5) / 0.8) ** 2)]))
        paths.append(path)
    return paths


def test_the_percentile_table_spans_the_friction_ratios_where_the_block_slides(run_cli, record_files):
    grid = ("--mu", "0.01:1:0.01", "--range-points", "0")
    code, out, err = run_cli("optimum", *record_files, "--units", "g", *grid)
    assert code == 0, err
    lines = out.splitlines()
    start = next(index for index, line in enumerate(lines) if line.startswith("over the 3 records"))
    heading = lines[start]
    rows = [line.split() for line in lines[start + 3:] if line.strip()]
    rows = rows[:next(index for index, row in enumerate(rows) if ":" in row[0])]  # up to the records' lines
    code, out, err = run_cli("optimum", *record_files, "--units", "g", *grid, "--json")
    statistics = json.loads(out)["statistics"]
    upper = np.array(statistics["energy_dissipated"][1])  # the 84th percentile of E_df at each mu
    last = np.flatnonzero(upper >= 0.01 * upper.max())[-1]
    mu_last = statistics["mu"][last]
    assert mu_last < 0.3  # the grid runs to 1: without the bound, most rows would be zeros
    assert f"mu up to {mu_last:g}, where the block slides: above it E_df's p84 is below 1% of its largest" in heading
    shown = [float(row[0]) for row in rows]
    assert len(shown) == 20 and shown[0] == 0.01 and shown[-1] == pytest.approx(mu_last)
    assert all(float(row[2]) > 0 for row in rows)  # no row of zeros: E_df's p84 is above zero on every one
    assert np.ptp(np.diff(shown)) <= 0.01 + 1e-9  # evenly spread over the range, to the grid's step
