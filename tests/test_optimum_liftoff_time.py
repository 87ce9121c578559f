"""``stickslip optimum`` with a vertical: the total time the slider spends lifted off [s] and how many times.

Lift-off is where g + a_v ≤ 0: the vertical's alone, so the time is the sweep's ``liftoff_time`` at every μ,
μ_max among them, and the sum of the intervals a solve reports.  Without a vertical, optimum gives neither.
"""

from __future__ import annotations

import csv
import json
from importlib.resources import files as package_files

import numpy as np
import pytest

import stickslip
from stickslip.records.readers import read_record
from stickslip.records.vertical import WithVertical
from stickslip.sweeps import read_cube

SAMPLES = package_files("pyslammer") / "sample_ground_motions"


@pytest.fixture
def files(tmp_path) -> dict:
    """Northridge VSP-360 (0.005 s, first 20 s) and Coalinga PVB-045 times −4 as its vertical, positive up (1.5 g at
    most downwards: the slider lifts off), in m/s2."""
    horizontal = read_record(SAMPLES / "Northridge_1994_VSP-360.csv").acceleration[:4001]
    vertical = -4.0 * read_record(SAMPLES / "Coalinga_1983_PVB-045.csv").acceleration[:4001]
    paths = {}
    for name, values in (("STA-000", horizontal), ("STA-UP", vertical)):
        paths[name] = tmp_path / f"{name}.txt"
        time = np.arange(values.size) * 0.005
        paths[name].write_text("\n".join(f"{t:.3f} {value:.12e}" for t, value in zip(time, values)) + "\n")
    return paths


def test_optimum_gives_the_time_lifted_off_and_the_intervals_in_every_output(run_cli, files, tmp_path):
    common = (files["STA-000"], "--radius", "2", "--units", "m/s2", "--vertical", files["STA-UP"], "--mu",
              "0.02:0.3:0.02")
    cube_path, csv_path = tmp_path / "cube.nc", tmp_path / "table.csv"
    code, out, err = run_cli("optimum", *common, "--out", cube_path, "--csv", csv_path)
    assert code == 0, err
    motion = WithVertical.of(stickslip.read_record(files["STA-000"], units="m/s2"),
                             stickslip.read_record(files["STA-UP"], units="m/s2"))
    cube = read_cube(cube_path).isel(record=0)
    at_mu_max = float(cube["liftoff_time"].sel(mu=float(cube["mu_max"])))
    solved = stickslip.solve(motion, model="pendulum", mu=float(cube["mu_max"]), radius=2.0)
    intervals = solved.liftoff
    assert len(intervals) >= 2 and at_mu_max == pytest.approx(np.sum(intervals[:, 1] - intervals[:, 0]), rel=1e-9)
    np.testing.assert_allclose(cube["liftoff_time"].values, at_mu_max, rtol=1e-9)  # the same at every mu

    lines = out.splitlines()
    header = next(index for index, line in enumerate(lines) if "lift-off" in line and "PGA" in line)
    assert lines[header + 1].split()[-4:] == ["[g]", "time", "[s]", "intervals"]
    assert lines[header + 2].split()[-2:] == [f"{at_mu_max:.4g}", str(len(intervals))]
    assert any(line.startswith("lift-off: the slider off its surface where g + a_v <= 0") for line in lines)

    with open(csv_path, newline="", encoding="utf-8") as handle:
        (row,) = list(csv.DictReader(handle))
    assert float(row["liftoff_time"]) == pytest.approx(at_mu_max, rel=1e-9)
    assert int(row["liftoff_intervals"]) == len(intervals)

    code, printed, err = run_cli("optimum", *common, "--json")
    assert code == 0, err
    document = json.loads(printed)
    assert document["records"][0]["liftoff_time"] == pytest.approx(at_mu_max, rel=1e-9)
    assert document["records"][0]["liftoff_intervals"] == len(intervals)
    assert document["units"]["liftoff_time"] == "s"


def test_optimum_without_a_vertical_has_no_lift_off(run_cli, files):
    code, out, err = run_cli("optimum", files["STA-000"], "--radius", "2", "--units", "m/s2", "--mu", "0.02:0.3:0.02",
                             "--json")
    assert code == 0, err
    row = json.loads(out)["records"][0]
    assert "liftoff_time" not in row and "liftoff_intervals" not in row
    code, out, err = run_cli("optimum", files["STA-000"], "--radius", "2", "--units", "m/s2", "--mu", "0.02:0.3:0.02")
    assert code == 0 and "lift-off" not in out
