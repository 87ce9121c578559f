"""Every quantity option takes a number with its unit, and a bare number outside its usual range is doubted.

``--radius 200cm`` is R = 2 m, ``--mu 6%`` a friction ratio of 0.06,
``--g 981cm/s2`` g = 9.81 m/s², ``--mass 5100g`` 5.1 kg, ``--time-step 1ms``
0.001 s: the same answers as the numbers in the options' own units.  A bare
``--g 981`` gets a warning that names cm/s² (and the energies it would scale
by 100); a unit of another quantity is one line naming the option and the
units it takes.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr
from conftest import assert_one_error_line

from stickslip.cli.quantities import of_unit, parse_quantity
from stickslip.errors import StickslipError


def write_record(path, pga: float = 0.4, samples: int = 2000):
    """A decaying two-tone motion with the peak ``pga`` [g], as a time,acc CSV (values in g)."""
    time = np.arange(samples) * 0.01
    wave = (np.sin(2 * np.pi * 1.1 * time) + 0.4 * np.sin(2 * np.pi * 3.7 * time)) * np.exp(-0.25 * time)
    np.savetxt(path, np.column_stack([time, pga * wave / np.max(np.abs(wave))]), delimiter=",", header="time,acc",
               comments="", fmt=["%.2f", "%.9g"])
    return path


@pytest.fixture
def record(tmp_path):
    return write_record(tmp_path / "site.csv")


@pytest.mark.parametrize(("text", "unit", "expected"), [
    ("200cm", "m", 2.0), ("0.2 m", "m", 0.2), ("1500mm", "m", 1.5), ("6%", "1", 0.06),
    ("5100g", "kg", 5.1), ("2t", "kg", 2000.0), ("981cm/s2", "m s-2", 9.81), ("981 gal", "m s-2", 9.81),
    ("9.80665m/s²", "m s-2", 9.80665), ("1ms", "s", 0.001), ("30cm/s", "m s-1", 0.3), ("0.3 m/s", "m s-1", 0.3),
    ("5deg", "degree", 5.0), ("500m", "km", 0.5),
])
def test_a_number_with_its_unit_is_read_in_the_quantitys_unit(text, unit, expected):
    value, bare = parse_quantity(text, "--x", of_unit(unit))
    assert value == expected and not bare  # 6% is 0.06 exactly, 5100g 5.1 exactly
    assert parse_quantity("2.5", "--x", of_unit(unit)) == (2.5, True)


@pytest.mark.parametrize(("text", "unit", "message"), [
    ("2ft", "m", "--x '2ft': expected a number with its unit, such as 1m, 1cm, 1mm, 1km or a bare number in m"),
    ("5cm", "kg", "--x '5cm': expected a number with its unit, such as 1kg, 1g, 1t or a bare number in kg"),
    ("1g", "m s-2", "--x '1g': expected a number with its unit, such as 1m/s2, 1cm/s2, 1gal or a bare number in "
                    "m/s2"),
    ("six", "1", "--x 'six': expected a number with its unit, such as 0.06 or 6%"),
])
def test_a_unit_of_another_quantity_is_refused_naming_the_units_taken(text, unit, message):
    with pytest.raises(StickslipError) as caught:
        parse_quantity(text, "--x", of_unit(unit))
    assert str(caught.value) == message


@pytest.mark.parametrize(("given", "bare"), [
    (("--mu", "6%"), ("--mu", "0.06")),
    (("--mu", "0.06", "--mass", "5100g"), ("--mu", "0.06", "--mass", "5.1")),
    (("--mu", "0.06", "--g", "981cm/s2"), ("--mu", "0.06", "--g", "9.81")),
    (("--mu", "0.06", "--radius", "200cm"), ("--mu", "0.06", "--radius", "2")),
    (("--ky", "0.1", "--model", "decoupled", "--height", "2000cm", "--vs", "30000cm/s", "--vs-base", "760m/s"),
     ("--ky", "0.1", "--model", "decoupled", "--height", "20", "--vs", "300", "--vs-base", "760")),
    (("--mu", "0.06", "--method", "newmark", "--time-step", "1ms"),
     ("--mu", "0.06", "--method", "newmark", "--time-step", "0.001")),
])
def test_solve_gives_the_same_answer_with_units_as_with_bare_numbers(run_cli, record, given, bare):
    code, out, err = run_cli("solve", record, *given, "--json")
    assert code == 0 and err == "", err
    code, expected, err = run_cli("solve", record, *bare, "--json")
    assert code == 0 and json.loads(out) == json.loads(expected)


def test_a_bare_g_of_981_is_doubted_as_cm_per_s2(run_cli, record):
    code, out, err = run_cli("solve", record, "--mu", "0.1", "--g", "981", "--json")
    assert code == 0 and err == ("stickslip: warning: --g 981: 981 m/s2 if the number is in m/s2, more than 9.9 m/s2; "
                                 "9.81 m/s2 if it is in cm/s2 (write the unit: 981cm/s2)\n")
    assert json.loads(out)["g"] == 981.0
    for command in (("measures",), ("records", "validate")):
        code, out, err = run_cli(*command, record, "--g", "981")
        assert code == 0 and err.startswith("stickslip: warning: --g 981: 981 m/s2 if the number is in m/s2"), err
        assert err.count("warning: --g") == 1
    code, out, err = run_cli("measures", record, "--g", "981cm/s2", "--json")
    assert code == 0 and err == "" and json.loads(out)["g"] == 9.81
    code, out, err = run_cli("solve", record, "--mu", "0.1", "--g", "9.80665")
    assert code == 0 and err == ""
    assert_one_error_line(*run_cli("measures", record, "--g", "1g"), "--g '1g'",
                          "expected a number with its unit, such as 9.81 or 9.81m/s2")


def test_grids_and_lists_take_units_value_by_value(run_cli, record, tmp_path):
    code, _, err = run_cli("sweep", record, "--mu", "5%:15%:5%", "--out", tmp_path / "percent.nc")
    assert code == 0 and err == "", err
    code, _, err = run_cli("sweep", record, "--mu-list", "5%", "0.1", "15%", "--out", tmp_path / "list.nc")
    assert code == 0 and err == "", err
    for name in ("percent", "list"):
        with xr.open_dataset(tmp_path / f"{name}.nc") as cube:
            np.testing.assert_array_equal(cube["mu"].values, [0.05, 0.1, 0.15])
    assert_one_error_line(*run_cli("sweep", record, "--mu", "5%:15cm:5%", "--out", tmp_path / "bad.nc"),
                          "--mu '15cm'", "expected a number with its unit, such as 0.06 or 6%")


def test_a_bare_value_in_a_grid_beyond_the_plausible_is_doubted_once_per_value(run_cli, record, tmp_path):
    code, out, err = run_cli("optimum", record, "--mu", "0.02:0.1:0.02", "--radius", "2", "--chart-radii",
                             "100cm,200cm", "--chart", tmp_path / "chart.png")
    assert code == 0 and err == "" and (tmp_path / "chart.png").stat().st_size > 0
    code, out, err = run_cli("optimum", record, "--mu-list", "0.5", "2", "3", "--json")
    warned = [line for line in err.splitlines() if "warning" in line]
    assert warned == [f"stickslip: warning: --mu-list 0.5 2 3: a friction ratio of {value}: the block slides only "
                      f"where the ground acceleration passes {value} g, which no ground motion reaches; a friction "
                      f"ratio is written as a fraction ({value / 100:g} for {value} %)" for value in (2, 3)]


@pytest.mark.parametrize(("arguments", "warning"), [
    (("--ky", "0.1", "--model", "decoupled", "--height", "2000", "--vs", "300", "--vs-base", "760"),
     "--height 2000: 2000 m if the number is in m, outside the 0.5 to 500 m usual for soil layers above a sliding "
     "surface; 20 m if it is in cm; 2 m if it is in mm (write the unit: 2000cm)"),
    (("--ky", "0.1", "--model", "decoupled", "--height", "20", "--vs", "30000", "--vs-base", "760"),
     "--vs 30000: 30000 m/s if the number is in m/s, outside the 50 to 2500 m/s usual for the shear-wave velocity of "
     "soil; 300 m/s if it is in cm/s (write the unit: 30000cm/s)"),
    (("--mu", "0.1", "--period", "500"), "--period 500: 500 s if the number is in s, outside the 0.02 to 20 s usual "
                                         "for the natural periods of structures; 0.5 s if it is in ms (write the "
                                         "unit: 500ms)"),
])
def test_a_bare_dimension_outside_its_usual_range_names_the_likely_unit(run_cli, record, arguments, warning):
    code, out, err = run_cli("solve", record, *arguments)
    assert code == 0 and err.splitlines()[0] == f"stickslip: warning: {warning}"
