"""The design answer over a grid of yield coefficients k_y (one-way, two-way, either polarity): the same definitions
as over friction ratios (``stickslip.optimum``), named after ky, with the downslope displacement, and a "never slides"
status that follows the resistance's thresholds rather than the PGA."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest
import xarray as xr

from conftest import assert_one_error_line
from stickslip.analysis import mu_max_on_grid, near_optimal_range
from stickslip.grids import Grid
from stickslip.models.rigid import RIGID
from stickslip.optimum import (
    NEVER_SLIDES,
    RESULTS,
    STATUS,
    optimum,
    refine_mu_max,
    results_of,
    solve_curves,
)
from stickslip.records.record import Record, RecordMeta
from stickslip.models import sweep, with_optimum
from test_optimum import MU, pulse, write_at2

G = 9.81
KY = np.round(np.arange(0.02, 0.42, 0.02), 6)


def lopsided(record_id: str = "lopsided") -> Record:
    """A pulse whose positive accelerations reach 0.05 g and whose negative ones reach about 0.5 g [m/s²]."""
    time = np.arange(600) * 0.01
    shape = np.sin(2 * np.pi * 1.7 * time) * np.exp(-((time - 2.5) / 1.2) ** 2)
    shape /= np.abs(shape).max()
    acceleration = np.where(shape > 0, 0.05, 0.5) * G * shape
    return Record(acceleration, 0.01, RecordMeta(record_id=record_id, event="Test 2024", station="L", component="N"))


@pytest.fixture(scope="module")
def records():
    return [pulse("strong", 4.0), pulse("stronger", 7.0, 2), lopsided()]


@pytest.fixture(scope="module")
def one_way(records):
    return with_optimum(sweep(records, ky=KY, mass=5.1), records, q=0.9, reference=0.1)


def test_a_yield_grid_names_its_results_after_ky_with_the_downslope_displacement(one_way, records):
    names = results_of("ky")
    assert list(names) == [name.replace("mu_", "ky_").replace("_mu", "_ky") for name in RESULTS] + [
        "downslope_displacement_at_ky_max", "downslope_displacement_at_ky_low", "downslope_displacement_at_ky_high",
        "largest_downslope_displacement"]
    for name, (units, long_name) in names.items():
        assert one_way[name].dims == ("record",) and one_way[name].attrs == {"units": units, "long_name": long_name}
        assert not re.search(r"\bmu\b", long_name) and "friction" not in long_name
    assert one_way.attrs["reference_ky"] == 0.1 and "reference_mu" not in one_way.attrs
    strong = one_way.sel(record="strong")
    energy = strong.energy_dissipated
    assert float(strong.ky_max) == float(mu_max_on_grid(energy, dim="ky"))
    low, high, _ = near_optimal_range(energy, q=0.9, dim="ky")
    assert (float(strong.ky_low), float(strong.ky_high)) == (float(low), float(high))
    for at in ("ky_max", "ky_low", "ky_high"):
        case = strong.sel(ky=float(strong[at]))
        assert float(strong[f"peak_relative_displacement_at_{at}"]) == float(case.peak_relative_displacement)
        assert float(strong[f"downslope_displacement_at_{at}"]) == float(case.downslope_displacement) > 0
    found = refine_mu_max(records[0], RIGID.design(Grid("ky", KY), mass=5.1, g=G), energy.values)
    assert float(strong.ky_max_continuous) == found.argument and found.argument != float(strong.ky_max)
    assert float(strong.energy_dissipated_reference) == pytest.approx(float(energy.sel(ky=0.1)), rel=1e-12)


def test_two_way_sliding_at_thrust_angle_zero_gives_the_friction_grids_answer_bit_for_bit(records):
    flat = with_optimum(sweep(records, mu=MU, mass=5.1), records, q=0.9)
    two_way = with_optimum(sweep(records, ky=MU, direction="both", thrust_angle=0.0, mass=5.1), records, q=0.9)
    for name in RESULTS:
        np.testing.assert_array_equal(two_way[name.replace("mu_", "ky_").replace("_mu", "_ky")].values,
                                      flat[name].values, err_msg=name)


def test_never_slides_follows_the_thresholds_of_the_resistance_and_the_polarity(one_way, records):
    """0.5 g one way, 0.05 g the other: one-way at k_y >= 0.06 it never slides in normal polarity, only inverse."""
    lopsided_record = records[2]
    assert str(one_way[STATUS].sel(record="lopsided").values) == "ok"  # 0.05 g exceeds k_y = 0.02 and 0.04
    ky_grid = KY[2:]  # from 0.06
    design = RIGID.design(Grid("ky", ky_grid), mass=5.1, g=G)
    results, statuses = optimum([lopsided_record], solve_curves([lopsided_record], design), design)
    assert statuses[0] == (f"{NEVER_SLIDES}: E_df = 0 at every ky of the grid; its largest a, 0.4905 m/s2 (0.05 g), "
                           "is at most the downslope level ky*g = 0.5886 m/s2 at the grid's smallest ky, 0.06 "
                           "(one-way: the block slides only downslope, where a exceeds ky*g)")  # although PGA = 0.47 g
    assert np.isnan(results["ky_max"][0]) and results["energy_dissipated_max"][0] == 0.0
    inverse = RIGID.design(Grid("ky", ky_grid), mass=5.1, g=G, inverse=True)  # the 0.5 g side now drives downslope
    results, statuses = optimum([lopsided_record], solve_curves([lopsided_record], inverse), inverse)
    assert statuses == ["ok"] and results["downslope_displacement_at_ky_max"][0] > 0
    both = RIGID.design(Grid("ky", ky_grid), mass=5.1, g=G, direction="both")  # upslope past -(ky*g): 0.5 g again
    results, statuses = optimum([lopsided_record], solve_curves([lopsided_record], both), both)
    assert statuses == ["ok"] and results["downslope_displacement_at_ky_max"][0] < 0  # it ends upslope


def test_a_weak_record_on_a_two_way_grid_names_both_levels():
    weak = pulse("weak", 0.1, 3)
    design = RIGID.design(Grid("ky", KY), mass=5.1, g=G, direction="both", thrust_angle=10.0, inverse=True)
    _, statuses = optimum([weak], solve_curves([weak], design), design)
    solved = -weak.acceleration
    assert statuses[0] == (
        f"{NEVER_SLIDES}: E_df = 0 at every ky of the grid; its largest a (the record's sign flipped: inverse "
        f"polarity), {solved.max():.4g} m/s2 ({solved.max() / G:.4g} g), is at most the downslope level ky*g = "
        f"{design.case.at('ky', 0.02).resistance.upper:.4g} m/s2 and its smallest, {solved.min():.4g} m/s2 ({solved.min() / G:.4g} g), "
        f"is at least the upslope level -(ky*g + 2 g sin(thrust angle)) = {design.case.at('ky', 0.02).resistance.lower:.4g} m/s2 at "
        "the grid's smallest ky, 0.02")


# --- the commands -----------------------------------------------------------------------------------------------


@pytest.fixture
def lopsided_file(tmp_path):
    path = tmp_path / "lopsided.AT2"
    write_at2(path, lopsided())
    return path


def test_optimum_over_yield_accelerations_prints_ky_and_the_downslope_displacement(run_cli, lopsided_file):
    code, out, err = run_cli("optimum", lopsided_file, "--ky", "0.02g:0.4g:0.02g")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0] == ("yield-coefficient grid: 20 values of ky from 0.02 to 0.4, step 0.02 (yield accelerations "
                        "k_y*g from 0.1962 to 3.924 m/s2); one-way (downslope only); block 1 kg, g = 9.81 m/s2; "
                        "exact solver")
    heading = next(line for line in lines if line.lstrip().startswith("PGA"))
    assert "ky_max" in heading and "E_df at ky = 0.1" in heading and "downslope [m]" in out
    assert err == (f"stickslip: note: {lopsided_file}: the block never slides at the 18 yield coefficients from 0.06 to 0.4: "
                   "its largest a, 0.4905 m/s2 (0.05 g), is at most the downslope level ky*g = 0.5886 m/s2 at ky = 0.06 "
                   "(one-way: the block slides only downslope, where a exceeds ky*g), so E_df = 0 there\n")
    code, out, err = run_cli("optimum", lopsided_file, "--ky", "0.02g:0.4g:0.02g", "--inverse")
    assert code == 0 and err == "" and "; one-way (downslope only); inverse polarity (record sign flipped); " in out


def test_optimum_json_over_yield_accelerations_matches_its_cube(run_cli, lopsided_file, tmp_path):
    cube_path = tmp_path / "cube.nc"
    code, out, err = run_cli("optimum", lopsided_file, "--ky-list", "0.02g", "0.04g", "0.6m/s2", "--direction", "both",
                             "--thrust-angle", "5", "--reference-ky", "0.05g", "--json", "--out", cube_path)
    assert code == 0, err
    document = json.loads(out)
    settings = document["settings"]
    assert settings["given_ky"] == pytest.approx([0.02, 0.04, 0.6 / G], rel=1e-15) and settings["reference_ky"] == 0.05
    assert settings["direction"] == "both" and settings["thrust_angle"] == 5.0 and settings["inverse"] is False
    assert document["units"]["downslope_displacement_at_ky_max"] == "m" and document["units"]["thrust_angle"] == "degree"
    row = document["records"][0]
    cube = xr.load_dataset(cube_path)
    assert cube.attrs["reference_ky"] == 0.05 and cube.attrs["direction"] == "both"
    np.testing.assert_array_equal(cube.ky.values, settings["ky"])  # the grid refined around the range, as printed
    for name in results_of("ky"):
        assert row[name] == pytest.approx(float(cube[name].item()), rel=1e-15, nan_ok=True), name


def test_sweep_adds_the_design_answer_to_a_yield_cube(run_cli, lopsided_file, tmp_path):
    out_path = tmp_path / "cube.nc"
    code, _, err = run_cli("sweep", lopsided_file, "--ky", "0.02g:0.1g:0.02g", "--reference-ky", "0.04g",
                           "--out", out_path)
    assert code == 0, err
    cube = xr.load_dataset(out_path)
    assert set(results_of("ky")) <= set(cube.data_vars) and cube.attrs["reference_ky"] == 0.04
    assert cube.energy_dissipated_reference.item() == pytest.approx(cube.energy_dissipated.sel(ky=0.04).item(), rel=1e-12)
    assert cube.downslope_displacement_at_ky_max.item() == cube.downslope_displacement.sel(ky=cube.ky_max.item()).item()


@pytest.mark.parametrize(("args", "name", "phrase"), [
    (("--ky", "0.05g:0.2g:0.05g", "--reference-mu", "0.1"), "--reference-mu 0.1", "applies to a friction grid"),
    (("--reference-ky", "0.1g"), "--reference-ky 0.1g", "applies to a yield grid (--ky or --ky-list)"),
    (("--ky", "0.05g:0.2g:0.05g", "--reference-ky", "-1"), "--reference-ky -1", "a yield coefficient must be a positive number"),
    (("--direction", "both"), "--direction", "applies with --ky only"),
])
def test_optimum_refuses_options_of_the_other_grid_in_one_line(run_cli, lopsided_file, args, name, phrase):
    assert_one_error_line(*run_cli("optimum", lopsided_file, *args), name, phrase)
